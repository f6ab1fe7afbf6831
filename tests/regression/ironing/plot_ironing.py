#!/usr/bin/python3
"""Plots shallow ironing runs against the five published codes' reaction curves.

    plot_ironing.py OUTPUT.png HISTORY.csv[=LABEL] [HISTORY.csv[=LABEL] ...]

Vertical (solid) and horizontal (dashed) reactions on the die's top against the normalised time
(0-1 the press, 1-2 the slide), the published curves thin and coloured (ironing_reference.py names the
sources), the Contessa runs thick and dark, and the spread checked by check_ironing.py marked at t = 1.0
and 1.5. Makes docs/figures/shallow_ironing.png (docs/verification-contact.md, "Shallow ironing").
"""
import sys

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

from ironing_reference import contessa_history, published_spread, reference_curves  # noqa: E402

REFERENCE_COLOURS = ['tab:red', 'tab:blue', 'tab:green', 'tab:orange', 'tab:cyan']
RUN_STYLES = [('black', 2.2), ('tab:purple', 1.6), ('tab:brown', 1.6), ('tab:gray', 1.6)]


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    output, runs = sys.argv[1], sys.argv[2:]
    curves = reference_curves()
    fig, ax = plt.subplots(figsize=(10, 6.5))
    for (label, (tv, v, th, h)), colour in zip(curves.items(), REFERENCE_COLOURS):
        ax.plot(tv, v, color=colour, lw=0.9, label=label)
        ax.plot(th, h, color=colour, lw=0.9, ls='--')
    for run, (colour, width) in zip(runs, RUN_STYLES):
        path, _, label = run.partition('=')
        t, vertical, horizontal = contessa_history(path)
        ax.plot(t, vertical, color=colour, lw=width, label=label or 'Contessa')
        ax.plot(t, horizontal, color=colour, lw=width, ls='--')
    for time in (1.0, 1.5):
        v_min, v_max, h_min, h_max = published_spread(time, curves)
        for low, high in ((v_min, v_max), (h_min, h_max)):
            ax.plot([time, time], [low, high], color='0.3', lw=5, alpha=0.25, solid_capstyle='butt')
    ax.set_xlim(0, 2)
    ax.set_ylim(0, 450)
    ax.set_xlabel('normalised time (0-1: press 1 mm, 1-2: slide 10 mm)')
    ax.set_ylabel('reaction on the die (N per mm thickness)')
    ax.set_title('Shallow ironing: vertical (solid) and horizontal (dashed) reactions; grey bars: '
                 'published spread at t = 1.0, 1.5', fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc='upper left', fontsize=9)
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    return 0


if __name__ == '__main__':
    sys.exit(main())
