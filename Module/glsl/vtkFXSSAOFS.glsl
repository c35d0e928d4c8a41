//VTK::System::Dec
// vtkFXSSAOFS: screen-space ambient occlusion from the vtkFX G-buffer.
//
// Normal-oriented hemisphere sampling (Crytek's SSAO with the normal-aligned
// kernel of later practice): FX_SAMPLES points around the receiver p,
//   q_i = p + R * l_i * (T x_i + B y_i + N z_i),
// with directions (x_i, y_i, z_i) cosine-distributed around the normal and
// lengths l_i = u^3, both after seed 000 (Vizerie 2009, from the Global
// Illumination Compendium): "more sampling importance for the occluders that
// are close to the sampling location". A sample counts as occluded when the
// surface seen through it lies in front of it. With solid occluders this
// estimates, without bias, the cosine-weighted ray-traced obscurance
//   A(p) = 1 - (1/pi) Int f(t(w)) cos(theta) dw,  f(t) = 1 - (t/R)^(1/3),
// because P(l < t/R) = (t/R)^(1/3): the reference vtkfx-bench traces.
// The kernel is rotated per pixel by a 4x4 tile of angles (seed 001's noise
// texture), a range check fades out occluders more than R in front of the
// receiver, and only surfaces in front of the receiver's tangent plane can
// occlude (a surface never occludes itself, at any viewing angle). Positions come from linear depth and the per-pixel frustum
// ray (seed 001), radii are world units, biases fractions of R: scaling the
// scene changes nothing.

// Texels are addressed through gl_FragCoord; texCoord is read once only so
// that the quad's texture-coordinate attribute stays in the program
// (vtkOpenGLQuadHelper binds it and complains when it is optimised away).
in vec2 texCoord;

uniform sampler2D fxLinearDepth;
uniform sampler2D fxNormal;
uniform ivec2 fxGBufferSize;  // full-resolution G-buffer texels
uniform int fxStep;           // G-buffer texels per occlusion texel (1 or 2)
uniform vec3 fxRayOrigin[3];
uniform vec3 fxRayDirection[3];
uniform mat4 fxProjection;    // view -> clip coordinates
uniform vec4 fxKernel[FX_SAMPLES];
uniform vec2 fxNoise[16];
uniform float fxRadius;       // world units
uniform float fxBias;         // world units

//VTK::FXNormalCoding::Dec

//VTK::Output::Dec

vec3 fxViewPosition(vec2 ndc, float depth)
{
  vec3 origin = fxRayOrigin[0] + ndc.x * fxRayOrigin[1] + ndc.y * fxRayOrigin[2];
  vec3 direction = fxRayDirection[0] + ndc.x * fxRayDirection[1] + ndc.y * fxRayDirection[2];
  return origin + depth * direction;
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see the declaration of texCoord
  }
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 texel = min(pixel * fxStep, fxGBufferSize - 1);
  float depth = texelFetch(fxLinearDepth, texel, 0).r;
  vec2 code = texelFetch(fxNormal, texel, 0).rg;
  if (!(depth > 0.0) || fxIsUnlit(code))
  {
    gl_FragData[0] = vec4(1.0, depth, 0.0, 1.0); // no surface, or one VTK does not light
    return;
  }
  vec2 ndc = (vec2(texel) + 0.5) / vec2(fxGBufferSize) * 2.0 - 1.0;
  vec3 p = fxViewPosition(ndc, depth);
  vec3 n = fxDecodeNormal(code);

  // Tangent frame rotated by this pixel's entry of the 4x4 noise tile.
  vec2 rotation = fxNoise[(pixel.x & 3) + 4 * (pixel.y & 3)];
  vec3 helper = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t0 = normalize(cross(helper, n));
  vec3 b0 = cross(n, t0);
  vec3 t = rotation.x * t0 + rotation.y * b0;
  vec3 b = cross(n, t);

  // Start just above the surface so that it does not occlude itself.
  vec3 origin = p + fxBias * n;
  float occlusion = 0.0;
  for (int i = 0; i < FX_SAMPLES; ++i)
  {
    vec4 k = fxKernel[i];
    vec3 q = origin + fxRadius * k.w * (k.x * t + k.y * b + k.z * n);
    vec4 clip = fxProjection * vec4(q, 1.0);
    if (clip.w <= 0.0)
    {
      continue; // behind the camera: nothing on screen can hide it
    }
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
    {
      continue; // off screen: unknown, counted as open
    }
    ivec2 texelQ = ivec2(uv * vec2(fxGBufferSize));
    float sceneDepth = texelFetch(fxLinearDepth, texelQ, 0).r;
    float sampleDepth = -q.z;
    // The texel may show the receiver's own surface: at a grazing angle its
    // depth changes a lot across the texel, and a sample just above the
    // surface would look occluded by it. What occludes lies in front of the
    // receiver's tangent plane, so compare with where that plane crosses
    // this texel's ray (exact for planes, conservative for convex surfaces;
    // a relative tolerance, as the receiver's own plane sits exactly on it
    // up to rounding).
    vec2 ndcQ = (vec2(texelQ) + 0.5) / vec2(fxGBufferSize) * 2.0 - 1.0;
    vec3 rayOrigin = fxRayOrigin[0] + ndcQ.x * fxRayOrigin[1] + ndcQ.y * fxRayOrigin[2];
    vec3 rayDirection = fxRayDirection[0] + ndcQ.x * fxRayDirection[1] + ndcQ.y * fxRayDirection[2];
    float facing = dot(n, rayDirection);
    float planeDepth = abs(facing) > 1e-8 ? dot(n, p - rayOrigin) / facing : -1.0;
    bool beforePlane = planeDepth <= 0.0 || sceneDepth < planeDepth * (1.0 - 1e-3);
    if (sceneDepth > 0.0 && sceneDepth < sampleDepth && beforePlane)
    {
      // Range check: a surface far in front of the receiver is not between
      // the receiver and the sample.
      float gap = depth - sceneDepth;
      occlusion += gap < fxRadius ? 1.0 : max(0.0, 2.0 - gap / fxRadius);
    }
  }
  float ao = clamp(1.0 - occlusion / float(FX_SAMPLES), 0.0, 1.0);
  // The depth rides along as the blur's guide.
  gl_FragData[0] = vec4(ao, depth, 0.0, 1.0);
}
