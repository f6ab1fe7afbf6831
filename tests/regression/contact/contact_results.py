#!/usr/bin/python3
"""Reading Contessa results for the contact verification (Hertz, patch test, Coulomb block).

Used by the check_*.py scripts of this directory (CTest) and by docs/scripts/*_study.py (the studies
behind docs/verification-contact.md), so the tests and the documented numbers come from the same code.
Only numpy and netCDF4 (Debian's /usr/bin/python3)."""
import argparse
import csv
import math
import sys

import netCDF4
import numpy as np


def _names(ds, var):
    if var not in ds.variables:
        return []
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


class Results:
    """One Exodus II results file: reference coordinates, node sets, nodal variables per step."""

    def __init__(self, path):
        self.path = path
        self.ds = netCDF4.Dataset(path)
        self.x = np.asarray(self.ds.variables["coordx"][:], dtype=float)
        self.y = np.asarray(self.ds.variables["coordy"][:], dtype=float)
        self.z = np.asarray(self.ds.variables["coordz"][:], dtype=float) if "coordz" in self.ds.variables else None
        self.times = np.asarray(self.ds.variables["time_whole"][:], dtype=float)
        self.nodal_names = _names(self.ds, "name_nod_var")
        self.node_set_names = _names(self.ds, "ns_names")

    def node_set(self, name):
        """0-based node ids of a node set (the generated meshes have a node set per side set)."""
        if name not in self.node_set_names:
            raise KeyError(f"{self.path}: no node set '{name}' (have {self.node_set_names})")
        return np.asarray(self.ds.variables[f"node_ns{self.node_set_names.index(name) + 1}"][:], dtype=int) - 1

    def nodal(self, name, step=-1):
        if name not in self.nodal_names:
            raise KeyError(f"{self.path}: no nodal variable '{name}' (have {self.nodal_names})")
        return np.asarray(self.ds.variables[f"vals_nod_var{self.nodal_names.index(name) + 1}"][step, :], dtype=float)


def required_options(positional, texts=(), numbers=(), pairs=()):
    """A check script's command line: the file `positional`, then options every call gives: `texts` as
    strings, `numbers` as floats, `pairs` as two floats each (the parsed arguments)."""
    parser = argparse.ArgumentParser()
    parser.add_argument(positional)
    for name in texts:
        parser.add_argument(name, required=True)
    for name in numbers:
        parser.add_argument(name, type=float, required=True)
    for name in pairs:
        parser.add_argument(name, type=float, nargs=2, required=True)
    return parser.parse_args()


def two_histories(first, second, required=(), defaults=()):
    """A comparison script's command line and inputs: the history CSVs `first` and `second` (positional),
    the options `required` as (name, type) that every call gives and `defaults` as (name, type, default).
    Returns the parsed arguments and the two histories as lists of rows (dicts of the CSV's strings)."""
    parser = argparse.ArgumentParser()
    parser.add_argument(first)
    parser.add_argument(second)
    for name, kind in required:
        parser.add_argument(name, type=kind, required=True)
    for name, kind, default in defaults:
        parser.add_argument(name, type=kind, default=default)
    args = parser.parse_args()
    return args, list(csv.DictReader(open(getattr(args, first)))), list(csv.DictReader(open(getattr(args, second))))


def hertz_parser(R, E, p0_rtol, a_rtol):
    """The Hertz checks' command line, EXO HISTORY and the body's radius, Young's modulus and Poisson's
    ratio (0.3), with the default tolerances on the peak pressure and on the fitted contact half-width or
    radius; a script adds its own options."""
    parser = argparse.ArgumentParser()
    parser.add_argument("exo")
    parser.add_argument("history")
    parser.add_argument("--R", type=float, default=R)
    parser.add_argument("--E", type=float, default=E)
    parser.add_argument("--nu", type=float, default=0.3)
    parser.add_argument("--p0-rtol", type=float, default=p0_rtol)
    parser.add_argument("--a-rtol", type=float, default=a_rtol)
    return parser


def exit_with_checks(checks):
    """Prints each check (name, what was measured, whether it holds, the bound) as an ok or FAIL line and
    exits 1 when one fails, 0 otherwise."""
    failed = 0
    for name, text, ok, tol in checks:
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {text} ({tol})")
        failed += not ok
    sys.exit(1 if failed else 0)


def read_history(path):
    """The history CSV as a list of dicts of floats."""
    return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(open(path))]


def surface_nodes(results, node_set, coordinate="x"):
    """Nodes of a straight surface sorted along `coordinate`, with their tributary lengths (half of each
    adjacent side, as Contessa weights the penalty tractions of a slave node)."""
    nodes = results.node_set(node_set)
    c = results.x if coordinate == "x" else results.y
    nodes = nodes[np.argsort(c[nodes])]
    s = c[nodes]
    length = np.zeros(len(nodes))
    length[:-1] += 0.5 * np.diff(s)
    length[1:] += 0.5 * np.diff(s)
    return nodes, length


