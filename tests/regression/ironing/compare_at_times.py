#!/usr/bin/python3
"""Compares two shallow ironing runs' reactions on the die at given normalised times.

    compare_at_times.py A.history.csv B.history.csv [--times 1.0 1.5] [--rtol R]

The vertical and horizontal reactions of each run, interpolated linearly between its increments at each
time t (times a run did not reach are an error), must agree within |a - b| <= R max(|a|, |b|). For runs
of the same deck whose increments differ (the 1- and 2-rank runs of the slide: its step control reacts to
round-off where a Newton solve ends at the edge of its basin, so a step is cut back in one run and not in
the other), where compare_history.py's row-by-row comparison does not apply. Prints one line per time and
quantity; exit 1 when one differs. docs/verification-contact.md, "Shallow ironing".
"""
import argparse
import sys

import numpy as np

from ironing_reference import contessa_history


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('a')
    parser.add_argument('b')
    parser.add_argument('--times', type=float, nargs='+', default=[1.0, 1.5])
    parser.add_argument('--rtol', type=float, default=1e-6)
    args = parser.parse_args()
    runs = [contessa_history(path) for path in (args.a, args.b)]
    failures = 0
    for time in args.times:
        if any(time > t[-1] + 1e-12 for t, _, _ in runs):
            print('t = %g: a run ended before it (at t = %g and %g)' % (time, runs[0][0][-1], runs[1][0][-1]))
            failures += 1
            continue
        for name, column in (('vertical', 1), ('horizontal', 2)):
            a, b = (float(np.interp(time, run[0], run[column])) for run in runs)
            difference = abs(a - b) / max(abs(a), abs(b))
            same = difference <= args.rtol
            failures += not same
            print('t = %g: %-10s reaction %.6f and %.6f N, relative difference %.2e (tolerance %.1e): %s'
                  % (time, name, a, b, difference, args.rtol, 'same' if same else 'DIFFERENT'))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
