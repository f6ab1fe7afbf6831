#!/usr/bin/python3
"""rotate_deck.py DECK OUT MESH [--angle DEG] [--axis AX AY AZ] [--translate TX TY [TZ]] [--vector LOAD ...]

Writes OUT: the objectivity deck DECK (objectivity_2d.xml, objectivity_3d.xml) in the frame make_block_msh.py
writes MESH in: its mesh file MESH, every rigid-surface Points (positions: rotated, then translated) and every
Motion (displacements: rotated), as make_block_msh.py rotates (Rodrigues' formula, the axis through the origin;
2D about z). Its title and header comment say so."""
import argparse
import re

import numpy as np

from msh_frames import rotation

parser = argparse.ArgumentParser()
parser.add_argument("deck")
parser.add_argument("out")
parser.add_argument("mesh")
parser.add_argument("--angle", type=float, default=0.0)
parser.add_argument("--axis", type=float, nargs=3, default=[0.0, 0.0, 1.0])
parser.add_argument("--translate", type=float, nargs="+", default=[0.0, 0.0, 0.0])
parser.add_argument("--vector", action="append", default=[], help="a load whose load-step values are vectors to rotate")
args = parser.parse_args()
R = rotation(args.angle, args.axis)
shift = np.array((list(args.translate) + [0.0, 0.0])[:3])
text = open(args.deck).read()
dim = 3 if "Facets" in text or "Traction" in text and "Spring" in text else 2  # the decks this writes
if '"Traction" type="Array(double)" value="{' in text:
    dim = len(re.search(r'"Traction" type="Array\(double\)" value="\{([^}]*)\}"', text).group(1).split(","))


def transform(match, is_point):
    values = [float(v) for v in match.group(2).split(",")]
    out = []
    for i in range(0, len(values), dim):
        p = np.array(values[i:i + dim] + [0.0] * (3 - dim))
        q = R @ p + (shift if is_point else 0.0)
        out += [repr(float(c)) for c in q[:dim]]
    return match.group(1) + "{" + ", ".join(out) + "}" + match.group(3)


text = re.sub(r'(name="Points" type="Array\(double\)" value=")\{([^}]*)\}(")', lambda m: transform(m, True), text)
text = re.sub(r'(name="Motion" type="Array\(double\)" value=")\{([^}]*)\}(")', lambda m: transform(m, False), text)
for load in args.vector:  # a Traction and its load steps' end values
    text = re.sub(r'(name="(?:Traction|%s)" type="Array\(double\)" value=")\{([^}]*)\}(")' % re.escape(load),
                  lambda m: transform(m, False), text)
text = re.sub(r'(name="File Name" type="string" value=")[^"]*(")', lambda m: m.group(1) + args.mesh + m.group(2), text)
frame = f"rotated by {args.angle:g} degrees about ({', '.join(f'{a:g}' for a in args.axis)}) and translated by " \
        f"({', '.join(f'{c:g}' for c in args.translate)})"
text = re.sub(r'(name="Title" type="string" value=")([^"]*)(")', lambda m: m.group(1) + m.group(2) + ", " + frame + m.group(3),
              text, count=1)
command = " ".join(["rotate_deck.py", args.deck, args.out, args.mesh, "--angle", f"{args.angle:g}", "--axis"]
                   + [f"{a:g}" for a in args.axis] + ["--translate"] + [f"{c:g}" for c in args.translate])
command += "".join(f" --vector '{v}'" for v in args.vector)
text = text.replace("<!--\n", f"<!--\n  Written by {command}: {args.deck} {frame}.\n", 1)
open(args.out, "w").write(text)
