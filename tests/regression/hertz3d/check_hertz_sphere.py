#!/usr/bin/python3
"""check_hertz_sphere.py EXO HISTORY [--R 50 --E 20000 --nu 0.3 --interface plane] [tolerances]

Compares the contact of inputs/verification/hertz_sphere.xml (an eighth of an elastic sphere, pole on a
rigid plane, symmetry about x = 0 and y = 0) with Hertz for the force P the run transmits
(P = 4 x |contact_force_<interface>_z|, the octant carrying a quarter of the contact area):
  a_H = (3 P R / (4 E*))^(1/3),  p0_H = 3 P / (2 pi a_H^2),  E* = E / (1 - nu^2).
Checks:
- peak pressure (the pole node): |p0 / p0_H - 1| <= --p0-rtol (0.03, the issue's 3 %);
- the contact edge: a_H lies within one element of the last node in contact (the discrete edge smears
  the pressure over one element), the element size there being the longest surface edge of the mesh at
  that node (from the Exodus connectivity: the r-gap to the next open node among all surface nodes is
  much shorter off the axes than the elements are);
- the contact radius: the least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to the contact nodes with
  r <= 0.8 a_H within --a-rtol (0.03, the issue's 3 %) of a_H;
- equilibrium: the reaction of the pushed equator equals the contact force (1e-6 relative).
--pressure recovered (for 6-node TRI6 slave faces, Tet10): the nodal contact_pressure of node-to-face
contact on TRI6 faces is not the contact traction (docs/verification-contact.md §11: in the stiff limit a
corner carries ~0, a mid-edge node 4/3 of a uniform pressure), so the traction is recovered from the nodal
forces instead: f_k = A_k p_k (A_k the slave weights, theory-contact.md §8.1: the face's four 3-node
sub-triangles, A/3 each to their nodes, scaled to the face's area), and t = M^-1 f with M = sum of the
faces' consistent TRI6 matrices int N_i N_j dA (the L2 projection of the traction whose consistent loads
are f: exact for any quadratic traction, a uniform one included). The checks above then use t; the sum of
f_k must equal the interface's force (1e-6 relative, checked).
Printed, not checked (docs/verification-contact.md, Hertz sphere): a and p0 against the
displacement-driven values of Code_Aster's SSNV104 (two hemispheres R = 50, each pushed 2 mm: a =
sqrt(R h / 2) = 10 mm, p0 = E/(pi (1 - nu^2)) sqrt(2 h / R) = 2798.3 MPa): the hemisphere pushed at its
equator carries 12 % more force than Hertz's half-space for the same approach, so those differ by more.
Exit 0 when every check holds."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact"))
import contact_results as cr  # noqa: E402

# Exodus TETRA10 sides (0-based local nodes: corners, then the mid-edge nodes of edges 0-1, 1-2, 2-0 of
# the side), the TRI6 order of the slave faces.
TET10_SIDES = [(0, 1, 3, 4, 8, 7), (1, 2, 3, 5, 9, 8), (0, 3, 2, 7, 9, 6), (0, 2, 1, 6, 5, 4)]
# The TRI6 face's four 3-node sub-triangles (theory-contact.md §8.1; MasterFacet.hpp Tri6Facet).
TRI6_SUB = [(0, 3, 5), (3, 1, 4), (5, 4, 2), (3, 4, 5)]


def tri6_shape(s, t):
    l0, l1, l2 = 1.0 - s - t, s, t
    n = np.array([l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0])
    dn = np.array([[1 - 4 * l0, 1 - 4 * l0], [4 * l1 - 1, 0.0], [0.0, 4 * l2 - 1],
                   [4 * (l0 - l1), -4 * l1], [4 * l2, 4 * l1], [-4 * l2, 4 * (l0 - l2)]])
    return n, dn


def triangle_rule(n=6):
    """Collapsed Gauss rule on the unit triangle (n x n points: exact to degree 2n - 2)."""
    g, w = np.polynomial.legendre.leggauss(n)
    u, wu = 0.5 * (g + 1), 0.5 * w
    return [(a * (1 - b), b, wa * wb * (1 - b)) for a, wa in zip(u, wu) for b, wb in zip(u, wu)]


def slave_faces(ds, side_set):
    """The TRI6 faces of a side set on TETRA10 cells (node indices, 0-based)."""
    ss = cr._names(ds, "ss_names").index(side_set) + 1
    elems = np.asarray(ds.variables[f"elem_ss{ss}"][:], dtype=int) - 1
    sides = np.asarray(ds.variables[f"side_ss{ss}"][:], dtype=int) - 1
    blocks = [k for k in sorted(ds.variables) if k.startswith("connect")]
    offsets, faces = {}, []
    start = 0
    for k in sorted(blocks, key=lambda k: int(k[len("connect"):])):
        offsets[k] = start
        start += ds.variables[k].shape[0]
    for e, side in zip(elems, sides):
        block = max((k for k in blocks if offsets[k] <= e), key=lambda k: offsets[k])
        cells = ds.variables[block]
        if cells.getncattr("elem_type").upper() != "TETRA10":
            sys.exit(f"--pressure recovered: side set {side_set} is on {cells.getncattr('elem_type')} cells, not TETRA10")
        cell = np.asarray(cells[e - offsets[block], :], dtype=int) - 1
        faces.append(cell[list(TET10_SIDES[side])])
    return faces


def recovered_traction(ds, side_set, nodal_pressure, displaced):
    """t = M^-1 f (module docstring): returns the traction at every node and the sum of the nodal forces."""
    reference = np.stack([np.asarray(ds.variables[f"coord{c}"][:], dtype=float) for c in "xyz"], axis=1)
    faces = slave_faces(ds, side_set)
    nodes = np.unique(np.concatenate(faces))
    index = {n: i for i, n in enumerate(nodes)}
    rule = triangle_rule()
    mass = np.zeros((len(nodes), len(nodes)))
    weights = np.zeros(len(nodes))
    for face in faces:
        x0, x1 = reference[face], displaced[face]
        sub = [0.5 * np.linalg.norm(np.cross(x0[b] - x0[a], x0[c] - x0[a])) for a, b, c in TRI6_SUB]
        area = 0.0
        local = np.zeros((6, 6))
        for s_, t_, w in rule:
            n, dn = tri6_shape(s_, t_)
            area += w * np.linalg.norm(np.cross(dn[:, 0] @ x0, dn[:, 1] @ x0))
            local += w * np.linalg.norm(np.cross(dn[:, 0] @ x1, dn[:, 1] @ x1)) * np.outer(n, n)
        ids = [index[n] for n in face]
        for (a, b, c), piece in zip(TRI6_SUB, sub):
            for v in (a, b, c):
                weights[ids[v]] += piece / 3.0 * area / sum(sub)
        mass[np.ix_(ids, ids)] += local
    forces = weights * nodal_pressure[nodes]
    traction = np.zeros_like(nodal_pressure)
    traction[nodes] = np.linalg.solve(mass, forces)
    return traction, forces.sum()


def main():
    parser = cr.hertz_parser(R=50.0, E=20000.0, p0_rtol=0.03, a_rtol=0.03)
    parser.add_argument("--interface", default="plane")
    parser.add_argument("--surface", default="surface")
    parser.add_argument("--reaction", default="equator")
    parser.add_argument("--pressure", choices=["nodal", "recovered"], default="nodal")
    parser.add_argument("--p0-known-excess", type=float, nargs=2, metavar=("LOW", "HIGH"),
                        help="instead of |p0/p0_H - 1| <= --p0-rtol: a known deviation, LOW < p0/p0_H - 1 <= HIGH "
                             "(the Tet10 deck's TRI6 faces miss the 3 %%: the test records by how much, and fails "
                             "when that changes either way)")
    args = parser.parse_args()

    res = cr.Results(args.exo)
    x, y, z = res.x, res.y, res.z
    pressure = res.nodal("contact_pressure")
    surface = res.node_set(args.surface)
    last = cr.read_history(args.history)[-1]
    force = last[f"contact_force_{args.interface}_z"]
    in_contact = pressure > 0  # the nodes in contact (a node's force is its weight times its pressure)
    recovery_check = None
    if args.pressure == "recovered":
        displaced = np.stack([coordinate + res.nodal("displ_" + c)
                              for c, coordinate in zip("xyz", (x, y, z))], axis=1)
        corner_p = pressure[np.unique(np.concatenate([f[:3] for f in slave_faces(res.ds, args.surface)]))]
        mid_p = pressure[np.unique(np.concatenate([f[3:] for f in slave_faces(res.ds, args.surface)]))]
        print(f"info: nodal contact_pressure: corners up to {corner_p.max():.1f}, mid-edge nodes up to {mid_p.max():.1f} MPa")
        pressure, force_sum = recovered_traction(res.ds, args.surface, pressure, displaced)
        recovery_check = ("nodal forces", f"sum of A_k p_k = {force_sum:.6f}, interface force {force:.6f}",
                          abs(abs(force_sum) - abs(force)) <= 1e-6 * abs(force), "<= 1e-6 x force")
    P = 4.0 * abs(force)
    a_h, p0_h = cr.hertz_sphere(P, args.R, args.E, args.nu)

    r = np.hypot(x[surface], y[surface])
    p = pressure[surface]
    order = np.argsort(r)
    r, p = r[order], p[order]
    touching = in_contact[surface][order]
    pole = int(np.argmin(r))
    p0 = p[pole]
    fit = touching & (r <= 0.8 * a_h)
    # p^2 = p0^2 - (p0^2 / a^2) r^2: a straight line in r^2.
    slope, intercept = np.polyfit(r[fit] ** 2, p[fit] ** 2, 1)
    a_fit = math.sqrt(-intercept / slope) if slope < 0 < intercept else float("nan")
    r_last = r[touching].max()
    beyond = r[(~touching) & (r > r_last)]
    r_open = beyond.min() if beyond.size else float("nan")
    # The element size at the last contact node: its longest corner-to-corner edge on the surface through it
    # (a mid-edge node of a quadratic cell: the edge it halves).
    last_node = surface[order][touching][np.argmax(r[touching])]
    on_surface = set(surface.tolist())
    HEX_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
    TET_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
    # The corner-to-corner edges of each solid cell type (nodes per cell); a quadratic cell's mid-edge nodes
    # halve its edges, the element size is the corners' distance. The rigid plane's SHELL4 block is skipped.
    CELL_EDGES = {8: HEX_EDGES, 20: HEX_EDGES, 27: HEX_EDGES, 4: TET_EDGES, 10: TET_EDGES}
    h_edge = 0.0
    for key in res.ds.variables:
        if not key.startswith("connect") or res.ds.variables[key].getncattr("elem_type").upper().startswith("SHELL"):
            continue
        cells = np.asarray(res.ds.variables[key][:], dtype=int) - 1
        if cells.ndim != 2 or cells.shape[1] not in CELL_EDGES:
            continue
        for cell in cells[np.any(cells == last_node, axis=1)]:
            for e, (i, j) in enumerate(CELL_EDGES[cells.shape[1]]):
                n1, n2 = cell[i], cell[j]
                on_edge = last_node in (n1, n2) or (cells.shape[1] == 10 and cell[4 + e] == last_node)
                if on_edge and n1 in on_surface and n2 in on_surface:
                    h_edge = max(h_edge, math.dist((x[n1], y[n1], z[n1]), (x[n2], y[n2], z[n2])))
    reaction = last.get(f"reaction_{args.reaction}_z", float("nan"))

    print(f"P = {P:.6f} N (4 x contact_force_{args.interface}_z), a_H = {a_h:.5f} mm, p0_H = {p0_h:.3f} MPa; "
          f"{int(touching.sum())} surface nodes in contact")
    print(f"info: contact radius from the fit of p^2: a_fit = {a_fit:.5f} mm, {a_fit / a_h - 1:+.2%} of a_H; "
          f"its peak sqrt(intercept) = {math.sqrt(max(intercept, 0.0)):.3f} MPa, {math.sqrt(max(intercept, 0.0)) / p0_h - 1:+.2%} of p0_H")
    print(f"info: SSNV104 (displacement-driven): a = 10 mm -> {a_fit / 10.0 - 1:+.2%}, p0 = 2798.3 MPa -> {p0 / 2798.3 - 1:+.2%}")
    p0_error = p0 / p0_h - 1
    if args.p0_known_excess:
        low, high = args.p0_known_excess
        p0_check = ("peak pressure (pole node), a known excess", f"p0 = {p0:.3f}, error {p0_error:+.2e}",
                    low < p0_error <= high, f"in ({low:g}, {high:g}]")
    else:
        p0_check = ("peak pressure (pole node)", f"p0 = {p0:.3f}, error {p0_error:+.2e}", abs(p0_error) <= args.p0_rtol,
                    f"<= {args.p0_rtol:g}")
    checks = [
        p0_check,
        ("contact edge", f"last contact node r = {r_last:.4f} (element {h_edge:.3f} mm), first open {r_open:.4f}",
         abs(r_last - a_h) <= h_edge, "within one element of a_H"),
        ("contact radius", f"a_fit = {a_fit:.5f}, error {a_fit / a_h - 1:+.2e}", abs(a_fit / a_h - 1) <= args.a_rtol,
         f"<= {args.a_rtol:g}"),
        ("equilibrium", f"reaction_{args.reaction}_z + contact force = {reaction + force:.2e}",
         abs(reaction + force) <= 1e-6 * abs(force), "<= 1e-6 x force"),
    ]
    if recovery_check:
        checks.append(recovery_check)
    cr.exit_with_checks(checks)


if __name__ == "__main__":
    main()
