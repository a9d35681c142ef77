"""The README's Python snippets, exactly as written: the first renders from a folder that holds a
link to Data/ (as from the repository's root), and its progressive loop stops with an error, instead
of spinning, where the environment file is missing; the environment-background snippet runs after it. Run by ctest with PYTHONPATH=<build>."""
import os
import re
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

README = os.environ["VISSWEEP_README"]
DATA = os.environ["VISSWEEP_DATA"]


def snippet(section, language):
    text = open(README, encoding="utf-8").read()
    at = text.index("\n### %s\n" % section)
    m = re.compile(r"\n```%s\n(.*?)\n```\n" % re.escape(language), re.S).search(text, at)
    return m.group(1) + "\n"


def indented_snippet(marker, language):
    """A fenced block indented in a list item, the first after `marker`, dedented."""
    with open(README, encoding="utf-8") as f:
        text = f.read()
    at = text.index(marker)
    m = re.compile(r"\n( +)```%s\n(.*?)\n\1```\n" % re.escape(language), re.S).search(text, at)
    return textwrap.dedent(m.group(2)) + "\n"


def run(code, cwd, timeout=600):
    t0 = time.monotonic()
    p = subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True, timeout=timeout)
    return p, time.monotonic() - t0


class ReadmePython(unittest.TestCase):
    def test_renders_as_written(self):
        with tempfile.TemporaryDirectory() as d:
            os.symlink(DATA, os.path.join(d, "Data"))
            p, _ = run(snippet("Python", "python"), d)
            self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
            self.assertIn("(256, 256, 1) 16 spp", p.stdout)

    def test_environment_background_as_written(self):
        # The "Several volumes in one renderer" snippet, run after the first one (it uses its objects).
        with tempfile.TemporaryDirectory() as d:
            os.symlink(DATA, os.path.join(d, "Data"))
            code = snippet("Python", "python") + indented_snippet("**Several volumes in one renderer**", "python")
            code += "window.Render()\nprint('props', renderer.GetViewProps().GetNumberOfItems(), 'error', repr(mapper.GetLastError()))\n"
            p, _ = run(code, d)
            self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
            self.assertIn("props 2 error ''", p.stdout)

    def test_loop_stops_on_error(self):
        with tempfile.TemporaryDirectory() as d:  # no Data/ here: the environment file is missing
            p, seconds = run(snippet("Python", "python"), d, timeout=300)
            self.assertNotEqual(p.returncode, 0, p.stdout)
            self.assertIn("render failed", p.stderr)
            # One failed frame, not thousands: a handful of logged errors at most (VTK logs them as
            # "ERR|" lines through loguru, or "ERROR:" through the plain output window).
            errors = p.stderr.count("ERR|") + p.stderr.count("ERROR:")
            self.assertGreater(errors, 0, p.stderr[-2000:])
            self.assertLess(errors, 10, p.stderr[-2000:])
            self.assertLess(seconds, 120)


if __name__ == "__main__":
    unittest.main()
