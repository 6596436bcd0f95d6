"""deploy/Dockerfile (and its ignore file), deploy/docker-compose.yml and
deploy/haproxy.cfg: their structure, the flags they give the server, the
image's health check run against a real server, and `haproxy -c` where
HAProxy is installed."""

import ipaddress
import json
import os
import re
import shutil
import subprocess

import yaml

from serve_cli import RunningServer, unknown_flags


def dockerfile_instructions(path):
    """[(KEYWORD, arguments)] of a Dockerfile, continuation lines joined."""
    instructions, pending = [], ""
    with open(path) as file:
        for line in file:
            stripped = line.strip()
            if not pending and (not stripped or stripped.startswith("#")):
                continue
            if stripped.startswith("#"):
                continue
            if stripped.endswith("\\"):
                pending += stripped[:-1] + " "
                continue
            text = pending + stripped
            pending = ""
            keyword, _, arguments = text.partition(" ")
            instructions.append((keyword.upper(), arguments.strip()))
    return instructions


def entrypoint_port(entrypoint):
    """The port of --http in the image's entrypoint."""
    if "--http" in entrypoint:
        return int(entrypoint[entrypoint.index("--http") + 1].rsplit(":", 1)[1])
    return None


def check_dockerfile(report, deploy, server, cli):
    path = os.path.join(deploy, "Dockerfile")
    steps = dockerfile_instructions(path)
    stages = [args for keyword, args in steps if keyword == "FROM"]
    report.check("Dockerfile: a bookworm build stage and a slim runtime stage",
                 len(stages) >= 2 and stages[0].startswith("debian:bookworm ") and
                 stages[-1].split()[0] == "debian:bookworm-slim", f"stages {stages}")
    last_from = max(i for i, (keyword, _) in enumerate(steps) if keyword == "FROM")
    runtime = steps[last_from + 1:]
    users = [args for keyword, args in runtime if keyword == "USER"]
    report.check("Dockerfile: the runtime stage runs as a non-root user",
                 bool(users) and users[-1].split(":")[0] not in ("0", "root"), f"USER {users}")
    report.check("Dockerfile: the build stage installs with install-deps.sh --build-only, an option it has",
                 any("install-deps.sh --build-only" in args for keyword, args in steps if keyword == "RUN") and
                 "--build-only)" in open(os.path.join(deploy, "install-deps.sh")).read(),
                 "no RUN bash deploy/install-deps.sh --build-only, or the script lacks the option")
    report.check("Dockerfile: the runtime stage copies the program from the build stage",
                 any(keyword == "COPY" and "--from=build" in args and "facewire-server" in args
                     for keyword, args in runtime), "no COPY --from=build of facewire-server")
    entrypoint = next((json.loads(args) for keyword, args in runtime if keyword == "ENTRYPOINT"), [])
    report.check("Dockerfile: ENTRYPOINT runs serve with flags the server has",
                 entrypoint[1:2] == ["serve"] and not unknown_flags(cli, entrypoint),
                 f"{entrypoint}; unknown: {unknown_flags(cli, entrypoint)}")
    port = entrypoint_port(entrypoint)
    exposed = [p.split("/")[0] for keyword, args in runtime if keyword == "EXPOSE" for p in args.split()]
    report.check("Dockerfile: EXPOSE names the HTTP port of the entrypoint", str(port) in exposed,
                 f"EXPOSE {exposed}, --http port {port}")
    report.check("Dockerfile: STOPSIGNAL SIGTERM (the server drains on it)",
                 ("STOPSIGNAL", "SIGTERM") in runtime, "no STOPSIGNAL SIGTERM")
    env_names = {word.split("=")[0] for keyword, args in runtime if keyword == "ENV" for word in args.split()}
    report.check("Dockerfile: ENV names variables the server reads", env_names <= cli.env,
                 f"unknown: {sorted(env_names - cli.env)}")
    volumes = [v for keyword, args in runtime if keyword == "VOLUME" for v in json.loads(args)]
    data = entrypoint[entrypoint.index("--data") + 1] if "--data" in entrypoint else None
    report.check("Dockerfile: the data directory is a VOLUME", data in volumes, f"--data {data}, VOLUME {volumes}")

    ignore = os.path.join(deploy, "Dockerfile.dockerignore")
    patterns = open(ignore).read().split() if os.path.exists(ignore) else []
    report.check("Dockerfile.dockerignore: leaves the build trees and .git out of the context",
                 {"build", "build-*", ".git"} <= set(patterns), f"patterns {patterns}")

    check_healthcheck(report, deploy, runtime, port, server)
    check_runtime_packages(report, deploy, server)


