#!/usr/bin/env python3
"""Contact at a master's free edge (issue 22): a block pressed by a punch whose edge lies between two rows
of the block's nodes. The contact set must be exactly the block's top nodes under the punch, whatever the
punch's facets: one face, or split into faces (the block's top then starts flush with interior edges and
vertices), rigid (inputs/punch_3d.xml) or deformable (punch_deformable.xml, a stiff block of its own).

With the edge exactly on a node row (--elements 10 or 20 and --edge 60: a row at x = 60 and one at y = 60) the
nodes of that row are carried past the edge as the block's top spreads under the punch, within the reach
over which the force of a node past a free edge fades (docs/theory-contact.md §3, rule 3): they are under
the punch and must be in contact; the row is reported.

Usage: punch_edge.py OUT --edge E [--split S] [--deformable] [--elements N] [--layers NZ] -- LAUNCH...
LAUNCH is the command that starts contessa (with mpiexec for several ranks). Exit 0 when the run finished
and the set is right; prints the set, the force and the Newton iterations either way.
"""
import argparse
import csv
import os
import subprocess
import sys

import netCDF4
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
INPUTS = os.path.join(HERE, '..', '..', '..', 'inputs')


def rigid_punch(edge, split):
    """The punch face [-10, edge]^2 at z = 50 as split x split faces, counter-clockwise seen from below."""
    xs = np.linspace(-10.0, edge, split + 1)
    points, facets, index = [], [], {}
    for i, x in enumerate(xs):
        for j, y in enumerate(xs):
            index[i, j] = len(points) // 3
            points += [float(x), float(y), 50.0]
    for i in range(split):
        for j in range(split):
            facets += [index[i, j], index[i, j + 1], index[i + 1, j + 1], index[i + 1, j]]
    return ['--set', 'Problem/Contact/punch/Rigid Surface/Points={%s}' % ', '.join(repr(v) for v in points),
            '--set', 'Problem/Contact/punch/Rigid Surface/Facets={%s}' % ', '.join(str(v) for v in facets)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('out')
    ap.add_argument('--edge', type=float, required=True)
    ap.add_argument('--split', type=int, default=1)
    ap.add_argument('--deformable', action='store_true')
    ap.add_argument('--elements', type=int, default=18)
    ap.add_argument('--layers', type=int, default=3)
    argv = sys.argv[1:]
    split_at = argv.index('--')
    a = ap.parse_args(argv[:split_at])
    launch = argv[split_at + 1:]
    n, nz = a.elements, a.layers
    if a.deformable:
        deck = os.path.join(HERE, 'punch_deformable.xml')
        name, base = 'punch_deformable', 'base/'
        args = ['--set', 'Problem/Mesh/punch/Length X=%r' % a.edge, '--set', 'Problem/Mesh/punch/Length Y=%r' % a.edge]
    else:
        deck = os.path.join(INPUTS, 'punch_3d.xml')
        name, base = 'punch_3d', ''
        args = rigid_punch(a.edge, a.split)
    for key, value in (('Elements X', n), ('Elements Y', n), ('Elements Z', nz)):
        args += ['--set', 'Problem/Mesh/%s%s=%d' % (base, key, value)]
    os.makedirs(a.out, exist_ok=True)
    run = subprocess.run(launch + [deck, '--output-dir', a.out, '--quiet'] + args, capture_output=True, text=True)
    print(run.stderr.strip())
    if run.returncode != 0:
        print('FAIL: the run exited with status %d' % run.returncode)
        return 1

    exo = netCDF4.Dataset(os.path.join(a.out, name + '.exo'))
    names = [''.join(c.decode() for c in row if c) for row in exo['name_nod_var'][:]]
    status = np.asarray(exo['vals_nod_var%d' % (names.index('contact_status') + 1)][-1])
    x, y, z = (np.asarray(exo[c][:]) for c in ('coordx', 'coordy', 'coordz'))
    # The block's nodes (the Box's, first in the file): its top face is z = 50.
    count = (n + 1) * (n + 1) * (nz + 1)
    x, y, z, status = x[:count], y[:count], z[:count], status[:count]
    top = np.abs(z - 50.0) < 1e-9
    under = top & (x <= a.edge) & (y <= a.edge)
    closed = status > 0
    rows = list(csv.DictReader(open(os.path.join(a.out, name + '.history.csv'))))
    force = [float(r['contact_force_punch_z']) for r in rows]
    iterations = [int(r['newton_iterations']) for r in rows]
    print('edge %g, %d face(s)%s: %d contact nodes, %d under the punch; force %s; Newton %s' %
          (a.edge, a.split * a.split, ' (deformable punch)' if a.deformable else '', closed.sum(), under.sum(),
           ', '.join('%.9g' % f for f in force), iterations))
    on_row = top & (x <= a.edge + 1e-9) & (y <= a.edge + 1e-9) & (
        (np.abs(x - a.edge) < 1e-9) | (np.abs(y - a.edge) < 1e-9))
    if on_row.any():
        print('%d nodes on the edge row, %d of them in contact' % (on_row.sum(), (closed & on_row).sum()))
    wrong = np.flatnonzero(closed != under)
    if len(wrong):
        for k in wrong[:5]:
            print('  node at (%.4g, %.4g, %.4g): %s' % (x[k], y[k], z[k], 'in contact, not under the punch'
                                                          if closed[k] else 'under the punch, not in contact'))
        print('FAIL: the contact set is not the nodes under the punch')
        return 1
    print('PASS')
    return 0


if __name__ == '__main__':
    sys.exit(main())
