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
  plugins_lists_three)
    code=$(run plugins); [ "$code" = 0 ] || fail "exit $code"
    for p in fixed_3d rotating_3d rotating_2d; do expect "^$p  \(ABI [0-9]+\)  .*libunimap_payload_$p\.so"; done
    expect "scans_per_3d_scan +N +"; expect "3 payload plugin\(s\) found" ;;
  plugins_env_path)
    mkdir -p "$work/empty_plugins"
    UNIMAP_PLUGIN_PATH="$work/empty_plugins" run plugins --brief >/dev/null
    expect "^  $work/empty_plugins$"; reject "defaults:" ;;
  help_lists_subcommands)
    code=$(run --help); [ "$code" = 0 ] || fail "exit $code"
    listed=$(sed -n '/^Subcommands:/,$p' "$work/$case_name.out" | grep -E '^  [a-z]' | awk '{print $1}' | sort | tr '\n' ' ')
    expected="bench config convert evaluate localize plugins run simulate "
    [ "$listed" = "$expected" ] || fail "listed subcommands '$listed', expected '$expected'"
    for sub in $listed; do
      "$exe" "$sub" --help >"$work/$case_name.$sub.out" 2>&1 || fail "'$sub --help' failed"
      grep -q "Usage" "$work/$case_name.$sub.out" || fail "'$sub --help' printed no usage"
    done ;;
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
  config_missing_plugin)
    f=$(printf 'plugin: no_such_payload\n' | platform)
    code=$(run config --platform "$f"); [ "$code" = 2 ] || fail "exit $code, expected 2"
    expect "$f:1: key 'plugin': .*not found" ;;
  *) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
