#!/bin/sh
# Regenerates the committed Gmsh meshes of GmshTest.cpp (Gmsh 4.8, apt package gmsh) in this directory.
set -e
cd "$(dirname "$0")"
g() { out=$1; geo=$2; shift 2; gmsh -v 0 "$@" -format msh41 "$geo" -o "$out"; }
g two_blocks.msh two_blocks.geo -3
g tet4.msh solid3d.geo -3 -setnumber kind 0 -setnumber order 1
g tet10.msh solid3d.geo -3 -setnumber kind 0 -setnumber order 2
g hex20.msh solid3d.geo -3 -setnumber kind 1 -setnumber order 2 -setnumber incomplete 1
g hex27.msh solid3d.geo -3 -setnumber kind 1 -setnumber order 2 -setnumber incomplete 0
g hex8_wedge6.msh solid3d.geo -3 -setnumber kind 2 -setnumber order 1
g hex20_wedge15.msh solid3d.geo -3 -setnumber kind 2 -setnumber order 2 -setnumber incomplete 1
g quad4_tri3.msh plane2d.geo -2 -setnumber order 1
g quad8_tri6.msh plane2d.geo -2 -setnumber order 2 -setnumber incomplete 1
g quad9_tri6.msh plane2d.geo -2 -setnumber order 2 -setnumber incomplete 0
