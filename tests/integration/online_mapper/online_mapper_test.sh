#!/usr/bin/env bash
# integration.online_mapper: BUILD_DIR SOURCE_DIR WORK_DIR CMAKE CXX GENERATOR [PYTHON].
# 1. installs the build to WORK_DIR/prefix and builds examples/online_mapper
#    against the install only;
# 2. simulates 30 s of the tunnel (rotating Hokuyo) and maps it with
#    `unimap run` from the install;
# 3. runs the example synchronously with one thread per stream, as fast as
#    they go: odometry and optimised trajectory must equal unimap run's, number
#    for number, and the map must hold the same points;
# 4. runs it live at the sensor rate: its odometry must stay within
#    1 cm (RMS, same time stamps) of unimap run's;
# 5. (given PYTHON and an installed module) maps the same data with the
#    installed Python module: trajectories identical to unimap run's.
set -euo pipefail
build=$1 src=$2 work=$3 cmake=$4 cxx=$5 generator=$6 python=${7:-}
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
step() { echo "=== $*"; }

step "build and install unimap"
"$cmake" --build "$build" >/dev/null
"$cmake" --install "$build" --prefix "$work/prefix" >/dev/null
[ -f "$work/prefix/include/unimap/Mapper.hpp" ] || fail "the install lacks include/unimap/Mapper.hpp"
if grep -El '#include *"(io|map|pipeline|matching|graph|estimation)/|yaml-cpp|pcl/|octomap|ceres' \
     "$work/prefix/include/unimap/Mapper.hpp" "$work/prefix/include/unimap/Dataset.hpp"; then
  fail "a public mapper header includes an internal or third-party header"
fi

step "build the example against the install"
"$cmake" -S "$src/examples/online_mapper" -B "$work/example" -G "$generator" -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
"$cmake" --build "$work/example" >/dev/null
example=$work/example/online_mapper
unimap=$work/prefix/bin/unimap
platform=$work/prefix/share/unimap/configs/platforms/rotating_hokuyo.yaml

step "simulate and run"
"$unimap" simulate --quiet --scenario "$src/configs/scenarios/tunnel.yaml" --duration-s 30 --out "$work/data"
"$unimap" run --quiet --platform "$platform" --data "$work/data" --out "$work/run" > "$work/run.log"

step "synchronous, one thread per stream"
"$example" --platform "$platform" --data "$work/data" --rate 0 --odometry-out "$work/sync_odometry.tum" \
  --trajectory-out "$work/sync_trajectory.tum" --map-out "$work/sync_map.ply" > "$work/sync.log"
grep -q "^pose t=" "$work/sync.log" || fail "the example printed no pose"
python3 - "$work" <<'PY'
import sys
w = sys.argv[1]
def rows(f):
    return [tuple(float(v) for v in line.split()) for line in open(f) if line.strip() and not line.startswith('#')]
for mine, theirs in (("sync_odometry.tum", "run/trajectory_odometry.tum"),
                     ("sync_trajectory.tum", "run/trajectory.tum")):
    a, b = rows(f"{w}/{mine}"), rows(f"{w}/{theirs}")
    if len(a) != len(b) or not a:
        sys.exit(f"FAIL: {mine} has {len(a)} poses, {theirs} {len(b)}")
    diff = [i for i, (x, y) in enumerate(zip(a, b)) if x != y]
    if diff:
        sys.exit(f"FAIL: {mine} differs from {theirs} at pose {diff[0]}: {a[diff[0]]} vs {b[diff[0]]}")
    print(f"{mine}: {len(a)} poses identical to {theirs}")
PY
cmp -s "$work/sync_map.ply" "$work/run/map.ply" || fail "sync_map.ply differs from unimap run's map.ply"
echo "sync_map.ply identical to map.ply"

step "live at the sensor rate"
"$example" --platform "$platform" --data "$work/data" --live --rate 1 --odometry-out "$work/live_odometry.tum" \
  > "$work/live.log"
grep -E "^lag at end of data" "$work/live.log"
python3 - "$work" <<'PY'
import math, sys
w = sys.argv[1]
def rows(f):
    return {round(float(l.split()[0]), 9): [float(v) for v in l.split()[1:4]] for l in open(f) if l.strip() and not l.startswith('#')}
live, ref = rows(f"{w}/live_odometry.tum"), rows(f"{w}/run/trajectory_odometry.tum")
common = sorted(set(live) & set(ref))
if len(common) < 0.95 * len(ref):
    sys.exit(f"FAIL: live gave {len(live)} poses, {len(common)} of unimap run's {len(ref)} matched by time")
rms = math.sqrt(sum(sum((a - b) ** 2 for a, b in zip(live[t], ref[t])) for t in common) / len(common))
print(f"live odometry vs unimap run: RMS position difference {rms:.4f} m over {len(common)} poses")
if not rms <= 0.01:
    sys.exit("FAIL: live odometry is more than 1 cm RMS from unimap run's")
PY

module=$(find "$work/prefix" -name 'unimap*.so' -path '*dist-packages*' | head -1)
if [ -n "$python" ] && [ -n "$module" ]; then
  step "the installed Python module"
  PYTHONPATH=$(dirname "$module") "$python" - "$work" "$platform" <<'PY'
import sys
import numpy as np
import unimap
w, platform = sys.argv[1:3]
assert unimap.__file__.startswith(w + "/prefix/"), unimap.__file__
mapper = unimap.Mapper(platform)
for event in unimap.read_dataset(f"{w}/data"):
    mapper.add(event)
mapper.finish()
def rows(f):
    return np.array([[float(v) for v in l.split()] for l in open(f) if l.strip() and not l.startswith('#')])
np.testing.assert_array_equal(mapper.poses(), rows(f"{w}/run/trajectory_odometry.tum"))
np.testing.assert_array_equal(mapper.trajectory(), rows(f"{w}/run/trajectory.tum"))
print(f"installed module: {len(mapper.poses())} poses identical to unimap run's")
PY
elif [ -n "$python" ]; then
  fail "no installed Python module under $work/prefix"
fi
echo "PASS"
