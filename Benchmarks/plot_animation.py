#!/usr/bin/python3
"""Draws `vissweep bench animation --json` output: per-frame MSE against the time step, one
line per method (log scale), and the update seconds per frame below it.

    /usr/bin/python3 Benchmarks/plot_animation.py RESULT.json OUT.png"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    r = json.load(open(sys.argv[1]))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 6), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    for m in r["methods"]:
        steps = [f["time_step"] for f in m["frames"]]
        top.plot(steps, [f["mse"] for f in m["frames"]], marker="o", ms=3, label=m["method"])
        bottom.plot(steps, [f["update_seconds"] for f in m["frames"]], marker="o", ms=3, label=m["method"])
    top.set_yscale("log")
    top.set_ylabel("MSE (linear radiance)")
    top.set_title("%s, %.2g s per frame, reference %d spp" % (os.path.basename(r["scene"]),
                  r["budget_per_frame_seconds"], r["reference_spp"]), fontsize=8)
    top.grid(True, which="both", alpha=0.3)
    top.legend(fontsize=7)
    bottom.set_ylabel("update seconds")
    bottom.set_xlabel("time step")
    bottom.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
