#!/usr/bin/env python3
"""The cost of the surface lobe and of VTK's lights per path (issue 38): `vissweep bench overhead` on
mri_sunrise (Benchmarks/scenes/mri_sunrise.json) with shading off and on, and with 0, 1 and 4 lights,
Environment sampling; the variants alternate within each round (so a machine whose speed drifts
slows them alike) and the ratios of time per path (and per scattering event) to the plain scene are
taken within a round, their median over the rounds printed. From the repository's root:

    /usr/bin/python3 Benchmarks/light_overhead.py --vissweep build/bin/vissweep --rounds 3
"""
import argparse
import copy
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
FOCAL = [90, 125, 68]
LIGHTS = [
    {"type": "directional", "direction": [-1.3, 0.58, 0.5], "focal_point": FOCAL, "intensity": 1.5},
    {"type": "directional", "direction": [1, 1, -0.2], "focal_point": FOCAL, "intensity": 0.3},
    {"type": "spot", "position": [90, 400, 200], "focal_point": FOCAL, "cone_angle": 25, "exponent": 2,
     "intensity": 1.0},
    {"type": "positional", "position": [250, 250, 150], "focal_point": FOCAL, "intensity": 0.5},
]
VARIANTS = [("plain (shade off, 0 lights)", False, 0), ("shade on", True, 0), ("1 light", False, 1),
            ("4 lights", False, 4), ("shade on, 4 lights", True, 4)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--vissweep", default=os.path.join(ROOT, "build", "bin", "vissweep"))
    ap.add_argument("--scene", default=os.path.join(ROOT, "Benchmarks", "scenes", "mri_sunrise.json"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--spp", type=int, default=4)
    args = ap.parse_args()
    base = json.load(open(args.scene))
    folder = os.path.dirname(os.path.abspath(args.scene))
    env = base["environment"]
    env["file"] = os.path.normpath(os.path.join(folder, env["file"]))
    tmp = tempfile.mkdtemp(prefix="vissweep-light-overhead-")
    scenes = []
    for name, shade, lights in VARIANTS:
        scene = copy.deepcopy(base)
        scene["transfer_function"]["shade"] = shade
        if lights:
            scene["lights"] = LIGHTS[:lights]
        path = os.path.join(tmp, "variant%d.json" % len(scenes))
        json.dump(scene, open(path, "w"))
        scenes.append(path)
    per_path = {name: [] for name, _, _ in VARIANTS}
    per_event = {name: [] for name, _, _ in VARIANTS}
    for r in range(args.rounds):
        figures = {}
        for (name, _, _), path in zip(VARIANTS, scenes):
            out = os.path.join(tmp, "out.json")
            subprocess.run([args.vissweep, "bench", "overhead", path, "--strategies", "environment", "--no-cell-modes",
                            "--width", str(args.size), "--height", str(args.size), "--spp", str(args.spp),
                            "--repeats", "3", "--json", out], check=True, stdout=subprocess.DEVNULL)
            m = json.load(open(out))["strategies"][0]
            figures[name] = (m["paths_per_second"], m["scattering_events_per_path"])
            print("round %d  %-28s %10.0f paths/s  %.2f events/path" % (r + 1, name, *figures[name]), flush=True)
        plain_pps, plain_events = figures[VARIANTS[0][0]]
        for name, (pps, events) in figures.items():
            per_path[name].append(plain_pps / pps)
            per_event[name].append((plain_pps * plain_events) / (pps * events))
    print("\ntime per path and per scattering event against the plain scene (median of %d alternated rounds):"
          % args.rounds)
    for name, _, _ in VARIANTS:
        print("  %-28s per path %.2fx (%s)   per event %.2fx" % (
            name, statistics.median(per_path[name]), ", ".join("%.2f" % v for v in per_path[name]),
            statistics.median(per_event[name])))


if __name__ == "__main__":
    sys.exit(main())
