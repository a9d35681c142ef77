#!/usr/bin/python3
"""Generates the synthetic benchmark volumes (run from this folder; the .vti files are checked in).

phantom.vti  96^3 uint8, a CT-like head phantom: a dense ellipsoidal shell (bone, 220) around a
             soft interior (tissue, 60-90, with two denser lesions, 140) in air (0).
blind.vti    64^3 uint8, a slatted blind: 8 thin dense slats (one voxel thick, 200) across a
             slab of soft fog (30) -- thin occluders that stress the visibility grid's resolution.
"""
import numpy as np
import vtk
from vtk.util import numpy_support


def write(name, values):
    nz, ny, nx = values.shape
    image = vtk.vtkImageData()
    image.SetDimensions(nx, ny, nz)
    array = numpy_support.numpy_to_vtk(values.ravel(order="C"), deep=True, array_type=vtk.VTK_UNSIGNED_CHAR)
    array.SetName("density")
    image.GetPointData().SetScalars(array)
    writer = vtk.vtkXMLImageDataWriter()
    writer.SetFileName(name)
    writer.SetInputData(image)
    writer.SetCompressorTypeToZLib()
    writer.Write()


def phantom(n=96):
    z, y, x = np.mgrid[0:n, 0:n, 0:n].astype(np.float32)
    c = (n - 1) / 2.0
    r = np.sqrt(((x - c) / (0.42 * n)) ** 2 + ((y - c) / (0.36 * n)) ** 2 + ((z - c) / (0.45 * n)) ** 2)
    v = np.zeros((n, n, n), np.float32)
    v[r < 1.0] = 220.0                                   # the shell
    inner = r < 0.88
    v[inner] = 60.0 + 30.0 * (1.0 - r[inner])            # soft interior, denser at the centre
    for (lx, ly, lz, lr) in ((0.35, 0.45, 0.55, 0.08), (0.62, 0.55, 0.4, 0.06)):
        d = np.sqrt((x - lx * n) ** 2 + (y - ly * n) ** 2 + (z - lz * n) ** 2)
        v[d < lr * n] = 140.0                            # lesions
    return v.astype(np.uint8)


def blind(n=64):
    v = np.zeros((n, n, n), np.float32)
    v[:, 8:56, 8:56] = 30.0                              # fog slab (x, y in 8..55, all z)
    for k in range(8):                                   # slats: planes z = 6 + 7k, one voxel thick
        v[6 + 7 * k, 4:60, 4:60] = 200.0
    return v.astype(np.uint8)


if __name__ == "__main__":
    write("phantom.vti", phantom())
    write("blind.vti", blind())
