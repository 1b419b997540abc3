#!/usr/bin/env python3
"""Whether a static tilting 2D rig reports the same angle for the same pose
on its way up and on its way down (docs/calibration.md):

    python3 scripts/tilt_passes.py DATASET [WINDOW_DEG]

DATASET is a folder written by `unimap convert` from a recording of one
tilt up and (part of) the way back: scans.bin with LineScan records and
encoder.csv with one angle per line. The stand does not move, so a line of
the way up and a line of the way down that were taken at the same tilt see
the same ranges. For each line of the way up, the line of the way down
within WINDOW_DEG (default 3) whose ranges differ least (median absolute
difference of the beams both have) is its match; the output gives, per
5 deg of the way up, the median of (matched angle down - angle up): 0 when
the encoder repeats, a lag or lost steps otherwise. Where the ranges change
little with the tilt (near level in front of vertical walls) the match is
weak. Needs python3-numpy only."""
import os
import struct
import sys

import numpy as np


def load_lines(path):
    data = open(path, 'rb').read()
    if data[:8] != b'UNIMAPSC':
        sys.exit(f"{path}: not a scans.bin (magic)")
    offset, lines = 12, []
    while offset < len(data):
        if offset + 5 > len(data):
            sys.exit(f"{path}: byte {offset}: truncated record header")
        kind = data[offset]
        size = struct.unpack_from('<I', data, offset + 1)[0]
        start = offset + 5
        if start + size > len(data):
            sys.exit(f"{path}: byte {offset}: truncated record")
        if kind == 1:  # LineScan: 6 f64, u32 n, n f32 ranges (docs/dataset-format.md)
            n = struct.unpack_from('<I', data, start + 48)[0]
            ranges = np.frombuffer(data, dtype='<f4', count=n, offset=start + 52).astype(float)
            lines.append(ranges)
        offset = start + size
    return lines


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    folder = sys.argv[1]
    window = float(sys.argv[2]) if len(sys.argv) == 3 else 3.0
    lines = load_lines(os.path.join(folder, 'scans.bin'))
    angles = np.degrees(np.loadtxt(os.path.join(folder, 'encoder.csv'), ndmin=2)[:, 1])
    if len(angles) != len(lines):
        sys.exit(f"{folder}: {len(lines)} lines but {len(angles)} angles: one angle per line expected")
    if len({len(r) for r in lines}) != 1:
        sys.exit(f"{folder}: lines have different beam counts")
    ranges = np.array(lines)
    ranges[~np.isfinite(ranges) | (ranges < 0.03)] = np.nan
    top = int(np.argmax(angles))
    up, down = np.arange(top), np.arange(top + 1, len(lines))
    if len(down) == 0:
        sys.exit(f"{folder}: no way down after the largest angle ({angles[top]:.2f} deg)")
    print(f"# {len(lines)} lines, up {angles[0]:.2f} -> {angles[top]:.2f} deg, down to {angles[-1]:.2f} deg")
    print("# up angle (deg)  lines  median (down - up) (deg)  median range difference (mm)")
    found = []
    for i in up:
        candidates = down[np.abs(angles[down] - angles[i]) < window]
        if len(candidates) == 0 or angles[i] < angles[down].min() + 0.5:
            continue
        with np.errstate(all='ignore'):
            differences = [np.nanmedian(np.abs(ranges[j] - ranges[i])) for j in candidates]
        if np.all(np.isnan(differences)):
            continue
        best = int(np.nanargmin(differences))
        found.append((angles[i], angles[candidates[best]] - angles[i], differences[best]))
    found = np.array(found)
    for low in np.arange(0.0, 90.0, 5.0):
        rows = found[(found[:, 0] >= low) & (found[:, 0] < low + 5.0)] if len(found) else found
        if len(rows):
            print(f"  {low:4.0f}-{low + 5:<4.0f}  {len(rows):5d}  {np.median(rows[:, 1]):+8.3f}  "
                  f"{1000 * np.median(rows[:, 2]):8.1f}")


if __name__ == '__main__':
    main()
