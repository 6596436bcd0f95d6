#!/usr/bin/env python3
"""Checks deploy/ against itself and against the built server, without a
container engine or a cluster (neither is on the test machines):
  check_deploy_files.py --source-dir DIR --server build/bin/facewire-server
Every YAML file parses; the Dockerfile, the compose file, HAProxy's
configuration, the Kubernetes manifests and the systemd unit have what each
is for (check_containers.py, check_kubernetes.py, check_systemd.py); every
flag, configuration key and FACEWIRE_* variable they give the server is in
its `serve --help`. Exits 1 if a check fails."""

import argparse
import json
import os
import sys
import tomllib

try:
    import yaml
except ImportError:
    sys.exit("check_deploy_files: PyYAML is missing: install python3-yaml (deploy/install-deps.sh does)")

# The checks beside this file, imported without leaving compiled copies in
# the source tree.
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from check_containers import (check_compose, check_dockerfile, check_haproxy,  # noqa: E402
                              dockerfile_instructions, entrypoint_port)
from check_kubernetes import check_kubernetes  # noqa: E402
from check_report import Report  # noqa: E402
from check_systemd import check_systemd  # noqa: E402
from serve_cli import read_serve_cli, unknown_flags  # noqa: E402


def yaml_files(deploy):
    for root, _, names in os.walk(deploy):
        for name in sorted(names):
            if name.endswith((".yml", ".yaml")):
                yield os.path.join(root, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source-dir", required=True, help="the repository's root")
    parser.add_argument("--server", required=True, help="the built facewire-server")
    args = parser.parse_args()
    deploy = os.path.join(args.source_dir, "deploy")
    report = Report()

    cli = read_serve_cli(args.server)
    report.check("serve --help lists the cluster flags the files use",
                 {"--redis", "--node", "--trusted-proxy"} <= cli.flags,
                 f"missing: {sorted({'--redis', '--node', '--trusted-proxy'} - cli.flags)}")

    for path in yaml_files(deploy):
        try:
            with open(path) as file:
                list(yaml.safe_load_all(file))
            report.check(f"parses: {os.path.relpath(path, args.source_dir)}", True)
        except yaml.YAMLError as error:
            report.check(f"parses: {os.path.relpath(path, args.source_dir)}", False, str(error))

    with open(os.path.join(deploy, "facewire-server.toml"), "rb") as file:
        keys = ["--" + key for key in tomllib.load(file).get("serve", {})]
    report.check("facewire-server.toml: its keys are flags of serve (the server ignores others silently)",
                 bool(keys) and not unknown_flags(cli, keys), f"unknown: {unknown_flags(cli, keys)}")

    entrypoint = next((json.loads(a) for k, a in dockerfile_instructions(os.path.join(deploy, "Dockerfile"))
                       if k == "ENTRYPOINT"), [])
    checks = {
        "Dockerfile": lambda: check_dockerfile(report, deploy, args.server, cli),
        "docker-compose.yml": lambda: check_compose(report, deploy, cli),
        "haproxy.cfg": lambda: check_haproxy(report, deploy, entrypoint_port(entrypoint)),
        "kubernetes": lambda: check_kubernetes(report, deploy, args.server, cli),
        "systemd": lambda: check_systemd(report, deploy, args.server, cli),
    }
    for name, check in checks.items():
        try:
            check()
        except Exception as error:  # a file too far from its expected shape to go on with
            report.check(f"{name}: checked to the end", False, f"{type(error).__name__}: {error}")

    print(f"\n{len(report.failures)} failed, {len(report.skips)} skipped")
    for failure in report.failures:
        print(f"  FAIL {failure}")
    return 1 if report.failures else 0


if __name__ == "__main__":
    sys.exit(main())
