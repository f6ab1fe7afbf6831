#!/usr/bin/python3
"""The exact inflation of a thick-walled cylinder of Contessa's compressible Neo-Hookean material in plane
strain under an internal pressure that follows the inner face (docs/verification-loads.md).

W = mu/2 (tr C - 3) - mu ln J + lam/2 (ln J)^2 (mechanics/NeoHookean.cpp). The deformation r = r(R),
theta = Theta, z = Z has the principal stretches l_r = r'(R), l_t = r/R, l_z = 1 and J = l_r l_t, and the
principal nominal stresses P_r = dW/dl_r = mu (l_r - 1/l_r) + lam ln J / l_r, P_t likewise. Equilibrium
in the reference configuration, dP_r/dR + (P_r - P_t)/R = 0, with P_r(B) = 0 (free outer face) and
sigma_r(A) = P_r(A) / l_t(A) = -p (the pressure on the deformed inner face) has no closed form for this
compressible law: for a given inner stretch l_a = r(A)/A, l_r(A) is found by shooting (Brent's method on
P_r(B)), the ODE for (r, l_r) integrated by an adaptive Runge-Kutta method to a relative 1e-11; then
p = -P_r(A) / l_a.

  neo_hookean_cylinder.py table A B E NU            p against l_a for l_a = 1.0 ... 1.6
  neo_hookean_cylinder.py pressure A B E NU L_A     p at one inner stretch
"""
import math
import sys

from scipy.integrate import solve_ivp
from scipy.optimize import brentq


def lame(E, nu):
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def nominal(lr, lt, lam, mu):
    lnJ = math.log(lr * lt)
    return mu * (lr - 1 / lr) + lam * lnJ / lr, mu * (lt - 1 / lt) + lam * lnJ / lt


def outer_traction(lr_a, la, A, B, lam, mu):
    """P_r at R = B for l_r(A) = lr_a, r(A) = la A; None where the deformation becomes inadmissible."""

    def rhs(R, y):
        r, lr = y
        lt = r / R
        Pr, Pt = nominal(lr, lt, lam, mu)
        lnJ = math.log(lr * lt)
        dPr_dlr = mu * (1 + 1 / lr**2) + lam * (1 - lnJ) / lr**2
        dPr_dlt = lam / (lr * lt)
        dlr = (-(Pr - Pt) / R - dPr_dlt * (lr - lt) / R) / dPr_dlr
        return [lr, dlr]

    sol = solve_ivp(rhs, (A, B), [la * A, lr_a], rtol=1e-11, atol=1e-13, method="DOP853")
    r, lr = sol.y[:, -1]
    return nominal(lr, r / B, lam, mu)[0]


def pressure(la, A, B, E, nu):
    lam, mu = lame(E, nu)
    if la == 1.0:
        return 0.0
    # l_r(A) < 1 under inflation (the wall thins); bracket the root of P_r(B) in (l_lo, 1.2).
    f = lambda lr_a: outer_traction(lr_a, la, A, B, lam, mu)
    lo, hi = 0.2, 1.2
    lr_a = brentq(f, lo, hi, xtol=1e-14, rtol=1e-14)
    Pr_a = nominal(lr_a, la, lam, mu)[0]
    return -Pr_a / la


if __name__ == "__main__":
    mode, A, B, E, nu = sys.argv[1], *map(float, sys.argv[2:6])
    if mode == "table":
        for k in range(0, 13):
            la = 1.0 + 0.05 * k
            print(f"{la:.3f} {pressure(la, A, B, E, nu):.10g}")
    else:
        print(f"{pressure(float(sys.argv[6]), A, B, E, nu):.12g}")
