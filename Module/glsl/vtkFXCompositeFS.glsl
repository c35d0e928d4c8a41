//VTK::System::Dec
// vtkFXCompositeFS: deferred lighting of the vtkFX G-buffer.
//
// The lighting is VTK 9.1's own Phong model (vtkFXLightingFS.glsl), called
// once per light by code vtkFXCompositePass generates, and fed by the same
// uniforms as VTK's mappers (vtkOpenGLRenderer::UpdateLightingUniforms), or,
// for more lights than those uniforms serve, by a light texture looped over.
// Positions come from linear depth and the affine per-pixel frustum ray
// (the "frustum corner ray" reconstruction of Crytek's SSAO, Mittring 2007),
// so no world-space position is stored.
//
// Effects add code at the hook tags (see vtkFXEffectPass): declarations,
// per-light visibility, each light's diffuse response, the ambient
// visibility, and the final colour.
//
// Defines set by vtkFXCompositePass: FX_LIGHTING (0..3), FX_LIGHT_TEXTURE,
// FX_LIGHT_TILES,
// FX_HAS_SPECULAR, FX_HAS_AMBIENT, FX_HAS_EMISSION, FX_NEEDS_POSITION,
// FX_WRITES_DEPTH (0 after the depth pre-pass, vtkFXCompositeDepthFS),
// FX_DEBUG_CHANNEL, FX_DEBUG_OCCLUSION, and the channel numbers
// FX_CHANNEL_NORMAL, FX_CHANNEL_DEPTH (vtkFXGBufferPass::Channel).

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
#if FX_NEEDS_POSITION
uniform sampler2D fxLinearDepth;
//VTK::FXViewPosition::Dec
#endif
#if FX_HAS_EMISSION
uniform sampler2D fxEmission;
#endif
#if FX_LIGHT_TEXTURE
// Lights beyond VTK's per-light uniforms: 4 RGBA32F texels per light (one
// row each): colour and attenuation a0; position (view space) and a1;
// direction (view space) and a2; cone angle, exponent and the light's
// place among those that are on. Rows sorted: directional lights, then
// point lights (no cone) from fxFirstPoint, then spot lights from
// fxFirstSpot (vtkFXCompositePass::UploadLightTexture).
uniform sampler2D fxLights;
uniform int fxLightCount;
uniform int fxFirstPoint;
uniform int fxFirstSpot;
#if FX_LIGHT_TILES
// Per 16 x 16 pixel tile, the positional lights that reach it
// (vtkFXLightTiles).
uniform sampler2D fxLightTileHeaders; // (first entry, point lights, spot lights)
uniform sampler2D fxLightTileEntries; // copies of the lights' rows
#endif
#endif
uniform float fxOcclusionDiffuseStrength;
#if FX_DEBUG_CHANNEL >= 0
uniform sampler2D fxDebugTexture;
uniform vec2 fxDepthRange;
#endif

//VTK::FXNormalCoding::Dec

//VTK::Light::Dec

//VTK::FXEffects::Dec

// One light's diffuse factor (max(0, n.l) times attenuation) as the
// effects' DiffuseResponse hooks reshape it; `df` in, `df` out.
float fxDiffuseResponse(float df)
{
  //VTK::FXEffects::DiffuseResponse
  return df;
}

//VTK::FXLighting::Dec

//VTK::Output::Dec


// Finite, non-negative colours only: NaN becomes 0, and +inf (VTK writes it
// for a light with zero attenuation coefficients) the largest half float, as
// an 8-bit framebuffer would clamp it to white.
vec3 fxSanitize(vec3 c)
{
  c = mix(c, vec3(0.0), bvec3(isnan(c.x), isnan(c.y), isnan(c.z)));
  return clamp(c, 0.0, 65504.0);
}

// A pre-lit (PBR) colour, sRGB as VTK writes it (its linear light raised
// to 1 / 2.2), occluded in linear light as the diffuse light is, by
// fxOcclusionDiffuseStrength: VTK's PBR colour is one sum of its
// environment (image-based) light, its lights and its emission (the
// prop's EMISSIVE_COLOR is taken out first where the emission channel
// holds it, and added back unoccluded).
vec3 fxOccludedPrelit(vec3 prelit, vec3 visibility)
{
  vec3 factor = clamp(mix(vec3(1.0), visibility, fxOcclusionDiffuseStrength), 0.0, 1.0);
  return prelit * pow(factor, vec3(1.0 / 2.2));
}

#if FX_DEBUG_CHANNEL >= 0
vec3 fxDebugColor()
{
  vec4 v = texture(fxDebugTexture, texCoord);
#if FX_DEBUG_CHANNEL == FX_CHANNEL_NORMAL || FX_DEBUG_CHANNEL == FX_CHANNEL_GEOMETRIC_NORMAL
  return fxIsUnlit(v.xy) ? vec3(0.0) : 0.5 + 0.5 * fxDecodeNormal(v.xy);
#elif FX_DEBUG_CHANNEL == FX_CHANNEL_DEPTH
  return vec3(clamp((v.r - fxDepthRange.x) / max(fxDepthRange.y - fxDepthRange.x, 1e-30), 0.0, 1.0));
#else
  return v.rgb;
#endif
}
#endif

