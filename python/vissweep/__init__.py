"""VisSweep: physically based volume rendering for VTK, computed with Vulkan.

    import vtk
    import vissweep
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()

The classes come from the wrapped modules vissweepFilters and vissweepRendering.
"""
import vtkmodules.vtkCommonCore  # noqa: F401  (VTK's base types first)
import vtkmodules.vtkRenderingCore  # noqa: F401
import vtkmodules.vtkRenderingVolume  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window factory)

from .vissweepFilters import *  # noqa: F401,F403
from .vissweepRendering import *  # noqa: F401,F403

__version__ = "0.1.0"


def read_checked(reader, what=None):
    """Update a volume reader and return its vtkImageData output, or raise RuntimeError naming
    `what` (default: the reader's file name) and the reason.

    VTK's readers report a truncated or corrupt file through error events, GetErrorCode() or an
    output with fewer values than points, and still hand the partial or uninitialised data down
    the pipeline (issue 13, item 2): a mapper then renders it without a word. This checks all of
    them, and the spacing and origin (zero or non-finite spacing cannot be rendered)::

        reader = vtk.vtkNIFTIImageReader(); reader.SetFileName("head.nii.gz")
        image = vissweep.read_checked(reader)   # RuntimeError for a truncated file
        mapper.SetInputData(image)
    """
    import math

    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkCommonDataModel import vtkImageData

    if what is None:
        name = reader.GetFileName() if hasattr(reader, "GetFileName") else None
        what = f"'{name}'" if name else reader.GetClassName()
    messages = {"reader": [], "executive": []}

    def collect(key):
        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, data=None):
            text = str(data or "").strip()
            text = text.split("): ", 1)[-1] if "): " in text else text
            messages[key].append(text.splitlines()[0].strip() if text else "")
        return on_error

    # MetaIO reports a missing data file on std::cerr only, and the reader returns uninitialised voxels.
    if reader.IsA("vtkMetaImageReader"):
        _check_meta_image_data_file(reader.GetFileName(), what)
    executive = reader.GetExecutive()
    tags = [(reader, reader.AddObserver(vtkCommand.ErrorEvent, collect("reader"))),
            (executive, executive.AddObserver(vtkCommand.ErrorEvent, collect("executive")))]
    try:
        reader.Update()
    finally:
        for obj, tag in tags:
            obj.RemoveObserver(tag)
    # The reader's own words first; the executive's "returned failure for request" only without them.
    said = messages["reader"] or messages["executive"]
    if said:
        raise RuntimeError(f"{what}: {'; '.join(said)}")
    if hasattr(reader, "GetErrorCode") and reader.GetErrorCode() != 0:
        from vtkmodules.vtkCommonMisc import vtkErrorCode
        raise RuntimeError(f"{what}: the reader reported {vtkErrorCode.GetStringFromErrorCode(reader.GetErrorCode())}"
                           " (truncated or corrupt file?)")
    image = vtkImageData.SafeDownCast(reader.GetOutputDataObject(0))
    if image is None or image.GetNumberOfPoints() == 0:
        raise RuntimeError(f"{what}: the file holds no voxels")
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        raise RuntimeError(f"{what}: the file holds no point scalars")
    if scalars.GetNumberOfTuples() != image.GetNumberOfPoints():
        raise RuntimeError(f"{what}: it describes {image.GetNumberOfPoints()} points but holds "
                           f"{scalars.GetNumberOfTuples()} values (truncated file?)")
    for axis, spacing, origin in zip("xyz", image.GetSpacing(), image.GetOrigin()):
        if not math.isfinite(spacing) or spacing == 0.0:
            raise RuntimeError(f"{what}: its spacing along {axis} is {spacing} (must be finite and non-zero)")
        if not math.isfinite(origin):
            raise RuntimeError(f"{what}: its origin along {axis} is {origin} (must be finite)")
    return image


def _check_meta_image_data_file(header, what):
    """Raise RuntimeError when a MetaImage header's ElementDataFile names a file that is not there."""
    import os

    if not header or not os.path.isfile(header):
        return
    with open(header, "rb") as f:
        text = f.read(1 << 16).decode("latin-1")
    for line in text.splitlines():
        key, _, value = line.partition("=")
        if key.strip() != "ElementDataFile":
            continue
        data = value.strip()
        if data.upper() in ("LOCAL", "LIST") or "%" in data:
            return
        path = data if os.path.isabs(data) else os.path.join(os.path.dirname(header), data)
        if not os.path.isfile(path):
            raise RuntimeError(f"{what}: its data file '{path}' does not exist")
        return
