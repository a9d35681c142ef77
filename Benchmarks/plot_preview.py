#!/usr/bin/python3
"""Draws `vissweep bench preview --json` output: each mode's relative MSE against converged Monte
Carlo over its frame time (log-log): Monte Carlo at 1/4/16/64 spp as a line, the preview as a point;
the modes that are no estimate of the radiance (emission-absorption, Phong, ambient occlusion) as
vertical lines at their frame times.

    /usr/bin/python3 Benchmarks/plot_preview.py RESULT.json OUT.png"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    result = json.load(open(sys.argv[1]))
    fig, ax = plt.subplots(figsize=(6, 4.2))
    mc = [m for m in result["modes"] if m["mode"].startswith("Monte Carlo") and "relative_mse" in m]
    ax.plot([m["frame_seconds"] for m in mc], [m["relative_mse"] for m in mc], "o-", label="Monte Carlo")
    for m in mc:
        ax.annotate(m["mode"].replace("Monte Carlo ", ""), (m["frame_seconds"], m["relative_mse"]),
                    textcoords="offset points", xytext=(4, 4), fontsize=7)
    for m in result["modes"]:
        if m["mode"] == "preview":
            ax.plot([m["frame_seconds"]], [m["relative_mse"]], "*", ms=12, label="preview")
        elif "relative_mse" not in m:
            ax.axvline(m["frame_seconds"], ls=":", lw=0.8, color="gray")
            ax.text(m["frame_seconds"], 1.0, " " + m["mode"], rotation=90,
                    fontsize=6, va="top", color="gray", transform=ax.get_xaxis_transform())
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("frame time (s; Monte Carlo: the whole accumulation)")
    ax.set_ylabel("relative MSE against %d spp" % result["reference_spp"])
    ax.set_title("%s at %d²" % (os.path.basename(result["scene"]), result["size"]), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
