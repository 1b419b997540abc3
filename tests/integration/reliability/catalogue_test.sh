#!/usr/bin/env bash
# The bad-input and fault catalogue (docs/reliability.md): every case runs
# one `unimap` command on damaged input and asserts its exact outcome: the
# exit code, the message (file, line or record, key, reason) and that no
# ".partial" file and no crash trace is left.
#   catalogue_test.sh CLASS UNIMAP_EXE SOURCE_DIR WORK_DIR   runs one class
#   catalogue_test.sh --list CLASS ...                       prints its rows (markdown) without running
# Classes: config metadata streams maps convert cli signals disk.
set -uo pipefail
LIST=0
if [ "$1" = "--list" ]; then
  LIST=1; shift
  set -- "$1" /bin/false "$(cd "$(dirname "$0")/../../.." && pwd)" /tmp/unimap-catalogue-list
fi
# shellcheck source=../script_helpers.sh
. "$(dirname "$0")/../script_helpers.sh"
class=$case_name
cases=0

# case_ ID "WHAT" EXIT 'REGEX' COMMAND...: runs the command (unimap's
# arguments when the first word is not a path) and checks exit code and output.
case_() {
  local id=$1 what=$2 want=$3 regex=$4; shift 4
  cases=$((cases + 1))
  if [ "$LIST" = 1 ]; then
    printf '| `%s` | %s | %s | `%s` |\n' "$id" "$what" "$want" "$(printf '%s' "$regex" | sed 's/|/\\|/g')"
    return
  fi
  local out="$work/$id.out" code
  if [ "${1#/}" != "$1" ] || [ "$1" = bash ]; then "$@" >"$out" 2>&1; else "$exe" "$@" >"$out" 2>&1; fi
  code=$?
  cat "$out" >>"$log"
  [ "$code" = "$want" ] || fail "$id: exit $code, expected $want; output: $(head -c 600 "$out")"
  grep -Eq -- "$regex" "$out" || fail "$id: output lacks /$regex/: $(head -c 600 "$out")"
  ! grep -Eq 'terminate called|Aborted|Segmentation fault|AddressSanitizer|runtime error:' "$out" ||
    fail "$id: crash trace in the output"
  local partial
  partial=$(find "$work" -name '*.partial' | head -3)
  [ -z "$partial" ] || fail "$id: left $partial"
}
# A fresh copy of the base dataset named $1 (the simulated tunnel, rotating Hokuyo).
variant() { rm -rf "$work/$1"; cp -r "$work/base" "$work/$1"; echo "$work/$1"; }
# Replaces field $3 of line $2 of file $1 by $4.
set_field() { awk -v l="$2" -v f="$3" -v v="$4" 'NR == l { $f = v } { print }' "$1" >"$1.tmp" && mv "$1.tmp" "$1"; }
base_dataset() {  # $1 seconds of the tunnel into $work/base
  [ "$LIST" = 1 ] && return
  local code
  code=$(run simulate --scenario "$src/configs/scenarios/tunnel.yaml" --duration-s "$1" --out "$work/base" --quiet)
  [ "$code" = 0 ] || fail "simulate exit $code"
  rm -f "$work/base/world_map.pcd"
}
text() { [ "$LIST" = 1 ] || printf "$2" >"$work/$1"; echo "$work/$1"; }  # text NAME FORMAT: a file from printf
data() { [ "$LIST" = 1 ] && { echo "$work/$1"; return; }; variant "$1"; }
run_on() { echo run --platform "$hokuyo" --quiet --data "$1" --out "$work/out_$(basename "$1")"; }

# A CARMEN log long enough to interrupt or to fill a small 'disk': 40,000
# FLASER lines of 180 beams (one hour at 10 Hz, 36 MB), written once.
big_clf() {
  [ -f "$work/big.clf" ] || awk 'BEGIN {
    for (i = 0; i < 40000; i++) {
      t = 10 + 0.1 * i; line = "FLASER 180"
      for (b = 0; b < 180; b++) line = line sprintf(" %.2f", 2 + 0.1 * (b % 30))
      printf "%s 1.0 2.0 0.0 1.0 2.0 0.0 %.3f host %.3f\n", line, t, t
    } }' > "$work/big.clf"
  echo "$work/big.clf"
}

