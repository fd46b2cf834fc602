#!/usr/bin/env bash
# Build the Dockerfile for real and check the container serves the app offline.
#
# No Docker engine runs here, so this uses Debian's podman (runtime runc, raised
# ulimits) with a throw-away storage root.  The Dockerfile's base image
# (python:3.11-slim) cannot be pulled from a registry here, so a stand-in with the
# same name is made from Debian bookworm (debootstrap + podman import + Python in
# a venv on PATH).  The container then runs with --network none and is checked
# from inside: /, a scene page, the static assets, a derivation, a simulation,
# and that no network but loopback exists; then a class recorded in one container is
# read back from a second one on the same volume (the classes' SQLite in /app/data).
#
# Usage: scripts/container_test.sh        (about 3-6 minutes; needs root and apt)
set -euo pipefail
cd "$(dirname "$0")/.."

need=()
for tool in podman runc debootstrap; do command -v "$tool" >/dev/null || need+=("$tool"); done
if [ ${#need[@]} -gt 0 ]; then
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends podman runc debootstrap uidmap slirp4netns fuse-overlayfs >/dev/null
fi

work=$(mktemp -d /tmp/lagrange-container.XXXXXX)
cleanup() {
    podman "${store[@]}" rm -af >/dev/null 2>&1 || true
    podman "${store[@]}" system reset -f >/dev/null 2>&1 || true
    rm -rf "$work"
}
store=(--root "$work/root" --runroot "$work/runroot" --storage-driver vfs)
trap cleanup EXIT

cat >"$work/containers.conf" <<'CONF'
[containers]
default_ulimits = ["nofile=20000:20000", "nproc=20000:20000"]
[engine]
runtime = "runc"
CONF
export CONTAINERS_CONF="$work/containers.conf"
pm() { podman "${store[@]}" "$@"; }

# A TLS-inspecting proxy's CA (if the host trusts one) is mounted for pip and npm
# in the build, at a path of its own so it never collides with the image's bundle.
ca=/etc/ssl/certs/ca-certificates.crt
mounts=()
if [ -f "$ca" ]; then
    mounts=(-v "$ca:/run/host-ca.crt:ro" --build-arg PIP_CERT=/run/host-ca.crt
            --build-arg NODE_EXTRA_CA_CERTS=/run/host-ca.crt)
fi

echo "== base image: Debian bookworm with Python 3.11, tagged python:3.11-slim"
debootstrap --variant=minbase bookworm "$work/rootfs" http://deb.debian.org/debian >"$work/debootstrap.log" 2>&1
tar -C "$work/rootfs" -c . | pm import - localhost/debian-base:bookworm >/dev/null
mkdir -p "$work/context"
cat >"$work/Base.Dockerfile" <<'BASE'
FROM localhost/debian-base:bookworm
RUN apt-get update -qq && apt-get install -y -qq --no-install-recommends python3 python3-venv ca-certificates \
    && rm -rf /var/lib/apt/lists/* && python3 -m venv /usr/local/python
ENV PATH=/usr/local/python/bin:$PATH
BASE
pm build --pull=never --format docker -t docker.io/library/python:3.11-slim -f "$work/Base.Dockerfile" \
    "$work/context" >"$work/base-build.log" 2>&1 || { grep -n -B2 -A8 "rror" "$work/base-build.log" | head -60; exit 1; }

echo "== build the app image"
start=$(date +%s)
if ! pm build --pull=never --format docker "${mounts[@]}" -t localhost/lagrange:test . >"$work/build.log" 2>&1; then
    tail -40 "$work/build.log"
    exit 1
fi
echo "built in $(($(date +%s) - start)) s; size $(pm image inspect localhost/lagrange:test --format '{{.Size}}' | awk '{printf "%.0f MB", $1/1e6}')"
pm image inspect localhost/lagrange:test --format '{{.Config.Healthcheck.Test}}' | grep -q healthz \
    || { echo "HEALTHCHECK missing from the image"; exit 1; }
user=$(pm image inspect localhost/lagrange:test --format '{{.Config.User}}')
[ -n "$user" ] && [ "$user" != "root" ] || { echo "image runs as root"; exit 1; }

echo "== run it with the network off"
pm run -d --name lagrange 2> >(grep -v "systemd connection" >&2) --network none -e WORKERS=2 localhost/lagrange:test >/dev/null
cat >"$work/check.py" <<'PY'
import json, socket, sys, time, urllib.request

base = "http://127.0.0.1:8000"
for _ in range(120):
    try:
        urllib.request.urlopen(base + "/healthz", timeout=2)
        break
    except OSError:
        time.sleep(0.5)
else:
    sys.exit("the app did not start")

def get(path):
    start = time.perf_counter()
    with urllib.request.urlopen(base + path, timeout=60) as r:
        status, body = r.status, r.read()
    print(f"     {path}: {1e3 * (time.perf_counter() - start):.0f} ms")
    return status, body

checks = []
status, body = get("/")
checks.append(("/", status == 200 and b"<html" in body.lower()))
scenes = json.loads(get("/api/scenes")[1])
first = scenes[0]["id"]
status, body = get(f"/scenes/{first}")
checks.append((f"/scenes/{first}", status == 200))
for asset in ("/static/vendor/katex/katex.min.js", "/static/vendor/plotly/plotly.min.js",
              "/static/vendor/katex/katex.min.css"):
    status, body = get(asset)
    checks.append((asset, status == 200 and len(body) > 1000))
status, body = get(f"/api/scenes/{first}/derivation")
checks.append(("derivation", status == 200 and "lagrangian" in json.loads(body)))
# precomputed at build: served from the image's cache, not computed now
status, body = get(f"/api/scenes/{first}/work-precision")
checks.append(("work-precision", status == 200 and len(json.loads(body)["runs"]) >= 4))
scene = scenes[0]
request = urllib.request.Request(
    base + f"/api/scenes/{first}/simulate",
    data=json.dumps({"initial": scene["initial"], "t_end": 2.0, "samples": 50}).encode(),
    headers={"Content-Type": "application/json"},
)
with urllib.request.urlopen(request, timeout=60) as r:
    result = json.loads(r.read())
checks.append(("simulate", len(result["t"]) == 50))
# Only loopback exists: connecting anywhere else fails at once.
try:
    socket.create_connection(("1.1.1.1", 80), timeout=3)
    offline = False
except OSError:
    offline = True
checks.append(("no network", offline))
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
pm cp "$work/check.py" lagrange:/tmp/check.py
if ! pm exec lagrange python /tmp/check.py; then
    pm logs lagrange | tail -40
    exit 1
fi
pm exec lagrange sh -c 'ls /sys/class/net' | tr '\n' ' ' | sed 's/^/interfaces: /'; echo
echo "== graceful stop"
pm stop -t 20 lagrange >/dev/null 2> >(grep -v "systemd connection" >&2)

echo "== classes kept on a volume across containers"
cat >"$work/classes.py" <<'PY'
import json, sys, time, urllib.error, urllib.request

base = "http://127.0.0.1:8000"
for _ in range(120):
    try:
        urllib.request.urlopen(base + "/healthz", timeout=2)
        break
    except OSError:
        time.sleep(0.5)
else:
    sys.exit("the app did not start")

def call(method, path, body=None, key=None):
    headers = {"Content-Type": "application/json"}
    if key:
        headers["Authorization"] = "Bearer " + key
    data = None if body is None else json.dumps(body).encode()
    request = urllib.request.Request(base + path, data=data, headers=headers, method=method)
    with urllib.request.urlopen(request, timeout=120) as r:
        return json.loads(r.read())

if sys.argv[1] == "record":
    created = call("POST", "/api/classes", {"title": "kept on a volume"})
    student = call("POST", f"/api/classes/{created['code']}/join", {"name": "Ada"})["student_key"]
    verdict = call("POST", f"/api/classes/{created['code']}/check",
                   {"scene": "simple-pendulum", "step": "kinetic", "answer": "m*R**2*theta_dot**2"}, student)
    assert verdict["verdict"] == "incorrect", verdict
    print(created["code"], created["teacher_key"])
else:
    code, key = sys.argv[2], sys.argv[3]
    summary = call("GET", f"/api/classes/{code}/summary", key=key)
    kept = summary["students"] == 1 and summary["attempts"] == 1
    print(("ok   " if kept else "FAIL ") + "classes kept on a volume", json.dumps(summary)[:200])
    sys.exit(0 if kept else 1)
PY
pm volume create lagrange-data >/dev/null
for round in 1 2; do
    pm run -d --name "classes$round" --network none -v lagrange-data:/app/data -e WORKERS=1 localhost/lagrange:test \
        >/dev/null 2> >(grep -v "systemd connection" >&2)
    pm cp "$work/classes.py" "classes$round:/tmp/classes.py"
    if [ "$round" = 1 ]; then
        kept=$(pm exec classes1 python /tmp/classes.py record) || { pm logs classes1 | tail -40; exit 1; }
    elif ! pm exec classes2 python /tmp/classes.py read $kept; then
        pm logs classes2 | tail -40
        exit 1
    fi
    pm stop -t 20 "classes$round" >/dev/null 2> >(grep -v "systemd connection" >&2)
    pm rm "classes$round" >/dev/null
done
echo "container test passed"
