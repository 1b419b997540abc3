#!/usr/bin/env python3
"""How much a run's pseudo measurements know beyond the prediction, per
axis, against the truth (docs/robustness.md):

    python3 scripts/measurement_errors.py RUN_DIR GROUNDTRUTH.tum FROM_S TO_S

RUN_DIR holds trace.csv (`unimap run --trace`) and trajectory_odometry.tum
(else trajectory.tum). For the matched scans between FROM_S and TO_S the
prediction is the filter's pose less its correction (corr_*) and the
measurement the prediction plus the innovation (innov_*); both are
start-anchored on the truth as scripts/errors_over_time.py does. Per world
axis it prints the standard deviations of the prediction's and the
measurement's errors, the slope of the measurement's error on the
prediction's (1: the measurement repeats the prediction's error, 0: it is
independent of it) and the median standard deviation the measurement
claimed (meas_sd_*). Needs python3-numpy only."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from errors_over_time import load, matrix, truth_at  # noqa: E402


def read_trace(path):
    names, rows = None, []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith('#'):
                names = [c.strip() for c in line[1:].split(',')]
                continue
            if names is None:
                sys.exit(f"{path}:{number}: no header before the first row")
            values = line.split(',')
            if len(values) != len(names):
                sys.exit(f"{path}:{number}: {len(values)} values, the header names {len(names)}")
            rows.append([float(v) for v in values])
    if names is None or not rows:
        sys.exit(f"{path}: no rows")
    needed = ['time_s', 'matched'] + [f'{k}_{a}' for k in ('corr', 'innov', 'meas_sd') for a in 'xyz']
    missing = [n for n in needed if n not in names]
    if missing:
        sys.exit(f"{path}: no column {missing[0]} in the header")
    a = np.array(rows)
    return {n: a[:, names.index(n)] for n in needed}


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    run = sys.argv[1]
    t_from, t_to = float(sys.argv[3]), float(sys.argv[4])
    trace = read_trace(os.path.join(run, 'trace.csv'))
    trajectory = os.path.join(run, 'trajectory_odometry.tum')
    if not os.path.exists(trajectory):
        trajectory = os.path.join(run, 'trajectory.tum')
    te, pe, qe = load(trajectory)
    tg, pg, qg = load(sys.argv[2])
    p0, R0 = truth_at(tg, pg, qg, te[0])
    A = R0 @ matrix(qe[0]).T
    pred_err, meas_err, claimed = [], [], []
    for k, t in enumerate(trace['time_s']):
        if trace['matched'][k] < 0.5 or t < t_from or t > t_to or t < tg[0] or t > tg[-1]:
            continue
        # The pose at this scan's time (poses ascend in time): the first at or after t, or the one before.
        after = int(np.searchsorted(te, t))
        i = min((j for j in (after - 1, after) if 0 <= j < len(te)), key=lambda j: abs(te[j] - t))
        if abs(te[i] - t) > 1e-4:
            continue  # no pose at this scan's time
        corr = np.array([trace[f'corr_{a}'][k] for a in 'xyz'])
        innov = np.array([trace[f'innov_{a}'][k] for a in 'xyz'])
        p_true, _ = truth_at(tg, pg, qg, t)
        predicted = A @ (pe[i] - corr - pe[0]) + p0
        measured = predicted + A @ innov
        pred_err.append(predicted - p_true)
        meas_err.append(measured - p_true)
        claimed.append([trace[f'meas_sd_{a}'][k] for a in 'xyz'])
    if len(pred_err) < 3:
        sys.exit("fewer than 3 matched scans with a pose in the window")
    pred_err, meas_err, claimed = np.array(pred_err), np.array(meas_err), np.array(claimed)
    print(f"# {len(pred_err)} matched scans, {t_from:g}-{t_to:g} s")
    print("# axis  prediction_error_sd_m  measurement_error_sd_m  slope  claimed_sd_m")
    for j, axis in enumerate('xyz'):
        dp = pred_err[:, j] - pred_err[:, j].mean()
        dm = meas_err[:, j] - meas_err[:, j].mean()
        slope = float(dp @ dm / (dp @ dp)) if dp @ dp > 0.0 else float('nan')
        print(f"{axis}  {dp.std():.4f}  {dm.std():.4f}  {slope:+.2f}  {np.median(claimed[:, j]):.3f}")


if __name__ == '__main__':
    main()