case $class in
config)
  p=$(text alias_map.yaml 'plugin: rotating_2d\nparameters: &a\n  g: *a\n')
  case_ platform_alias_cycle_map "platform file: a group holding an alias to itself" 2 \
    "alias_map.yaml:3: key 'g': a YAML alias refers to a group that contains it \(a cycle\)" config --platform "$p"
  p=$(text alias_list.yaml 'plugin: rotating_2d\nparameters:\n  x: &a [*a]\n')
  case_ platform_alias_cycle_list "platform file: a list holding itself (x: &a [*a])" 2 \
    "alias_list.yaml:3: key 'x': expected a list of numbers, but element 1 is a list" config --platform "$p"
  p=$(text alias_deep.yaml 'plugin: rotating_2d\nparameters: &a\n  g:\n    h: *a\n')
  case_ platform_alias_cycle_nested "platform file: an alias to an enclosing group two levels up" 2 \
    "alias_deep.yaml:4: key 'g.h': .*a cycle" config --platform "$p"
  if [ "$LIST" = 0 ]; then
    { printf 'plugin: rotating_2d\nparameters:\n  l0: &l0 {a: 1, b: 2, c: 3, d: 4, e: 5, f: 6, g: 7, h: 8, i: 9, j: 10}\n'
      for l in 1 2 3 4 5 6 7 8 9; do
        printf '  l%d: &l%d {a: *l%d, b: *l%d, c: *l%d, d: *l%d, e: *l%d, f: *l%d, g: *l%d, h: *l%d, i: *l%d, j: *l%d}\n' \
          "$l" "$l" $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1)) $((l - 1))
      done; } >"$work/laughs.yaml"
    { printf 'plugin: rotating_2d\nparameters:\n  x: '; head -c 5000 /dev/zero | tr '\0' '['; } >"$work/deep.yaml"
    head -c 3000 "$exe" >"$work/random.yaml"  # binary bytes, the same every run
    mkdir -p "$work/folder.yaml"
  fi
  case_ platform_alias_expansion "platform file: 10^10 keys by nested aliases (billion laughs)" 2 \
    "laughs.yaml:[0-9]+: key 'l[0-9.a-j]+': more than 10000 parameters \(YAML aliases expanding\?\)" \
    config --platform "$work/laughs.yaml"
  case_ platform_deep_nesting "platform file: 5000 nested lists" 2 "deep.yaml:[0-9]+: YAML syntax error" \
    config --platform "$work/deep.yaml"
  p=$(text tab.yaml 'plugin: rotating_2d\nparameters:\n\tscans_per_3d_scan: 3\n')
  case_ platform_tab_indent "platform file: a tab as indentation" 2 "tab.yaml:3: YAML syntax error" config --platform "$p"
  p=$(text empty.yaml '')
  case_ platform_empty "platform file: empty" 2 "empty.yaml: key 'plugin': missing 'plugin': the file is empty" \
    config --platform "$p"
  case_ platform_directory "platform file: a folder" 105 "--platform: File is actually a directory: .*folder.yaml" \
    config --platform "$work/folder.yaml"
  p=$(text dup.yaml 'plugin: rotating_2d\nparameters:\n  scans_per_3d_scan: 3\n  scans_per_3d_scan: 4\n')
  case_ platform_duplicate_key "platform file: a key set twice" 2 \
    "dup.yaml:4: key 'scans_per_3d_scan': set twice \(first on line 3\)" config --platform "$p"
  p=$(text nan.yaml 'plugin: rotating_2d\nparameters:\n  sigma_accel_m_s2: .nan\n')
  case_ platform_nan_value "platform file: .nan for a number" 2 "nan.yaml:3: key 'sigma_accel_m_s2'" \
    config --platform "$p"
  p=$(text list.yaml 'plugin: rotating_2d\nparameters:\n  extrinsic:\n    body_motor:\n      rpy_deg: [0, 0]\n')
  case_ platform_short_list "platform file: a 2-element rotation" 2 "list.yaml:5: key 'extrinsic.body_motor.rpy_deg'" \
    config --platform "$p"
  case_ platform_binary_garbage "platform file: 3000 bytes of an executable" 2 "random.yaml" config --platform "$work/random.yaml"
  p="$work/long.yaml"
  [ "$LIST" = 1 ] || { printf 'plugin: rotating_2d\nparameters:\n  sigma_accel_m_s2: '; head -c 300000 /dev/zero | tr '\0' 1
    printf '\n'; } >"$p"
  case_ platform_long_number "platform file: a 300,000-digit number" 2 \
    "long.yaml:3: key 'sigma_accel_m_s2': expected number, got string 1111" config --platform "$p"
  ;;
