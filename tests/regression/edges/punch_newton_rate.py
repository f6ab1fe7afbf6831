#!/usr/bin/env python3
"""Newton's rate with the block's top nodes exactly on interior edges and vertices of a rigid punch
(issue 22, point 3, rigid 3D): inputs/punch_3d.xml with the punch [-10, 60]^2 split into 7 x 7 faces of
10 mm (punch_edge.py's rigid_punch), so that at n = 18 the block's node rows x, y = 0 and 50 mm lie on the
punch's interior edges and their crossings on its interior vertices, flush from the start. Runs
tests/regression/friction/run_budget.py on it with Newton Details and the given budget options (the test
bounds the Newton iterations and the failed attempts).

Usage: punch_newton_rate.py OUT [run_budget options] -- LAUNCH...
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from punch_edge import rigid_punch  # noqa: E402

ROOT = os.path.join(HERE, '..', '..', '..')


def main():
    argv = sys.argv[1:]
    split_at = argv.index('--')
    out, budget, launch = argv[0], argv[1:split_at], argv[split_at + 1:]
    os.makedirs(out, exist_ok=True)
    deck = ['--set', 'Problem/Mesh/Elements X=18', '--set', 'Problem/Mesh/Elements Y=18',
            '--set', 'Problem/Mesh/Elements Z=3', '--set', 'Piro/NOX/Printing/Newton Details=true']
    command = ([sys.executable, os.path.join(ROOT, 'tests', 'regression', 'friction', 'run_budget.py')] + budget +
               ['--history', os.path.join(out, 'punch_3d.history.csv'), '--'] + launch +
               [os.path.join(ROOT, 'inputs', 'punch_3d.xml'), '--quiet', '--output-dir', out] + deck +
               rigid_punch(60.0, 7))
    return subprocess.run(command).returncode


if __name__ == '__main__':
    sys.exit(main())
