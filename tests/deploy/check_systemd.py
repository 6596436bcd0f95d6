"""deploy/facewire-server.service: `systemd-analyze verify` (with this
build's server in place of the installed path), its exposure score, the
flags of ExecStart, the stop time-out against the drain, and the example
environment file's variables."""

import os
import re
import shlex
import shutil
import subprocess
import tempfile
import tomllib

from serve_cli import unknown_flags

UNIT = "facewire-server.service"
# `systemd-analyze security` rates 0 (locked down) to 10 (exposed); the unit
# scores 1.4 with systemd 252.
MAX_EXPOSURE = 2.0


def unit_settings(text):
    """{key: [values]} of a unit file's settings."""
    settings = {}
    for line in text.splitlines():
        line = line.strip()
        if line and not line.startswith(("#", ";", "[")) and "=" in line:
            key, _, value = line.partition("=")
            settings.setdefault(key.strip(), []).append(value.strip())
    return settings


def check_systemd(report, deploy, server, cli):
    path = os.path.join(deploy, UNIT)
    text = open(path).read()
    settings = unit_settings(text)
    exec_start = shlex.split(settings.get("ExecStart", [""])[0])
    installed = exec_start[0] if exec_start else ""
    report.check("systemd: ExecStart runs serve with flags the server has",
                 exec_start[1:2] == ["serve"] and not unknown_flags(cli, exec_start),
                 f"{exec_start}; unknown: {unknown_flags(cli, exec_start)}")

    with open(os.path.join(deploy, "facewire-server.toml"), "rb") as file:
        example = tomllib.load(file).get("serve", {})
    drain = float(example.get("drain-seconds", cli.defaults.get("--drain-seconds", 10)))
    stop = settings.get("TimeoutStopSec", ["90"])[-1]
    report.check(f"systemd: TimeoutStopSec is over the example configuration's drain ({drain:g} s)",
                 stop.isdigit() and int(stop) > drain and settings.get("KillSignal") == ["SIGTERM"],
                 f"TimeoutStopSec {stop}, KillSignal {settings.get('KillSignal')}")
    for key in ("NoNewPrivileges", "ProtectSystem", "ProtectHome", "PrivateTmp", "PrivateDevices",
                "MemoryDenyWriteExecute", "RestrictAddressFamilies", "SystemCallFilter", "CapabilityBoundingSet"):
        report.check(f"systemd: {key} is set", key in settings, "missing")

    env_file = os.path.join(deploy, "facewire-server.env")
    names = set(re.findall(r"^#?(FACEWIRE_[A-Z0-9_]+)=", open(env_file).read(), re.MULTILINE))
    report.check("systemd: the example environment file names variables the server reads",
                 bool(names) and names <= cli.env, f"unknown: {sorted(names - cli.env)}")

    analyze = shutil.which("systemd-analyze")
    if not analyze:
        report.skip("systemd-analyze verify", "systemd-analyze is not installed (Debian: the systemd package)")
        return
    with tempfile.TemporaryDirectory(prefix="fw-unit-") as directory:
        # verify wants the program where ExecStart says: this build's, here.
        copy = os.path.join(directory, UNIT)
        with open(copy, "w") as file:
            file.write(text.replace(installed, os.path.abspath(server)))
        result = subprocess.run([analyze, "verify", copy], capture_output=True, text=True, timeout=60)
        report.check("systemd-analyze verify: no error or warning",
                     result.returncode == 0 and not result.stderr.strip(),
                     f"exit {result.returncode}: {result.stderr.strip()}")
        result = subprocess.run([analyze, "security", "--offline=true", "--no-pager", copy],
                                capture_output=True, text=True, timeout=60)
        score = re.search(r"Overall exposure level for \S+: ([0-9.]+)", result.stdout)
        if result.returncode != 0 and not score:
            report.skip("systemd-analyze security", f"this systemd cannot rate a unit file offline: "
                                                    f"{result.stderr.strip()[:200]}")
            return
        report.check(f"systemd-analyze security: exposure at most {MAX_EXPOSURE}",
                     score is not None and float(score.group(1)) <= MAX_EXPOSURE,
                     score.group(0) if score else result.stdout[-300:])