def check_healthcheck(report, deploy, runtime, port, server):
    """Runs the image's HEALTHCHECK command against a real server (its port
    put in place of the image's), and against the port once it is closed."""
    healthcheck = next((args for keyword, args in runtime if keyword == "HEALTHCHECK"), "")
    if "CMD [" not in healthcheck:
        report.check("Dockerfile: HEALTHCHECK (exec form)", False, f"HEALTHCHECK {healthcheck!r}")
        return
    command = json.loads(healthcheck[healthcheck.index("CMD [") + 4:])
    if not any("/healthz" in word for word in command):
        report.check("Dockerfile: HEALTHCHECK asks /healthz", False, f"{command}")
        return
    # The example configuration file along (flags win over it: loopback
    # addresses, a fresh data directory), so that the server checks it too.
    example = os.path.join(deploy, "facewire-server.toml")
    try:
        running = RunningServer(server, ["--config", example])
    except RuntimeError as error:
        report.check("facewire-server.toml: the server starts with it", False, str(error))
        return
    report.check("facewire-server.toml: the server starts with it", True)
    live = [word.replace(f"127.0.0.1/{port}", f"127.0.0.1/{running.port}") for word in command]
    try:
        up = subprocess.run(live, capture_output=True, text=True, timeout=30)
    finally:
        running.stop()
    down = subprocess.run(live, capture_output=True, text=True, timeout=30)
    report.check("Dockerfile: HEALTHCHECK passes against a running server and fails once it stopped",
                 up.returncode == 0 and down.returncode != 0,
                 f"running: exit {up.returncode} {up.stderr.strip()}; stopped: exit {down.returncode}")


def check_runtime_packages(report, deploy, server):
    """runtime-packages.sh, as the Dockerfile's build stage runs it, on this build's server."""
    header = os.path.join(deploy, "..", "avatar", "photo", "include", "fw", "photo", "landmark_model.hpp")
    data_files = re.findall(r'"(/usr/share/[^"]+)"', open(header).read())
    result = subprocess.run(["bash", os.path.join(deploy, "runtime-packages.sh"), server, *data_files],
                            capture_output=True, text=True, timeout=120)
    packages = result.stdout.split()
    report.check("runtime-packages.sh: lists the server's libraries and the landmark model's package",
                 result.returncode == 0 and len(data_files) == 2 and "libdlib-data" in packages and
                 any(p.startswith("libopencv-core") for p in packages),
                 f"exit {result.returncode}: {result.stderr.strip()} {packages} (data files {data_files})")


