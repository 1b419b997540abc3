#!/usr/bin/env python3
"""Per-window medians of columns of a run's trace.csv (`unimap run --trace`),
for seeing whether the scans' pseudo measurements pull one way over time
(docs/robustness.md):

    python3 scripts/trace_windows.py TRACE.csv STEP_S FROM_S TO_S [COLUMN ...]

Each line covers STEP_S seconds between FROM_S and TO_S and gives, over the
matched scans in it, the count and the median of each COLUMN (default:
innov_x innov_y innov_z innov_rz, the measured pose error against the
prediction; see the trace's header for the others). Standard library
only."""
import statistics
import sys


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    path = sys.argv[1]
    step, start, end = (float(v) for v in sys.argv[2:5])
    if not step > 0.0 or not end > start:
        sys.exit("STEP_S must be positive and TO_S after FROM_S")
    columns = sys.argv[5:] or ["innov_x", "innov_y", "innov_z", "innov_rz"]
    names = None
    windows = {}
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("#"):
                names = [c.strip() for c in line[1:].split(",")]
                missing = [c for c in columns + ["time_s", "matched"] if c not in names]
                if missing:
                    sys.exit(f"{path}:{number}: no column {', '.join(missing)} in the header")
                continue
            if names is None:
                sys.exit(f"{path}:{number}: data before the header line")
            values = line.strip().split(",")
            if len(values) != len(names):
                sys.exit(f"{path}:{number}: {len(values)} fields, the header has {len(names)}")
            row = dict(zip(names, values))
            t = float(row["time_s"])
            if t < start or t >= end or float(row["matched"]) != 1.0:
                continue
            k = int((t - start) // step)
            windows.setdefault(k, []).append([float(row[c]) for c in columns])
    print("# from_s  to_s  scans  " + "  ".join(f"median {c}" for c in columns))
    for k in sorted(windows):
        rows = windows[k]
        medians = [statistics.median(r[i] for r in rows) for i in range(len(columns))]
        w0 = start + k * step
        print(f"{w0:8.2f} {w0 + step:8.2f} {len(rows):6d}  " + "  ".join(f"{m:+.4f}" for m in medians))


if __name__ == "__main__":
    main()