metadata)
  base_dataset 2
  d=$(data md_alias); [ "$LIST" = 1 ] || printf 'format_version: 1\npayload: rotating_2d\npayload_parameters: &a\n  g: *a\n' >"$d/metadata.yaml"
  case_ metadata_alias_cycle "metadata.yaml: payload_parameters holding an alias to itself" 2 \
    "metadata.yaml:4: key 'g': a YAML alias refers to a group that contains it \(a cycle\)" $(run_on "$d")
  d=$(data md_root); [ "$LIST" = 1 ] || printf '&r\nformat_version: 1\npayload: rotating_2d\npayload_parameters: *r\n' >"$d/metadata.yaml"
  case_ metadata_alias_root "metadata.yaml: the file as its own payload_parameters" 2 "metadata.yaml:[0-9]+: key '[a-z_.]+': .*a cycle" $(run_on "$d")
  d=$(data md_missing); [ "$LIST" = 1 ] || rm "$d/metadata.yaml"
  case_ metadata_missing "no metadata.yaml (an unfinished dataset)" 2 "md_missing: no metadata.yaml: not a dataset, or an incomplete one" $(run_on "$d")
  d=$(data md_newer); [ "$LIST" = 1 ] || sed -i 's/^format_version: 1/format_version: 7/' "$d/metadata.yaml"
  case_ metadata_newer_format "format_version 7" 2 "metadata.yaml:[0-9]+: key 'format_version': dataset format version 7 is newer than this build reads" $(run_on "$d")
  d=$(data md_unknown); [ "$LIST" = 1 ] || printf 'imu_rate: 200\n' >>"$d/metadata.yaml"
  case_ metadata_unknown_key "an unknown key (imu_rate)" 2 "metadata.yaml:[0-9]+: key 'imu_rate': unknown key" $(run_on "$d")
  d=$(data md_payload_type); [ "$LIST" = 1 ] || sed -i 's/^payload: .*/payload: [a, b]/' "$d/metadata.yaml"
  case_ metadata_payload_list "payload given as a list" 2 "metadata.yaml:[0-9]+: key 'payload': expected a string, got a list" $(run_on "$d")
  d=$(data md_mismatch); [ "$LIST" = 1 ] || sed -i 's/^payload: .*/payload: "fixed_3d"/' "$d/metadata.yaml"
  case_ payload_mismatch "dataset recorded for fixed_3d, platform rotating_2d" 2 \
    "the dataset was recorded for payload 'fixed_3d', the platform's plugin is 'rotating_2d'.*--force-payload" $(run_on "$d")
  case_ payload_mismatch_forced "the same with --force-payload: a warning, the run goes on" 0 \
    "warning: .*recorded for payload 'fixed_3d'.*\(--force-payload\)" $(run_on "$d") --force-payload
  d=$(data md_binary); [ "$LIST" = 1 ] || head -c 2000 "$exe" >"$d/metadata.yaml"
  case_ metadata_binary "metadata.yaml of binary bytes" 2 "metadata.yaml" $(run_on "$d")
  ;;
