#!/usr/bin/env python3
"""Crops a PNG at 100% (no scaling): scripts/crop-png.py IN.png OUT.png X Y SIZE writes the SIZE x SIZE
pixels whose top-left corner is (X, Y), counted from the image's top-left, as the docs' gallery crops."""
import sys

import vtk


def main():
    if len(sys.argv) != 6:
        raise SystemExit(__doc__)
    src, dst = sys.argv[1], sys.argv[2]
    x, y, size = (int(v) for v in sys.argv[3:6])
    reader = vtk.vtkPNGReader()
    reader.SetFileName(src)
    reader.Update()
    w, h, _ = reader.GetOutput().GetDimensions()
    if x < 0 or y < 0 or size < 1 or x + size > w or y + size > h:
        raise SystemExit(f"the crop ({x}, {y}) + {size} is not inside the {w} x {h} image")
    voi = vtk.vtkExtractVOI()
    voi.SetInputConnection(reader.GetOutputPort())
    # VTK's rows are bottom-up.
    voi.SetVOI(x, x + size - 1, h - y - size, h - y - 1, 0, 0)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(dst)
    writer.SetInputConnection(voi.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode():
        raise SystemExit(f"cannot write {dst}")


if __name__ == "__main__":
    main()
