#!/usr/bin/env bash
# Memory over a long run (issue 24, docs/reliability.md): the tunnel flown at
# a quarter of its speed (`unimap simulate --speed-scale 0.25`: the same
# path in 61 minutes) mapped by `unimap run` with the rotating Hokuyo, its
# resident and peak memory sampled every 10 s of wall time against the data
# time it has reached (from its progress line: the share of the data done).
#   bash scripts/memory_curve.sh [WORK_DIR]   (default build/memory-curve)
# Writes WORK_DIR/memory.txt and prints the peak at data minutes 30 and 60.
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
  sleep 10
done
wait "$pid" || { echo "unimap run failed (see $W/run.log)" >&2; exit 1; }
awk '!/^#/ && $2 != "" {
       if (!m30 && $2 >= 1800) m30 = $4;
       last = $4; lt = $2
     }
     END {
       if (!m30) { print "the run ended before data minute 30" > "/dev/stderr"; exit 1 }
       printf "peak RSS at data minute 30: %d MiB; at the end (data %.0f s): %d MiB; growth %.1f %%\n",
              m30, lt, last, 100.0 * (last - m30) / m30
     }' "$W/memory.txt"
