// Octahedral unit-vector encoding: Cigolle, Donow, Evangelakos, Mara,
// McGuire, Meyer, "A Survey of Efficient Representations for Independent Unit
// Vectors", JCGT 3(2), 2014. Two 16-bit floats keep the angular error below
// 1e-3 rad, well under what lighting a 8-bit image can show.
vec2 fxSignNotZero(vec2 v)
{
  return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

vec2 fxEncodeNormal(vec3 n)
{
  // Degenerate normals (zero length or NaN) encode as +z, facing the viewer.
  float l1 = abs(n.x) + abs(n.y) + abs(n.z);
  if (!(l1 > 1e-20))
  {
    return vec2(0.0);
  }
  vec2 p = n.xy / l1;
  return (n.z <= 0.0) ? (1.0 - abs(p.yx)) * fxSignNotZero(p) : p;
}

vec3 fxDecodeNormal(vec2 e)
{
  e.x = e.x > 1.5 ? e.x - 3.0 : e.x; // (a pre-lit fragment's, see below)
  vec3 v = vec3(e.xy, 1.0 - abs(e.x) - abs(e.y));
  if (v.z < 0.0)
  {
    v.xy = (1.0 - abs(v.yx)) * fxSignNotZero(v.xy);
  }
  return normalize(v);
}

// Fragments that VTK does not light carry this value instead of a normal.
const vec2 fxUnlitNormal = vec2(4.0, 4.0);
bool fxIsUnlit(vec2 e)
{
  return e.y > 2.0;
}

// Fragments that VTK lights with a model the composite does not reproduce
// (PBR) keep VTK's colour, but carry their normal for the effects that read
// one (occlusion, feature lines, the blur's planes): its code with x moved
// up by 3, out of the octahedral square ([-1, 1]^2), into [2, 4], which
// fxDecodeNormal undoes. (In 16-bit floats x then keeps 9 bits after the
// point: the code is off by up to 0.0025 rad, the octahedral map's
// stretch included, against 0.00085 without the move (0.0049 moved up by
// 4); for geometry only, never for lighting.)
vec2 fxEncodePrelitNormal(vec3 n)
{
  return fxEncodeNormal(n) + vec2(3.0, 0.0);
}

bool fxIsPrelit(vec2 e)
{
  return e.x > 1.5 && e.y <= 2.0;
}

// Two values in [0, 1] in one 32-bit float, 12 bits each: an integer below
// 2^24, which the float's mantissa holds exactly. (How
// vtkFXDirectionalOcclusionPass carries two channels and an octahedral
// normal, so that its blur reads a pixel in one fetch.)
float fxPack12(vec2 v)
{
  vec2 q = floor(clamp(v, 0.0, 1.0) * 4095.0 + 0.5);
  return q.x * 4096.0 + q.y;
}

vec2 fxUnpack12(float code)
{
  float high = floor(code / 4096.0);
  return vec2(high, code - high * 4096.0) / 4095.0;
}
