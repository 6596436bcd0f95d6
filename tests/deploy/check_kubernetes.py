"""deploy/kubernetes/: every manifest parses, kustomization.yaml lists files
that exist, and the objects fit together and with the server: probes on
/readyz and /healthz at the container's HTTP port, a grace period over the
drain, a locked-down pod, a ConfigMap that the server itself accepts."""

import os
import tempfile
import tomllib
from urllib.parse import urlparse

import yaml

from serve_cli import RunningServer, unknown_flags

SERVER_CONTAINER = "facewire-server"


def load_manifests(directory):
    """{file name: [documents]} of every YAML file in `directory`."""
    manifests = {}
    for name in sorted(os.listdir(directory)):
        if name.endswith((".yaml", ".yml")):
            with open(os.path.join(directory, name)) as file:
                manifests[name] = [doc for doc in yaml.safe_load_all(file) if doc]
    return manifests


def port_number(container, port):
    """A probe's or service's port (a number or a port name) as the container's number."""
    for entry in container.get("ports", []):
        if port in (entry.get("name"), entry.get("containerPort")):
            return entry.get("containerPort")
    return None


def selects(selector, labels):
    return bool(selector) and all(labels.get(key) == value for key, value in selector.items())


def check_kubernetes(report, deploy, server, cli):
    directory = os.path.join(deploy, "kubernetes")
    manifests = load_manifests(directory)
    report.check("kubernetes: every manifest parses", bool(manifests), f"no YAML files in {directory}")
    kustomization = manifests.get("kustomization.yaml", [{}])[0]
    resources = kustomization.get("resources", [])
    report.check("kubernetes: kustomization.yaml lists existing files", bool(resources) and
                 all(os.path.exists(os.path.join(directory, r)) for r in resources), f"resources {resources}")
    objects = [doc for name in resources for doc in manifests.get(name, [])]
    by_kind = {}
    for doc in objects:
        by_kind.setdefault(doc.get("kind"), []).append(doc)
    report.check("kubernetes: a Deployment, Services, a ConfigMap, Redis and a PodDisruptionBudget",
                 {"Deployment", "Service", "ConfigMap", "PodDisruptionBudget"} <= set(by_kind) and
                 ("StatefulSet" in by_kind or len(by_kind.get("Deployment", [])) >= 2), f"kinds {sorted(by_kind)}")

    deployment = next((d for d in by_kind.get("Deployment", [])
                       for c in d["spec"]["template"]["spec"]["containers"] if c["name"] == SERVER_CONTAINER), None)
    if not report.check("kubernetes: a Deployment runs the server", deployment is not None,
                        f"no container named {SERVER_CONTAINER}"):
        return
    pod = deployment["spec"]["template"]["spec"]
    container = next(c for c in pod["containers"] if c["name"] == SERVER_CONTAINER)
    labels = deployment["spec"]["template"]["metadata"]["labels"]
    report.check("kubernetes: two replicas or more", deployment["spec"].get("replicas", 1) >= 2,
                 f"replicas {deployment['spec'].get('replicas')}")

    # The ConfigMap the container reads its configuration from.
    command = container.get("command", []) + container.get("args", [])
    config_path = command[command.index("--config") + 1] if "--config" in command[:-1] else ""
    mounts = {m["name"]: m for m in container.get("volumeMounts", [])}
    volumes = {v["name"]: v for v in pod.get("volumes", [])}
    config_map_name = next((volumes[n]["configMap"]["name"] for n, m in mounts.items()
                            if config_path.startswith(m["mountPath"] + "/") and "configMap" in volumes.get(n, {})), None)
    config_map = next((c for c in by_kind.get("ConfigMap", []) if c["metadata"]["name"] == config_map_name), None)
    key = os.path.basename(config_path)
    if not report.check("kubernetes: --config is a file of a mounted ConfigMap",
                        config_map is not None and key in config_map.get("data", {}),
                        f"--config {config_path!r}, ConfigMap {config_map_name}"):
        return
    settings = tomllib.loads(config_map["data"][key]).get("serve", {})
    keys = ["--" + k for k in settings]
    report.check("kubernetes: the ConfigMap's keys and the container's flags exist in the server",
                 not unknown_flags(cli, keys + command),
                 f"unknown: {unknown_flags(cli, keys + command)}")
    env = {e["name"] for e in container.get("env", [])}
    report.check("kubernetes: the container's environment names variables the server reads", env <= cli.env,
                 f"unknown: {sorted(env - cli.env)}")
    check_config_map_accepted(report, server, config_map["data"][key])

    http_port = int(str(settings.get("http", "")).rsplit(":", 1)[-1] or 0)
    for probe, path in (("readinessProbe", "/readyz"), ("livenessProbe", "/healthz")):
        get = container.get(probe, {}).get("httpGet", {})
        report.check(f"kubernetes: {probe} asks {path} on the server's HTTP port ({http_port})",
                     get.get("path") == path and port_number(container, get.get("port")) == http_port,
                     f"{probe} {get}")

    drain = float(settings.get("drain-seconds", cli.defaults.get("--drain-seconds", 10)))
    pre_stop = container.get("lifecycle", {}).get("preStop", {}).get("exec", {}).get("command", [])
    pause = float(pre_stop[1]) if pre_stop[:1] == ["sleep"] else 0
    grace = pod.get("terminationGracePeriodSeconds", 30)
    report.check(f"kubernetes: terminationGracePeriodSeconds is over the preStop pause and the drain "
                 f"({pause:g} + {drain:g} s)", grace > pause + drain, f"{grace}")

    context = {**pod.get("securityContext", {}), **container.get("securityContext", {})}
    report.check("kubernetes: non-root, read-only root, no privilege escalation, every capability dropped",
                 context.get("runAsNonRoot") is True and context.get("readOnlyRootFilesystem") is True and
                 context.get("allowPrivilegeEscalation") is False and
                 "ALL" in context.get("capabilities", {}).get("drop", []), f"securityContext {context}")
    data_mount = next((n for n, m in mounts.items() if m["mountPath"] == settings.get("data")), None)
    report.check("kubernetes: the data directory is an emptyDir",
                 data_mount is not None and "emptyDir" in volumes.get(data_mount, {}),
                 f"data {settings.get('data')}, mounts {list(mounts)}")
    resources = container.get("resources", {})
    report.check("kubernetes: the server asks for CPU and memory and has a memory limit",
                 {"cpu", "memory"} <= set(resources.get("requests", {})) and
                 "memory" in resources.get("limits", {}), f"resources {resources}")

    services = [s for s in by_kind.get("Service", []) if selects(s["spec"].get("selector"), labels)]
    target_ports = [p.get("targetPort") for s in services for p in s["spec"].get("ports", [])]
    report.check("kubernetes: a Service sends to the server's HTTP port",
                 http_port in [port_number(container, t) for t in target_ports],
                 f"services {[s['metadata']['name'] for s in services]}, target ports {target_ports}")

    budgets = by_kind.get("PodDisruptionBudget", [])
    report.check("kubernetes: a PodDisruptionBudget keeps at least one server",
                 any(b["spec"].get("minAvailable") == 1 and
                     selects(b["spec"].get("selector", {}).get("matchLabels"), labels) for b in budgets),
                 f"budgets {[b['spec'] for b in budgets]}")

    check_redis(report, by_kind, settings)
    check_ingress(report, manifests.get("ingress.yaml", []))


