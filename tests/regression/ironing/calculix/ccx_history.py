#!/usr/bin/python3
"""Writes CalculiX's reactions on the die's top (the *NODE PRINT totals of shallow_ironing.inp, in the .dat
file) as a history CSV with the columns check_ironing.py and plot_ironing.py read.

    ccx_history.py shallow_ironing.dat OUTPUT.csv

Columns: time (CalculiX's total time: the normalised time t, the press 0-1 and the slide 1-2),
reaction_die_top_x, reaction_die_top_y (N per mm of thickness: the mesh is one 1 mm layer).
"""
import re
import sys


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    rows = []
    lines = open(sys.argv[1]).read().splitlines()
    header = re.compile(r'total force \(fx,fy,fz\) for set DIE_TOP and time\s+(\S+)')
    for i, line in enumerate(lines):
        match = header.search(line)
        if not match:
            continue
        values = next(l for l in lines[i + 1:] if l.strip()).split()
        rows.append((float(match.group(1)), float(values[0]), float(values[1])))
    with open(sys.argv[2], 'w') as out:
        out.write('time,reaction_die_top_x,reaction_die_top_y\n')
        for row in rows:
            out.write('%.9g,%.9g,%.9g\n' % row)
    print('%d increments, t = %g to %g' % (len(rows), rows[0][0] if rows else 0, rows[-1][0] if rows else 0))
    return 0 if rows else 1


if __name__ == '__main__':
    sys.exit(main())
