"""vissweep.read_checked (issue 13, item 2): VTK's readers hand truncated or corrupt volumes down
the pipeline as partial or uninitialised data; the helper turns every way they report it (error
events, GetErrorCode(), too few values) into a RuntimeError naming the file. The shipped example
render_brain.py reads through it."""
import argparse
import gzip
import os
import sys
import tempfile

import vtk
import vissweep


def write_volume(folder):
    source = vtk.vtkImageData()
    source.SetDimensions(16, 16, 16)
    source.AllocateScalars(vtk.VTK_FLOAT, 1)
    scalars = source.GetPointData().GetScalars()
    for i in range(scalars.GetNumberOfTuples()):
        scalars.SetValue(i, float(i % 97))
    paths = {}
    for name, writer in (("good.nii", vtk.vtkNIFTIImageWriter()), ("good.nii.gz", vtk.vtkNIFTIImageWriter()),
                         ("good.mhd", vtk.vtkMetaImageWriter())):
        path = os.path.join(folder, name)
        writer.SetFileName(path)
        if name.endswith(".mhd"):
            writer.SetRAWFileName(os.path.join(folder, "good.raw"))
            writer.SetCompression(False)
        writer.SetInputData(source)
        writer.Write()
        paths[name] = path
    return paths


def truncated(path, keep, folder, name):
    out = os.path.join(folder, name)
    with open(path, "rb") as f:
        data = f.read()
    with open(out, "wb") as f:
        f.write(data[:int(len(data) * keep)])
    return out


def expect_error(reader_class, path, failures, why):
    reader = reader_class()
    reader.SetFileName(path)
    try:
        vissweep.read_checked(reader)
    except RuntimeError as e:
        print(f"{why}: {e}")
        if os.path.basename(path) not in str(e):
            failures.append(f"{why}: the error does not name the file: {e}")
        return
    failures.append(f"{why}: read without an error")


def main():
    ap = argparse.ArgumentParser()
    ap.parse_known_args()  # the python tests' common arguments (--data, --baseline, --output) are not used
    failures = []
    # VTK's own messages go to its output window as well; keep them off the test's stderr.
    vtk.vtkObject.GlobalWarningDisplayOff()
    with tempfile.TemporaryDirectory(prefix="vissweep_read_checked_") as folder:
        paths = write_volume(folder)
        for name in ("good.nii", "good.nii.gz", "good.mhd"):
            reader = vtk.vtkMetaImageReader() if name.endswith(".mhd") else vtk.vtkNIFTIImageReader()
            reader.SetFileName(paths[name])
            image = vissweep.read_checked(reader)
            if image.GetDimensions() != (16, 16, 16):
                failures.append(f"{name}: dimensions {image.GetDimensions()}")
        expect_error(vtk.vtkNIFTIImageReader, truncated(paths["good.nii"], 0.5, folder, "half.nii"), failures,
                     "truncated .nii")
        with open(paths["good.nii.gz"], "rb") as f:
            packed = f.read()
        half_gz = os.path.join(folder, "half.nii.gz")
        with open(half_gz, "wb") as f:
            f.write(packed[:len(packed) // 2])
        expect_error(vtk.vtkNIFTIImageReader, half_gz, failures, "truncated .nii.gz")
        os.remove(os.path.join(folder, "good.raw"))
        expect_error(vtk.vtkMetaImageReader, paths["good.mhd"], failures, ".mhd without its raw file")
        expect_error(vtk.vtkNIFTIImageReader, os.path.join(folder, "missing.nii"), failures, "missing file")
    for f in failures:
        print("FAILED:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
