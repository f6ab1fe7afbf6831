#!/usr/bin/python3
"""Figures of the tube benchmark (Vulovic et al., section 6) from two Contessa runs of
inputs/tube_bending.xml: the Contact Beta run and the fixed-step run (Method=Constant).

    /usr/bin/python3 scripts/plot_tube.py BETA_DIR FIXED_DIR OUT_DIR [--contacts-per-step 2]

BETA_DIR and FIXED_DIR each hold tube_bending.history.csv and tube_bending.exo (any one
*.history.csv and its .exo are accepted). Writes into OUT_DIR:

  tube_step_size.png  plate displacement increment (75.2 mm x dlambda) per increment (paper's Fig. 4)
  tube_reaction.png   plate force -contact_force_plate_y (N/mm, quarter model) vs plate displacement
  tube_deformed.png   deformed tube at the last step of the Contact Beta run, coloured by the
                      displacement magnitude, with the plate and the contact nodes (paper's Fig. 3)
  tube_contacts.png   new contacts per increment (Contact Beta) and active contacts vs displacement
"""
import argparse
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402
from netCDF4 import Dataset, chartostring  # noqa: E402

PLATE_TRAVEL = 75.2  # mm of plate motion at load factor 1 (deck: Rigid Surface/Motion)
PLATE_Y0 = 120.0  # initial plate height, mm (= inner radius 100 + thickness 20)
PLATE_X = (-20.0, 300.0)  # plate extent in the deck, mm
FORCE_COLUMN = "contact_force_plate_y"

BETA_STYLE = dict(color="tab:red", marker="o", markersize=4, linewidth=1.2)
FIXED_STYLE = dict(color="tab:blue", marker=".", markersize=3, linewidth=1.0)


def find_results(directory):
    """(history csv, exodus file) in a run's output directory."""
    hist = sorted(glob.glob(os.path.join(directory, "*.history.csv")))
    if not hist:
        sys.exit(f"plot_tube.py: no *.history.csv in {directory}")
    if len(hist) > 1:
        preferred = [h for h in hist if os.path.basename(h) == "tube_bending.history.csv"]
        hist = preferred or hist
    exo = hist[0][: -len(".history.csv")] + ".exo"
    return hist[0], exo


