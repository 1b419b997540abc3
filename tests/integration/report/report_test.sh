#!/usr/bin/env bash
# One report check per call: report_test.sh CASE UNIMAP_EXE SOURCE_DIR WORK_DIR.
set -uo pipefail
source "$(dirname "$0")/../script_helpers.sh" "$@"
browser_test="$(dirname "$0")/report_browser.py"

chromium=$(command -v chromium || command -v chromium-browser || true)
need_chromium() {
  if [ -z "$chromium" ]; then
    echo "SKIP [$case_name]: chromium is not installed (scripts/install-deps.sh installs Debian's chromium)"
    exit 77
  fi
}
# ply_vertices FILE: the vertex count in a PLY header.
ply_vertices() { head -c 400 "$1" | grep -a '^element vertex' | awk '{ print $3 }'; }
# browse REPORT ARGS...: report_browser.py, its output logged; fails the case when it fails.
browse() {
  python3 "$browser_test" "$chromium" "$@" >>"$log" 2>&1 || fail "headless Chromium check of $1"
  tail -4 "$log"
}
# The 20 s hallway flight (rotating Hokuyo), simulated once per case.
simulate_hallway() {
  code=$(run simulate --scenario "$src/configs/scenarios/narrow_hallway.yaml" --duration-s 20 --out "$work/data" --quiet)
  [ "$code" = 0 ] || fail "simulate exit $code"
}
# check_run_report OUT PLOTS...: the report of a run folder in the browser: the
# map holds every map.ply point (fewer than the 250,000 budget), each plot one
# row per pose of trajectory.tum (each associated with the truth when there is one).
check_run_report() {
  local out=$1; shift
  local vertices poses plot_args=()
  vertices=$(ply_vertices "$out/map.ply")
  poses=$(grep -vc '^#' "$out/trajectory.tum")
  [ "$vertices" -gt 1000 ] || fail "map.ply has only '$vertices' points"
  for p in "$@"; do plot_args+=(--plot "$p=$poses"); done
  browse "$out/report.html" --map-points "$vertices" "${plot_args[@]}" --trajectory "estimate=$poses" \
         --loops "$(grep -vc '^#' "$out/loop_closures.csv")"
}

case $case_name in
  browser_run)
    need_chromium
    simulate_hallway
    code=$(run run --platform "$hokuyo" --data "$work/data" --out "$work/out" --quiet)
    [ "$code" = 0 ] || fail "run exit $code"
    expect "^report: $work/out/report.html$"
    [ "$(json_number "$work/out/metrics.json" poses_associated)" = "$(grep -vc '^#' "$work/out/trajectory.tum")" ] ||
      fail "not every pose is associated with the truth"
    grep -q '"source": "plugin default"' "$work/out/run.json" || fail "run.json lacks the parameters' sources"
    check_run_report "$work/out" position position_error rotation_error ;;
  browser_no_truth)
    # The same flight without groundtruth.tum: a report all the same, the position plot only.
    need_chromium
    simulate_hallway
    rm "$work/data/groundtruth.tum"
    code=$(run run --platform "$hokuyo" --data "$work/data" --out "$work/out" --quiet)
    [ "$code" = 0 ] || fail "run exit $code"
    [ ! -e "$work/out/metrics.json" ] || fail "metrics.json without ground truth"
    check_run_report "$work/out" position
    grep -q 'No ground truth' "$work/out/report.html" || fail "the report does not say there is no ground truth" ;;
  browser_demo)
    # The README's first command, shortened to 20 s of the tunnel.
    need_chromium
    code=$(cd "$work" && run demo --configs "$src/configs" --duration-s 20 --out "$work/demo")
    [ "$code" = 0 ] || fail "demo exit $code"
    check_run_report "$work/demo" position position_error rotation_error ;;
  rebuild_and_other_tools)
    simulate_hallway
    code=$(run run --platform "$hokuyo" --data "$work/data" --out "$work/out" --quiet)
    [ "$code" = 0 ] || fail "run exit $code"
    # unimap report RUN_DIR writes the same page again (nothing depends on the time of day).
    cp "$work/out/report.html" "$work/first.html"
    code=$(run report "$work/out"); [ "$code" = 0 ] || fail "report exit $code"
    cmp -s "$work/first.html" "$work/out/report.html" || fail "report.html differs when rebuilt"
    expect "^map: [0-9]+ of [0-9]+ points shown, coloured by error against the true world$"
    # Another tool's output: a TUM trajectory and a PCD map, no run.json; a map budget.
    mkdir -p "$work/other"
    cp "$work/out/trajectory.tum" "$work/other/poses.tum"; cp "$work/out/map.pcd" "$work/other/cloud.pcd"
    code=$(run report "$work/other" --estimate "$work/other/poses.tum" --map "$work/other/cloud.pcd" --map-points 5000)
    [ "$code" = 0 ] || fail "report of another tool's output: exit $code"
    n=$(ply_vertices "$work/out/map.ply")  # every k-th point, k = ceil(n / 5000)
    expect "^map: $(awk -v n="$n" 'BEGIN { k = int((n + 4999) / 5000); print int((n + k - 1) / k) }') of $n points shown$"
    expect "^plots: 1 of 800 rows$"
    [ -s "$work/other/report.html" ] || fail "no report.html for another tool's output"
    # Errors name the file; nothing half-written is left.
    code=$(run report "$work/other" --map "$work/other/nope.ply"); [ "$code" = 2 ] || fail "exit $code for a missing map"
    expect "error: map $work/other/nope.ply: no such file"
    ls "$work/other" | grep -q partial && fail "a .partial file was left behind" ;;
  *) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
