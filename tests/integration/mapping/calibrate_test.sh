#!/usr/bin/env bash
# `unimap calibrate` end to end (issue 22): a simulated rig whose platform
# file's LiDAR extrinsic is off by 2 cm and 1 deg is calibrated back.
#   calibrate_test.sh CASE UNIMAP_EXE SOURCE_DIR WORK_DIR
set -uo pipefail
source "$(dirname "$0")/../script_helpers.sh"

# The numbers of a "key: [a, b, c]" line of a platform file, one a line.
vector() { sed -n "s/^ *$2: \[\(.*\)\]$/\1/p" "$1" | tr ',' '\n' | tr -d ' '; }
# near A B TOL: |A - B| < TOL
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d < t) }'; }

case "$case_name" in
  moving_rig)
    # The rotating Hokuyo carried down the narrow hallway for 30 s; the body's
    # poses are the simulation's truth (a real rig would give a run's
    # trajectory.tum). The shipped extrinsic is the truth: motor_lidar
    # translation [0, 0, -0.05] m, rpy [90, 0, 0] deg.
    code=$(run simulate --scenario "$src/configs/scenarios/narrow_hallway.yaml" --payload "$hokuyo" --duration-s 31 --out "$work/data")
    [ "$code" = 0 ] || fail "simulate exit $code"
    sed -e 's|translation_m: \[0.0, 0.0, -0.05\]|translation_m: [0.02, 0.01, -0.05]|' \
        -e 's|rpy_deg: \[90.0, 0.0, 0.0\]|rpy_deg: [91.0, -1.0, 0.5]|' "$hokuyo" > "$work/perturbed.yaml"
    grep -q "0.02, 0.01, -0.05" "$work/perturbed.yaml" || fail "the perturbed platform file was not written"
    code=$(run calibrate --platform "$work/perturbed.yaml" --data "$work/data" --trajectory "$work/data/groundtruth.tum" \
             --max-duration-s 30 --out "$work/calibrated.yaml")
    [ "$code" = 0 ] || fail "calibrate exit $code"
    # Five of six directions are observed; the sixth, a shift along the
    # motor axis (the LiDAR's y), keeps the platform's value (-0.05: not perturbed).
    expect "directions estimated: 5 of 6"
    expect "not estimated: direction \[translation \[-?0.0[0-9]+, -?1.000,"
    t=($(vector "$work/calibrated.yaml" extrinsic.motor_lidar.translation_m))
    r=($(vector "$work/calibrated.yaml" extrinsic.motor_lidar.rpy_deg))
    echo "calibrated translation_m ${t[*]}, rpy_deg ${r[*]}"
    near "${t[0]}" 0 0.005 && near "${t[1]}" 0 0.005 && near "${t[2]}" -0.05 0.005 ||
      fail "translation ${t[*]} is not within 5 mm of [0, 0, -0.05]"
    near "${r[0]}" 90 0.2 && near "${r[1]}" 0 0.2 && near "${r[2]}" 0 0.2 ||
      fail "rpy ${r[*]} is not within 0.2 deg of [90, 0, 0]"
    # The written platform file loads, with everything else as it was.
    code=$(run config --platform "$work/calibrated.yaml")
    [ "$code" = 0 ] || fail "the calibrated platform file does not load"
    expect "extrinsic.body_motor.translation_m +\[0, 0, -0.1\]"
    # Without --static or --trajectory the body's motion is unknown: an error.
    code=$(run calibrate --platform "$hokuyo" --data "$work/data" --out "$work/x.yaml")
    [ "$code" = 2 ] || fail "calibrate without --static or --trajectory: exit $code, expected 2"
    expect "give either --static"
    [ ! -e "$work/x.yaml" ] || fail "a platform file was written after an error" ;;
  *) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