def check_config_map_accepted(report, server, text):
    """The server starts with the ConfigMap's file (its addresses, data
    directory and Redis replaced by loopback ones: flags win over the file,
    and no Redis runs here)."""
    lines = [line for line in text.splitlines() if not line.strip().startswith("redis")]
    with tempfile.NamedTemporaryFile("w", suffix=".toml") as file:
        file.write("\n".join(lines) + "\n")
        file.flush()
        try:
            RunningServer(server, ["--config", file.name]).stop()
            report.check("kubernetes: the server starts with the ConfigMap's configuration file", True)
        except RuntimeError as error:
            report.check("kubernetes: the server starts with the ConfigMap's configuration file", False, str(error))


def check_redis(report, by_kind, settings):
    url = urlparse(str(settings.get("redis", "")))
    report.check("kubernetes: the ConfigMap names a Redis (redis://HOST:PORT)", url.scheme == "redis" and
                 url.hostname is not None, f"redis {settings.get('redis')!r}")
    workloads = [w for kind in ("StatefulSet", "Deployment") for w in by_kind.get(kind, [])
                 for c in w["spec"]["template"]["spec"]["containers"] if str(c.get("image", "")).startswith("redis:")]
    if not report.check("kubernetes: Redis runs", bool(workloads), "no workload with a redis: image"):
        return
    redis = workloads[0]
    container = next(c for c in redis["spec"]["template"]["spec"]["containers"]
                     if str(c.get("image", "")).startswith("redis:"))
    report.check("kubernetes: Redis keeps an append-only file on a persistent volume",
                 "--appendonly yes" in " ".join(container.get("args", []) + container.get("command", [])) and
                 bool(redis["spec"].get("volumeClaimTemplates")), f"args {container.get('args')}")
    labels = redis["spec"]["template"]["metadata"]["labels"]
    service = next((s for s in by_kind.get("Service", []) if s["metadata"]["name"] == url.hostname), None)
    report.check(f"kubernetes: the Service '{url.hostname}' sends to Redis on port {url.port or 6379}",
                 service is not None and selects(service["spec"].get("selector"), labels) and
                 any(p.get("port") == (url.port or 6379) for p in service["spec"].get("ports", [])),
                 f"service {service}")


def check_ingress(report, documents):
    for ingress in (d for d in documents if d.get("kind") == "Ingress"):
        annotations = ingress["metadata"].get("annotations", {})
        timeouts = [int(annotations.get(f"nginx.ingress.kubernetes.io/proxy-{w}-timeout", 0)) for w in ("read", "send")]
        report.check("kubernetes: the Ingress keeps WebSockets for 10 min of quiet or more", min(timeouts) >= 600,
                     f"read/send time-outs {timeouts}")
