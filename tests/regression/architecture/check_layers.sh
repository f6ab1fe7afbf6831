#!/bin/sh
# check_layers.sh PACKAGES: the layering contracts of docs/architecture.md that a change can break without a
# failing answer (issue 18): (1) no header of solvers/ includes a deck, mesh, mechanics or contact header
# (solvers see the Thyra model evaluator and small interfaces only); (2) the continuation driver loop says
# "ContactBeta" nowhere (a step-size method adds what it needs through its registry row). Prints every
# offending line and exits 1 when there is one.
packages=${1:?usage: check_layers.sh PACKAGES_DIR}
status=0
if grep -nE '#include[[:space:]]+"(deck|mesh|mechanics|contact)/' "$packages"/solvers/*.hpp; then
  echo "FAIL: a solvers/ header includes a deck, mesh, mechanics or contact header (above)"
  status=1
fi
loop="ContinuationDriver IncrementBookkeeper StopMessage NewtonStatusTests ContinuationRestart LocaResume StaticSolveDriver StepControlRelay"
for name in $loop; do
  for file in "$packages/solvers/$name.hpp" "$packages/solvers/$name.cpp" "$packages/solvers/StepControl.hpp"; do
    [ -f "$file" ] || continue
    if grep -n "ContactBeta" "$file"; then
      echo "FAIL: $file names ContactBeta: the driver loop must not know the step-size method"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "ok: solvers/ headers include no deck, mesh, mechanics or contact header; the driver loop names no step-size method"
exit $status