void main()
{
#if FX_WRITES_DEPTH
  float hardwareDepth = texture(fxHardwareDepth, texCoord).r;
  if (hardwareDepth >= 1.0)
  {
    discard; // background: keep what the renderer cleared
  }
  gl_FragDepth = hardwareDepth;
#endif
  // (after the depth pre-pass, the depth test has already left the
  // background out: a depth the pre-pass copied exactly, within 2^-25 of
  // 1, can read as 1.0 here and must not be discarded)
  vec4 albedo = texture(fxAlbedo, texCoord);
  vec3 color = albedo.rgb; // unlit fragments store their final colour here
  bool lit = false;
  vec3 n = vec3(0.0, 0.0, 1.0);
  // (fxPixelDepth: this pixel's linear depth, for the effects' code; 0
  // without a depth channel)
#if FX_NEEDS_POSITION
  float fxPixelDepth = texture(fxLinearDepth, texCoord).r;
  vec3 position = fxViewPosition(2.0 * texCoord - 1.0, fxPixelDepth);
  vec3 view = normalize(-position);
#else
  float fxPixelDepth = 0.0;
  vec3 position = vec3(0.0);
  vec3 view = vec3(0.0, 0.0, 1.0);
#endif
  // What the effects' ambient hooks leave here (1 = open) scales the ambient
  // term; VTK's materials have none by default (Ambient = 0), so it also
  // scales the light reaching the surface diffusely, by a strength (0:
  // physically ambient only; 1: like vtkSSAOPass, which darkens the whole
  // colour). Highlights are kept.
  vec3 ambientVisibility = vec3(1.0);

#if FX_DEBUG_CHANNEL >= 0
  color = fxDebugColor();
  albedo.a = 1.0;
#elif FX_LIGHTING > 0
  vec2 encodedNormal = texture(fxNormal, texCoord).rg;
  if (!fxIsUnlit(encodedNormal))
  {
    // (pre-lit, PBR: VTK's colour, occluded below, not lit again)
    lit = !fxIsPrelit(encodedNormal);
    n = fxDecodeNormal(encodedNormal);
    vec3 diffuseColor = albedo.rgb;
#if FX_HAS_AMBIENT
    vec3 ambientColor = texture(fxAmbient, texCoord).rgb;
#else
    vec3 ambientColor = vec3(0.0);
#endif
#if FX_HAS_SPECULAR
    vec4 specularTexel = texture(fxSpecular, texCoord);
    vec3 specularColor = specularTexel.rgb;
    // (stored as sqrt(power / 128), vtkFXGBufferPass; at least 1e-3, so
    // that pow(0, power) is 0, never the undefined pow(0, 0))
    float specularPower = max(specularTexel.a * specularTexel.a * 128.0, 1e-3);
#else
    vec3 specularColor = vec3(0.0);
    float specularPower = 1.0;
#endif
    vec3 diffuseLight = vec3(0.0);
    vec3 specularLight = vec3(0.0);
    if (lit)
    {
      //VTK::FXLight::Impl
    }
    //VTK::FXEffects::Ambient
#if FX_HAS_EMISSION
    // Emission of lit and pre-lit props (vtkFXGBufferPass::EMISSIVE_COLOR):
    // light the surface gives off, which no occlusion darkens; unlit ones
    // already carry theirs in the albedo. (Read once for both branches: a
    // software rasteriser runs both.)
    vec3 emission = texture(fxEmission, texCoord).rgb;
#endif
    if (lit)
    {
      ambientColor *= ambientVisibility;
      diffuseLight *= mix(vec3(1.0), ambientVisibility, fxOcclusionDiffuseStrength);
      color = ambientColor + diffuseLight * diffuseColor + specularLight * specularColor;
#if FX_HAS_EMISSION
      color += emission;
#endif
    }
    else
    {
#if FX_HAS_EMISSION
      // The G-buffer added the prop's emission to VTK's colour, so only the
      // rest is occluded. (Where colour and emission summed above the
      // albedo's 1, the rest reads less than VTK's colour: unoccluded, the
      // sum is still exact.)
      color = fxOccludedPrelit(max(albedo.rgb - emission, 0.0), ambientVisibility) + emission;
#else
      color = fxOccludedPrelit(albedo.rgb, ambientVisibility);
#endif
    }
  }
#endif
  //VTK::FXEffects::Color
#if FX_DEBUG_OCCLUSION
  color = clamp(ambientVisibility, 0.0, 1.0);
  albedo.a = 1.0;
  if (texCoord.x < -1.0)
  {
    discard; // never: keeps texCoord in the program when nothing else reads it
  }
#endif
  gl_FragData[0] = vec4(fxSanitize(color), clamp(albedo.a, 0.0, 1.0));
}
