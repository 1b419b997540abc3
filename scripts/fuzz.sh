#!/usr/bin/env bash
# Fuzzes every reader with libFuzzer (Debian's clang, ASan + UBSan), one
# harness at a time (docs/reliability.md):
#   scripts/fuzz.sh [harness ...]        (default: all of them)
# Environment: FUZZ_RUNS (executions per harness, default 1000000),
# FUZZ_SECONDS (time cap per harness, default 3600), BUILD_DIR (default
# build-fuzz), RELEASE_DIR (a normal build whose unimap makes seeds from
# ../shared/data, default build). Seeds: ../shared/data files (cut to
# the harness's max_len), small datasets converted / simulated from them,
# and tests/fuzz/regressions/<harness>/. A crash stops that harness and
# leaves build-fuzz/findings/<harness>/crash-*: fix it, then copy the input
# into tests/fuzz/regressions/<harness>/ (the ctest fuzz.<harness> replays it).
# Each harness's line "harness runs seconds result" goes to
# $BUILD_DIR/fuzz-summary.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build-fuzz}"
RELEASE_DIR="${RELEASE_DIR:-build}"
FUZZ_RUNS="${FUZZ_RUNS:-1000000}"
FUZZ_SECONDS="${FUZZ_SECONDS:-3600}"
DATA=../shared/data
ALL="platform_yaml metadata_yaml dataset_streams scans_bin tum kitti pcd ply carmen rosbag ros2_cdr ros1_definition bt"
HARNESSES="${*:-$ALL}"

sanitize="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  "${launcher[@]}" \
  -DUNIMAP_FUZZ=ON -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $sanitize" -DCMAKE_C_FLAGS="$sanitize" \
  -DCMAKE_EXE_LINKER_FLAGS="$sanitize" -DCMAKE_SHARED_LINKER_FLAGS="$sanitize" >/dev/null
targets=""
for h in $HARNESSES; do targets="$targets fuzz_$h"; done
cmake --build "$BUILD_DIR" -j2 --target $targets

# ---- seeds
seeds="$BUILD_DIR/seeds"
mkdir -p "$seeds"
cut_to() { head -c "$1" "$2"; }  # the first $1 bytes of file $2
# prefix BYTE FILE OUT: OUT = one selector byte + FILE (harnesses that pick a file kind by the first byte)
prefix() { { printf "\\x$(printf %02x "$1")"; cut_to 65535 "$2"; } > "$3"; }
if [ -x "$RELEASE_DIR/bin/unimap" ] && [ ! -d "$seeds/sim" ]; then
  "$RELEASE_DIR/bin/unimap" simulate --scenario configs/scenarios/tunnel.yaml --duration-s 1 --out "$seeds/sim" \
    --quiet >/dev/null
  [ -f "$DATA/radish/mit-csail.clf.bz2" ] &&
    "$RELEASE_DIR/bin/unimap" convert --format carmen --input "$DATA/radish/mit-csail.clf.bz2" \
      --out "$seeds/carmen" >/dev/null
