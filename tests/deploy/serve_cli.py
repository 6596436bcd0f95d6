"""What the built facewire-server accepts, read from its own help, and a
server started from it: the deployment files are checked against the
binary, so that they cannot name a flag it does not have."""

import os
import re
import select
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass, field


@dataclass
class ServeCli:
    flags: set = field(default_factory=set)        # long flags of `serve` and the top level: "--http", ...
    env: set = field(default_factory=set)          # FACEWIRE_* variables that `serve` reads
    defaults: dict = field(default_factory=dict)   # "--drain-seconds" -> "10"


def read_serve_cli(server):
    """The flags, environment variables and defaults of `server serve --help`
    and of the top-level help (--config lives there)."""
    cli = ServeCli()
    for args in ([server, "serve", "--help"], [server, "--help"]):
        text = subprocess.run(args, capture_output=True, text=True, timeout=30, check=True).stdout
        for line in text.splitlines():
            match = re.match(r"\s+(?:-\w,)?(--[a-z][a-z0-9-]*)(\S*)", line)
            if not match:
                continue
            cli.flags.add(match.group(1))
            default = re.search(r"=(\S+)$", match.group(2))
            if default:
                cli.defaults[match.group(1)] = default.group(1)
        cli.env.update(re.findall(r"\(Env:(FACEWIRE_[A-Z0-9_]+)\)", text))
    return cli


def unknown_flags(cli, words):
    """The --flags among `words` (a command line) that the server lacks; a
    flag's value after '=' is ignored."""
    return sorted({w.split("=", 1)[0] for w in words if w.startswith("--")} - cli.flags)


class RunningServer:
    """A facewire-server started with `args` (plus a fresh data directory and
    loopback ports), until stop(). Raises RuntimeError with its output if it
    exits or says nothing within the time-out."""

    def __init__(self, server, args, timeout=60):
        self.data = tempfile.TemporaryDirectory(prefix="fw-deploy-")
        command = [server, "serve", *args, "--http", "127.0.0.1:0", "--tcp", "127.0.0.1:0",
                   "--data", self.data.name, "--no-demo-room"]
        self.log = tempfile.TemporaryFile(mode="w+")
        self.process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=self.log, text=True,
                                        env={k: v for k, v in os.environ.items() if not k.startswith("FACEWIRE_")})
        deadline = time.monotonic() + timeout
        self.port = None
        while self.port is None:
            remaining = deadline - time.monotonic()
            if remaining <= 0 or not select.select([self.process.stdout], [], [], remaining)[0]:
                self.stop()
                raise RuntimeError(f"{' '.join(command)} did not say where it listens within {timeout} s: "
                                   f"{self.stderr()}")
            line = self.process.stdout.readline()
            if not line:
                self.process.wait()
                error = f"{' '.join(command)} exited with {self.process.returncode}: {self.stderr()}"
                self.stop()
                raise RuntimeError(error)
            match = re.search(r"listening on http://127\.0\.0\.1:(\d+)/", line)
            if match:
                self.port = int(match.group(1))

    def stderr(self):
        self.log.seek(0)
        return self.log.read()[-2000:]

    def stop(self):
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.data.cleanup()
