#!/bin/sh
# Regenerates the committed meshes of the shallow ironing benchmark (Gmsh 4.8, apt package gmsh) from
# shallow_ironing.geo: the verification mesh and the coarse one of the regression test
# (docs/verification-contact.md, "Shallow ironing").
set -e
cd "$(dirname "$0")"
g() { out=$1; shift; gmsh -v 0 -2 "$@" -format msh41 shallow_ironing.geo -o "$out"; }
g shallow_ironing.msh -setnumber nx 120 -setnumber ny 20 -setnumber grade 6 -setnumber na 24 -setnumber nd 10
g shallow_ironing_coarse.msh -setnumber nx 60 -setnumber ny 10 -setnumber grade 6 -setnumber na 12 -setnumber nd 5
