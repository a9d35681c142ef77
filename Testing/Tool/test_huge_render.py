"""Memory before limits (issue 13, item 7): `vissweep render --width 16384 --height 16384` must fail
fast with a message naming the limit, without growing host memory. It used to grow past 10 GB
(the window, the depth read back and its copies) before the device's limit error came.

Usage: test_huge_render.py VISSWEEP SCENE OUT_DIR
The child's resident set is polled; past RSS_LIMIT_KB it is killed (so a regression costs the
machine at most that much) and the test fails.
"""
import os
import resource
import subprocess
import sys
import time

RSS_LIMIT_KB = 1024 * 1024  # 1 GiB: a tiny scene's render takes about a quarter of that
TIME_LIMIT_S = 120.0        # the first use of the device compiles nothing; this is seconds


def rss_kb(pid):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


def main():
    vissweep, scene, out_dir = sys.argv[1:4]
    os.makedirs(out_dir, exist_ok=True)
    out = os.path.join(out_dir, "huge.png")
    if os.path.exists(out):
        os.remove(out)
    cmd = [vissweep, "render", scene, "--width", "16384", "--height", "16384", "-o", out, "-q"]
    start = time.monotonic()
    child = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    peak = 0
    failure = None
    while child.poll() is None:
        peak = max(peak, rss_kb(child.pid))
        if peak > RSS_LIMIT_KB:
            failure = f"the resident set grew past {RSS_LIMIT_KB // 1024} MiB ({peak // 1024} MiB) before any error"
            child.kill()
            break
        if time.monotonic() - start > TIME_LIMIT_S:
            failure = f"no error within {TIME_LIMIT_S:.0f} s"
            child.kill()
            break
        time.sleep(0.02)
    stdout, stderr = child.communicate()
    elapsed = time.monotonic() - start
    peak = max(peak, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
    print(f"exit {child.returncode} after {elapsed:.2f} s, peak RSS {peak // 1024} MiB")
    print(stderr.strip())
    if failure:
        sys.exit("FAILED: " + failure)
    if peak > RSS_LIMIT_KB:
        sys.exit(f"FAILED: peak RSS {peak // 1024} MiB, more than {RSS_LIMIT_KB // 1024} MiB")
    if child.returncode != 2:
        sys.exit(f"FAILED: exit {child.returncode}, expected 2")
    if "16384 x 16384" not in stderr:
        sys.exit("FAILED: the error does not name the size")
    if not any(limit in stderr for limit in ("maxStorageBufferRange", "device-local heap", "of host memory")):
        sys.exit("FAILED: the error names no limit")
    if os.path.exists(out):
        sys.exit("FAILED: an output was written")
    print("passed")


if __name__ == "__main__":
    main()
