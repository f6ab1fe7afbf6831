#!/bin/sh
# element_kernel_callgrind.sh [BENCH] [ELEMENT...]: instructions per element evaluation of the solid element kernels,
# counted by valgrind's callgrind on one run of element_kernel_bench's workload (--once): unlike wall
# time, the count does not depend on the load of the machine. Prints one line per element and material:
# instructions per residual evaluation and per Jacobian (force + tangent) evaluation.
# Needs valgrind (Debian package valgrind); takes about a minute for the default four elements (Q4, Q4
# Enhanced, Hex8, Hex8 Enhanced); name others after BENCH (e.g. Tet10 Hex20: the quadratic hexahedra take
# several minutes each).
set -eu
BENCH=${1:-build/bin/element_kernel_bench}
[ $# -gt 0 ] && shift
[ $# -eq 0 ] && set -- "Q4" "Q4 Enhanced" "Hex8" "Hex8 Enhanced"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
printf '%-14s %-24s %16s %16s\n' element material "residual Ir/el" "jacobian Ir/el"
for element in "$@"; do
  for material in "Saint Venant-Kirchhoff" "Neo-Hookean"; do
    out=""
    for pass in residualPass jacobianPass; do
      log=$("$BENCH" --case "$element" "$material" --once)
      case $pass in
        residualPass) evals=$(echo "$log" | sed -n 's/.*one run: \([0-9]*\) residual.*/\1/p') ;;
        jacobianPass) evals=$(echo "$log" | sed -n 's/.* and \([0-9]*\) Jacobian.*/\1/p') ;;
      esac
      valgrind --tool=callgrind --collect-atstart=no "--toggle-collect=*$pass*" \
        --callgrind-out-file="$TMP/cg.out" "$BENCH" --case "$element" "$material" --once >/dev/null 2>"$TMP/log"
      total=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p' "$TMP/cg.out")
      out="$out $(awk -v t="$total" -v n="$evals" 'BEGIN { printf "%16.0f", t / n }')"
    done
    printf '%-14s %-24s%s\n' "$element" "$material" "$out"
  done
done
