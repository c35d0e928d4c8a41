"""'import vtkfx' works with Debian's python3 and python3-vtk9, and the
wrapped passes are VTK render passes that Python can configure."""
import sys

import vtkfx
from vtkmodules.vtkRenderingCore import vtkRenderPass
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderPass

pipeline = vtkfx.vtkFXPipelinePass()
assert isinstance(pipeline, vtkRenderPass), type(pipeline).__mro__
gbuffer = pipeline.GetGBufferPass()
assert isinstance(gbuffer, vtkOpenGLRenderPass)
assert isinstance(pipeline.GetCompositePass(), vtkRenderPass)
assert vtkfx.vtkFXGBufferPass.GetChannelName(vtkfx.vtkFXGBufferPass.LinearDepth) == "depth"
assert vtkfx.vtkFXGBufferPass.GetChannelFromName("albedo") == vtkfx.vtkFXGBufferPass.Albedo
pipeline.SetDebugChannel(9)  # clamped by vtkSetClampMacro
assert pipeline.GetDebugChannel() == vtkfx.vtkFXGBufferPass.GeometricNormal, pipeline.GetDebugChannel()
gbuffer.SetRequiredChannels(0)
assert gbuffer.GetRequiredChannels() == 0

# Directional occlusion replaces ambient occlusion in the pipeline.
pipeline.SetAmbientOcclusion(True)
pipeline.SetDirectionalOcclusion(True)
assert not pipeline.GetAmbientOcclusion()
directional = pipeline.GetDirectionalOcclusionPass()
assert isinstance(directional, vtkfx.vtkFXSSAOPass)
directional.SetBleeding(50.0)  # clamped to 10
assert directional.GetBleeding() == 10.0
directional.SetNumberOfSamples(16)
assert directional.GetEffectiveNumberOfSamples() == 18

# The effects: toon shading and bloom plug into the pipeline by name.
toon = vtkfx.vtkFXToonPass()
toon.RemoveAllBandThresholds()
toon.AddBandThreshold(0.5)
assert toon.GetNumberOfBandThresholds() == 1
toon.SetFeatureLines(False)
assert toon.GetStage() == vtkfx.vtkFXEffectPass.Composite
bloom = vtkfx.vtkFXBloomPass()
bloom.SetRadius(5.0)  # clamped to 1
assert bloom.GetRadius() == 1.0
pipeline.AddEffect("toon", toon)
pipeline.AddEffect("bloom", bloom)
assert pipeline.GetNumberOfEffects() >= 2
composite = pipeline.GetCompositePass()
composite.SetLightCutoff(0.01)
assert abs(composite.GetLightCutoff() - 0.01) < 1e-12
print("vtkfx imported from", vtkfx.__file__, "with", sys.executable)
