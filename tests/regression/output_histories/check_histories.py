#!/usr/bin/python3
"""Checks a run's point histories (Problem/Output/History) against what the same run's Exodus file shows,
computed here from the file alone: for every request and every step,
  Displacement at Coordinates   displ_* of the mesh node nearest the point (reference coordinates; of two
                                at the same distance the lower id);
  Displacement over a Node Set  the mean of displ_* over the file's node set;
  Contact Pressure / Slip       contact_pressure / contact_slip of the node of the interface's slave side
                                set nearest the point;
  Applied Force                 load factor x the deck's Nodal Forces, each shared equally by its set's
                                nodes, over the nodes the request's set shares with it;
  Reaction Force                in a component where the set is the deck's only Dirichlet set: the body's
                                equilibrium, -(applied forces + contact forces) (history columns
                                lambda and contact_force_*); where the set is a Reaction Node Set too: its
                                reaction_<set>_* columns.
The history CSV (12 digits) and the Exodus globals of the same names must agree, and a Reaction Force
request's set that is not a Reaction Node Set has no reaction_<set>_* columns.
Usage: check_histories.py DECK OUTPUT_DIR
"""
import csv
import os
import sys
import xml.etree.ElementTree as ET

import netCDF4
import numpy as np


def sublist(node, name):
    for child in node.findall('ParameterList'):
        if child.get('name') == name:
            return child
    return None


def children(node):
    return [] if node is None else node.findall('ParameterList')


def params(node):
    out = {}
    for p in node.findall('Parameter'):
        value = p.get('value')
        if p.get('type') == 'Array(double)':
            value = [float(v) for v in value.strip('{}').split(',')]
        elif p.get('type') == 'double':
            value = float(value)
        out[p.get('name')] = value
    return out


def names(exo, var):
    return [netCDF4.chartostring(n).item().strip() for n in exo.variables[var][:]] if var in exo.variables else []