streams)
  base_dataset 4
  d=$(data imu_1e300); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 301 2 1e300
  case_ imu_accel_1e300 "imu.csv: one accelerometer sample of 1e300" 2 \
    "imu.csv:301: accelerometer x 1e\+300 m/s\^2 is beyond \+-392.3 m/s\^2" $(run_on "$d")
  d=$(data imu_gyro); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 120 7 -1000
  case_ imu_gyro_beyond "imu.csv: gyroscope z -1000 rad/s" 2 "imu.csv:120: gyroscope z -1000 rad/s is beyond \+-69.81 rad/s" $(run_on "$d")
  d=$(data imu_nan); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 50 3 nan
  case_ imu_nan "imu.csv: a NaN accelerometer value" 2 "imu.csv:50: accelerometer y nan m/s\^2 is not a number" $(run_on "$d")
  d=$(data imu_jump); [ "$LIST" = 1 ] || awk 'NR >= 400 && !/^#/ { $1 = sprintf("%.6f", $1 + 1e6) } { print }' "$work/base/imu.csv" >"$d/imu.csv"
  case_ imu_clock_jump "imu.csv: the clock jumps +1e6 s at line 400" 2 \
    "imu.csv:400: time jumps 1000000.00[0-9]* s ahead .*a clock jump or lost data" $(run_on "$d")
  d=$(data imu_back); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 200 1 0.1
  case_ imu_time_backwards "imu.csv: time goes backwards at line 200" 2 "imu.csv:200: time goes backwards: 0.1 s after" $(run_on "$d")
  d=$(data imu_huge_time); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 2 1 1e300
  case_ imu_time_1e300 "imu.csv: first time 1e300 s" 2 "imu.csv:2: time 1e\+300 s is beyond \+-1e\+10 s" $(run_on "$d")
  d=$(data imu_word); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 77 4 abc
  case_ imu_not_a_number "imu.csv: a word for a number" 2 "imu.csv:77: field 4 'abc' is not a number" $(run_on "$d")
  d=$(data imu_short); [ "$LIST" = 1 ] || set_field "$d/imu.csv" 90 7 ''
  case_ imu_missing_field "imu.csv: a row of 6 numbers" 2 "imu.csv:90: expected 7 numbers, found 6" $(run_on "$d")
  d=$(data imu_empty); [ "$LIST" = 1 ] || : >"$d/imu.csv"
  case_ imu_empty_motion_imu "empty imu.csv with --motion imu" 2 "--motion imu: the dataset has no IMU data" $(run_on "$d") --motion imu
  case_ imu_empty_auto "empty imu.csv, --motion auto: says it uses constant velocity" 0 \
    "motion: constant-velocity \(the dataset has neither IMU data" $(run_on "$d")
  d=$(data imu_none); [ "$LIST" = 1 ] || rm "$d/imu.csv"
  case_ imu_missing_auto "no imu.csv, --motion auto: says it uses constant velocity" 0 \
    "motion: constant-velocity \(the dataset has neither IMU data" $(run_on "$d")
  d=$(data enc_1e300); [ "$LIST" = 1 ] || set_field "$d/encoder.csv" 50 2 1e300
  case_ encoder_1e300 "encoder.csv: one angle of 1e300 rad" 2 "encoder.csv:50: encoder angle 1e\+300 rad is beyond \+-1e\+09 rad" $(run_on "$d")
  d=$(data enc_jump); [ "$LIST" = 1 ] || awk 'NR >= 100 && !/^#/ { $1 = sprintf("%.6f", $1 + 20) } { print }' "$work/base/encoder.csv" >"$d/encoder.csv"
  case_ encoder_clock_jump "encoder.csv: the clock jumps +20 s" 2 "encoder.csv:100: time jumps 20.01[0-9]* s ahead" $(run_on "$d")
  d=$(data enc_none); [ "$LIST" = 1 ] || rm "$d/encoder.csv"
  case_ encoder_missing "no encoder.csv for a motor payload" 2 "payload 'rotating_2d' needs motor encoder samples \(encoder.csv\), the dataset has none" $(run_on "$d")
  d=$(data odo_pos); [ "$LIST" = 1 ] || printf '0 0 0 0 0 0 0 1\n0.1 1e300 0 0 0 0 0 1\n' >"$d/odometry.csv"
  case_ odometry_position_1e300 "odometry.csv: a position of 1e300 m" 2 "odometry.csv:2: position x 1e\+300 m is beyond \+-1e\+08 m" $(run_on "$d")
  d=$(data odo_quat); [ "$LIST" = 1 ] || printf '0 0 0 0 0 0 0 1\n0.1 0 0 0 0 0 0 2\n' >"$d/odometry.csv"
  case_ odometry_non_unit_quaternion "odometry.csv: |q| = 2" 2 "odometry.csv:2: quaternion \(qx qy qz qw\) is not unit: \|q\| = 2" $(run_on "$d")
  d=$(data scans_header); [ "$LIST" = 1 ] || printf 'UNIMAPSC\001\000\000\000' >"$d/scans.bin"
  case_ scans_header_only "scans.bin with only its file header" 2 "holds no scan \(scans.bin is absent or has no record\): nothing to map" $(run_on "$d")
  d=$(data scans_none); [ "$LIST" = 1 ] || rm "$d/scans.bin"
  case_ scans_missing "no scans.bin" 2 "holds no scan" $(run_on "$d")
  d=$(data scans_magic); [ "$LIST" = 1 ] || printf 'NOTASCAN\001\000\000\000' | dd of="$d/scans.bin" conv=notrunc 2>/dev/null
  case_ scans_bad_magic "scans.bin with another magic" 2 "scans.bin: not a unimap scan file \(the magic is not UNIMAPSC\)" $(run_on "$d")
  d=$(data scans_cut); [ "$LIST" = 1 ] || truncate -s -100 "$d/scans.bin"
  case_ scans_truncated "scans.bin cut 100 bytes short" 2 "scans.bin: record [0-9]+ \(byte [0-9]+\): truncated: its header announces [0-9]+ payload bytes, only [0-9]+ remain" $(run_on "$d")
  d=$(data scans_size); [ "$LIST" = 1 ] || printf '\377\377\377\177' | dd of="$d/scans.bin" bs=1 seek=13 conv=notrunc 2>/dev/null
  case_ scans_huge_record "scans.bin: first record announcing 2 GiB" 2 "scans.bin: record 1 \(byte 12\): truncated: its header announces 2147483647 payload bytes" $(run_on "$d")
  d=$(data scans_kind); [ "$LIST" = 1 ] || printf '\011' | dd of="$d/scans.bin" bs=1 seek=12 conv=notrunc 2>/dev/null
  case_ scans_unknown_kind "scans.bin: record kind 9" 2 "scans.bin: record 1 \(byte 12\): unknown record kind 9" $(run_on "$d")
  # (outside $work: case_ fails on any .partial file left in it)
  d="${work}_only_partial"
  [ "$LIST" = 1 ] || { rm -rf "$d"; cp -r "$work/base" "$d"; mv "$d/metadata.yaml" "$d/metadata.yaml.partial"; }
  case_ dataset_only_partial "a dataset whose writer never finished (metadata.yaml.partial)" 2 "no metadata.yaml: not a dataset, or an incomplete one" $(run_on "$d")
  [ "$LIST" = 1 ] || rm -rf "$d"
  ;;
