#!/usr/bin/env bash
# One CLI check per call: cli_test.sh CASE UNIMAP_EXE SOURCE_DIR WORK_DIR.
set -uo pipefail
case_name=$1 exe=$2 src=$3 work=$4
mkdir -p "$work"
fail() { echo "FAIL [$case_name]: $*"; echo "--- output:"; cat "$work/$case_name.out"; exit 1; }
run() { "$exe" "$@" >"$work/$case_name.out" 2>&1; echo $?; }
expect() { grep -Eq -- "$1" "$work/$case_name.out" || fail "expected /$1/"; }
reject() { ! grep -Eq -- "$1" "$work/$case_name.out" || fail "did not expect /$1/"; }
platform() {  # writes a platform file from stdin, prints its path
  cat >"$work/$case_name.yaml"; echo "$work/$case_name.yaml"; }

case $case_name in
  plugins_lists_all)
    code=$(run plugins); [ "$code" = 0 ] || fail "exit $code"
    for p in fixed_3d rotating_3d rotating_2d fixed_2d; do expect "^$p  \(ABI [0-9]+\)  .*libunimap_payload_$p\.so"; done
    expect "scans_per_3d_scan +N +"; expect "4 payload plugin\(s\) found" ;;
  plugins_env_path)
    mkdir -p "$work/empty_plugins"
    UNIMAP_PLUGIN_PATH="$work/empty_plugins" run plugins --brief >/dev/null
    expect "^  $work/empty_plugins$"; reject "defaults:" ;;
  help_lists_subcommands)
    code=$(run --help); [ "$code" = 0 ] || fail "exit $code"
    listed=$(sed -n '/^Subcommands:/,$p' "$work/$case_name.out" | grep -E '^  [a-z]' | awk '{print $1}' | sort | tr '\n' ' ')
    expected="bench calibrate config convert demo evaluate localize plugins report run simulate "
    [ "$listed" = "$expected" ] || fail "listed subcommands '$listed', expected '$expected'"
    for sub in $listed; do
      "$exe" "$sub" --help >"$work/$case_name.$sub.out" 2>&1 || fail "'$sub --help' failed"
      grep -q "Usage" "$work/$case_name.$sub.out" || fail "'$sub --help' printed no usage"
    done ;;
  convert_ros2_nodding)
    # The nodding RPLIDAR recording (a ROS 2 bag beside the repository; skipped, exit 77, when absent).
    bag="$src/../shared/data/nodding_rplidar"
    [ -d "$bag" ] || { echo "SKIP: $bag not found"; exit 77; }
    code=$(run convert --input "$bag" --format ros2 --out "$work/nodding_no_unit")
    if grep -q "UNIMAP_WITH_ROS2BAG" "$work/$case_name.out"; then echo "SKIP: built without ROS 2 bags"; exit 77; fi
    [ "$code" = 2 ] || fail "exit $code without --angle-unit, expected 2"
    expect "give its unit with --angle-unit deg\\|rad"
    code=$(run convert --input "$bag" --format rosbag --out "$work/nodding_ros1")
    [ "$code" = 2 ] || fail "exit $code with --format rosbag, expected 2"
    expect "a ROS 2 bag .*--format ros2"
    code=$(run convert --input "$bag" --format ros2 --angle-unit deg --out "$work/nodding")
    [ "$code" = 0 ] || fail "exit $code"
    expect "payload rotating_2d"
    expect "^  scans: +295$"
    expect "^  encoder: +1372$"
    expect "^    3  /scan: LaserScan without beams$"
    expect "angle \\(encoder\\) topic: /lidar_servo_angle \\(std_msgs/msg/Int32, deg\\): its times are the bag's receive times"
    # The scans carry the scanner's uptime, the angles the receive time: moved onto one clock.
    expect "clocks: the topics' stamps disagree \\(/scan is stamped 1748602190\\.[0-9]+ s behind its receive times"
    expect "clocks: /scan moved by \\+1748602190\\.[0-9]+ s"
    code=$(run convert --input "$bag" --format ros2 --angle-unit deg --no-clock-alignment --out "$work/nodding_unaligned")
    [ "$code" = 2 ] || fail "exit $code with --no-clock-alignment, expected 2"
    expect "the topics are on different clocks" ;;
  convert_rosbag_tilting)
    # The tilting stand's ROS 1 bag: lines and angles from one custom message (skipped, exit 77, when absent).
    bag="$src/../shared/data/tilting_hokuyo/room_240.bag"
    [ -f "$bag" ] || { echo "SKIP: $bag not found"; exit 77; }
    code=$(run convert --input "$bag" --format rosbag --out "$work/tilting_auto")
    if grep -q "UNIMAP_WITH_ROSBAG" "$work/$case_name.out"; then echo "SKIP: built without ROS 1 bags"; exit 77; fi
    [ "$code" = 0 ] || fail "exit $code without an angle"
    expect "payload fixed_2d"
    expect "laser topic: /slice"
    code=$(run convert --input "$bag" --format rosbag --laser-topic /slice --angle-topic /slice \
      --angle-field tiltAngle --angle-unit deg --out "$work/tilting_bad_field")
    [ "$code" = 2 ] || fail "exit $code with a field the message lacks, expected 2"
    expect "--angle-field tiltAngle: topic /slice \(pcg_node/LaserScanAngle\) has no field of that name"
    code=$(run convert --input "$bag" --format rosbag --laser-topic /slice --angle-topic /slice \
      --angle-field stepAngle --angle-unit deg --out "$work/tilting")
    [ "$code" = 0 ] || fail "exit $code"
    expect "payload rotating_2d"
    expect "^  scans: +865$"
    expect "^  encoder: +865$"
    expect "angle \(encoder\) topic: /slice \(pcg_node/LaserScanAngle, field stepAngle, deg, read by the bag's message definition\): stamped with its line's header stamp" ;;
  config_effective)
    code=$(run config --platform "$src/configs/platforms/rotating_hokuyo.yaml"); [ "$code" = 0 ] || fail "exit $code"
    expect "^plugin: +rotating_2d"
    expect "^scans_per_3d_scan +N +[0-9]+ +.*rotating_hokuyo.yaml:[0-9]+"
    expect "plugin default" ;;
  config_unknown_key)
    f=$(printf 'plugin: fixed_3d\nparameters:\n  scans_per_3d_scan: 1\n  sigma_acel_m_s2: 0.1\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:4: key 'sigma_acel_m_s2': .*unknown" ;;
  config_wrong_type)
    f=$(printf 'plugin: fixed_3d\nparameters:\n  scans_per_3d_scan: 1.5\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:3: key 'scans_per_3d_scan': expected integer" ;;
  config_out_of_range)
    f=$(printf 'plugin: rotating_2d\nparameters:\n  distance_map_resolution_m: -0.1\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:3: key 'distance_map_resolution_m': .*out of range" ;;
  config_mapper_settings)
    # Every mapper knob is listed with its source; the file's own at its line.
    f=$(printf 'plugin: rotating_2d\nmapper:\n  gpf:\n    num_particles: 250\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 0 ] || fail "exit $code"
    expect "mapper.gpf.num_particles +250 +count +$f:4"
    expect "mapper.loop_closure.min_score +0.6 +default"
    f=$(printf 'plugin: rotating_2d\nmapper:\n  loop_search:\n    max_radius: 3\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:4: key 'mapper.loop_search.max_radius': unknown key \\(did you mean mapper.loop_search.max_radius_m\\?\\)"
    f=$(printf 'plugin: rotating_2d\nmapper:\n  reacquire:\n    coarse_factor: 0\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:4: key 'mapper.reacquire.coarse_factor': " ;;
  config_missing_plugin)
    f=$(printf 'plugin: no_such_payload\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:1: key 'plugin': .*not found" ;;
  bench_matrix)
    # The robustness matrix's machinery on one short case: a child process
    # simulates and maps it, the table replaces only the generated part.
    printf '# Kept\n\nhand-written text\n\n<!-- matrix:begin -->\nold table\n<!-- matrix:end -->\n\nafter\n' >"$work/robustness.md"
    code=$(run bench --matrix --configs "$src/configs" --only narrow_hallway_rotating_vlp16_nom --max-duration-s 12 \
      --work-dir "$work/matrix" --out "$work/robustness.md")
    # 12 s of a loop scenario close no loop: the case may miss its targets (exit 1), never fail to run.
    [ "$code" = 0 ] || [ "$code" = 1 ] || fail "exit $code"
    expect "matrix: narrow_hallway_rotating_vlp16_nom done"
    grep -q "hand-written text" "$work/robustness.md" || fail "text before the table was lost"
    grep -q "^after$" "$work/robustness.md" || fail "text after the table was lost"
    grep -q "old table" "$work/robustness.md" && fail "the old table was kept"
    grep -Eq '^\| narrow_hallway \| rotating_vlp16 \| nominal \| 0\.[0-9]{3} \| ' "$work/robustness.md" ||
      fail "no measured row for the case"
    grep -q "1 cases met\|0 of 1 cases met\|1 of 1 cases met" "$work/robustness.md" || fail "no summary line" ;;
  run_trace_windows)
    # trace.csv carries each matched scan's pseudo measurement (innov_*, zero
    # when none was applied); scripts/trace_windows.py counts and medians them
    # per window: its counts must equal the matched lines of the trace.
    ds="$work/$case_name.ds" out="$work/$case_name.run"; rm -rf "$ds" "$out"
    code=$(run simulate --scenario "$src/configs/scenarios/narrow_hallway.yaml" --duration-s 6 --out "$ds" --quiet)
    [ "$code" = 0 ] || fail "simulate exit $code"
    code=$(run run --platform "$src/configs/platforms/rotating_hokuyo.yaml" --data "$ds" --out "$out" --trace --quiet \
      --no-loop-closure); [ "$code" = 0 ] || fail "run exit $code"
    head -1 "$out/trace.csv" | grep -q ',innov_x,innov_y,innov_z,innov_rx,innov_ry,innov_rz$' ||
      fail "trace.csv header lacks the innov_* columns: $(head -1 "$out/trace.csv")"
    col=$(head -1 "$out/trace.csv" | tr -d '# ' | tr ',' '\n' | grep -n '^innov_x$' | cut -d: -f1)
    awk -F, -v c="$col" 'NR > 1 && $2 == 0 && ($c != 0 || $(c + 1) != 0) { bad = 1 } END { exit bad }' "$out/trace.csv" ||
      fail "an unmatched scan has a pseudo measurement"
    awk -F, -v c="$col" 'NR > 1 && $2 == 1 && $c != 0 { n++ } END { exit n < 100 }' "$out/trace.csv" ||
      fail "fewer than 100 matched scans with a pseudo measurement"
    command -v python3 >/dev/null || exit 0
    python3 "$src/scripts/trace_windows.py" "$out/trace.csv" 2 0 6 innov_x vx >"$work/$case_name.out" 2>&1 ||
      fail "trace_windows.py failed"
    for w in 0 1 2; do
      want=$(awk -F, -v w="$w" 'NR > 1 && $2 == 1 && int($1 / 2) == w { n++ } END { print n + 0 }' "$out/trace.csv")
      [ "$want" -gt 0 ] || continue
      expect "^ +$((2 * w))\.00 +$((2 * w + 2))\.00 +$want +[-+][0-9]+\.[0-9]{4} +[-+][0-9]+\.[0-9]{4}$"
    done
    python3 "$src/scripts/trace_windows.py" "$out/trace.csv" 2 0 6 no_such_column >"$work/$case_name.out" 2>&1 &&
      fail "an unknown column was accepted"
    expect "no column no_such_column in the header" ;;
  localize_trace)
    # localize --trace writes run's trace.csv, per scan matched in the prior map.
    ds="$work/$case_name.ds" out="$work/$case_name.loc"; rm -rf "$ds" "$out"
    code=$(run simulate --scenario "$src/configs/scenarios/narrow_hallway.yaml" --duration-s 6 --out "$ds" --quiet)
    [ "$code" = 0 ] || fail "simulate exit $code"
    code=$(run localize --platform "$src/configs/platforms/rotating_hokuyo.yaml" --data "$ds" --map "$ds/world_map.pcd" \
      --out "$out" --trace --quiet); [ "$code" = 0 ] || fail "localize exit $code"
    head -1 "$out/trace.csv" | grep -q '^# time_s,matched,.*,innov_rz$' || fail "header: $(head -1 "$out/trace.csv")"
    awk -F, 'NR > 1 && $2 == 1 { n++ } END { exit n < 100 }' "$out/trace.csv" || fail "fewer than 100 matched scans"
    [ "$(wc -l <"$out/trace.csv")" -gt "$(grep -vc '^#' "$out/trajectory.tum")" ] ||
      fail "fewer trace lines than poses" ;;
  measurement_errors_script)
    # scripts/measurement_errors.py on a synthetic run with known answers: the
    # truth stands at the origin, the filter's x and y errors are 0.01 k^2;
    # x's measurement repeats the prediction (slope 1), y's halves it (0.5).
    python3 -c 'import numpy' 2>/dev/null || exit 77
    run_dir="$work/$case_name.run"; mkdir -p "$run_dir"
    awk 'BEGIN { for (i = 0; i <= 20; i++) print i * 0.5, 0, 0, 0, 0, 0, 0, 1 }' >"$work/$case_name.gt.tum"
    awk 'BEGIN { for (k = 0; k < 10; k++) print k, 0.01 * k * k, 0.01 * k * k, 0, 0, 0, 0, 1 }' \
      >"$run_dir/trajectory_odometry.tum"
    { echo "# time_s,matched,corr_x,corr_y,corr_z,innov_x,innov_y,innov_z,meas_sd_x,meas_sd_y,meas_sd_z"
      awk 'BEGIN { for (k = 0; k < 10; k++) print k ",1,0,0,0,0," (-0.005 * k * k) ",0,0.3,0.3,0.3" }'; } \
      >"$run_dir/trace.csv"
    python3 "$src/scripts/measurement_errors.py" "$run_dir" "$work/$case_name.gt.tum" 0 10 >"$work/$case_name.out" 2>&1 ||
      fail "exit $?: $(cat "$work/$case_name.out")"
    expect "^# 10 matched scans, 0-10 s$"
    expect "^x  ([0-9.]+)  \1  \+1\.00  0\.300$"
    x_sd=$(awk '$1 == "x" { print $2 }' "$work/$case_name.out")
    y_sd=$(awk '$1 == "y" { print $3 }' "$work/$case_name.out")
    awk -v x="$x_sd" -v y="$y_sd" 'BEGIN { exit !(x > 0 && (y - x / 2) ^ 2 < 1e-8) }' || fail "y's measurement sd $y_sd is not half of $x_sd"
    expect "^y  $x_sd  [0-9.]+  \+0\.50  0\.300$"
    python3 "$src/scripts/measurement_errors.py" "$run_dir" "$work/$case_name.gt.tum" 20 30 >"$work/$case_name.out" 2>&1 &&
      fail "an empty window was accepted"
    expect "fewer than 3 matched scans" ;;
  tilt_passes_script)
    # scripts/tilt_passes.py on a synthetic static tilting rig with a known
    # answer: up 0 -> 60 deg in 0.1 deg lines, then down 60 -> 40 deg with
    # every angle of the way down reported 0.5 deg too high; each line's
    # ranges are a smooth function of its true tilt.
    python3 -c 'import numpy' 2>/dev/null || exit 77
    ds="$work/$case_name.ds"; rm -rf "$ds"; mkdir -p "$ds"
    python3 - "$ds" <<'PY' || fail "could not write the synthetic rig"
