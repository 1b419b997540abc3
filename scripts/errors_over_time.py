#!/usr/bin/env python3
"""Start-anchored errors of an estimated trajectory over time, for finding
when and where a run went wrong (docs/robustness.md):

    python3 scripts/errors_over_time.py ESTIMATE.tum GROUNDTRUTH.tum [STEP_S] [FROM_S] [TO_S]

The first estimated pose is placed on the truth at its time (position and
orientation); each line gives, every STEP_S seconds (default 10) between
FROM_S and TO_S, the position error (estimate - truth, world axes, m), the
rotation error (roll, pitch, yaw of R_est^-1 R_true, deg) and the true
position. Needs python3-numpy only."""
import sys

import numpy as np


def load(path):
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.lstrip().startswith('#'):
                continue
            values = line.split()
            if len(values) != 8:
                sys.exit(f"{path}:{number}: expected 8 numbers (t x y z qx qy qz qw)")
            rows.append([float(v) for v in values])
    if len(rows) < 2:
        sys.exit(f"{path}: fewer than 2 poses")
    a = np.array(rows)
    q = a[:, 4:8] / np.linalg.norm(a[:, 4:8], axis=1, keepdims=True)
    return a[:, 0], a[:, 1:4], q


def matrix(q):
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def slerp(q0, q1, s):
    d = float(np.dot(q0, q1))
    if d < 0.0:
        q1, d = -q1, -d
    if d > 0.9995:
        q = q0 + s * (q1 - q0)
        return q / np.linalg.norm(q)
    theta = np.arccos(d)
    return (np.sin((1 - s) * theta) * q0 + np.sin(s * theta) * q1) / np.sin(theta)


def truth_at(tg, pg, qg, t):
    i = int(np.searchsorted(tg, t))
    i = min(max(i, 1), len(tg) - 1)
    s = (t - tg[i - 1]) / (tg[i] - tg[i - 1]) if tg[i] > tg[i - 1] else 0.0
    return pg[i - 1] + s * (pg[i] - pg[i - 1]), matrix(slerp(qg[i - 1], qg[i], s))


def rpy_deg(R):
    roll = np.arctan2(R[2, 1], R[2, 2])
    pitch = np.arcsin(np.clip(-R[2, 0], -1.0, 1.0))
    yaw = np.arctan2(R[1, 0], R[0, 0])
    return np.degrees([roll, pitch, yaw])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    te, pe, qe = load(sys.argv[1])
    tg, pg, qg = load(sys.argv[2])
    step = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0
    t_from = float(sys.argv[4]) if len(sys.argv) > 4 else -np.inf
    t_to = float(sys.argv[5]) if len(sys.argv) > 5 else np.inf
    inside = (te >= tg[0]) & (te <= tg[-1])
    te, pe, qe = te[inside], pe[inside], qe[inside]
    if len(te) == 0:
        sys.exit("no estimated pose lies within the truth's time span")
    p0, R0 = truth_at(tg, pg, qg, te[0])
    A = R0 @ matrix(qe[0]).T  # anchor: the first estimated orientation onto the truth's
    print("# time_s  position error x y z (m)  rotation error roll pitch yaw (deg)  true position x y z (m)")
    last = -np.inf
    for i, t in enumerate(te):
        if t < t_from or t > t_to or (t - last < step and i != len(te) - 1):
            continue
        last = t
        p_true, R_true = truth_at(tg, pg, qg, t)
        p_est = A @ (pe[i] - pe[0]) + p0
        R_est = A @ matrix(qe[i])
        e = p_est - p_true
        r = rpy_deg(R_est.T @ R_true)
        print(f"{t:9.2f}  {e[0]:+7.3f} {e[1]:+7.3f} {e[2]:+7.3f}  {r[0]:+6.2f} {r[1]:+6.2f} {r[2]:+6.2f}"
              f"  {p_true[0]:7.2f} {p_true[1]:7.2f} {p_true[2]:6.2f}")


if __name__ == '__main__':
    main()
