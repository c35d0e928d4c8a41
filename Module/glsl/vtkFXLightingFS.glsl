// VTK 9.1's Phong lighting, one function per light complexity, transcribed
// from vtkOpenGLPolyDataMapper::ReplaceShaderLight (non-PBR branch). VTK's
// forward shaders inline these statements once per light; vtkFXCompositePass
// calls these functions once per light with the same uniforms
// (lightColorN, lightDirectionVCN, lightPositionVCN, ...), accumulating the
// light that reaches the surface; the caller multiplies by the material:
//   colour = ambient + diffuseLight * diffuseColor + specularLight * specularColor
// which is VTK's "ambientColor + diffuse + specular".
// Each light's diffuse factor passes through fxDiffuseResponse (identity
// unless an effect reshapes it, e.g. toon bands); highlights keep the raw
// factor.

// Complexity 1: one headlight; light and view both along +z.
void fxHeadlight(vec3 n, vec3 lightColor, float specularPower,
  inout vec3 diffuseLight, inout vec3 specularLight)
{
  float df = max(0.0, n.z);
  diffuseLight += fxDiffuseResponse(df) * lightColor;
#if FX_HAS_SPECULAR
  float sf = pow(df, specularPower);
  specularLight += sf * lightColor;
#endif
}

// Complexity 2: a directional light (light kit, camera and scene lights).
// `lightDirection` points from the light; `view` is normalize(-vertexVC).
void fxDirectionalLight(vec3 n, vec3 view, vec3 lightDirection, vec3 lightColor,
  float specularPower, inout vec3 diffuseLight, inout vec3 specularLight)
{
  float df = max(0.0, dot(n, -lightDirection));
  diffuseLight += fxDiffuseResponse(df) * lightColor;
#if FX_HAS_SPECULAR
  float sf = sign(df) * pow(max(0.0, dot(reflect(lightDirection, n), view)), specularPower);
  specularLight += sf * lightColor;
#endif
}

// Complexity 3: directional or positional lights, with VTK's attenuation
// 1 / (a.x + a.y d + a.z d^2) and, for cone angles below 90 degrees, a spot
// cone with falloff pow(cos, exponent).
void fxPositionalLight(vec3 n, vec3 position, vec3 view, int positional,
  vec3 lightDirection, vec3 lightPosition, vec3 lightAttenuation, float coneAngle,
  float exponent, vec3 lightColor, float specularPower,
  inout vec3 diffuseLight, inout vec3 specularLight)
{
  float attenuation = 1.0;
  vec3 toSurface = lightDirection;
  if (positional != 0)
  {
    toSurface = position - lightPosition;
    float distanceVC = length(toSurface);
    // (a surface exactly at the light: lit along the light's direction,
    // where normalize(0) would be NaN)
    toSurface = distanceVC > 0.0 ? toSurface / distanceVC : lightDirection;
    // At most 1e30: zero attenuation coefficients make VTK's 1 / 0 = inf,
    // and inf x 0 (a back face's specular) NaN, which would blacken the
    // pixel; capped, such a light saturates instead. (Not lower: a dim
    // light close to a small scene's surface has an attenuation far above
    // 65504, and its product with the light's colour is what VTK shows.)
    attenuation = min(1.0 /
      (lightAttenuation.x + lightAttenuation.y * distanceVC +
        lightAttenuation.z * distanceVC * distanceVC), 1e30);
    // (VTK 9.1's polygonal Phong shader, vtkOpenGLPolyDataMapper: a cone
    // below 90 degrees only; at 90 a light has none. A cosine that rounds
    // below 0 would have an undefined power, as would 0 to the power 0 (a
    // cone angle of -90 or less, which VTK does not refuse, lets cosines of
    // 0 and below in): no light there.)
    if (coneAngle < 90.0)
    {
      float coneDot = dot(toSurface, lightDirection);
      attenuation = coneDot >= cos(radians(coneAngle)) && coneDot > 0.0
        ? attenuation * pow(coneDot, exponent)
        : 0.0;
    }
  }
  float df = max(0.0, attenuation * dot(n, -toSurface));
  // Each light's share at most 1e30: finite whatever the light's colour,
  // so that a zero albedo or specular colour times it stays 0, not NaN.
  diffuseLight += min(fxDiffuseResponse(df) * lightColor, vec3(1e30));
#if FX_HAS_SPECULAR
  float sf = sign(df) * attenuation * pow(max(0.0, dot(reflect(toSurface, n), view)), specularPower);
  specularLight += min(sf * lightColor, vec3(1e30));
#endif
}
