"""Shadows of a translucent particle cloud on the ground, from Python.

    python3 translucent_shadows.py OUT.png

A cloud of point-gaussian splats (opacity 0.3) floats over an opaque
ground and a sphere, lit by a sun fixed in the scene. vtkFXAVSMPass renders
the cloud from the sun into adaptive volumetric shadow maps; the ground,
the sphere and the cloud itself receive the shadows. The camera then
orbits: the casters and the sun do not move, so the shadow maps are kept
and each frame costs the look-up only (a camera light, like the light
kit's, would move with the camera and remake them every frame).

Prints whether the orbiting frames reused the maps and how much the
shadows darken the image (against the same view without them); exits
non-zero when the shadows are missing or the maps were not kept.
"""
import os
import random
import sys

import vtkfx
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPointGaussianMapper,
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL classes)


def cloud_actor():
    """2000 splats in a flattened ball 1.6 units above the ground."""
    rng = random.Random(2025)  # the same cloud every run
    points = vtkPoints()
    for _ in range(2000):
        x, y, z = (rng.gauss(0.0, 1.0) for _ in range(3))
        points.InsertNextPoint(0.9 * x, 1.6 + 0.3 * y, 0.9 * z)
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    mapper = vtkPointGaussianMapper()
    mapper.SetInputData(cloud)
    mapper.SetScaleFactor(0.08)
    mapper.EmissiveOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.88, 0.95)
    actor.GetProperty().SetOpacity(0.3)
    return actor


def opaque_actor(source, color):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def main(out):
    ground = vtkPlaneSource()
    ground.SetOrigin(-4.0, 0.0, -4.0)
    ground.SetPoint1(4.0, 0.0, -4.0)
    ground.SetPoint2(-4.0, 0.0, 4.0)
    sphere = vtkSphereSource()
    sphere.SetCenter(1.8, 0.5, 1.0)
    sphere.SetRadius(0.5)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)

    renderer = vtkRenderer()
    renderer.AddActor(opaque_actor(ground, (0.8, 0.8, 0.75)))
    renderer.AddActor(opaque_actor(sphere, (0.9, 0.5, 0.3)))
    renderer.AddActor(cloud_actor())
    renderer.SetBackground(0.32, 0.34, 0.43)
    # A sun fixed in the scene (a scene light; headlights never cast).
    renderer.AutomaticLightCreationOff()
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPosition(0.4, 1.0, 0.3)
    sun.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(sun)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(400, 300)
    window.AddRenderer(renderer)

    pipeline = vtkfx.vtkFXPipelinePass()
    avsm = vtkfx.vtkFXAVSMPass()
    avsm.SetNumberOfNodes(8)  # 4, 8 or 16 nodes per shadow-map texel
    pipeline.AddEffect("avsm", avsm)
    renderer.SetPass(pipeline)

    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 5.5, 11.0)
    camera.SetFocalPoint(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()
    # Two frames: VTK's mappers set themselves up during the first (a
    # default lookup table), which the second sees as a change of the
    # casters and makes the shadow maps once more.
    window.Render()
    window.Render()

    passes = [pipeline.GetPassThatRan(i) for i in range(pipeline.GetNumberOfPassesThatRan())]
    if "avsm" not in passes:
        print("no shadows: vtkFXAVSMPass did not run (it needs OpenGL 4.3; passes: %s)"
              % " ".join(passes))
        window.Finalize()
        return 1

    reused = 0
    orbit = 12
    for _ in range(orbit):
        camera.Azimuth(3.0)
        renderer.ResetCameraClippingRange()
        window.Render()
        reused += 1 if avsm.GetReusedShadowMaps() else 0
    print("orbiting: %d of %d frames reused the shadow maps" % (reused, orbit))
    shadowed = mean_brightness(window)
    write_png(window, out)

    # The same view without the shadows, for comparison.
    avsm.EnabledOff()
    window.Render()
    unshadowed = mean_brightness(window)
    darker = 1.0 - shadowed / unshadowed
    print("the cloud's shadows darken the image by %.1f%%" % (100.0 * darker))
    window.Finalize()  # (its GL objects go with its own context current)
    ok = reused == orbit and darker > 0.01 and os.path.getsize(out) > 0
    return 0 if ok else 1


def mean_brightness(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    values = grab.GetOutput().GetPointData().GetScalars()
    total = sum(values.GetValue(i) for i in range(values.GetNumberOfValues()))
    return total / max(values.GetNumberOfValues(), 1)


def write_png(window, out):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(out)
    writer.Write()


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
