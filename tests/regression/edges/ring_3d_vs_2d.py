#!/usr/bin/env python3
"""The half ring pressed onto a base in 3D against 2D (issue 22, point 3): inputs/verification/
ring_on_node_line_3d.xml is the plane-strain extrusion of ring_on_node_line.xml (z held on the front and
back faces of both bodies; the ring 2 layers, the base 1), so per mm of thickness its base reaction and
contact force must be those of the 2D deck, and its contact nodes three per 2D contact node (z = 0, 2, 4).

Usage: ring_3d_vs_2d.py OUT [--base-elements N] [--rtol R] [--friction MU] -- LAUNCH...
LAUNCH starts contessa (with mpiexec for several ranks). Both decks run with the base's Elements X = N.
N = 21 puts the ring's lowest line of nodes between two lines of base nodes; with the decks' own N = 20 it
lies on a line of base nodes, on the edge of two base faces and on their vertices, in the valley the base
forms under the ring: there the contact is blended over the two faces (contact/ValleyBlend.hpp;
docs/verification-contact.md §6). Before the blend the 3D deck stopped at load factor 0.0022 on the node
line. Exit 0 when both runs reached load factor 1, with the same number of increments, and every
increment's force agrees within R relative (default 1e-9; measured 3e-12 (N = 21) and 5e-13 (N = 20) on
one rank). --friction MU runs both decks with Coulomb friction (Friction Coefficient MU, the default Slip
Tolerance) and the backtracking line search of the 2D deck: the blend then carries the tangential part too
(docs/theory-contact.md §6.5), and the 3D deck's stick and slip counts must also be three times the 2D
deck's.
"""
import argparse
import csv
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
VERIFICATION = os.path.join(HERE, '..', '..', '..', 'inputs', 'verification')
THICKNESS = 4.0  # Length Z of both bodies in the 3D deck [mm]


def run(launch, deck, out, base_elements, friction):
    os.makedirs(out, exist_ok=True)
    command = launch + [os.path.join(VERIFICATION, deck + '.xml'), '--quiet', '--output-dir', out,
                        '--set', 'Problem/Mesh/base/Elements X=%d' % base_elements]
    if friction is not None:
        # Both with the 2D deck's backtracking line search: with full steps both decks 2-cycle once, alike,
        # where the ring's next nodes (x = +-1.3 mm, off the valley) first touch in stick.
        # A constant stick penalty (Slip Tolerance 0: epsilon_T = epsilon_N): the default ties it to L_k,
        # which is not the same in 2D (the segments' length) and 3D (the faces' size).
        command += ['--set', 'Problem/Contact/ring/Friction Coefficient=%g' % friction,
                    '--set', 'Problem/Contact/ring/Slip Tolerance=0',
                    '--set', 'Piro/NOX/Line Search/Method=Backtrack']
    p = subprocess.run(command, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit('FAIL: %s exited %d: %s' % (deck, p.returncode, p.stderr.strip()[-500:]))
    return list(csv.DictReader(open(os.path.join(out, deck + '.history.csv'))))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('out')
    ap.add_argument('--base-elements', type=int, default=21)
    ap.add_argument('--rtol', type=float, default=1e-9)
    ap.add_argument('--friction', type=float, default=None)
    argv = sys.argv[1:]
    split_at = argv.index('--')
    a = ap.parse_args(argv[:split_at])
    launch = argv[split_at + 1:]
    rows2 = run(launch, 'ring_on_node_line', os.path.join(a.out, '2d'), a.base_elements, a.friction)
    rows3 = run(launch, 'ring_on_node_line_3d', os.path.join(a.out, '3d'), a.base_elements, a.friction)
    for deck, rows in (('2D', rows2), ('3D', rows3)):
        if abs(float(rows[-1]['lambda']) - 1.0) > 1e-12:
            sys.exit('FAIL: the %s run ended at load factor %s' % (deck, rows[-1]['lambda']))
    if len(rows2) != len(rows3):
        sys.exit('FAIL: %d rows in 2D, %d in 3D' % (len(rows2), len(rows3)))
    failures, worst = 0, 0.0
    for r2, r3 in zip(rows2, rows3):
        forces = []
        for column in ('reaction_base_bottom_y', 'contact_force_ring_y'):
            f2, f3 = float(r2[column]), float(r3[column]) / THICKNESS
            difference = abs(f3 - f2) / max(abs(f2), 1e-30) if f2 != 0 or f3 != 0 else 0.0
            worst = max(worst, difference)
            forces.append('%s %.12g (2D) %.12g (3D / %g) rel. %.1e' % (column, f2, f3, THICKNESS, difference))
            if difference > a.rtol:
                failures += 1
        # Plane strain: no force across the thickness, none along x (symmetric ring).
        for column in ('reaction_base_bottom_x', 'reaction_base_bottom_z'):
            if abs(float(r3[column])) > a.rtol * max(abs(float(r3['reaction_base_bottom_y'])), 1.0):
                failures += 1
                forces.append('%s = %s' % (column, r3[column]))
        contacts2, contacts3 = int(float(r2['active_contacts'])), int(float(r3['active_contacts']))
        if contacts3 != 3 * contacts2:
            failures += 1
        for column in ('stick', 'slip'):
            if int(float(r3[column])) != 3 * int(float(r2[column])):
                failures += 1
                forces.append('%s %s (2D) %s (3D)' % (column, r2[column], r3[column]))
        print('step %s: contacts %d (2D) %d (3D); %s' % (r2['step'], contacts2, contacts3, '; '.join(forces)))
    print('worst relative difference %.2e (tolerance %.0e)' % (worst, a.rtol))
    if failures:
        sys.exit('FAIL: %d disagreements' % failures)


if __name__ == '__main__':
    main()
