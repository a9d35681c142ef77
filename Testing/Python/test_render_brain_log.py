"""Examples/Python/render_brain.py (what scripts/demo.sh runs) writing into a log, not a terminal:
its progress comes as whole lines, not one run-together line of '\\r'-redrawn counts
("1/1024 samples per pixel9/1024 samples per pixel..." in a log, issue 37).
Needs an X display (the example renders in a vtkRenderWindow)."""
import argparse
import os
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--script", required=True)
    ap.add_argument("--data", required=True)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "brain.png")
        p = subprocess.run([sys.executable, args.script, "--volume", args.data, "--output", out, "--size", "32",
                            "--spp", "24", "--strategy", "Environment"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
        # Bytes, decoded without newline translation (text=True would turn '\r' into '\n').
        stdout = p.stdout.decode("utf-8", "replace")
        print(stdout)
        if p.returncode != 0:
            sys.exit(f"FAILED: render_brain.py exited {p.returncode}: {p.stderr.decode('utf-8', 'replace')[-2000:]}")
        if "\r" in stdout:
            sys.exit("FAILED: '\\r' in a log: the progress is redrawn in place instead of written as lines")
        lines = stdout.split("\n")
        # 8 samples per frame: 8 and 16 of 24 are progress lines, each a line of its own.
        for expected in ("8/24 samples per pixel", "16/24 samples per pixel"):
            if expected not in lines:
                sys.exit(f"FAILED: no line '{expected}' in the log")
        if not any(line.startswith("rendered 32x32: 24 spp") for line in lines):
            sys.exit("FAILED: no 'rendered 32x32: 24 spp' line")
        if not os.path.getsize(out) > 100:
            sys.exit("FAILED: no image")
    print("render_brain.py writes whole progress lines into a log")


if __name__ == "__main__":
    main()
