#!/usr/bin/python3
"""check_column.py RESULTS L RHOG E WEIGHT NODAL_TOLERANCE
   check_column.py --order COARSE FINE L RHOG E MEASURE MIN_ORDER

A column 0 <= y <= L under its own weight (column.xml, column_3d.xml), nu = 0, base held in y:
    u_y(y) = -rho g (L y - y^2 / 2) / E,   u_x = u_z = 0,   eps_yy(y) = -rho g (L - y) / E.
RESULTS is a run's <name> (RESULTS.exo, RESULTS.history.csv). The first form checks, at the last step:
  - every node's displacement against the exact one: the largest error over the tip's |u_y(L)| <= NODAL_TOLERANCE
    (round-off for the quadratic cells, which hold the quadratic u_y; the linear ones are exact at the nodes too);
  - the base's reaction reaction_bottom_y against WEIGHT (rho g times the volume, or the revolved volume), 1e-9.
It also prints, for linear cells, the errors between the nodes: of u_y at the middle of every edge (the cell
interpolates linearly along an edge) and of the strain along every edge at its ends, over the tip's values.
The second form takes the runs on a coarse and a fine mesh (half the cell size in every direction) and checks
the order log2(e_c / e_f) of one MEASURE: "nodal" (the largest error of u_y at the nodes), "rms" (its root
mean square over the nodes), "midpoint" (u_y at the middle of the linear cells' edges) or "strain" (along their
edges).
"""
import csv
import math
import sys

import netCDF4
import numpy as np

EDGES = {
    "QUAD4": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "TRI3": [(0, 1), (1, 2), (2, 0)],
    "HEX8": [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)],
    "TETRA4": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
    "WEDGE6": [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5)],
}
ALIASES = {"QUAD": "QUAD4", "TRI": "TRI3", "HEX": "HEX8", "TETRA": "TETRA4", "TET4": "TETRA4", "WEDGE": "WEDGE6"}


def names(ds, var):
    return ["".join(c.decode() for c in row if c not in (b"", b"\x00")).strip() for row in ds.variables[var][:].data]


def read(results):
    ds = netCDF4.Dataset(results + ".exo")
    nodal = names(ds, "name_nod_var")
    axes = "xyz" if "coordz" in ds.variables else "xy"
    X = np.array([ds.variables["coord" + c][:] for c in axes])
    U = np.array([ds.variables[f"vals_nod_var{nodal.index('displ_' + c) + 1}"][-1, :] for c in axes])
    blocks = []
    for b in range(1, len(ds.dimensions["num_el_blk"]) + 1):
        conn = ds.variables[f"connect{b}"]
        kind = conn.getncattr("elem_type").upper()
        blocks.append((ALIASES.get(kind, kind), np.asarray(conn[:]) - 1))
    return X, U, blocks


def exact(y, L, rhog, E):
    return -rhog * (L * y - 0.5 * y * y) / E


def between_nodes(X, U, blocks, L, rhog, E):
    """Largest errors (over the tip's |u_y|, |eps_yy(0)|) of u_y at edge midpoints and of the strain along edges."""
    tip, strain0 = abs(exact(L, L, rhog, E)), rhog * L / E
    e_mid, e_strain = 0.0, 0.0
    for kind, conn in blocks:
        for a, b in EDGES.get(kind, []):
            ya, yb = X[1, conn[:, a]], X[1, conn[:, b]]
            ua, ub = U[1, conn[:, a]], U[1, conn[:, b]]
            mid = 0.5 * (ua + ub) - exact(0.5 * (ya + yb), L, rhog, E)
            e_mid = max(e_mid, np.abs(mid).max() / tip)
            vertical = np.abs(yb - ya) > 1e-12
            if vertical.any():
                slope = (ub - ua)[vertical] / (yb - ya)[vertical]
                for y in (ya[vertical], yb[vertical]):
                    e_strain = max(e_strain, np.abs(slope + rhog * (L - y) / E).max() / strain0)
    return e_mid, e_strain


def check(results, L, rhog, E, weight, tolerance):
    X, U, blocks = read(results)
    tip = abs(exact(L, L, rhog, E))
    error = np.abs(U[1] - exact(X[1], L, rhog, E)).max() / tip
    lateral = max(np.abs(U[i]).max() for i in range(U.shape[0]) if i != 1) / tip
    print(f"{results}.exo: {X.shape[1]} nodes, cells {sorted({k for k, _ in blocks})}; u_y(L) = "
          f"{U[1][np.isclose(X[1], L)].mean():.12e} (exact {-tip:.12e})")
    print(f"largest nodal error of u_y over |u_y(L)|: {error:.3e}; of the lateral displacement: {lateral:.3e}; "
          f"tolerance {tolerance:g}")
    ok = error <= tolerance and lateral <= tolerance
    if any(k in EDGES for k, _ in blocks):
        e_mid, e_strain = between_nodes(X, U, blocks, L, rhog, E)
        print(f"between the nodes (linear cells): u_y at edge midpoints {e_mid:.3e}, strain along edges {e_strain:.3e}")
    with open(results + ".history.csv") as f:
        reaction = float(list(csv.DictReader(f))[-1]["reaction_bottom_y"])
    rel = abs(reaction - weight) / abs(weight)
    print(f"reaction_bottom_y = {reaction:.12e}, the weight {weight:.12e}: relative {rel:.2e} (tolerance 1e-9)")
    return ok and rel <= 1e-9


def errors(results, L, rhog, E):
    X, U, blocks = read(results)
    nodal = np.abs(U[1] - exact(X[1], L, rhog, E)).max() / abs(exact(L, L, rhog, E))
    midpoint, strain = between_nodes(X, U, blocks, L, rhog, E)
    rms = np.sqrt(np.mean((U[1] - exact(X[1], L, rhog, E)) ** 2)) / abs(exact(L, L, rhog, E))
    return {"nodal": nodal, "rms": rms, "midpoint": midpoint, "strain": strain}


def order(coarse, fine, L, rhog, E, measure, min_order):
    e = [errors(r, L, rhog, E)[measure] for r in (coarse, fine)]
    p = math.log2(e[0] / e[1])
    print(f"{measure} error over the tip's: {e[0]:.4e} (coarse) -> {e[1]:.4e} (fine), order {p:.3f} (>= {min_order:g})")
    return p >= min_order


if sys.argv[1] == "--order":
    ok = order(sys.argv[2], sys.argv[3], *map(float, sys.argv[4:7]), sys.argv[7], float(sys.argv[8]))
else:
    ok = check(sys.argv[1], *map(float, sys.argv[2:7]))
print("passed" if ok else "FAIL")
sys.exit(0 if ok else 1)
