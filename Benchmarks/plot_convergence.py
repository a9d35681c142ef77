#!/usr/bin/python3
"""Draws `vissweep bench convergence --json` output: error against time (or spp), log-log,
one line per strategy, the spread over repeats as error bars.

    /usr/bin/python3 Benchmarks/plot_convergence.py RESULT.json OUT.png [RESULT2.json ...]
(several JSON files: one panel each)."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def panel(ax, result):
    equal_spp = result["mode"] == "equal-spp"
    for name, s in result["strategies"].items():
        x = s["spp"] if equal_spp else s["seconds"]
        ax.errorbar(x, s["mse"], yerr=s["mse_spread"], marker="o", ms=3, capsize=2, label=name)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("samples per pixel" if equal_spp else "seconds (sweeps included)")
    ax.set_ylabel("MSE (linear radiance)")
    ref = result["reference"]
    ax.set_title("%s\nreference %d spp %s" % (os.path.basename(result["scene"]), ref["spp"], ref["strategy"]),
                 fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    inputs = [sys.argv[1]] + sys.argv[3:]
    results = [json.load(open(p)) for p in inputs]
    fig, axes = plt.subplots(1, len(results), figsize=(4.5 * len(results), 4), squeeze=False)
    for ax, r in zip(axes[0], results):
        panel(ax, r)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
