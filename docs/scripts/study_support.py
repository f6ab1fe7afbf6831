"""What the contact study scripts share: the repository root, the result readers of the contact
regression tests (tests/regression/contact/contact_results.py, as `cr`), matplotlib drawing to files,
the options every study takes and one run of a deck."""
import argparse
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "regression", "contact"))
import contact_results as cr  # noqa: E402,F401  (for the studies)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (for the studies)


def study_arguments(doc, name):
    """An argument parser with the options every study takes: the binary, the work directory
    (/tmp/contessa_<name>_study) and the figures' directory (docs/figures); the caller adds its own."""
    parser = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--contessa", default=os.path.join(ROOT, "build", "bin", "contessa"))
    parser.add_argument("--work", default=f"/tmp/contessa_{name}_study")
    parser.add_argument("--figures", default=os.path.join(ROOT, "docs", "figures"))
    return parser


def run_deck(contessa, deck, out, sets):
    """`contessa deck --quiet --output-dir out --set ...`; the finished process (its output captured)."""
    command = [contessa, deck, "--quiet", "--output-dir", out]
    for s in sets:
        command += ["--set", s]
    return subprocess.run(command, capture_output=True, text=True)


def save_figure(fig, figures, name, dpi=120):
    """Lays out FIG, writes it to the figures' directory as NAME and says so."""
    fig.tight_layout()
    os.makedirs(figures, exist_ok=True)
    fig.savefig(os.path.join(figures, name), dpi=dpi)
    print(f"\nwrote {figures}/{name}")
