#!/usr/bin/env bash
# The paper's tube benchmark (Vulovic et al., section 6): runs inputs/tube_bending.xml twice,
#   OUTPUT_DIR/beta   Contact Beta, N_c = 2 (the deck as it stands)
#   OUTPUT_DIR/fixed  fixed 1.6 mm steps (Method=Constant, 47 increments)
# prints both increment tables, draws the figures (scripts/plot_tube.py) into OUTPUT_DIR and prints a
# short comparison. Exits non-zero if a run or the plotting fails.
#
#   scripts/run_tube_benchmark.sh [OUTPUT_DIR]     (default: results/tube, relative to the repository)
#
# Needs build/bin/contessa (scripts/build.sh) and /usr/bin/python3 with matplotlib, numpy, netCDF4.
# About 20 s on one core.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CONTESSA="$ROOT/build/bin/contessa"
DECK="$ROOT/inputs/tube_bending.xml"
PYTHON=/usr/bin/python3

if [[ $# -gt 1 || "${1:-}" == "-h" || "${1:-}" == "--help" ]]; then
  sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  [[ $# -gt 1 ]] && exit 2 || exit 0
fi

OUT="${1:-$ROOT/results/tube}"
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

if [[ ! -x "$CONTESSA" ]]; then
  echo "run_tube_benchmark.sh: $CONTESSA not found; build it first with scripts/build.sh" >&2
  exit 2
fi

# run LABEL DIR [contessa options...]: the log goes to the terminal and to DIR/contessa.log.
run() {
  local label="$1" dir="$2"
  shift 2
  mkdir -p "$dir"
  echo
  echo "=== $label ==="
  local shown=""
  [[ $# -gt 0 ]] && shown="$(printf ' %q' "$@")"
  echo "+ build/bin/contessa inputs/tube_bending.xml --output-dir $dir$shown"
  local status=0
  "$CONTESSA" "$DECK" --output-dir "$dir" "$@" 2>&1 | tee "$dir/contessa.log" || status=$?
  if [[ $status -ne 0 ]]; then
    echo "run_tube_benchmark.sh: the $label run failed (contessa exit status $status); log: $dir/contessa.log" >&2
    exit "$status"
  fi
}

run "Contact Beta, N_c = 2" "$OUT/beta"
run "fixed step, 47 x 1.6 mm" "$OUT/fixed" \
  --set "Piro/LOCA/Step Size/Method=Constant" \
  --set "Problem/Regression/increments/Expected=47"

echo
echo "=== figures ==="
"$PYTHON" "$ROOT/scripts/plot_tube.py" "$OUT/beta" "$OUT/fixed" "$OUT"

echo
echo "=== tube benchmark: results in $OUT ==="
echo "  Contact Beta: $OUT/beta/tube_bending.exo, .history.csv, contessa.log"
echo "  fixed step:   $OUT/fixed/tube_bending.exo, .history.csv, contessa.log"
echo "  figures:      $OUT/tube_step_size.png tube_reaction.png tube_deformed.png tube_contacts.png"
"$PYTHON" - "$OUT/beta" "$OUT/fixed" <<'EOF'
import csv, re, sys

def summary(d):
    with open(f"{d}/tube_bending.history.csv", newline="") as f:
        last = list(csv.DictReader(f))[-1]
    m = re.search(r"finished after (\d+) increments \((\d+) failed attempts\), (\d+) Newton iterations",
                  open(f"{d}/contessa.log").read())
    return int(last["step"]), int(m.group(2)), int(m.group(3)), -float(last["contact_force_plate_y"])

b, f = summary(sys.argv[1]), summary(sys.argv[2])
print(f"  {'':14s}{'increments':>11s}{'failed att.':>12s}{'Newton it.':>11s}{'plate force [N/mm]':>20s}")
print(f"  {'Contact Beta':14s}{b[0]:11d}{b[1]:12d}{b[2]:11d}{b[3]:20.5f}")
print(f"  {'fixed step':14s}{f[0]:11d}{f[1]:12d}{f[2]:11d}{f[3]:20.5f}"
      f"   (relative difference {abs(b[3] - f[3]) / abs(f[3]):.1e}; paper: 47 fixed, 32 with N_c = 2)")
EOF
