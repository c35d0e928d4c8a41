//VTK::System::Dec
// vtkFXCompositeDepthFS: the composite's depth pre-pass. It writes the
// G-buffer's depth into the renderer's framebuffer, depth-tested like the
// composite itself, and no colour. The composite then draws at the far
// plane with the depth test GL_GREATER and writes no depth, so that the
// test, which runs before its fragment shader, leaves out the background:
// a software rasteriser (llvmpipe) skips whole 4x4 blocks that fail it,
// where a discard inside the shader saves nothing (measured: a composite
// discarding every pixel cost as much as one lighting them all).

in vec2 texCoord;

uniform sampler2D fxHardwareDepth;

void main()
{
  float hardwareDepth = texture(fxHardwareDepth, texCoord).r;
  if (hardwareDepth >= 1.0)
  {
    discard; // background: keep what the renderer cleared
  }
  gl_FragDepth = hardwareDepth;
}