fi
corpus_for() {  # fills $BUILD_DIR/corpus/$1 with that harness's seeds
  local h=$1 c="$BUILD_DIR/corpus/$1"
  mkdir -p "$c"
  cp -r tests/fuzz/regressions/"$h"/. "$c"/ 2>/dev/null || true
  case "$h" in
    platform_yaml) cp configs/platforms/*.yaml "$c"/ ;;
    metadata_yaml)
      [ -f "$seeds/sim/metadata.yaml" ] && cp "$seeds/sim/metadata.yaml" "$c/sim.yaml"
      [ -f "$seeds/carmen/metadata.yaml" ] && cp "$seeds/carmen/metadata.yaml" "$c/carmen.yaml"
      [ -f "$DATA/nodding_rplidar/metadata.yaml" ] && cp "$DATA/nodding_rplidar/metadata.yaml" "$c/rosbag2.yaml" ;;
    dataset_streams)
      for f in "$seeds/sim/imu.csv:0" "$seeds/sim/encoder.csv:1" "$seeds/carmen/odometry.csv:2" \
               "$seeds/sim/groundtruth.tum:3"; do
        [ -f "${f%:*}" ] && prefix "${f##*:}" "${f%:*}" "$c/$(basename "${f%:*}")"
      done ;;
    scans_bin)
      [ -f "$seeds/sim/scans.bin" ] && cut_to 65536 "$seeds/sim/scans.bin" > "$c/sim.bin"
      [ -f "$seeds/carmen/scans.bin" ] && cut_to 65536 "$seeds/carmen/scans.bin" > "$c/carmen.bin" ;;
    tum)
      [ -f "$seeds/sim/groundtruth.tum" ] && cut_to 65536 "$seeds/sim/groundtruth.tum" > "$c/sim.tum"
      [ -f "$seeds/carmen/odometry.csv" ] && cut_to 65536 "$seeds/carmen/odometry.csv" > "$c/carmen.tum" ;;
    kitti)
      [ -f "$DATA/kitti00/000000.pcd" ] && prefix 1 "$DATA/kitti00/000000.pcd" "$c/pcd"
      [ -f "$DATA/kitti00/times.txt" ] && prefix 2 "$DATA/kitti00/times.txt" "$c/times"
      [ -f "$DATA/kitti00/poses_camera_frame.txt" ] && prefix 4 "$DATA/kitti00/poses_camera_frame.txt" "$c/poses" ;;
    pcd) for f in "$DATA"/kitti00/00000[0-2].pcd; do [ -f "$f" ] && cut_to 65536 "$f" > "$c/$(basename "$f")"; done ;;
    ply) printf 'ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n' > "$c/ascii.ply"
         printf 'ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty double x\nproperty float y\nproperty uchar z\nend_header\n' > "$c/bin.ply"
         head -c 13 /dev/zero >> "$c/bin.ply" ;;
    carmen) for f in "$DATA"/radish/*.clf.bz2; do  # (bzcat ends on SIGPIPE once head has its bytes)
              [ -f "$f" ] && { bzcat "$f" | head -c 16384 > "$c/$(basename "$f" .bz2)" || true; }
            done
            [ -f "$c/intel.clf" ] && head -c 8000 "$c/intel.clf" | bzip2 > "$c/intel-head.clf.bz2" ;;
    rosbag) ;;  # the regressions' small complete bags (plain, bz2, lz4 chunks): the 3.8 MB stage bag made 18 executions/s
    ros1_definition) cp tests/fuzz/regressions/ros1_definition/* "$c/" ;;  # the tilting stand's LaserScanAngle
    ros2_cdr)  # a type byte (the harness's switch) + the first messages of the nodding recording
      db="$DATA/nodding_rplidar/lidarServo_0.db3"
      if [ -f "$db" ] && command -v python3 >/dev/null; then
        python3 - "$db" "$c" <<'PY'
import sqlite3, sys
db, out = sys.argv[1], sys.argv[2]
con = sqlite3.connect("file:" + db + "?mode=ro", uri=True)
for topic_id, selector, name in ((1, 0, "laserscan"), (2, 8, "int32")):
    rows = con.execute("select data from messages where topic_id = ? limit 3", (topic_id,)).fetchall()
    for k, (data,) in enumerate(rows):
        open("%s/%s-%d.bin" % (out, name, k), "wb").write(bytes([selector]) + data)
PY
      fi ;;
  esac
}
max_len_for() {
  case "$1" in
    platform_yaml|metadata_yaml) echo 8192 ;;
    carmen) echo 16384 ;;  # a few laser lines of each kind: 64 KB seeds made 190 executions/s
    bt) echo 4096 ;;  # small trees (seed-small-walls.bt, 475 bytes): 15 KB trees made 56-115 executions/s, these ~1,100 with the same coverage
    *) echo 65536 ;;
  esac
}

summary="$BUILD_DIR/fuzz-summary.txt"
for h in $HARNESSES; do
  corpus_for "$h"
  mkdir -p "$BUILD_DIR/findings/$h" "$BUILD_DIR/work/$h"
  log="$BUILD_DIR/fuzz-$h.log"
  start=$(date +%s)
  set +e
  (cd "$BUILD_DIR/work/$h" && "../../bin/fuzz_$h" -runs="$FUZZ_RUNS" -max_total_time="$FUZZ_SECONDS" \
     -max_len="$(max_len_for "$h")" -rss_limit_mb=2048 -timeout=30 -print_final_stats=1 \
     -artifact_prefix="../../findings/$h/" "../../corpus/$h") >"$log" 2>&1
  code=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  result="clean"
  [ "$code" != 0 ] && result="FINDING (exit $code, see $log and $BUILD_DIR/findings/$h/)"
  line="$h ${runs:-0} $(( $(date +%s) - start )) $result"
  echo "$line" | tee -a "$summary"
done
