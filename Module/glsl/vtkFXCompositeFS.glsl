//VTK::System::Dec
// vtkFXCompositeFS: deferred lighting of the vtkFX G-buffer.
//
// The lighting is VTK 9.1's own Phong model as vtkOpenGLPolyDataMapper::
// ReplaceShaderLight writes it for light complexity 1 (headlight), 2
// (directional) and 3 (positional, cone and attenuation), generated per light
// by vtkFXCompositePass with the same variable names, and fed by the same uniforms (vtkOpenGLRenderer::
// UpdateLightingUniforms). Positions come from linear depth and the affine
// per-pixel frustum ray (the "frustum corner ray" of seed 001), so no
// world-space position is ever stored.
//
// Defines set by vtkFXCompositePass: FX_LIGHTING (0..3), FX_HAS_SPECULAR,
// FX_HAS_AMBIENT, FX_HAS_EMISSION, FX_NEEDS_POSITION, FX_DEBUG_CHANNEL.

in vec2 texCoord;

uniform sampler2D fxHardwareDepth;
uniform sampler2D fxAlbedo;
#if FX_LIGHTING > 0
uniform sampler2D fxNormal;
#endif
#if FX_HAS_SPECULAR
uniform sampler2D fxSpecular;
#endif
#if FX_HAS_AMBIENT
uniform sampler2D fxAmbient;
#endif
#if FX_HAS_EMISSION
uniform sampler2D fxEmission;
#endif
#if FX_NEEDS_POSITION
uniform sampler2D fxLinearDepth;
uniform vec3 fxRayOrigin[3];
uniform vec3 fxRayDirection[3];
#endif
#if FX_DEBUG_CHANNEL >= 0
uniform sampler2D fxDebugTexture;
uniform vec2 fxDepthRange;
#endif

//VTK::FXNormalCoding::Dec

//VTK::Light::Dec

//VTK::Output::Dec

#if FX_NEEDS_POSITION
// View-space position seen through this pixel at linear depth `depth`.
vec3 fxViewPosition(float depth)
{
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec3 origin = fxRayOrigin[0] + ndc.x * fxRayOrigin[1] + ndc.y * fxRayOrigin[2];
  vec3 direction = fxRayDirection[0] + ndc.x * fxRayDirection[1] + ndc.y * fxRayDirection[2];
  return origin + depth * direction;
}
#endif

// Finite, non-negative colours only: NaN or infinite input never reaches
// the screen.
vec3 fxSanitize(vec3 c)
{
  bvec3 bad = bvec3(isnan(c.x) || isinf(c.x), isnan(c.y) || isinf(c.y), isnan(c.z) || isinf(c.z));
  return clamp(mix(c, vec3(0.0), bad), 0.0, 65504.0);
}

#if FX_DEBUG_CHANNEL >= 0
vec3 fxDebugColor()
{
  vec4 v = texture(fxDebugTexture, texCoord);
#if FX_DEBUG_CHANNEL == 0
  return fxIsUnlit(v.xy) ? vec3(0.0) : 0.5 + 0.5 * fxDecodeNormal(v.xy);
#elif FX_DEBUG_CHANNEL == 1
  return vec3(clamp((v.r - fxDepthRange.x) / max(fxDepthRange.y - fxDepthRange.x, 1e-30), 0.0, 1.0));
#else
  return v.rgb;
#endif
}
#endif

void main()
{
  float hardwareDepth = texture(fxHardwareDepth, texCoord).r;
  if (hardwareDepth >= 1.0)
  {
    discard; // background: keep what the renderer cleared
  }
  gl_FragDepth = hardwareDepth;
  vec4 albedo = texture(fxAlbedo, texCoord);
  vec3 color = albedo.rgb; // unlit fragments store their final colour here

#if FX_DEBUG_CHANNEL >= 0
  color = fxDebugColor();
  albedo.a = 1.0;
#elif FX_LIGHTING > 0
  vec2 encodedNormal = texture(fxNormal, texCoord).rg;
  if (!fxIsUnlit(encodedNormal))
  {
    vec3 normalVCVSOutput = fxDecodeNormal(encodedNormal);
    vec3 diffuseColor = albedo.rgb;
    float opacity = albedo.a;
#if FX_HAS_AMBIENT
    vec3 ambientColor = texture(fxAmbient, texCoord).rgb;
#else
    vec3 ambientColor = vec3(0.0);
#endif
#if FX_HAS_SPECULAR
    vec4 specularTexel = texture(fxSpecular, texCoord);
    vec3 specularColor = specularTexel.rgb;
    float specularPower = specularTexel.a * 128.0;
#else
    vec3 specularColor = vec3(0.0);
    float specularPower = 1.0;
#endif
#if FX_NEEDS_POSITION
    vec4 vertexVC = vec4(fxViewPosition(texture(fxLinearDepth, texCoord).r), 1.0);
#endif
    //VTK::FXLight::Impl
#if FX_HAS_EMISSION
    color += texture(fxEmission, texCoord).rgb;
#endif
  }
#endif
  gl_FragData[0] = vec4(fxSanitize(color), clamp(albedo.a, 0.0, 1.0));
}
