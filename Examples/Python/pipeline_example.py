"""Render a mesh through the vtkFX pipeline from Python and write a PNG.

    python3 pipeline_example.py MESH.obj OUT.png

Prints the passes that ran and the G-buffer's bytes per pixel; exits
non-zero if the deferred path did not run or the image was not written.
"""
import os
import sys

import vtkfx
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL classes)


def main(mesh, out):
    reader = vtkOBJReader()
    reader.SetFileName(mesh)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(reader.GetOutputPort())
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.7, 0.8, 0.9)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(400, 300)
    window.AddRenderer(renderer)

    pipeline = vtkfx.vtkFXPipelinePass()
    renderer.SetPass(pipeline)  # the one line that installs vtkFX

    # Optional: ambient occlusion, with the three settings users reach for.
    pipeline.AmbientOcclusionOn()
    pipeline.SetAmbientOcclusionQuality(vtkfx.vtkFXPipelinePass.Medium)  # Low, Medium, High
    pipeline.SetAmbientOcclusionFalloff(vtkfx.vtkFXSSAOPass.Binary)  # visibility within R
    pipeline.GetSSAOPass().SetRadiusFraction(0.1)  # of the data's diagonal (or SetRadius)
    renderer.ResetCamera()
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(out)
    writer.Write()

    passes = [pipeline.GetPassThatRan(i) for i in range(pipeline.GetNumberOfPassesThatRan())]
    print("passes: " + " ".join(passes))
    print("G-buffer: %d bytes/pixel" % pipeline.GetGBufferBytesPerPixel())
    return 0 if "gbuffer" in passes and os.path.getsize(out) > 0 else 1


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
