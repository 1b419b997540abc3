#!/usr/bin/env bash
# Memory over a long run (issue 24, docs/reliability.md): the tunnel flown at
# a quarter of its speed (`unimap simulate --speed-scale 0.25`: the same
# path in 61 minutes) mapped by `unimap run` with the rotating Hokuyo, its
# resident and peak memory sampled every 2 s of wall time against the data
# time it has reached (from its progress line: the share of the data done,
# so to 1 % = 36 s of data).
#   bash scripts/memory_curve.sh [WORK_DIR]   (default build/memory-curve)
# Writes WORK_DIR/memory.txt and prints the peak reached by data minute 30
# (the last sample at or before it) and by the end of mapping (run.json's
# peak_rss_mb, read before the outputs are written), and the growth.
set -euo pipefail
cd "$(dirname "$0")/.."
U="${UNIMAP:-build/bin/unimap}"
W="${1:-build/memory-curve}"
mkdir -p "$W"
if [ ! -f "$W/data/metadata.yaml" ]; then
  "$U" simulate --quiet --scenario configs/scenarios/tunnel.yaml --speed-scale 0.25 --out "$W/data"
fi
rm -rf "$W/out"
duration=$(awk '/^duration_s:/ {print $2}' "$W/data/metadata.yaml")
"$U" run --platform configs/platforms/rotating_hokuyo.yaml --data "$W/data" --out "$W/out" > "$W/run.log" 2> "$W/progress.log" &
pid=$!
echo "# wall_s data_time_s rss_mib peak_rss_mib" > "$W/memory.txt"
start=$(date +%s)
while kill -0 "$pid" 2>/dev/null; do
  status=$(cat "/proc/$pid/status" 2>/dev/null || true)
  rss=$(awk '/^VmRSS/ {print int($2 / 1024)}' <<< "$status")
  hwm=$(awk '/^VmHWM/ {print int($2 / 1024)}' <<< "$status")
  pct=$(tr '\r' '\n' < "$W/progress.log" | grep -ao '| [0-9]*% |' | tail -n 1 | tr -dc '0-9' || true)
  t=$(awk -v p="${pct:-0}" -v d="${duration:-0}" 'BEGIN { printf "%.0f", p * d / 100 }')
  [ -n "$rss" ] && echo "$(( $(date +%s) - start )) ${t:-0} $rss $hwm" >> "$W/memory.txt"
  sleep 2
done
wait "$pid" || { echo "unimap run failed (see $W/run.log)" >&2; exit 1; }
end=$(grep -o '"peak_rss_mb": [0-9.]*' "$W/out/run.json" | awk '{print $2}')
awk -v end="$end" '!/^#/ && $2 != "" && $2 <= 1800 { m30 = $4; t30 = $2 }
     END {
       if (!m30) { print "no sample before data minute 30" > "/dev/stderr"; exit 1 }
       printf "peak RSS by data minute 30 (sample at %d s): %d MiB; by the end of mapping (run.json): %.1f MiB; growth %.1f %%\n",
              t30, m30, end, 100.0 * (end - m30) / m30
     }' "$W/memory.txt"
