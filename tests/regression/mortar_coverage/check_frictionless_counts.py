#!/usr/bin/python3
"""check_frictionless_counts.py HISTORY.csv [HISTORY.csv ...]

Issue 25, point 4: a frictionless interface's closed nodes are neither sticking nor slipping. In every row
of every history the `stick` and `slip` counts are 0, and the run closed nodes (active_contacts > 0 in its
last row), so the zeros are not those of an open interface. Exit 0 when every history passes."""
import csv
import sys


def check(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return [f"{path}: no rows"]
    failures = [f"{path}: step {r['step']}: stick {r['stick']}, slip {r['slip']} with {r['active_contacts']} closed"
                for r in rows if float(r["stick"]) != 0 or float(r["slip"]) != 0]
    if float(rows[-1]["active_contacts"]) <= 0:
        failures.append(f"{path}: no node closed at the end")
    print(f"{path}: {len(rows)} rows, {rows[-1]['active_contacts']} nodes closed at the end, "
          f"{len(failures)} failure(s)")
    return failures


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    failures = [f for path in sys.argv[1:] for f in check(path)]
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
