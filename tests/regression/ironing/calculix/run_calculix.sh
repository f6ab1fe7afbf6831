#!/bin/sh
# Runs the shallow ironing benchmark in CalculiX on one of Contessa's meshes (docs/verification-contact.md §8,
# "CalculiX on the same mesh"):
#   run_calculix.sh [MESH.msh [OUTDIR [DECK.inp]]]
# MESH defaults to inputs/verification/shallow_ironing_coarse.msh, OUTDIR to ./ironing-calculix, DECK to
# shallow_ironing.inp beside this script. Writes OUTDIR/mesh.inp (msh_to_ccx.py), runs ccx (Debian package
# calculix-ccx, 2.20) on one thread, and writes OUTDIR/shallow_ironing.history.csv (ccx_history.py), which
# tests/regression/ironing/check_ironing.py and plot_ironing.py read. Exit status: ccx's.
set -e
here=$(cd "$(dirname "$0")" && pwd)
mesh=${1:-$here/../../../../inputs/verification/shallow_ironing_coarse.msh}
out=${2:-ironing-calculix}
deck=${3:-$here/shallow_ironing.inp}
command -v ccx > /dev/null || { echo "run_calculix.sh: ccx not found (apt package calculix-ccx)" >&2; exit 2; }
mkdir -p "$out"
/usr/bin/python3 "$here/msh_to_ccx.py" "$mesh" "$out/mesh.inp"
cp "$deck" "$out/shallow_ironing.inp"
cd "$out"
status=0
OMP_NUM_THREADS=1 ccx -i shallow_ironing > ccx.log 2>&1 || status=$?
/usr/bin/python3 "$here/ccx_history.py" shallow_ironing.dat shallow_ironing.history.csv || true
exit $status
