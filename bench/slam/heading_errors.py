#!/usr/bin/env python3
"""Heading errors of a SLAM pass, per minute, against a recording's ground truth.

    bench/slam/heading_errors.py RECORDING/groundtruth.txt MAP/slam_scans.csv [WALL_SIGMA_RAD]

Prints, per minute of the pass: how far dead reckoning's heading drifted (the odometry
increments `dynamap map` fused, against the true ones), the heading error of the fused
estimate, that of the registrations themselves (recovered from each fusion step by
undoing its Kalman gain, which is recomputed with SlamConfig's default sigmas) and, when
the pass fused the walls' heading (wall_heading in SlamConfig; WALL_SIGMA_RAD its
sigma_rad, 0.005 unless given), that of the walls' measurements. Then the
RMS heading error of the same measurements re-filtered offline with a gyro-bias state
(no feedback through the map: each registration stays what it was in the pass).
Python 3 standard library only.
"""
import bisect
import csv
import math
import sys

# SlamConfig defaults (mapping/include/dynamap/mapping/SlamLoop.hpp).
ODOMETRY_SIGMA_PER_SQRT_RAD = 0.01
HEADING_SIGMA_PER_SQRT_S = 0.001
REGISTRATION_SIGMA_RAD = 0.002
WALL_SIGMA_RAD = 0.005
# The offline re-filter: registration heading noise, bias random walk, gyro angle noise.
REFILTER_SIGMA_RAD = 0.1
REFILTER_BIAS_WALK = 1e-6
REFILTER_GYRO_PER_SQRT_S = 0.0004


def wrap(a):
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def true_heading(groundtruth):
    stamps, yaws, previous, offset = [], [], None, 0.0
    for line in open(groundtruth):
        if line.startswith('#'):
            continue
        f = line.split()
        yaw = 2.0 * math.atan2(float(f[6]), float(f[7]))
        if previous is not None:
            offset -= 2.0 * math.pi * round((yaw + offset - previous) / (2.0 * math.pi))
        previous = yaw + offset
        stamps.append(float(f[0]))
        yaws.append(previous)

    def at(t):
        i = bisect.bisect_left(stamps, t)
        if i <= 0:
            return yaws[0]
        if i >= len(stamps):
            return yaws[-1]
        w = (t - stamps[i - 1]) / (stamps[i] - stamps[i - 1])
        return (1.0 - w) * yaws[i - 1] + w * yaws[i]
    return at


def main(groundtruth, scans_csv, wall_sigma=WALL_SIGMA_RAD):
    truth = true_heading(groundtruth)
    scans = []  # (t, odometry increment, registration heading or None, fused, true, walls)
    variance, last_t, last_theta = 0.0, None, None
    for row in csv.DictReader(open(scans_csv)):
        t, predicted, fused = (float(row[k]) for k in ('stamp_s', 'predicted_theta', 'theta'))
        increment = wrap(predicted - last_theta) if last_theta is not None else 0.0
        elapsed = t - last_t if last_t is not None else 0.0
        variance += (ODOMETRY_SIGMA_PER_SQRT_RAD ** 2 * abs(increment) +
                     HEADING_SIGMA_PER_SQRT_S ** 2 * elapsed)
        walls = float(row['wall_theta']) if row.get('wall_theta') else None
        if walls is not None:
            # The walls were fused after the registration: undo their step first.
            registered_variance = variance * (1.0 if row['accepted'] != '1' else
                                              REGISTRATION_SIGMA_RAD ** 2 /
                                              (variance + REGISTRATION_SIGMA_RAD ** 2))
            wall_gain = registered_variance / (registered_variance + wall_sigma ** 2)
            after_registration = walls + wrap(fused - walls) / (1.0 - wall_gain)
        else:
            after_registration = fused
        registered = None
        if row['accepted'] == '1':
            gain = variance / (variance + REGISTRATION_SIGMA_RAD ** 2)
            if gain > 1e-3:
                registered = predicted + wrap(after_registration - predicted) / gain
            variance *= 1.0 - gain
        if walls is not None:
            variance *= wall_sigma ** 2 / (variance + wall_sigma ** 2)
        scans.append((t, increment, registered, fused, truth(t), walls))
        last_t, last_theta = t, fused

    degrees = math.degrees
    drift = 0.0
    minutes = {}
    for k, (t, increment, registered, fused, true, walls) in enumerate(scans):
        if k > 0:
            drift += increment - (true - scans[k - 1][4])
        m = minutes.setdefault(int(t // 60), {'drift': [], 'fused': [], 'registered': [], 'walls': []})
        m['drift'].append(drift)
        m['fused'].append(wrap(fused - true))
        if registered is not None:
            m['registered'].append(wrap(registered - true))
        if walls is not None:
            m['walls'].append(wrap(walls - true))
    mean = lambda v: sum(v) / len(v)
    rms = lambda v: math.sqrt(sum(x * x for x in v) / len(v))
    print('minute  dead reckoning drift deg (total)  fused mean / rms deg  registrations mean / rms deg'
          '  walls mean / rms deg (scans)')
    for minute, m in sorted(minutes.items()):
        reg = m['registered'] or [float('nan')]
        walls = m['walls'] or [float('nan')]
        print(f'{minute:6d}  {degrees(m["drift"][-1] - m["drift"][0]):8.3f} ({degrees(m["drift"][-1]):7.2f})'
              f'  {degrees(mean(m["fused"])):8.3f} / {degrees(rms(m["fused"])):6.3f}'
              f'  {degrees(mean(reg)):8.3f} / {degrees(rms(reg)):6.3f}'
              f'  {degrees(mean(walls)):8.3f} / {degrees(rms(walls)):6.3f} ({len(m["walls"])})')

    # Re-filter: state (heading, residual gyro bias).
    theta, bias = 0.0, 0.0
    p00, p01, p11 = 1e-8, 0.0, 1e-8
    errors, last_t = [], None
    for t, increment, registered, fused, true, _ in scans:
        dt = t - last_t if last_t is not None else 0.0
        last_t = t
        theta += increment - bias * dt
        p00, p01 = p00 - 2.0 * dt * p01 + dt * dt * p11, p01 - dt * p11
        p00 += ODOMETRY_SIGMA_PER_SQRT_RAD ** 2 * abs(increment) + REFILTER_GYRO_PER_SQRT_S ** 2 * dt
        p11 += REFILTER_BIAS_WALK ** 2 * dt
        if registered is not None:
            innovation = wrap(registered - theta)
            s = p00 + REFILTER_SIGMA_RAD ** 2
            k0, k1 = p00 / s, p01 / s
            theta += k0 * innovation
            bias += k1 * innovation
            p00, p01, p11 = (1.0 - k0) * p00, (1.0 - k0) * p01, p11 - k1 * p01
        errors.append(wrap(theta - true))
    fused_errors = [wrap(s[3] - s[4]) for s in scans]
    print(f'heading RMS over the pass: fused {degrees(rms(fused_errors)):.3f} deg, '
          f're-filtered with a gyro-bias state {degrees(rms(errors)):.3f} deg')


if __name__ == '__main__':
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], *(float(a) for a in sys.argv[3:]))
