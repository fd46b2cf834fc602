"""Deployment files say what docs/deployment.md promises."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_dockerfile_is_offline_non_root_and_healthchecked():
    text = (ROOT / "Dockerfile").read_text()
    assert "HEALTHCHECK" in text and "/healthz" in text
    assert "USER lagrange" in text
    assert "python -m app.web.warm" in text
    # node only in the asset stage
    final = text[text.rindex("\nFROM ") :]
    assert "npm" not in final and "nodejs" not in final


def test_kubernetes_manifest_has_probes_service_and_autoscaler():
    text = (ROOT / "deploy" / "kubernetes.yaml").read_text()
    for kind in ("kind: Deployment", "kind: Service", "kind: HorizontalPodAutoscaler"):
        assert kind in text
    assert "startupProbe" in text and "readinessProbe" in text and "livenessProbe" in text
    assert "path: /healthz" in text


def test_serve_script_takes_port_and_workers_from_the_environment():
    text = (ROOT / "scripts" / "serve.sh").read_text()
    assert "${PORT:-8000}" in text and "WORKERS" in text and "LAGRANGE_WEB_PROCESSES" in text


@pytest.mark.parametrize("script", ["serve.sh", "run.sh"])
def test_the_scripts_bound_slow_clients_with_the_settings_options(script):
    # keep-alive, connection cap and header deadline: app/web/http/server_options.py, one home for both scripts
    assert "-m app.web.http.server_options" in (ROOT / "scripts" / script).read_text()


def _mebibytes(quantity: str) -> int:
    units = {"Mi": 1, "Gi": 1024}
    return int(quantity[:-2]) * units[quantity[-2:]]


def test_the_memory_budget_fits_the_kubernetes_limits():
    import yaml

    from app.settings import Settings

    deployment = next(
        d for d in yaml.safe_load_all((ROOT / "deploy" / "kubernetes.yaml").read_text()) if d["kind"] == "Deployment"
    )
    container = deployment["spec"]["template"]["spec"]["containers"][0]
    limit = _mebibytes(container["resources"]["limits"]["memory"])
    env = {e["name"]: e["value"] for e in container["env"]}
    cpus = int(container["resources"]["limits"]["cpu"])
    # what the server derives inside this container (cgroup memory.max = the limit)
    s = Settings(memory_budget_mb=int(0.9 * limit), web_processes=int(env["WORKERS"]))
    assert s.worst_case_mb <= s.budget_mb < limit
    # two pool workers per web process (issue 35: a job at its time limit must not hold every other session's),
    # which wait on their jobs' limits as often as they compute: at most two per CPU
    assert s.web_process_count * s.worker_count <= 2 * cpus
    assert s.job_memory_mb >= 256  # a useful derivation fits
    # what a replica is guaranteed is no more than what it may use (benchmarks/bench_replica_size.py sized both)
    assert _mebibytes(container["resources"]["requests"]["memory"]) <= limit
    assert float(container["resources"]["requests"]["cpu"]) <= cpus
    for probe in ("startupProbe", "readinessProbe", "livenessProbe"):
        assert container[probe]["httpGet"]["path"] == "/healthz"
        assert container[probe].get("timeoutSeconds", 1) <= container[probe]["periodSeconds"]
    # the start-up probe, not a fixed delay, holds the liveness probe off while a replica starts
    assert "initialDelaySeconds" not in container["livenessProbe"]


@pytest.mark.slow
def test_the_kubernetes_manifest_validates_against_the_api_schemas():
    """Every document of deploy/kubernetes.yaml against the Kubernetes API's own schemas (kubernetes-validate,
    offline), strictly: a misspelt or misplaced field fails."""
    import kubernetes_validate
    import yaml

    documents = list(yaml.safe_load_all((ROOT / "deploy" / "kubernetes.yaml").read_text()))
    assert {d["kind"] for d in documents} == {"Deployment", "Service", "HorizontalPodAutoscaler", "PodDisruptionBudget"}
    for document in documents:
        kubernetes_validate.validate(document, "1.30", strict=True)


def test_the_replicas_share_postgresql_and_the_session_secret():
    import yaml

    documents = list(yaml.safe_load_all((ROOT / "deploy" / "kubernetes.yaml").read_text()))
    deployment = next(d for d in documents if d["kind"] == "Deployment")
    container = deployment["spec"]["template"]["spec"]["containers"][0]
    env = {e["name"]: e.get("value") for e in container["env"]}
    assert int(env["LAGRANGE_REPLICAS"]) > 1 and env["LAGRANGE_PROXY_HEADER"]
    # the rate windows are counted together in the manifest's own Redis, reached through its Service
    store = env["LAGRANGE_SHARED_STORE_URL"]
    redis_service = next(d for d in documents if d["kind"] == "Service" and d["metadata"]["name"] == "lagrange-redis")
    assert store == f"redis://lagrange-redis:{redis_service['spec']['ports'][0]['port']}/0"
    from app.settings import Settings

    assert Settings(shared_store_url=store).shared_store_url == store  # the setting accepts it
    secrets = [s["secretRef"] for s in container["envFrom"]]
    assert {s["name"] for s in secrets} == {"lagrange-database", "lagrange-session"}
    assert not any(s.get("optional") for s in secrets)  # without them a pod would keep classes of its own
    service = next(d for d in documents if d["kind"] == "Service" and d["metadata"]["name"] == "lagrange")
    assert "sessionAffinity" not in service["spec"]  # ingress controllers ignore it; nothing relies on it
    budget = next(d for d in documents if d["kind"] == "PodDisruptionBudget")
    assert budget["spec"]["selector"] == deployment["spec"]["selector"] and budget["spec"]["minAvailable"] >= 1


def test_the_compose_file_runs_two_replicas_behind_nginx_with_what_they_must_share():
    import yaml

    from app.settings import Settings

    compose = yaml.safe_load((ROOT / "deploy" / "compose" / "compose.yaml").read_text())
    services = compose["services"]
    replicas = [name for name, s in services.items() if "build" in s]
    assert len(replicas) == 2 and services[replicas[0]] == services[replicas[1]]  # one definition, twice
    env = services[replicas[0]]["environment"]
    assert int(env["LAGRANGE_REPLICAS"]) == len(replicas)
    # what the compose file fills in from the shell, given values; the settings must accept the result
    filled = {
        k: re.sub(r"\$\{(\w+):\?[^}]*\}", lambda m: {"POSTGRES_PASSWORD": "pw"}.get(m.group(1), "secret"), v)
        for k, v in env.items()
    }
    s = Settings(**{k.removeprefix("LAGRANGE_").lower(): v for k, v in filled.items()})
    assert s.replicas == 2 and s.database_url.startswith("postgresql://") and s.session_secret
    assert s.shared_store_url == "redis://redis:6379/0" and "redis" in services and "postgres" in services
    # nginx's upstream is exactly the replicas, on the port the image serves
    nginx = (ROOT / "deploy" / "compose" / "nginx.conf").read_text()
    upstream = re.search(r"upstream lagrange \{([^}]*)\}", nginx).group(1)
    port = re.search(r"EXPOSE (\d+)", (ROOT / "Dockerfile").read_text()).group(1)
    assert sorted(re.findall(r"server (\S+?):(\d+)", upstream)) == [(r, port) for r in sorted(replicas)]
    assert "proxy_next_upstream error timeout non_idempotent" in nginx  # retried presses: exactly once by attempt id
    assert services["balancer"]["volumes"] == ["./nginx.conf:/etc/nginx/conf.d/default.conf:ro"]