import math, struct, sys
folder = sys.argv[1]
true_deg = [i / 10 for i in range(601)] + [60 - i / 10 for i in range(1, 201)]
reported = true_deg[:601] + [a + 0.5 for a in true_deg[601:]]
with open(folder + '/scans.bin', 'wb') as f, open(folder + '/encoder.csv', 'w') as enc:
    f.write(b'UNIMAPSC' + struct.pack('<I', 1))
    enc.write('# time_s angle_rad\n')
    for k, (tilt, angle) in enumerate(zip(true_deg, reported)):
        ranges = [1.5 + 0.3 * math.sin(0.2 * tilt + 0.05 * b) for b in range(181)]
        payload = struct.pack('<6dI', 0.1 * k, -1.5, 0.0167, 1e-4, 0.02, 5.6, 181)
        payload += struct.pack('<181f', *ranges) + struct.pack('<I', 0)
        f.write(struct.pack('<BI', 1, len(payload)) + payload)
        enc.write(f'{0.1 * k} {math.radians(angle)}\n')
PY
    python3 "$src/scripts/tilt_passes.py" "$ds" >"$work/$case_name.out" 2>&1 || fail "exit $?: $(cat "$work/$case_name.out")"
    expect "^# 801 lines, up 0.00 -> 60.40 deg, down to 40.50 deg$"
    expect "^ +45-50 +50 +\+0\.500 +0\.0$"
    expect "^ +50-55 +50 +\+0\.500 +0\.0$"
    grep -Eq "^ +(0-5|35-40) " "$work/$case_name.out" && fail "a bin without a way down: $(cat "$work/$case_name.out")"
    rm -f "$ds/encoder.csv"; echo "# time_s angle_rad" >"$ds/encoder.csv"; echo "0 0" >>"$ds/encoder.csv"
    python3 "$src/scripts/tilt_passes.py" "$ds" >"$work/$case_name.out" 2>&1 && fail "a short encoder.csv was accepted"
    expect "801 lines but 1 angles" ;;
  evaluate_map_quality)
    # A map alone, no ground truth: a noise-free 2 m x 2 m plane (0.05 m grid)
    # is all planar with no thickness; the same plane doubled 0.15 m apart is not.
    plane() { awk -v z="$1" 'BEGIN { for (i = 0; i < 40; i++) for (j = 0; j < 40; j++) print i * 0.05, j * 0.05, z }'; }
    { printf 'ply\nformat ascii 1.0\nelement vertex 1600\nproperty float x\nproperty float y\nproperty float z\nend_header\n'
      plane 0; } >"$work/$case_name.plane.ply"
    code=$(run evaluate --map "$work/$case_name.plane.ply" --out "$work/$case_name.eval"); [ "$code" = 0 ] || fail "exit $code"
    expect "^map_planar_share +1\.000 "; expect "^map_plane_variance_m2 +0\.000000 "; expect "^map_quality_points +1600 "
    grep -Eq '^  "map_mean_entropy": -[0-9.e-]+,?$' "$work/$case_name.eval/metrics.json" || fail "metrics.json lacks the entropy"
    { printf 'ply\nformat ascii 1.0\nelement vertex 3200\nproperty float x\nproperty float y\nproperty float z\nend_header\n'
      plane 0; plane 0.15; } >"$work/$case_name.double.ply"
    code=$(run evaluate --map "$work/$case_name.double.ply" --out "$work/$case_name.eval2"); [ "$code" = 0 ] || fail "exit $code"
    expect "^map_planar_share +0\.[0-4][0-9]* "
    # Its largest planes: the plane 1 m from the origin, all its points, no
    # thickness (a plane through the origin is a sensor's fan, not taken).
    { printf 'ply\nformat ascii 1.0\nelement vertex 1600\nproperty float x\nproperty float y\nproperty float z\nend_header\n'
      plane 1; } >"$work/$case_name.plane1.ply"
    code=$(run evaluate --map "$work/$case_name.plane1.ply" --out "$work/$case_name.eval3"); [ "$code" = 0 ] || fail "exit $code"
    expect "^map_plane_1_thickness_m +0\.0000 "; expect "^map_plane_1_points +1600 "; expect "^map_plane_1_normal_z +-?1\.00 "
    grep -Eq '^  "map_plane_1_median_range_m": [0-9.e-]+,?$' "$work/$case_name.eval3/metrics.json" || fail "metrics.json lacks the plane's range"
    ! grep -q map_plane_2 "$work/$case_name.eval3/metrics.json" || fail "a second plane in a one-plane map"
    code=$(run evaluate --estimate "$work/$case_name.plane.ply"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "--estimate needs --truth" ;;
  evaluate_map)
    # A plane world z = 0; the estimate is the truth raised by 1 m, and so is
    # the map (map points live in the estimate's frame): unaligned errors are
    # the offsets + 1 m, ATE-aligned ones the offsets 0.1 0.2 0.3 0.4 m.
    ds="$work/$case_name.ds" out="$work/$case_name.eval"; rm -rf "$ds" "$out"; mkdir -p "$ds"
    printf -- '- {type: plane, center: [0, 0, 0], size: [100, 100], rpy_deg: [0, 0, 0]}\n' >"$ds/world.yaml"
    printf '0 0 0 1 0 0 0 1\n1 4 0 1 0 0 0 1\n2 4 4 1.5 0 0 0 1\n3 0 4 1 0 0 0 1\n4 0 0 2 0 0 0 1\n' >"$ds/groundtruth.tum"
    awk '{ $4 += 1; print }' "$ds/groundtruth.tum" >"$work/$case_name.est.tum"
    printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 1 1.1\n2 -1 0.8\n-3 2 1.3\n0.5 0.5 1.4\n' >"$work/$case_name.map.ply"
    code=$(run evaluate --estimate "$work/$case_name.est.tum" --truth "$ds/groundtruth.tum" --out "$out" \
                        --map "$work/$case_name.map.ply"); [ "$code" = 0 ] || fail "exit $code"
    expect "^world: +$ds/world.yaml"
    expect "^map_error_mean_m +1\.1500 "; expect "^map_error_p95_m +1\.4000 "; expect "^map_error_max_m +1\.4000 "
    expect "^map_points +4 "; expect "^map_error_aligned_mean_m +0\.2500 "; expect "^map_error_aligned_max_m +0\.4000 "
    for key in map_error_mean_m map_error_p95_m map_error_max_m map_error_aligned_mean_m map_error_aligned_p95_m \
               map_error_aligned_max_m; do
      grep -Eq "^  \"$key\": [0-9.e-]+,?$" "$out/metrics.json" || fail "metrics.json lacks a number for $key"
      grep -q "\"key\":\"$key\"" "$out/report.html" || fail "report.html lacks $key"
    done
    grep -Eq '^  "map_points": 4,?$' "$out/metrics.json" || fail "metrics.json: map_points is not 4"
    if command -v python3 >/dev/null; then
      python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$out/metrics.json" || fail "metrics.json is not JSON"
    fi
    # Without a world there is nothing to compare with: a note, no map keys.
    rm "$ds/world.yaml"
    code=$(run evaluate --estimate "$work/$case_name.est.tum" --truth "$ds/groundtruth.tum" --out "$out" \
                        --map "$work/$case_name.map.ply"); [ "$code" = 0 ] || fail "exit $code without a world"
    expect "note: no world file"; ! grep -q map_error "$out/metrics.json" || fail "map keys without a world"
    # A named world that does not exist is an error.
    code=$(run evaluate --estimate "$work/$case_name.est.tum" --truth "$ds/groundtruth.tum" --out "$out" \
                        --map "$work/$case_name.map.ply" --world "$ds/nope.yaml"); [ "$code" = 2 ] || fail "exit $code"
    expect "error: world $ds/nope.yaml: no such file" ;;
  *) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