def check_compose(report, deploy, cli):
    path = os.path.join(deploy, "docker-compose.yml")
    with open(path) as file:
        compose = yaml.safe_load(file)
    services = compose.get("services", {})
    report.check("docker-compose.yml: redis, node-a, node-b and a proxy",
                 {"redis", "node-a", "node-b", "proxy"} <= set(services), f"services {sorted(services)}")
    redis = services.get("redis", {})
    report.check("docker-compose.yml: Redis 7 with its append-only file on a volume",
                 str(redis.get("image", "")).startswith("redis:7") and
                 "--appendonly yes" in " ".join(redis.get("command", [])) and
                 any(str(v).endswith(":/data") for v in redis.get("volumes", [])), f"redis {redis}")

    proxy = services.get("proxy", {})
    proxy_address = proxy.get("networks", {}).get("cluster", {}).get("ipv4_address") \
        if isinstance(proxy.get("networks"), dict) else None
    drain = float(cli.defaults.get("--drain-seconds", "10"))
    names = set()
    for name in ("node-a", "node-b"):
        node = services.get(name, {})
        command = node.get("command", [])
        report.check(f"docker-compose.yml: {name} is built from deploy/Dockerfile",
                     node.get("build", {}).get("dockerfile") == "deploy/Dockerfile", f"build {node.get('build')}")
        report.check(f"docker-compose.yml: {name}'s flags exist in the server", not unknown_flags(cli, command),
                     f"unknown: {unknown_flags(cli, command)}")
        has = {flag: command[command.index(flag) + 1] for flag in ("--redis", "--node", "--trusted-proxy")
               if flag in command[:-1]}
        report.check(f"docker-compose.yml: {name} joins Redis under its own name and trusts the proxy alone",
                     has.get("--redis", "").startswith("redis://redis:") and "--trusted-proxy" in has and
                     proxy_address is not None and
                     ipaddress.ip_address(proxy_address) in ipaddress.ip_network(has["--trusted-proxy"]),
                     f"{has}, proxy at {proxy_address}")
        names.add(has.get("--node"))
        env = set(node.get("environment", {}))
        report.check(f"docker-compose.yml: {name}'s environment names variables the server reads",
                     env <= cli.env, f"unknown: {sorted(env - cli.env)}")
        grace = str(node.get("stop_grace_period", "10s"))
        report.check(f"docker-compose.yml: {name}'s stop_grace_period is over the drain ({drain:g} s)",
                     grace.endswith("s") and float(grace[:-1]) > drain, f"stop_grace_period {grace}")
    report.check("docker-compose.yml: the nodes have different names", len(names) == 2, f"{names}")

    mounts = [str(v) for v in proxy.get("volumes", [])]
    config = next((m.split(":")[0] for m in mounts if "haproxy.cfg" in m), None)
    report.check("docker-compose.yml: the proxy is HAProxy with deploy/haproxy.cfg",
                 str(proxy.get("image", "")).startswith("haproxy:") and config == "./haproxy.cfg",
                 f"image {proxy.get('image')}, mounts {mounts}")


def check_haproxy(report, deploy, http_port):
    path = os.path.join(deploy, "haproxy.cfg")
    text = open(path).read()
    lines = [line.split("#")[0].strip() for line in text.splitlines()]
    tunnel = next((line.split()[2] for line in lines if line.startswith("timeout tunnel")), "")
    seconds = {"s": 1, "m": 60, "h": 3600, "d": 86400}.get(tunnel[-1:], 0) * float(tunnel[:-1] or 0)
    report.check("haproxy.cfg: WebSockets stay up (HTTP mode, timeout tunnel of 10 min or more)",
                 "mode http" in lines and seconds >= 600, f"timeout tunnel {tunnel!r}")
    report.check("haproxy.cfg: the client's address goes in X-Forwarded-For",
                 "http-request set-header X-Forwarded-For %[src]" in lines or "option forwardfor" in lines,
                 "neither set-header X-Forwarded-For nor option forwardfor")
    report.check("haproxy.cfg: nodes are checked on /readyz",
                 any(line.startswith("http-check send") and "uri /readyz" in line for line in lines),
                 "no http-check send ... uri /readyz")
    servers = [line.split()[2] for line in lines if line.startswith("server ")]
    report.check("haproxy.cfg: both compose nodes on their HTTP port",
                 {f"node-a:{http_port}", f"node-b:{http_port}"} <= set(servers), f"servers {servers}")

    haproxy = os.environ.get("FW_HAPROXY") or shutil.which("haproxy")
    if not haproxy:
        report.skip("haproxy -c", "HAProxy is not installed (apt-get install haproxy, or FW_HAPROXY=PATH)")
        return
    result = subprocess.run([haproxy, "-c", "-f", path], capture_output=True, text=True, timeout=30)
    # Outside compose the node names do not resolve; HAProxy says so and
    # starts anyway (init-addr none). Any other warning is a finding.
    warnings = [line for line in result.stderr.splitlines()
                if "[WARNING]" in line and "could not resolve address" not in line]
    report.check("haproxy -c: the configuration is valid, with no warning but unresolved node names",
                 result.returncode == 0 and not warnings, f"exit {result.returncode}: {result.stderr.strip()}")
