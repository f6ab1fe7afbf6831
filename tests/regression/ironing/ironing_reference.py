"""The published reaction curves of the shallow ironing benchmark and this code's history, on one time axis.

The five codes' curves are in inputs/verification/shallow_ironing_reference (their headers name the sources):
normalised time t in column 1, the reactions on the die's top in units of 1e8 (x 100 = N per mm of
thickness). Contessa's history gives t as its `time` column when the run has load steps (continuous across
them) and as `lambda` otherwise (the press alone, t = load factor); the vertical reaction on the die is
-reaction_die_top_y (the support pushes the die down), the horizontal one reaction_die_top_x.
"""
import csv
import os

import numpy as np

REFERENCE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'inputs',
                             'verification', 'shallow_ironing_reference')
# (label, file stem): the vertical and horizontal curves are <stem>Vertical.dat and <stem>Horizontal.dat,
# except Yastrebov's one file with both.
CODES = [('Code_Aster (SSNP153)', 'aster'), ('Hartmann et al. 2009', 'hartmannOliver'),
         ('Fischer and Wriggers 2006', 'fischerWriggers'), ('Yastrebov 2011', 'yastrebov'),
         ('Poulios and Renard 2015', 'pouliosRenard')]
NEWTON_PER_MM = 100.0  # the curves' unit (1e8) in N per mm of thickness


def reference_curves(directory=REFERENCE_DIR):
    """{label: (t_v, vertical N, t_h, horizontal N)} for the five published codes."""
    curves = {}
    for label, stem in CODES:
        if stem == 'yastrebov':
            data = np.loadtxt(os.path.join(directory, 'yastrebov.dat'))
            t = data[:, 0]
            curves[label] = (t, -NEWTON_PER_MM * data[:, 2], t, NEWTON_PER_MM * data[:, 1])
            continue
        vertical = np.loadtxt(os.path.join(directory, stem + 'Vertical.dat'))
        horizontal = np.loadtxt(os.path.join(directory, stem + 'Horizontal.dat'))
        curves[label] = (vertical[:, 0], NEWTON_PER_MM * vertical[:, 1],
                         horizontal[:, 0], NEWTON_PER_MM * horizontal[:, 1])
    return curves


def interpolate(t, times, values):
    """Linear interpolation of a curve at t, its points sorted by time first (digitised curves are not
    always in order)."""
    order = np.argsort(times, kind='stable')
    return float(np.interp(t, np.asarray(times)[order], np.asarray(values)[order]))


def published_spread(t, curves):
    """(vertical min, max, horizontal min, max) over the five codes at normalised time t."""
    vertical = [interpolate(t, tv, v) for tv, v, _, _ in curves.values()]
    horizontal = [interpolate(t, th, h) for _, _, th, h in curves.values()]
    return min(vertical), max(vertical), min(horizontal), max(horizontal)


def contessa_history(path):
    """(t, vertical N, horizontal N) of a Contessa run's history CSV."""
    with open(path, newline='') as stream:
        rows = list(csv.DictReader(stream))
    if not rows:
        raise SystemExit('%s: empty history' % path)
    time_column = 'time' if 'time' in rows[0] else 'lambda'
    t = np.array([float(row[time_column]) for row in rows])
    vertical = np.array([-float(row['reaction_die_top_y']) for row in rows])
    horizontal = np.array([float(row['reaction_die_top_x']) for row in rows])
    return t, vertical, horizontal
