"""The demo's image (issue 39): render_brain.py with scripts/demo.sh's render flags (read from it; at
128^2 instead of 384^2 to keep the suite short, and at least 20 s of budget: see below) writes the estimate, past the hand-over from the preview
(it says so: the preview's share is below 0.05, then 0), and the image has no periodic pattern: the
power spectrum of its difference from a render of more samples (no preview) has no peak far above its
neighbours (the fixed offsets of the preview drew a moire of curved bands; noise has a flat spectrum).
The detector itself is checked: the same difference with a faint periodic pattern added (a quarter of the
noise's standard deviation) is flagged.

When demo.sh renders with --denoise (the display's filter guided by the preview, DisplayDenoise), what this
checks is the image the demo writes: the estimate past the hand-over, shown through the filter (the
script says both), and the spectral test then applies to the filtered image's difference from the plain
estimate of more samples: a pattern the filter copied from its guide (the preview's offsets) would peak
there. The reference is never filtered."""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
import vtk
from vtkmodules.util.numpy_support import vtk_to_numpy

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "Examples", "Python", "render_brain.py")


def demo_flags():
    """The render flags of scripts/demo.sh's render_brain.py call, as a dict."""
    text = open(os.path.join(ROOT, "scripts", "demo.sh")).read()
    call = text[text.index("render_brain.py"):]
    call = call[:call.index("\nt3=")] if "\nt3=" in call else call
    flags = {}
    for name in ("rotation", "strategy", "spp", "seconds"):
        m = re.search(r"--%s\s+(\S+)" % name, call)
        if not m:
            raise SystemExit(f"scripts/demo.sh's render call has no --{name}")
        flags[name] = m.group(1)
    flags["preview-first"] = "--preview-first" in call
    flags["denoise"] = "--denoise" in call
    return flags


def render(volume, output, args):
    cmd = [sys.executable, SCRIPT, "--volume", volume, "--output", output, "--size", "128"] + args
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    sys.stdout.write(r.stdout)
    if r.returncode != 0:
        sys.stderr.write(r.stderr)
        raise SystemExit(f"render_brain.py failed ({r.returncode})")
    return r.stdout


def load(path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    img = reader.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).astype(np.float64)
    return a.reshape(h, w, -1)[:, :, :3]


def largest_peak(diff):
    """The largest ratio of a frequency's power to the median power of its 7x7 neighbourhood, over the
    spectrum without its lowest frequencies (|k| <= 2: the bias's smooth part). Periodograms of the
    four quadrants and the channels averaged (Welch), so that noise's ratios stay near 1."""
    h, w, c = diff.shape
    hh, hw = h // 2, w // 2
    window = np.outer(np.hanning(hh), np.hanning(hw))
    power = np.zeros((hh, hw))
    for y0 in (0, hh):
        for x0 in (0, hw):
            for k in range(c):
                block = diff[y0:y0 + hh, x0:x0 + hw, k]
                block = (block - block.mean()) * window
                power += np.abs(np.fft.fft2(block)) ** 2
    power = np.fft.fftshift(power)
    cy, cx = hh // 2, hw // 2
    worst = 0.0
    where = None
    r = 3
    for y in range(r, hh - r):
        for x in range(r, hw - r):
            if abs(y - cy) <= 2 and abs(x - cx) <= 2:
                continue
            around = np.median(power[y - r:y + r + 1, x - r:x + r + 1])
            if around > 0 and power[y, x] / around > worst:
                worst = power[y, x] / around
                where = (y - cy, x - cx)
    return worst, where


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", required=True)
    ap.add_argument("--baseline", required=False)
    ap.add_argument("--output", required=True)
    a = ap.parse_args()
    flags = demo_flags()
    print("demo.sh's render flags:", flags)
    if not flags["preview-first"]:
        raise SystemExit("the demo no longer starts from the preview: this test checks its hand-over")
    out = tempfile.mkdtemp(dir=a.output if os.path.isdir(a.output) else None)
    demo = os.path.join(out, "demo.png")
    # The suite runs lavapipe on 1 thread, often beside other work: the fixed costs of the first frames
    # (pipelines, the grid's sweeps, the light volume) can then take the demo's whole budget, and the
    # image is whatever frame ended last. A budget of at least 20 s leaves the hand-over (3 s after the
    # view is still) its frames (the preview's first frame took 10.6 s here on a loaded machine); the
    # demo's 10 s on 2 threads at 384^2 is a benchmark figure.
    seconds = str(max(float(flags["seconds"]), 20.0))
    text = render(a.data, demo, ["--rotation", flags["rotation"], "--strategy", flags["strategy"],
                                 "--spp", flags["spp"], "--seconds", seconds, "--preview-first"]
                  + (["--denoise"] if flags["denoise"] else []))
    m = re.search(r"rendered \d+x\d+: (\d+) spp \((\w+)\) in ([0-9.]+) s(.*)", text)
    if not m:
        raise SystemExit("render_brain.py did not print spp, strategy and time")
    spp, strategy, seconds, shown = int(m.group(1)), m.group(2), float(m.group(3)), m.group(4)
    failures = []
    if "share" in shown or "estimate alone" not in shown:
        failures.append(f"the demo's image is not the estimate alone: '{shown.strip()}'")
    if flags["denoise"] and "display filter" not in shown:
        failures.append(f"demo.sh asks for --denoise, but the image written is not filtered: '{shown.strip()}'")
    reference = os.path.join(out, "reference.png")
    render(a.data, reference, ["--rotation", flags["rotation"], "--strategy", flags["strategy"],
                               "--spp", str(min(max(4 * spp, 64), 256))])
    diff = load(demo) - load(reference)
    noise = diff.std()
    peak, where = largest_peak(diff)
    print(f"demo: {spp} spp ({strategy}) in {seconds:.2f} s; difference from the reference: std {noise:.2f}, "
          f"largest spectral peak {peak:.1f}x its neighbours at {where}")
    if peak > 12.0:
        failures.append(f"a periodic pattern: a spectral peak {peak:.1f}x its neighbours at {where}")
    # The detector finds a faint pattern: bands a quarter of the noise's standard deviation.
    h, w, _ = diff.shape
    yy, xx = np.mgrid[0:h, 0:w]
    bands = 0.25 * noise * np.sqrt(2.0) * np.sin(2 * np.pi * (12 * xx / w + 8 * yy / h))
    faint, _ = largest_peak(diff + bands[:, :, None])
    print(f"with faint bands added: largest spectral peak {faint:.1f}x")
    if faint <= 12.0:
        failures.append(f"the detector misses faint bands ({faint:.1f}x)")
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
