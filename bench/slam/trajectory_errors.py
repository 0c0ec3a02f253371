#!/usr/bin/env python3
"""Position and heading errors of trajectories against the truth, per minute.

    bench/slam/trajectory_errors.py TRUTH ESTIMATE [ESTIMATE ...] [--every S]

TRUTH and each ESTIMATE are TUM trajectories (a recording's groundtruth.txt, a
mission's groundtruth.tum, trajectory.tum, trajectory_online.tum, a map's
trajectory_before_loop_closure.tum); no alignment, as report.json's ATE of a mission.
Prints per estimate the heading RMS over the whole run and, per minute from its first
stamp, the position RMS and the mean heading error; with --every S also the x, y and
heading error every S seconds, the estimates side by side. Python 3 standard library only.
"""
import bisect
import math
import sys


def load(path):
    stamps, poses = [], []
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        f = line.split()
        stamps.append(float(f[0]))
        poses.append((float(f[1]), float(f[2]), 2.0 * math.atan2(float(f[6]), float(f[7]))))
    return stamps, poses


def wrap(a):
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def errors(truth, estimate):
    """(stamp, dx, dy, heading error rad) per estimated pose, truth at the nearest stamp after."""
    truth_stamps, truth_poses = truth
    out = []
    for t, p in zip(*estimate):
        g = truth_poses[min(bisect.bisect_left(truth_stamps, t), len(truth_stamps) - 1)]
        out.append((t, p[0] - g[0], p[1] - g[1], wrap(p[2] - g[2])))
    return out


def main(args):
    every = None
    if '--every' in args:
        i = args.index('--every')
        every = float(args[i + 1])
        del args[i:i + 2]
    if len(args) < 2:
        sys.exit(__doc__)
    truth = load(args[0])
    runs = [(path, errors(truth, load(path))) for path in args[1:]]
    for path, run in runs:
        start = run[0][0]
        minutes = {}
        for t, dx, dy, dh in run:
            minutes.setdefault(int((t - start) // 60), []).append((math.hypot(dx, dy), dh))
        heading_rms = math.sqrt(sum(e[3] ** 2 for e in run) / len(run))
        print(f'{path}: heading RMS {math.degrees(heading_rms):.3f} deg; per minute position '
              f'RMS m / mean heading error deg:')
        print('  ' + '  '.join(
            f'{m}: {math.sqrt(sum(p * p for p, _ in v) / len(v)):.3f} / '
            f'{math.degrees(sum(h for _, h in v) / len(v)):+.2f}' for m, v in sorted(minutes.items())))
    if every:
        start = runs[0][1][0][0]
        stamps = [[e[0] for e in run] for _, run in runs]
        print('s  ' + ' | '.join('dx dy m, heading deg' for _ in runs))
        k = 0.0
        while True:
            row = []
            for (_, run), run_stamps in zip(runs, stamps):
                i = bisect.bisect_left(run_stamps, start + k)
                if i < len(run):
                    _, dx, dy, dh = run[i]
                    row.append(f'{dx:6.3f} {dy:6.3f} {math.degrees(dh):6.2f}')
            if not row:
                break
            print(f'{k:5.0f}  ' + ' | '.join(row))
            k += every


if __name__ == '__main__':
    main(sys.argv[1:])