maps)
  base_dataset 2
  if [ "$LIST" = 0 ]; then
    printf 'VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH 2147483647\nHEIGHT 1\nPOINTS 2147483647\nDATA binary\n' >"$work/huge.pcd"
    head -c 234000 /dev/zero >>"$work/huge.pcd"
    printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 300000000\nHEIGHT 1\nPOINTS 300000000\nDATA ascii\n' >"$work/m300.pcd"
    head -c 234000 /dev/zero | tr '\0' '1' | fold -w 5 | sed 's/$/ 1 1/' >>"$work/m300.pcd"
    printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\nthe map ends here\n4 5 6\n' >"$work/text.pcd"
    printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4294967295\nproperty float x\nproperty float y\nproperty float z\nend_header\n' >"$work/huge.ply"
    head -c 1200 /dev/zero >>"$work/huge.ply"
    head -c 4000 "$exe" >"$work/random.bt"
    printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\nnan nan nan\ninf 1 1\n' >"$work/nan.pcd"
    printf '0 0 0\n' >"$work/map.txt"
  fi
  loc() { echo localize --platform "$hokuyo" --quiet --data "$work/base" --out "$work/loc_$1" --map; }
  case_ pcd_huge_points "localize --map: a 234 KB PCD announcing 2^31-1 points" 2 \
    "huge.pcd: the header announces 2147483647 points of 16 bytes \(34359738352 bytes\), only 234000 bytes follow the header" $(loc huge) "$work/huge.pcd"
  case_ pcd_300M_ascii "localize --map: an ascii PCD announcing 300 M points" 2 \
    "m300.pcd: the header announces 300000000 points, the [0-9]+ bytes of ascii data after it cannot hold them" $(loc m300) "$work/m300.pcd"
  case_ pcd_ascii_text_line "localize --map: an ascii PCD with a line of text" 2 "text.pcd:10: value 1 'the' is not a number" $(loc text) "$work/text.pcd"
  case_ pcd_no_finite_points "localize --map: a PCD of NaN / inf points only" 2 "nan.pcd': no finite points" $(loc nan) "$work/nan.pcd"
  case_ bt_random "localize --map: 4000 binary bytes as an OctoMap .bt" 2 "cannot read octree '.*random.bt': not a valid OctoMap .bt file" $(loc bt) "$work/random.bt"
  if [ "$LIST" = 0 ]; then
    code=$(run run --platform "$hokuyo" --quiet --data "$work/base" --out "$work/mapped")
    [ "$code" = 0 ] || fail "run exit $code"
    head -c 2000 "$work/mapped/map.bt" >"$work/cut.bt"
  fi
  case_ bt_truncated "localize --map: an OctoMap .bt cut after 2000 bytes" 2 "cannot read octree '.*cut.bt': not a valid OctoMap .bt file" $(loc cut) "$work/cut.bt"
  case_ map_missing "localize --map: no such file" 2 "map '.*nothing.pcd': no such file" $(loc missing) "$work/nothing.pcd"
  case_ map_extension "localize --map: a .txt map" 2 "unsupported format '.txt' \(expected .bt or .pcd\)" $(loc txt) "$work/map.txt"
  [ "$LIST" = 1 ] || printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n' >"$work/line.tum"
  case_ ply_huge_count "evaluate --map: a PLY announcing 2^32-1 vertices" 2 "huge.ply: PLY data ends after 100 of 4294967295 vertices" \
    evaluate --estimate "$work/line.tum" --truth "$work/line.tum" --map "$work/huge.ply" --world "$work/base/world.yaml" --out "$work/ev_ply"
  [ "$LIST" = 1 ] || printf '0 0 0 0 0 0 0 1\n' >"$work/one.tum"
  case_ evaluate_disjoint "evaluate: trajectories that do not overlap in time" 2 "do not overlap|no pose" \
    evaluate --estimate "$work/one.tum" --truth "$work/line.tum" --out "$work/ev_disjoint"
  ;;