def read_history(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_tube.py: {path} is empty")
    out = {}
    for key in rows[0]:
        out[key] = np.array([float(r[key]) for r in rows])
    if FORCE_COLUMN not in out:
        sys.exit(f"plot_tube.py: {path} has no column {FORCE_COLUMN}")
    return out


def read_exodus_last(path):
    """Mesh, nodal fields and load factor at the last time step of an Exodus II file."""
    with Dataset(path) as d:
        x = np.array(d["coordx"][:], dtype=float)
        y = np.array(d["coordy"][:], dtype=float)
        conn = np.array(d["connect1"][:], dtype=int) - 1  # Exodus numbers nodes from 1
        names = [str(s) for s in chartostring(d["name_nod_var"][:])]
        last = d.dimensions["time_step"].size - 1
        fields = {n: np.array(d[f"vals_nod_var{i + 1}"][last, :], dtype=float) for i, n in enumerate(names)}
        lam = float(d["time_whole"][last])
    return x, y, conn, fields, lam


def boundary_edges(conn):
    """Edges of a quad mesh that belong to one element only (the outline)."""
    count = {}
    for quad in conn:
        for a, b in zip(quad, np.roll(quad, -1)):
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    return np.array([k for k, n in count.items() if n == 1])


def quads_to_triangles(conn):
    return np.vstack([conn[:, [0, 1, 2]], conn[:, [0, 2, 3]]])


def plot_step_size(beta, fixed, out):
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot(fixed["step"][1:], PLATE_TRAVEL * fixed["dlambda"][1:],
            label=f"fixed step ({int(fixed['step'][-1])} increments)", **FIXED_STYLE)
    ax.plot(beta["step"][1:], PLATE_TRAVEL * beta["dlambda"][1:],
            label=f"Contact Beta ({int(beta['step'][-1])} increments)", **BETA_STYLE)
    restarted = beta["attempts"][1:] > 1
    if restarted.any():
        ax.plot(beta["step"][1:][restarted], PLATE_TRAVEL * beta["dlambda"][1:][restarted], "o",
                markersize=9, markerfacecolor="none", markeredgecolor="black", linewidth=0,
                label="Contact Beta increment restarted with β")
    ax.set_xlabel("increment")
    ax.set_ylabel("plate displacement increment Δu (mm)")
    ax.set_title("Tube bending: evolution of the load step (cf. paper Fig. 4)")
    ax.set_xlim(0, max(fixed["step"][-1], beta["step"][-1]) + 1)
    ax.set_ylim(0, None)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def plot_against_travel(ax, fixed, beta, column, sign, labels, fixed_style, markersize, ylabel, title):
    """`sign` x `column` of the fixed-step run (a line in `fixed_style`) and of the Contact Beta run (open
    circles) against the plate displacement, on axes from 0."""
    ax.plot(PLATE_TRAVEL * fixed["lambda"], sign * fixed[column], color="tab:blue", label=labels[0], **fixed_style)
    ax.plot(PLATE_TRAVEL * beta["lambda"], sign * beta[column], "o", color="tab:red", markersize=markersize,
            markerfacecolor="none", label=labels[1])
    ax.set_xlabel("plate displacement u (mm)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.set_xlim(0, PLATE_TRAVEL * 1.02)
    ax.set_ylim(0, None)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left")


def plot_reaction(beta, fixed, out):
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    labels = (f"fixed step ({int(fixed['step'][-1])} increments)", f"Contact Beta ({int(beta['step'][-1])} increments)")
    plot_against_travel(ax, fixed, beta, FORCE_COLUMN, -1, labels, {"linewidth": 1.5}, 5,
                        "plate force (N/mm, quarter model)", "Tube bending: plate force vs plate displacement")
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def plot_deformed(exo, out, label):
    x, y, conn, f, lam = read_exodus_last(exo)
    ux, uy = f["displ_x"], f["displ_y"]
    xd, yd = x + ux, y + uy
    mag = np.hypot(ux, uy)

    fig, ax = plt.subplots(figsize=(9.0, 6.0))
    edges = boundary_edges(conn)
    ax.add_collection(LineCollection(np.stack([np.c_[x[edges[:, 0]], y[edges[:, 0]]],
                                               np.c_[x[edges[:, 1]], y[edges[:, 1]]]], axis=1),
                                     colors="0.7", linewidths=1.0, label="undeformed"))
    tri = Triangulation(xd, yd, quads_to_triangles(conn))
    pc = ax.tripcolor(tri, mag, shading="gouraud", cmap="viridis")
    # element edges of the deformed mesh, thin, so the 13 x 101 mesh is visible
    corners = np.stack([xd[conn], yd[conn]], axis=-1)  # (elements, 4, 2)
    segs = np.stack([corners, np.roll(corners, -1, axis=1)], axis=2).reshape(-1, 2, 2)
    ax.add_collection(LineCollection(segs, colors="k", linewidths=0.15, alpha=0.3))
    plate_y = PLATE_Y0 - PLATE_TRAVEL * lam
    ax.fill_between(PLATE_X, plate_y, plate_y + 4.0, facecolor="0.85", edgecolor="0.4", hatch="////",
                    linewidth=0.0)
    ax.plot(PLATE_X, [plate_y, plate_y], color="0.15", linewidth=1.5,
            label=f"rigid plate (y = 120 − 75.2 λ = {plate_y:.1f} mm)")
    status = f.get("contact_status")
    if status is not None:
        on = status > 0
        ax.plot(xd[on], yd[on], "o", markersize=4, markerfacecolor="tab:red", markeredgecolor="white",
                markeredgewidth=0.5, linewidth=0, label=f"contact nodes ({int(on.sum())})")
    cb = fig.colorbar(pc, ax=ax, shrink=0.8)
    cb.set_label("displacement magnitude |u| (mm)")
    ax.set_aspect("equal")
    xmax = max(x.max(), xd.max())
    ax.set_xlim(-10, xmax + 10)
    ax.set_ylim(-8, PLATE_Y0 + 8)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title(f"Tube bending, {label}: deformed quarter tube (cf. paper Fig. 3)\n"
                 f"last step, λ = {lam:g}, plate moved {PLATE_TRAVEL * lam:.1f} mm")
    ax.legend(loc="lower left", fontsize=9, framealpha=0.9)
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def plot_contacts(beta, fixed, out, nc):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(12, 4.5))
    steps = beta["step"][1:]
    a1.bar(steps, beta["new_contacts"][1:], color="tab:red", alpha=0.8, label="Contact Beta")
    a1.axhline(nc, color="k", linestyle="--", linewidth=1, label=f"N_c = {nc}")
    a1.set_xlabel("increment")
    a1.set_ylabel("new contact nodes in the increment")
    a1.set_title("New contacts per increment (Contact Beta)")
    a1.set_xlim(0, steps[-1] + 1)
    a1.set_ylim(0, max(beta["new_contacts"].max(), nc) + 1)
    a1.yaxis.get_major_locator().set_params(integer=True)
    a1.grid(True, axis="y", alpha=0.3)
    a1.legend()

    plot_against_travel(a2, fixed, beta, "active_contacts", 1, ("fixed step", "Contact Beta"),
                        {"drawstyle": "steps-post", "linewidth": 1.2}, 4, "active contact nodes",
                        "Active contacts vs plate displacement")
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("beta_dir")
    p.add_argument("fixed_dir")
    p.add_argument("out_dir")
    p.add_argument("--contacts-per-step", type=int, default=2,
                   help="N_c of the Contact Beta run, drawn as a reference line (default 2)")
    a = p.parse_args()
    beta_csv, beta_exo = find_results(a.beta_dir)
    fixed_csv, _ = find_results(a.fixed_dir)
    beta, fixed = read_history(beta_csv), read_history(fixed_csv)
    os.makedirs(a.out_dir, exist_ok=True)
    outs = {k: os.path.join(a.out_dir, f"tube_{k}.png") for k in ("step_size", "reaction", "deformed", "contacts")}
    plot_step_size(beta, fixed, outs["step_size"])
    plot_reaction(beta, fixed, outs["reaction"])
    plot_deformed(beta_exo, outs["deformed"], f"Contact Beta N_c = {a.contacts_per_step}")
    plot_contacts(beta, fixed, outs["contacts"], a.contacts_per_step)
    for path in outs.values():
        print(path)


if __name__ == "__main__":
    main()
