#!/usr/bin/python3
"""Checks a shallow ironing run against the spread of the five published codes.

    check_ironing.py HISTORY.csv [--times 1.0 1.5] [--print-only]

At each normalised time t (default 1.0, the end of the press, and 1.5, the middle of the slide; times the
run did not reach are an error) the run's vertical and horizontal reactions on the die, interpolated
linearly between its increments, must lie between the smallest and the largest of the five published
curves at t (Code_Aster SSNP153, Hartmann et al., Fischer and Wriggers, Yastrebov, Poulios and Renard;
ironing_reference.py). Prints one line per time and quantity; exit 1 when one lies outside.
docs/verification-contact.md, "Shallow ironing", gives the figures.
"""
import argparse
import sys

import numpy as np

from ironing_reference import contessa_history, published_spread, reference_curves


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('history')
    parser.add_argument('--times', type=float, nargs='+', default=[1.0, 1.5])
    parser.add_argument('--print-only', action='store_true', help='print the comparison, never fail')
    args = parser.parse_args()

    t, vertical, horizontal = contessa_history(args.history)
    curves = reference_curves()
    failures = 0
    for time in args.times:
        if time > t[-1] + 1e-12:
            print('t = %g: the run ended at t = %g' % (time, t[-1]))
            failures += 1
            continue
        v_min, v_max, h_min, h_max = published_spread(time, curves)
        for name, ours, low, high in (('vertical', np.interp(time, t, vertical), v_min, v_max),
                                      ('horizontal', np.interp(time, t, horizontal), h_min, h_max)):
            inside = low <= ours <= high
            failures += not inside
            print('t = %g: %-10s reaction %8.2f N, published %7.2f to %7.2f N: %s'
                  % (time, name, ours, low, high, 'inside' if inside else 'OUTSIDE'))
    if failures and not args.print_only:
        print('%d value(s) outside the published spread' % failures)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