convert)
  if [ "$LIST" = 0 ]; then
    printf 'FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 1e300 host 10.2\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.3 host 10.3\n' >"$work/huge.clf"
    printf 'FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 5000 host 10.2\n' >"$work/jump.clf"
    printf 'FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.1 host 10.1\nFLASER 3 1.0 2.0 0 0 0 0 0 0 10.2 host 10.2\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 10.3 host 10.3\n' >"$work/short.clf"
    printf 'BZh91AY&SYgarbage' >"$work/bad.clf.bz2"
    mkdir -p "$work/kitti_odd" "$work/kitti_empty" "$work/kitti_pcd"
    head -c 20 /dev/zero >"$work/kitti_odd/000000.bin"
    mkdir -p "$work/kitti_huge"
    printf 'VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nWIDTH 2147483647\nHEIGHT 1\nPOINTS 2147483647\nDATA binary\n' >"$work/kitti_huge/000000.pcd"
    head -c 1000 /dev/zero >>"$work/kitti_huge/000000.pcd"
    printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n1 2 3\nx y z\n4 5 6\n' >"$work/kitti_pcd/000000.pcd"
    head -c 5000 "$exe" >"$work/random.bag"
    printf '#ROSBAG V2.0\n' >"$work/header.bag"
  fi
  case_ carmen_huge_timestamp "CARMEN: a FLASER stamped 1e300" 2 "huge.clf:2: ipc timestamp 1e\+300 s is beyond \+-1e\+10 s" \
    convert --format carmen --input "$work/huge.clf" --out "$work/c_huge"
  case_ carmen_clock_jump "CARMEN: a FLASER 4990 s after the previous one" 2 "jump.clf:2: ipc timestamp 5000 s jumps 4989.9 s past the previous message's \(10.1 s\), more than 60 s: a clock jump" \
    convert --format carmen --input "$work/jump.clf" --out "$work/c_jump"
  case_ carmen_clock_jump_allowed "the same with --carmen-max-time-step-s 10000" 0 "scans: +2" \
    convert --format carmen --input "$work/jump.clf" --out "$work/c_jump2" --carmen-max-time-step-s 10000
  case_ carmen_short_line "CARMEN: a FLASER with a field missing mid-log" 2 "short.clf:2: FLASER with 3 beams needs 14 fields, found 13" \
    convert --format carmen --input "$work/short.clf" --out "$work/c_short"
  case_ carmen_corrupt_bz2 "CARMEN: bzip2 data cut after its block header: nothing converted" 2 \
    "bad.clf.bz2: no scan converted: the dataset written holds none" convert --format carmen --input "$work/bad.clf.bz2" --out "$work/c_bz2"
  case_ kitti_bin_size "KITTI: a .bin of 20 bytes (not float32 x 4)" 2 "000000.bin: size 20 bytes is not a multiple of 16" \
    convert --format kitti --input "$work/kitti_odd" --out "$work/k_odd"
  case_ kitti_no_scans "KITTI: a folder without scans" 2 "kitti_empty: no KITTI scans \(\*.bin or \*.pcd\)" \
    convert --format kitti --input "$work/kitti_empty" --out "$work/k_empty"
  case_ kitti_pcd_huge_points "KITTI: a .pcd announcing 2^31-1 points" 2 \
    "000000.pcd: the header announces 2147483647 points of 16 bytes \(34359738352 bytes\), only 1000 bytes follow" \
    convert --format kitti --input "$work/kitti_huge" --out "$work/k_huge"
  case_ kitti_pcd_text "KITTI: an ascii .pcd with a line of text" 2 "000000.pcd:10: value 1 'x' is not a number" \
    convert --format kitti --input "$work/kitti_pcd" --out "$work/k_pcd"
  case_ rosbag_random "ROS bag: 5000 binary bytes" 2 "random.bag: cannot read ROS bag" \
    convert --format rosbag --input "$work/random.bag" --out "$work/r_random"
  case_ rosbag_header_only "ROS bag: only the version line" 2 "header.bag: cannot read ROS bag" \
    convert --format rosbag --input "$work/header.bag" --out "$work/r_header"
  # The same recordings given to `run` directly (converted as it reads them).
  case_ run_direct_kitti_bin_size "run on a KITTI folder directly: a .bin of 20 bytes" 2 \
    "000000.bin: size 20 bytes is not a multiple of 16" \
    run --platform "$src/configs/platforms/kitti_hdl64.yaml" --quiet --data "$work/kitti_odd" --out "$work/d_kitti"
  case_ run_direct_carmen_clock_jump "run on a CARMEN log directly: a FLASER 4990 s after the previous one" 2 \
    "jump.clf:2: ipc timestamp 5000 s jumps 4989.9 s past the previous message's" \
    run --platform "$hokuyo" --force-payload --quiet --data "$work/jump.clf" --out "$work/d_jump"
  case_ run_direct_rosbag_random "run on a .bag of 5000 binary bytes" 2 "random.bag: cannot read ROS bag" \
    run --platform "$hokuyo" --quiet --data "$work/random.bag" --out "$work/d_random"
  ;;
