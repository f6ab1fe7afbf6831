#!/usr/bin/python3
"""Contact Beta delivers N_c counted events per increment (docs/theory-load-stepping.md section 11).

Reads a history CSV and checks that `new_events` equals N_c in at least --share of the increments,
except the last one (it closes what is left) and increments whose step is the Max Step Size bound
(the user's bound, not beta, set them: beta asked for more). Prints the events per increment.

    check_events_per_increment.py HISTORY.csv --nc N [--share 0.9] [--max-step 0.25]
"""
import argparse
import csv
import sys


def main():
    p = argparse.ArgumentParser()
    p.add_argument("history")
    p.add_argument("--nc", type=int, required=True)
    p.add_argument("--share", type=float, default=0.9)
    p.add_argument("--max-step", type=float, default=0.25)
    a = p.parse_args()
    with open(a.history, newline="") as f:
        rows = list(csv.DictReader(f))[1:]  # row 0 is the initial state
    if not rows or abs(float(rows[-1]["lambda"]) - 1.0) > 1e-12:
        sys.exit("FAIL: the run did not reach load factor 1")
    events = [int(r["new_events"]) for r in rows]
    counted = [e for r, e in zip(rows[:-1], events[:-1]) if float(r["dlambda"]) < a.max_step * (1 - 1e-9)]
    exact = sum(1 for e in counted if e == a.nc)
    print(f"N_c = {a.nc}: {len(rows)} increments, new events per increment {events}")
    print(f"exactly N_c in {exact} of {len(counted)} counted increments "
          f"(last and Max Step Size increments excepted)")
    if not counted or exact < a.share * len(counted):
        sys.exit(f"FAIL: exactly N_c in {exact} of {len(counted)} increments, fewer than {a.share:.0%}")
    print("ok")


if __name__ == "__main__":
    main()
