#!/usr/bin/python3
"""check_factorizations.py SUMMARY.json all|some|none

Checks which MUMPS factorisations a run did (docs/user-guide.md, "Symmetric Jacobians"): `all` of them
LDLᵀ (a symmetric Jacobian throughout: hyperelastic solids, frictionless contact, one rank), `some`
(a frictional run: stick is symmetric, slip is not), or `none` (several ranks, or Exploit Symmetry off)."""
import json
import sys

summary = json.load(open(sys.argv[1]))
expected = sys.argv[2]
direct, symmetric = summary["direct_factorizations"], summary["symmetric_factorizations"]
print(f"{direct} factorisations, {symmetric} of them LDLT")
ok = direct > 0 and {"all": symmetric == direct, "some": 0 < symmetric < direct, "none": symmetric == 0}[expected]
if not ok:
    sys.exit(f"FAIL: expected {expected} of the {direct} factorisations to be LDLT, got {symmetric}")
