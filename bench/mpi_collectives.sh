#!/usr/bin/env bash
# Counts the MPI collectives and the bytes a Contessa run moves, per rank: builds bench/mpi_call_count.c
# (a PMPI library) with mpicc into a temporary directory and runs the command under LD_PRELOAD. Each rank
# prints at MPI_Finalize, on stderr: mpi_call_count rank R: allreduce=CALLS/BYTES reduce=... send=...
# Usage: bench/mpi_collectives.sh RANKS DECK [contessa arguments...]
#   bench/mpi_collectives.sh 2 inputs/punch_3d.xml --set "Problem/Mesh/Elements X=20" ...
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ranks="$1"; shift
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mpicc -O2 -shared -fPIC -o "$work/libmpi_call_count.so" "$root/bench/mpi_call_count.c"
mpiexec --oversubscribe --allow-run-as-root -n "$ranks" -x LD_PRELOAD="$work/libmpi_call_count.so" \
  "$root/build/bin/contessa" "$@" --output-dir "$work/out" 2>&1 | grep -E "^mpi_call_count|summary"
