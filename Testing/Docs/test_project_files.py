"""Issue 14, "the first hour": the repository is self-contained and says what it is.

- No file cites a design document that is not in the repository, nor its internal seed names
  (the project's own reference is docs/reference.md);
- the README links docs/reference.md and docs/paraview.md, and it and the reference cite the
  paper by its authors and title;
- the code has a LICENSE;
- the README's images exist, and its gallery shows every example scene with its command, each image
  under 100 KiB;
- the library's modules and the command-line tool need no test-only VTK module (RenderingImage,
  TestingRendering), so they configure against a VTK without them (ParaView's, docs/paraview.md).

Run by ctest with VISSWEEP_SOURCE=<repository root>; no build products are read."""
import os
import re
import unittest

SOURCE = os.environ["VISSWEEP_SOURCE"]
# Spelled in two parts so that this file does not match itself.
FORBIDDEN = [re.compile("DESIGN" + r"\.md"), re.compile("seed" + r"\s+000", re.I)]
PAPER_TITLE = "Efficient stochastic rendering of static and animated volumes using visibility sweeps"


def text_files():
    for root, dirs, files in os.walk(SOURCE):
        rel = os.path.relpath(root, SOURCE)
        dirs[:] = [d for d in dirs if not d.startswith(".") and not (rel == "." and d.startswith("build"))]
        for f in files:
            path = os.path.join(root, f)
            if os.path.islink(path) or os.path.getsize(path) > 4 << 20:
                continue
            with open(path, "rb") as fh:
                data = fh.read()
            if b"\0" in data:
                continue
            yield os.path.relpath(path, SOURCE), data.decode("utf-8", "replace")


def read(rel):
    with open(os.path.join(SOURCE, rel), encoding="utf-8") as f:
        return f.read()


class ProjectFiles(unittest.TestCase):
    def test_no_citation_of_files_outside_the_repository(self):
        hits = []
        n = 0
        for rel, text in text_files():
            n += 1
            for pattern in FORBIDDEN:
                for m in pattern.finditer(text):
                    line = text.count("\n", 0, m.start()) + 1
                    hits.append("%s:%d: %s" % (rel, line, m.group(0)))
        self.assertGreater(n, 100, "walked too few files: %d" % n)
        self.assertEqual(hits, [], "cites what is not in the repository:\n" + "\n".join(hits))

    def test_readme_links_the_docs_and_cites_the_paper(self):
        readme = read("README.md")
        for doc in ("docs/reference.md", "docs/paraview.md"):
            self.assertIn("(%s)" % doc, readme, "README links " + doc)
            self.assertTrue(os.path.isfile(os.path.join(SOURCE, doc)), doc)
        for rel in ("README.md", "docs/reference.md"):
            text = " ".join(read(rel).split())
            self.assertIn(PAPER_TITLE, text, rel + " cites the paper by its title")
            self.assertIn("von Radziewsky", text, rel + " cites the paper by its authors")

    def test_readme_images_exist_and_the_gallery_is_small(self):
        # Issue 37: the README's gallery shows each demo scene as the tool renders it, with its command;
        # its images stay small (the repository carries them).
        readme = read("README.md")
        images = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", readme)
        for rel in images:
            self.assertTrue(os.path.isfile(os.path.join(SOURCE, rel)), "README shows a missing image " + rel)
        gallery = [rel for rel in images if rel.startswith("docs/gallery/")]
        scenes = sorted(f[:-5] for f in os.listdir(os.path.join(SOURCE, "Examples", "Scenes")) if f.endswith(".json"))
        for scene in scenes:
            self.assertIn("docs/gallery/%s.png" % scene, gallery, "the gallery lacks Examples/Scenes/%s.json" % scene)
            self.assertIn("vissweep render Examples/Scenes/%s.json -o docs/gallery/%s.png" % (scene, scene),
                          readme, "the gallery gives no command for " + scene)
        for rel in gallery:
            size = os.path.getsize(os.path.join(SOURCE, rel))
            self.assertLess(size, 100 << 10, "%s is %d bytes: keep the gallery's images under 100 KiB" % (rel, size))

    def test_license(self):
        text = read("LICENSE")
        self.assertIn("BSD 3-Clause", text)
        self.assertIn("Redistribution and use in source and binary forms", text)

    def test_library_needs_no_test_only_vtk_module(self):
        test_only = re.compile(r"VTK::(RenderingImage|TestingRendering)\b")
        for rel in ("Module/vtk.module", "Bridge/vtk.module", "Filters/vtk.module", "Rendering/vtk.module", "vtk.module",
                    "Bridge/CMakeLists.txt",
                    "Module/CMakeLists.txt", "Filters/CMakeLists.txt", "Rendering/CMakeLists.txt",
                    "Tool/CMakeLists.txt", "Benchmarks/CMakeLists.txt"):
            if os.path.isfile(os.path.join(SOURCE, rel)):
                self.assertIsNone(test_only.search(read(rel)), rel + " uses a test-only VTK module")
        root = read("CMakeLists.txt")
        m = re.search(r"find_package\(VTK[^)]*\)", root, re.S)
        self.assertIsNotNone(m)
        required, _, optional = m.group(0).partition("OPTIONAL_COMPONENTS")
        for module in ("RenderingImage", "TestingRendering"):
            self.assertNotIn(module, required, module + " must be an optional component")
            self.assertIn(module, optional)


if __name__ == "__main__":
    unittest.main()
