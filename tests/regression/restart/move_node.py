#!/usr/bin/python3
"""move_node.py MESH.exo: moves the mesh's middle node by 1 % of the x extent in x (in place), so the mesh
keeps its node and element counts but no longer matches a restart file written with it."""
import sys

import netCDF4

with netCDF4.Dataset(sys.argv[1], "r+") as mesh:
    x = mesh.variables["coordx"]
    values = x[:]
    middle = len(values) // 2
    values[middle] += 0.01 * (values.max() - values.min())
    x[:] = values