def main():
    deck_path, out_dir = sys.argv[1], sys.argv[2]
    name = os.path.splitext(os.path.basename(deck_path))[0]
    problem = sublist(ET.parse(deck_path).getroot(), 'Problem')
    output = sublist(problem, 'Output')
    requests = [(r.get('name'), params(r)) for r in children(sublist(output, 'History'))]
    reaction_sets = params(output).get('Reaction Node Sets', '{}').strip('{}').replace(' ', '').split(',')
    forces = [params(f) for f in children(sublist(problem, 'Nodal Forces'))]
    dirichlet = [params(d) for d in children(sublist(problem, 'Dirichlet Conditions'))]
    contacts = {c.get('name'): params(c) for c in children(sublist(problem, 'Contact'))}

    with open(os.path.join(out_dir, name + '.history.csv')) as f:
        rows = list(csv.DictReader(f))
    history = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    exo = netCDF4.Dataset(os.path.join(out_dir, name + '.exo'))
    dim = exo.dimensions['num_dim'].size
    axes = 'xyz'[:dim]
    coords = np.stack([exo.variables['coord' + a][:] for a in axes], axis=1)
    nodal = {n: exo.variables['vals_nod_var%d' % (i + 1)][:] for i, n in enumerate(names(exo, 'name_nod_var'))}
    glob = {n: exo.variables['vals_glo_var'][:, i] for i, n in enumerate(names(exo, 'name_glo_var'))}
    node_sets = {n: exo.variables['node_ns%d' % (i + 1)][:] - 1 for i, n in enumerate(names(exo, 'ns_names'))}
    steps = exo.dimensions['time_step'].size
    assert steps == len(rows) and steps > 1, f'{steps} Exodus steps, {len(rows)} history rows'
    # Mesh nodes: those of the solid blocks (the rigid surfaces' points follow them).
    blocks = [exo.variables['connect%d' % (k + 1)] for k in range(exo.dimensions['num_el_blk'].size)
              if 'connect%d' % (k + 1) in exo.variables]
    solids = [b for b in blocks if b.elem_type.upper() not in ('BAR2', 'SHELL4')]
    mesh_nodes = np.array(sorted({int(n) - 1 for b in solids for n in b[:].ravel()}))

    def nearest(candidates, point):
        d2 = ((coords[candidates] - np.array(point)) ** 2).sum(axis=1)
        return min(zip(d2, candidates))[1]

    def slave_nodes(side_set):
        # QUAD4 sides (Exodus numbering): side s joins corners s and s+1.
        k = names(exo, 'ss_names').index(side_set) + 1
        elements, sides = exo.variables['elem_ss%d' % k][:] - 1, exo.variables['side_ss%d' % k][:] - 1
        connect = np.concatenate([b[:] - 1 for b in solids])
        return np.array(sorted({int(connect[e][(s + j) % 4]) for e, s in zip(elements, sides) for j in (0, 1)}))

    checked = 0

    def expect(column, expected, scale, rtol=1e-12, csv_rtol=1e-11):
        nonlocal checked
        got = glob[column]
        tol = rtol * max(scale, 1e-300)
        bad = np.abs(got - expected) > tol
        assert not bad.any(), f'{column}: Exodus global {got[bad]} != {expected[bad]} (from the nodal fields; tol {tol})'
        bad = np.abs(history[column] - got) > csv_rtol * max(np.abs(got).max(), 1e-300)
        assert not bad.any(), f'{column}: history {history[column][bad]} != Exodus global {got[bad]}'
        checked += 1
        print(f'{column}: {steps} steps agree (largest |value| {np.abs(expected).max():.6g})')

    contact_force = {a: sum(history[c] for c in history if c.startswith('contact_force_') and c.endswith('_' + a))
                     for a in axes}
    for request, p in requests:
        base = request.replace(' ', '_').replace(',', '_')
        quantity = p.get('Quantity', 'Displacement')
        if quantity == 'Displacement':
            nodes = node_sets[p['Node Set']] if 'Node Set' in p else [nearest(mesh_nodes, p['Coordinates'])]
            for a in axes:
                values = nodal['displ_' + a][:, nodes].mean(axis=1)
                expect(f'{base}_{a}', values, np.abs(nodal['displ_' + a]).max())
        elif quantity in ('Contact Pressure', 'Contact Slip'):
            node = nearest(slave_nodes(contacts[p['Interface']]['Slave Side Set']), p['Coordinates'])
            field = nodal['contact_pressure' if quantity == 'Contact Pressure' else 'contact_slip']
            expect(base, field[:, node], np.abs(field).max())
        elif quantity == 'Applied Force':
            own = set(node_sets[p['Node Set']].tolist())
            for c, a in enumerate(axes):
                total = sum(f['Total Force'] * len(own & set(node_sets[f['Node Set']].tolist())) /
                            len(node_sets[f['Node Set']]) for f in forces if f.get('Component', 'x') == a)
                values = history['lambda'] * total
                expect(f'{base}_{a}', values, max(np.abs(values).max(), 1.0))
        elif quantity == 'Reaction Force':
            s = p['Node Set']
            if s not in reaction_sets:
                assert not any(c.startswith(f'reaction_{s}_') for c in history), f'reaction_{s}_* columns written'
            for a in axes:
                holders = {d['Node Set'] for d in dirichlet if d.get('Component', 'x') == a}
                if holders == {s}:
                    applied = history['lambda'] * sum(f['Total Force'] for f in forces if f.get('Component', 'x') == a)
                    expected = -(applied + contact_force[a])
                    expect(f'{base}_{a}', expected, 1.0, rtol=1e-7)  # the Newton tolerance
                elif s in reaction_sets:
                    expect(f'{base}_{a}', history[f'reaction_{s}_{a}'], np.abs(history[f'reaction_{s}_{a}']).max(),
                           rtol=1e-11)
                else:
                    print(f'{base}_{a}: no independent value (the set shares component {a} with {holders - {s}})')
    assert checked > 0
    print(f'{checked} history columns agree with the Exodus file over {steps} steps')


if __name__ == '__main__':
    main()
