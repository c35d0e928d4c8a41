"""vtkFX: VTK render passes for ambient occlusion, shadows and illustrative shading.

Install a pipeline on a renderer with::

    import vtkfx
    renderer.SetPass(vtkfx.vtkFXPipelinePass())
"""
# The wrapped classes derive from VTK's OpenGL render passes: import those
# modules first so Python knows the superclasses.
from vtkmodules import vtkRenderingOpenGL2 as _vtkRenderingOpenGL2  # noqa: F401
from vtkmodules import vtkRenderingCore as _vtkRenderingCore  # noqa: F401

from .vtkFX import *  # noqa: F401,F403
