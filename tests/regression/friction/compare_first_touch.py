#!/usr/bin/python3
"""compare_first_touch.py REFERENCE.exo OTHER.exo [OTHER.exo ...] [--node-set bottom] [--tolerance 1e-3]

Friction from the first touch (inputs/verification/first_touch_friction*.xml): the same deck run with
different first steps must reach load factor 1 with the same tangential displacements (displ_x, and
displ_z in 3D) of the contact surface's nodes. For each OTHER run, the largest difference from the
REFERENCE run over the node set's nodes and tangential components, relative to the reference's largest
tangential displacement there, must be at most --tolerance. Exit 0 when every run agrees."""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
from contact_results import Results  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("reference")
parser.add_argument("others", nargs="+")
parser.add_argument("--node-set", default="bottom")
parser.add_argument("--tolerance", type=float, default=1e-3)
args = parser.parse_args()


def tangential(path):
    r = Results(path)
    if not abs(r.times[-1] - 1.0) < 1e-12:
        sys.exit(f"{path}: the last step is at load factor {r.times[-1]}, 1 expected")
    nodes = np.sort(r.node_set(args.node_set))
    components = [c for c in ("displ_x", "displ_z") if c in r.nodal_names]
    return np.stack([r.nodal(c)[nodes] for c in components]), len(r.times) - 1


reference, steps = tangential(args.reference)
scale = np.max(np.abs(reference))
print(f"{args.reference}: {steps} increments, largest tangential displacement {scale:.9e}")
failed = False
for path in args.others:
    u, n = tangential(path)
    if u.shape != reference.shape:
        sys.exit(f"{path}: {u.shape} tangential values, the reference has {reference.shape}")
    difference = np.max(np.abs(u - reference)) / scale
    verdict = "ok" if difference <= args.tolerance else "FAILED"
    print(f"{path}: {n} increments, max |u_t - u_t,ref| / max |u_t,ref| = {difference:.3e} "
          f"(tolerance {args.tolerance:g}) {verdict}")
    failed |= difference > args.tolerance
sys.exit(1 if failed else 0)
