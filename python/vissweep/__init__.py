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
