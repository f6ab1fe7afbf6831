#!/usr/bin/python3
"""check_contact_sequence.py HISTORY.csv --nc N [options]

Checks the history of inputs/verification/contact_sequence.xml run with Contact Beta (reference paper,
section 2.1): a tilted rigid flat closes the block's top nodes one by one, node k (vertical gap
g_k = gap0 + k * gap_step) at the load factor lambda_k = g_k / travel if the block did not deform.

Checked, row by row (row 0 is the initial state):
  * no contact is lost: active_contacts[i] = active_contacts[i-1] + new_contacts[i];
  * exactly N_c nodes close in every increment while at least N_c remain open, and all that remain in
    the increment that has fewer than N_c left: new_contacts[i] = min(N_c, slaves - active[i-1]);
    once all are closed, 0;
  * the run reaches the end: the last lambda is --final-lambda, and every slave node is in contact;
  * the order and loads are the hand-computed ones: active_contacts[i] = #{k : lambda_k <= lambda[i]},
    with lambda[i] at least --margin (a fraction of the spacing) away from every lambda_k;
  * --fraction f: every increment but the last ends at lambda_{a-1} + f (lambda_a - lambda_{a-1}), where
    a = active_contacts[i] (the "Next Contact Fraction" of the deck), to --placement-tol;
  * --equilibrium: every converged increment is in equilibrium: |reaction_Y + contact_force_Y| and
    residual_norm below --equilibrium-tol (the contact force on the flat balances the support).
Prints one line per failure ("FAIL: increment i: ...") and exits 1 if any."""
import argparse
import csv
import sys

parser = argparse.ArgumentParser()
parser.add_argument("history")
parser.add_argument("--nc", type=int, required=True, help="Contacts Per Step N_c")
parser.add_argument("--slaves", type=int, default=11, help="number of slave (top) nodes")
parser.add_argument("--gap0", type=float, default=0.01, help="vertical gap of the first node to close")
parser.add_argument("--gap-step", type=float, default=0.01, help="gap increase from node to node")
parser.add_argument("--travel", type=float, default=0.12, help="downward motion of the flat at lambda = 1")
parser.add_argument("--final-lambda", type=float, default=1.0)
parser.add_argument("--margin", type=float, default=0.05,
                    help="smallest |lambda_i - lambda_k| allowed, as a fraction of the spacing of lambda_k")
parser.add_argument("--fraction", type=float, default=None, help="check the placement of the increments")
parser.add_argument("--placement-tol", type=float, default=1e-4, help="absolute, in lambda")
parser.add_argument("--equilibrium", action="store_true")
parser.add_argument("--equilibrium-tol", type=float, default=1e-8)
parser.add_argument("--reaction", default="reaction_bottom_y")
parser.add_argument("--contact-force", default="contact_force_flat_y")
args = parser.parse_args()

rows = list(csv.DictReader(open(args.history)))
if len(rows) < 2:
    sys.exit(f"FAIL: {args.history}: no converged increment")

closing = [(args.gap0 + k * args.gap_step) / args.travel for k in range(args.slaves)]  # lambda_k
spacing = args.gap_step / args.travel
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


previous_active = int(rows[0]["active_contacts"])
if previous_active != 0 or float(rows[0]["lambda"]) != 0.0:
    fail(f"row 0 is not the initial state without contact: {rows[0]}")
last = len(rows) - 1
for i in range(1, len(rows)):
    r = rows[i]
    lam = float(r["lambda"])
    active, new = int(r["active_contacts"]), int(r["new_contacts"])
    if active != previous_active + new:
        fail(f"increment {i}: active_contacts {active} != {previous_active} before + {new} new (a contact was lost)")
    expected_new = min(args.nc, args.slaves - previous_active)
    if new != expected_new:
        fail(f"increment {i} (lambda = {lam:.6f}): {new} new contacts, expected {expected_new} "
             f"(N_c = {args.nc}, {args.slaves - previous_active} open before)")
    predicted = sum(1 for lk in closing if lk <= lam)
    if active != predicted:
        fail(f"increment {i}: {active} nodes in contact at lambda = {lam:.6f}, the hand-computed "
             f"lambda_k give {predicted}")
    nearest = min(abs(lam - lk) for lk in closing)
    if nearest < args.margin * spacing and i != last:
        fail(f"increment {i}: lambda = {lam:.6f} is within {nearest:.2e} of a closing load (margin "
             f"{args.margin * spacing:.2e}): the count would be decided by the deformation, not the gaps")
    if args.fraction is not None and i != last and 0 < active < args.slaves:
        target = closing[active - 1] + args.fraction * (closing[active] - closing[active - 1])
        if abs(lam - target) > args.placement_tol:
            fail(f"increment {i}: lambda = {lam:.8f}, expected {target:.8f} (node {active - 1} closed, "
                 f"{args.fraction} of the way to node {active})")
    if args.equilibrium:
        imbalance = abs(float(r[args.reaction]) + float(r[args.contact_force]))
        residual = float(r["residual_norm"])
        if imbalance > args.equilibrium_tol or residual > args.equilibrium_tol:
            fail(f"increment {i}: not in equilibrium: |{args.reaction} + {args.contact_force}| = "
                 f"{imbalance:.3e}, residual_norm = {residual:.3e} (> {args.equilibrium_tol:g}); "
                 f"{r['newton_iterations']} Newton iteration(s), {r['attempts']} attempt(s)")
    previous_active = active

final_lambda = float(rows[last]["lambda"])
if abs(final_lambda - args.final_lambda) > 1e-12:
    fail(f"the run stopped at lambda = {final_lambda}, not {args.final_lambda}")
if previous_active != args.slaves:
    fail(f"{previous_active} nodes in contact at the end, expected all {args.slaves}")

print(f"{args.history}: {last} increments, N_c = {args.nc}, new contacts "
      f"{[int(r['new_contacts']) for r in rows[1:]]}, final lambda {final_lambda:g}, "
      f"{previous_active} of {args.slaves} nodes in contact: " + ("FAILED" if failures else "OK"))
sys.exit(1 if failures else 0)