cli)
  base_dataset 3
  if [ "$LIST" = 0 ]; then
    : >"$work/a_file"; : >"$work/any.bt"; mkdir -p "$work/readonly"; chmod 555 "$work/readonly"
    # Root writes into a mode-555 folder anyway: /proc/self is read-only for everyone.
    ro="$work/readonly"; [ "$(id -u)" = 0 ] && ro=/proc/self
  else
    ro="<read-only folder>"
  fi
  r() { echo run --platform "$hokuyo" --quiet --data "$work/base"; }
  case_ out_is_a_file "run --out an existing file" 2 "--out .*a_file: exists and is not a folder" $(r) --out "$work/a_file"
  case_ out_dev_null "run --out /dev/null" 2 "--out /dev/null: exists and is not a folder" $(r) --out /dev/null
  case_ out_read_only "run --out a read-only folder" 2 "--out .*: cannot write into the folder: " $(r) --out "$ro"
  case_ out_under_file "run --out a path below a file" 2 "--out .*a_file/sub: cannot create the folder" $(r) --out "$work/a_file/sub"
  case_ localize_out_dev_null "localize --out /dev/null" 2 "--out /dev/null: exists and is not a folder" \
    localize --platform "$hokuyo" --quiet --data "$work/base" --map "$work/any.bt" --out /dev/null
  case_ simulate_out_file "simulate --out an existing file" 2 "--out .*a_file: exists and is not a folder" \
    simulate --scenario "$src/configs/scenarios/tunnel.yaml" --duration-s 1 --out "$work/a_file"
  case_ convert_out_dev_null "convert --out /dev/null" 2 "--out /dev/null: exists and is not a folder" \
    convert --format carmen --input "$src/README.md" --out /dev/null
  case_ max_duration_negative "run --max-duration-s -5" 105 "--max-duration-s: '-5' is not a finite number > 0" $(r) --out "$work/o1" --max-duration-s -5
  case_ max_duration_nan "run --max-duration-s nan" 105 "--max-duration-s: 'nan' is not a finite number > 0" $(r) --out "$work/o2" --max-duration-s nan
  case_ max_duration_inf "run --max-duration-s inf" 105 "--max-duration-s: 'inf' is not a finite number > 0" $(r) --out "$work/o3" --max-duration-s inf
  case_ max_duration_word "localize --max-duration-s soon" 105 "--max-duration-s: 'soon' is not a number" \
    localize --platform "$hokuyo" --data "$work/base" --map x.pcd --out "$work/o4" --max-duration-s soon
  case_ simulate_duration_nan "simulate --duration-s nan" 105 "--duration-s: 'nan' is not a finite number > 0" \
    simulate --scenario "$src/configs/scenarios/tunnel.yaml" --duration-s nan --out "$work/o5"
  case_ max_duration_ok "run --max-duration-s 2 on 3 s of data: maps the first 2 s" 0 "scans 80 \(matched [1-9][0-9]*\), data 2 s" $(r) --out "$work/o6" --max-duration-s 2
  ;;
