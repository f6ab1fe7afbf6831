#!/usr/bin/python3
"""check_factorizations.py SUMMARY.json all|some|none|reused|unchanged-setups

Checks which MUMPS factorisations a run did (docs/user-guide.md, "Symmetric Jacobians"): `all` of them
LDLᵀ (a symmetric Jacobian throughout: hyperelastic solids, frictionless contact, one rank), `some`
(a frictional run: stick is symmetric, slip is not), or `none` (several ranks, or Exploit Symmetry off).
`reused`: some Jacobians equal to the last factorised one reused its factors, and every linear solve's
Jacobian was either factorised or reused; `unchanged-setups`: MueLu skipped the set-up of some Jacobians
equal to the last one it was set up for (docs/user-guide.md, "Linear solver")."""
import json
import sys

summary = json.load(open(sys.argv[1]))
expected = sys.argv[2]
if expected in ("reused", "unchanged-setups"):
    solves, direct, reused = summary["linear_solves"], summary["direct_factorizations"], summary["reused_factorizations"]
    skipped = summary["preconditioner_unchanged_setups"]
    print(f"{solves} linear solves, {direct} factorisations, {reused} reused factors, {skipped} MueLu set-ups skipped")
    ok = reused > 0 and direct + reused == solves if expected == "reused" else skipped > 0 and direct == 0
    sys.exit(0 if ok else f"FAIL: expected {expected}")
direct, symmetric = summary["direct_factorizations"], summary["symmetric_factorizations"]
print(f"{direct} factorisations, {symmetric} of them LDLT")
ok = direct > 0 and {"all": symmetric == direct, "some": 0 < symmetric < direct, "none": symmetric == 0}[expected]
if not ok:
    sys.exit(f"FAIL: expected {expected} of the {direct} factorisations to be LDLT, got {symmetric}")
