#!/usr/bin/env bash
# integration.online_mapper: BUILD_DIR SOURCE_DIR WORK_DIR CMAKE CXX GENERATOR [PYTHON].
# 1. installs the build to WORK_DIR/prefix and builds examples/online_mapper
#    against the install only;
# 2. simulates 30 s of the tunnel (rotating Hokuyo) and maps it with
#    `unimap run` from the install;
# 3. runs the example synchronously with one thread per stream, as fast as
#    they go: odometry and optimised trajectory must equal unimap run's, number
#    for number, and the map must hold the same points;
#    The same for 12 s of the patio with the fixed VLP-16, whose scene
#    spans more than 40 of the platform's voxels: both must size the map's
#    voxel from the first 3D scan alike (0.3 m, docs/mapping.md);
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
compare_sync() {  # DIR_PREFIX RUN_DIR: the example's outputs against unimap run's, number for number
  python3 - "$1" "$2" <<'PY'
import sys
prefix, run = sys.argv[1:3]
def rows(f):
    return [tuple(float(v) for v in line.split()) for line in open(f) if line.strip() and not line.startswith('#')]
for mine, theirs in ((f"{prefix}odometry.tum", f"{run}/trajectory_odometry.tum"),
                     (f"{prefix}trajectory.tum", f"{run}/trajectory.tum")):
    a, b = rows(mine), rows(theirs)
    if len(a) != len(b) or not a:
        sys.exit(f"FAIL: {mine} has {len(a)} poses, {theirs} {len(b)}")
    diff = [i for i, (x, y) in enumerate(zip(a, b)) if x != y]
    if diff:
        sys.exit(f"FAIL: {mine} differs from {theirs} at pose {diff[0]}: {a[diff[0]]} vs {b[diff[0]]}")
    print(f"{mine}: {len(a)} poses identical to {theirs}")
PY
}
compare_sync "$work/sync_" "$work/run"
cmp -s "$work/sync_map.ply" "$work/run/map.ply" || fail "sync_map.ply differs from unimap run's map.ply"
echo "sync_map.ply identical to map.ply"

step "synchronous, a scene that coarsens the map's voxel"
"$unimap" simulate --quiet --scenario "$src/configs/scenarios/patio.yaml" \
  --payload "$work/prefix/share/unimap/configs/platforms/fixed_vlp16.yaml" --duration-s 12 --out "$work/patio"
"$unimap" run --quiet --platform "$work/prefix/share/unimap/configs/platforms/fixed_vlp16.yaml" --data "$work/patio" \
  --out "$work/patio_run" > "$work/patio_run.log"
grep -q "^map voxel: 0.3 m" "$work/patio_run.log" || fail "unimap run did not coarsen the patio's voxel to 0.3 m"
"$example" --platform "$work/prefix/share/unimap/configs/platforms/fixed_vlp16.yaml" --data "$work/patio" --rate 0 \
  --odometry-out "$work/patio_odometry.tum" --trajectory-out "$work/patio_trajectory.tum" \
  --map-out "$work/patio_map.ply" > "$work/patio_sync.log"
compare_sync "$work/patio_" "$work/patio_run"
python3 - "$work/patio_map.ply" "$work/patio_run/map.ply" <<'PY'
import struct, sys
def xyz(path):  # binary little-endian PLY of float properties: the x, y, z of every vertex
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    n = int(next(l.split()[2] for l in header if l.startswith("element vertex")))
    props = [l.split()[2] for l in header if l.startswith("property float")]
    values = struct.unpack(f"<{n * len(props)}f", data[end:end + 4 * n * len(props)])
    return [values[i * len(props):i * len(props) + 3] for i in range(n)]
a, b = xyz(sys.argv[1]), xyz(sys.argv[2])
if a != b:
    sys.exit(f"FAIL: the example's map ({len(a)} points) differs from unimap run's ({len(b)})")
print(f"patio_map.ply: {len(a)} points identical to unimap run's map.ply (x, y, z)")
PY

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