# ---------------------------------------------------------------------------------------------------
# Hertz: elastic cylinder on a rigid flat, plane strain
# ---------------------------------------------------------------------------------------------------

def hertz(P, R, E, nu):
    """Half-width a and peak pressure p0 of a cylinder (radius R, E, nu) on a rigid flat under the
    force P per unit length (plane strain): a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), E* = E/(1-nu^2)."""
    e_star = E / (1.0 - nu * nu)
    a = math.sqrt(4.0 * P * R / (math.pi * e_star))
    return a, 2.0 * P / (math.pi * a)


def hertz_sphere(P, R, E, nu):
    """Contact radius a and peak pressure p0 of a sphere (radius R, E, nu) on a rigid flat under the total
    force P: a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2), E* = E/(1-nu^2) (Johnson, Contact
    Mechanics, eq. 4.22-4.23). The pressure is the same ellipse as the cylinder's, p0 sqrt(1 - r^2/a^2)."""
    e_star = E / (1.0 - nu * nu)
    a = (3.0 * P * R / (4.0 * e_star)) ** (1.0 / 3.0)
    return a, 3.0 * P / (2.0 * math.pi * a * a)


def hertz_analysis(exo, history, R, E, nu, interface="flat", surface="outer", symmetry_factor=2.0,
                   interior=0.8, formula=hertz):
    """Compares the contact pressure of a cylinder quarter/half model (or, with formula=hertz_sphere and
    symmetry_factor=1, an axisymmetric sphere, whose forces are those of the full circumference) with Hertz.

    The contact nodes are those of the `surface` node set with contact_pressure > 0 at the last step,
    sorted by |X| (reference x, distance from the symmetry line x = 0 through the initial contact point:
    with a rigid FLAT the gap of a material point depends only on its height, so the discrete problem is
    the linear Hertz problem in reference coordinates). P = symmetry_factor * contact_force_<i>_y."""
    res = Results(exo)
    rows = read_history(history)
    last = rows[-1]
    force = last[f"contact_force_{interface}_y"]
    P = symmetry_factor * force
    a_h, p0_h = formula(P, R, E, nu)
    nodes = res.node_set(surface)
    x = np.abs(res.x[nodes])
    order = np.argsort(x)
    nodes, x = nodes[order], x[order]
    p = res.nodal("contact_pressure")[nodes]
    contact = p > 0
    nc = int(contact.sum())
    if nc < 3 or not np.all(contact[:nc]) or np.any(contact[nc:]):
        raise RuntimeError(f"{exo}: the contact zone is not a connected set of >= 3 nodes from x = 0")
    p_hertz = p0_h * np.sqrt(np.clip(1.0 - (x / a_h) ** 2, 0.0, None))
    # Interior nodes (|x| <= interior * a_H): away from the edge, where one node straddles a_H and
    # carries the smeared force of the edge region.
    inner = x <= interior * a_h
    profile_error = float(np.max(np.abs(p - p_hertz)[inner]) / p0_h)
    # Least-squares fit of the Hertz ellipse p^2 = p0^2 (1 - x^2/a^2) to the interior nodes.
    A = np.vstack([np.ones(inner.sum()), -x[inner] ** 2]).T
    c0, c1 = np.linalg.lstsq(A, p[inner] ** 2, rcond=None)[0]
    a_fit, p0_fit = math.sqrt(c0 / c1), math.sqrt(c0)
    # Average error over the whole surface (trapezoidal rule on the nodes, edge included).
    dx = np.diff(x)
    err = np.abs(p - p_hertz)
    l1_error = float(np.sum(0.5 * (err[1:] + err[:-1]) * dx) / (0.5 * math.pi * a_h * p0_h / 2.0))
    return {
        "P": P, "force_y": force, "reaction_end_y": last.get("reaction_end_y", float("nan")),
        "a_hertz": a_h, "p0_hertz": p0_h, "active_contacts": int(last["active_contacts"]),
        "contact_nodes": nc, "h0": float(x[1] - x[0]), "h_edge": float(x[nc] - x[nc - 1]),
        "a_last": float(x[nc - 1]), "a_open": float(x[nc]),
        "a_fit": a_fit, "p0_fit": p0_fit, "p0": float(p[0]),
        "p0_error": float(p[0] / p0_h - 1.0), "a_fit_error": a_fit / a_h - 1.0,
        "a_last_error": float((x[nc - 1] - a_h) / a_h), "profile_error": profile_error, "l1_error": l1_error,
        "x": x, "p": p, "p_hertz": p_hertz, "newton": sum(int(r["newton_iterations"]) for r in rows),
    }