signals)
  # Long enough that a run is still mapping well after its first progress
  # line (a second in): the 12 s this used to be were mapped in 0.9 s once
  # the mapper ran at 13x real time, and the signal came after the exit.
  base_dataset 60
  # signal_run ID SIGNAL WHEN CODE: `unimap run` stopped by SIGNAL when the
  # condition WHEN holds (start: the output folder exists; loop: the first
  # progress line, after a second of mapping; final: the trajectory of the
  # loop is complete, the map is being written).
  signal_run() {
    local id=$1 sig=$2 when=$3 want=$4 out="$work/out_$1"
    case_ "$id" "run, SIG$sig at the $when" "$want" "interrupted|none of the" bash -c "
      '$exe' run --platform '$hokuyo' --data '$work/base' --out '$out' --no-loop-closure 2>'$out.progress' & pid=\$!
      for i in \$(seq 1 20000); do
        case $when in
          start) [ -d '$out' ] && break ;;
          loop) grep -q 'scans |' '$out.progress' && break ;;
          final) [ -f '$out/trajectory_odometry.tum' ] && break ;;
        esac
        sleep 0.001
      done
      kill -STOP \$pid; [ -f '$out/run.json' ] && touch '$out.late'; kill -$sig \$pid; kill -CONT \$pid
      wait \$pid; code=\$?; cat '$out.progress'; echo; echo interrupted exit \$code; exit \$code"
    [ "$LIST" = 1 ] && return
    for f in run.json trajectory.tum trajectory_kitti.txt trajectory_odometry.tum map.pcd map.ply map.bt; do
      [ -f "$out/$f" ] || fail "$id: no $f"
    done
    [ -f "$out.late" ] || grep -q '"interrupted": true' "$out/run.json" || fail "$id: run.json lacks \"interrupted\": true"
    [ "$(grep -cv '^#' "$out/trajectory_odometry.tum")" = "$(json_number "$out/run.json" poses)" ] ||
      fail "$id: trajectory_odometry.tum does not hold every pose run.json counts"
  }
  signal_run sigint_start INT start 130
  signal_run sigterm_loop TERM loop 143
  signal_run sighup_loop HUP loop 129
  signal_run sigint_loop INT loop 130
  signal_run sigint_final INT final 130
  signal_run sigterm_final TERM final 143
  sim="$work/sim_int"
  case_ simulate_sigint "simulate, SIGINT while writing: a complete, shorter dataset" 130 "interrupted: the dataset holds the first" bash -c "
    '$exe' simulate --scenario '$src/configs/scenarios/tunnel.yaml' --out '$sim' --quiet & pid=\$!
    for i in \$(seq 1 20000); do [ -f '$sim/scans.bin.partial' ] && break; sleep 0.001; done
    sleep 0.3; kill -INT \$pid; wait \$pid"
  [ "$LIST" = 1 ] || { [ -f "$sim/metadata.yaml" ] || fail "simulate_sigint: no metadata.yaml"; \
    code=$(run run --platform "$hokuyo" --quiet --data "$sim" --out "$work/sim_int_run" --max-duration-s 1); \
    [ "$code" = 0 ] || [ "$code" = 3 ] || fail "simulate_sigint: the interrupted dataset does not read (exit $code)"; }
  dm="$work/demo_int"
  case_ demo_sigint "demo, SIGINT while simulating: the shorter dataset, no mapping of it" 130 "interrupted: the dataset holds the first" bash -c "
    '$exe' demo --duration-s 60 --out '$dm' & pid=\$!
    for i in \$(seq 1 20000); do [ -f '$dm/data/scans.bin.partial' ] && break; sleep 0.001; done
    kill -INT \$pid; wait \$pid"
  [ "$LIST" = 1 ] || [ -f "$dm/data/metadata.yaml" ] || fail "demo_sigint: no metadata.yaml"
  cv="$work/conv_term"
  case_ convert_sigterm "convert, SIGTERM while converting: a complete dataset of what was read" 143 "interrupted \(signal 15\)" bash -c "
    '$exe' convert --format carmen --input '$(big_clf)' --out '$cv' & pid=\$!
    for i in \$(seq 1 20000); do [ -f '$cv/scans.bin.partial' ] && break; sleep 0.001; done
    sleep 0.05; kill -TERM \$pid; wait \$pid"
  [ "$LIST" = 1 ] || [ -f "$cv/metadata.yaml" ] || fail "convert_sigterm: no metadata.yaml"
  ;;
disk)
  # A file-size limit (ulimit -f) makes writes fail like a full disk (EFBIG instead of ENOSPC).
  case_ simulate_disk_full "simulate into a 'disk' of 2 MB" 2 "write failed: File too large|cannot complete the file" bash -c "
    ulimit -f 2048; trap '' XFSZ; exec '$exe' simulate --scenario '$src/configs/scenarios/tunnel.yaml' --duration-s 20 --out '$work/sim_full' --quiet"
  [ "$LIST" = 1 ] || [ ! -f "$work/sim_full/metadata.yaml" ] || fail "simulate_disk_full: a metadata.yaml was written"
  case_ convert_disk_full "convert into a 'disk' of 1 MB" 2 "write failed: File too large|cannot complete the file" bash -c "
    ulimit -f 1024; trap '' XFSZ; exec '$exe' convert --format carmen --input '$(big_clf)' --out '$work/conv_full'"
  ;;
*) fail "unknown class $class" ;;
esac
[ "$LIST" = 1 ] || echo "$class: $cases cases passed"
