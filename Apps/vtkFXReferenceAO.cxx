#include "vtkFXReferenceAO.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMolecule.h"
#include "vtkMoleculeMapper.h"
#include "vtkNew.h"
#include "vtkPeriodicTable.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedShortArray.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <atomic>
#include <cmath>
#include <thread>

struct vtkFXReferenceAO::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;

  ~Internals() { this->Reset(); }
  void Reset()
  {
    if (this->Scene)
    {
      rtcReleaseScene(this->Scene);
      this->Scene = nullptr;
    }
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
      this->Device = nullptr;
    }
  }

  // Triangles of `poly` (any cells; strips and polygons are triangulated),
  // transformed by `matrix` (world from model coordinates). With `smooth`
  // (VTK interpolates the normals: Gouraud or Phong) and point normals, the
  // triangles carry them, for the normal VTK shades and the G-buffer holds.
  bool AddPolyData(vtkPolyData* poly, vtkMatrix4x4* matrix, bool smooth)
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(poly);
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    vtkPolyData* tri = triangles->GetOutput();
    const vtkIdType nPoints = tri->GetNumberOfPoints();
    const vtkIdType nCells = tri->GetNumberOfPolys();
    if (nPoints == 0 || nCells == 0)
    {
      return false;
    }
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry)
    {
      return false;
    }
    float* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nPoints));
    for (vtkIdType i = 0; i < nPoints; ++i)
    {
      double p[4] = { 0, 0, 0, 1 }, w[4];
      tri->GetPoint(i, p);
      matrix->MultiplyPoint(p, w);
      for (int c = 0; c < 3; ++c)
      {
        vertices[3 * i + c] = static_cast<float>(w[c] / w[3]);
      }
    }
    unsigned int* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), nCells));
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtkCellArray* polys = tri->GetPolys();
    vtkIdType k = 0;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids); ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        indices[3 * k + c] = static_cast<unsigned int>(n == 3 ? ids[c] : ids[0]);
      }
    }
    vtkDataArray* normals = smooth ? tri->GetPointData()->GetNormals() : nullptr;
    if (normals && normals->GetNumberOfComponents() == 3)
    {
      // Normals transform by the inverse transpose of the matrix's linear part.
      double linear[3][3], normalMatrix[3][3];
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          linear[r][c] = matrix->GetElement(r, c);
        }
      }
      vtkMath::Invert3x3(linear, normalMatrix);
      vtkMath::Transpose3x3(normalMatrix, normalMatrix);
      rtcSetGeometryVertexAttributeCount(geometry, 1);
      float* out = static_cast<float*>(rtcSetNewGeometryBuffer(geometry,
        RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nPoints));
      for (vtkIdType i = 0; i < nPoints; ++i)
      {
        double nm[3], w[3];
        normals->GetTuple(i, nm);
        vtkMath::Multiply3x3(normalMatrix, nm, w);
        for (int c = 0; c < 3; ++c)
        {
          out[3 * i + c] = static_cast<float>(w[c]);
        }
      }
    }
    this->Attach(geometry, normals != nullptr && normals->GetNumberOfComponents() == 3);
    return true;
  }

  // Ball-and-stick geometry as vtkMoleculeMapper draws it: spheres of radius
  // scale x (VDW or covalent or unit) radius, and round sticks between
  // bonded atoms (their ends hide inside the atoms).
  bool AddMolecule(vtkMoleculeMapper* mapper, vtkMatrix4x4* matrix)
  {
    vtkMolecule* molecule = mapper->GetInput();
    if (!molecule || molecule->GetNumberOfAtoms() == 0)
    {
      return false;
    }
    // The ray-traced scene uses the matrix's uniform scale for radii.
    const double scale = std::cbrt(std::fabs(matrix->Determinant()));
    vtkNew<vtkPeriodicTable> table;
    auto world = [matrix](const double p[3], float out[3]) {
      double in[4] = { p[0], p[1], p[2], 1.0 }, w[4];
      matrix->MultiplyPoint(in, w);
      for (int c = 0; c < 3; ++c)
      {
        out[c] = static_cast<float>(w[c] / w[3]);
      }
    };
    if (mapper->GetRenderAtoms())
    {
      const vtkIdType nAtoms = molecule->GetNumberOfAtoms();
      RTCGeometry spheres = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
      if (!spheres)
      {
        return false; // an Embree built without point geometry
      }
      float* data = static_cast<float*>(rtcSetNewGeometryBuffer(spheres, RTC_BUFFER_TYPE_VERTEX,
        0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), nAtoms));
      for (vtkIdType a = 0; a < nAtoms; ++a)
      {
        double p[3];
        molecule->GetAtomPosition(a, p);
        world(p, data + 4 * a);
        const unsigned short z = molecule->GetAtomAtomicNumber(a);
        double r = 1.0;
        switch (mapper->GetAtomicRadiusType())
        {
          case vtkMoleculeMapper::VDWRadius:
            r = table->GetVDWRadius(z);
            break;
          case vtkMoleculeMapper::CovalentRadius:
            r = table->GetCovalentRadius(z);
            break;
          default:
            break;
        }
        data[4 * a + 3] = static_cast<float>(r * mapper->GetAtomicRadiusScaleFactor() * scale);
      }
      this->Attach(spheres);
    }
    const vtkIdType nBonds = molecule->GetNumberOfBonds();
    if (mapper->GetRenderBonds() && nBonds > 0)
    {
      RTCGeometry sticks = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
      if (!sticks)
      {
        return false; // an Embree built without curve geometry
      }
      float* data = static_cast<float*>(rtcSetNewGeometryBuffer(sticks, RTC_BUFFER_TYPE_VERTEX, 0,
        RTC_FORMAT_FLOAT4, 4 * sizeof(float), 2 * nBonds));
      unsigned int* segments = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(
        sticks, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned int), nBonds));
      for (vtkIdType b = 0; b < nBonds; ++b)
      {
        vtkBond bond = molecule->GetBond(b);
        double p0[3], p1[3];
        molecule->GetAtomPosition(bond.GetBeginAtomId(), p0);
        molecule->GetAtomPosition(bond.GetEndAtomId(), p1);
        world(p0, data + 8 * b);
        world(p1, data + 8 * b + 4);
        data[8 * b + 3] = data[8 * b + 7] = static_cast<float>(mapper->GetBondRadius() * scale);
        segments[b] = static_cast<unsigned int>(2 * b);
      }
      this->Attach(sticks);
    }
    return true;
  }

  // (the scene keeps the geometry, and with it the handle kept here)
  void Attach(RTCGeometry geometry, bool withNormals = false)
  {
    rtcCommitGeometry(geometry);
    const unsigned int id = rtcAttachGeometry(this->Scene, geometry);
    rtcReleaseGeometry(geometry);
    if (this->Albedo.size() <= id)
    {
      this->Albedo.resize(id + 1, { 0.0, 0.0, 0.0 });
      this->Normals.resize(id + 1, nullptr);
    }
    this->Albedo[id] = this->CurrentAlbedo;
    this->Normals[id] = withNormals ? geometry : nullptr;
  }

  // Per geometry: its actor's albedo (VTK's diffuse colour x Diffuse).
  std::array<double, 3> CurrentAlbedo = { 0.0, 0.0, 0.0 };
  std::vector<std::array<double, 3>> Albedo;
  // Per geometry: itself where it carries point normals to interpolate,
  // else null (the facet normal is the one VTK shades with).
  std::vector<RTCGeometry> Normals;
};

vtkFXReferenceAO::vtkFXReferenceAO()
  : Impl(new Internals)
{
}

vtkFXReferenceAO::~vtkFXReferenceAO() = default;

bool vtkFXReferenceAO::Build(vtkRenderer* renderer, std::string& error)
{
  this->Impl->Reset();
  this->Impl->Device = rtcNewDevice(nullptr);
  if (!this->Impl->Device)
  {
    error = "Embree could not create a device";
    return false;
  }
  this->Impl->Scene = rtcNewScene(this->Impl->Device);
  rtcSetSceneFlags(this->Impl->Scene, RTC_SCENE_FLAG_ROBUST);
  int added = 0;
  this->Skipped.clear();
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (!actor->GetVisibility() || !actor->GetMapper())
    {
      continue;
    }
    const int addedBefore = added;
    vtkNew<vtkMatrix4x4> matrix;
    actor->GetMatrix(matrix);
    const bool smooth = actor->GetProperty()->GetInterpolation() != VTK_FLAT;
    double color[3];
    actor->GetProperty()->GetDiffuseColor(color);
    for (int c = 0; c < 3; ++c)
    {
      this->Impl->CurrentAlbedo[c] = actor->GetProperty()->GetDiffuse() * color[c];
    }
    if (auto* molecule = vtkMoleculeMapper::SafeDownCast(actor->GetMapper()))
    {
      added += this->Impl->AddMolecule(molecule, matrix) ? 1 : 0;
    }
    else if (auto* composite = vtkCompositePolyDataMapper2::SafeDownCast(actor->GetMapper()))
    {
      composite->Update();
      vtkCompositeDataSet* blocks = vtkCompositeDataSet::SafeDownCast(composite->GetInputDataObject(0, 0));
      if (!blocks)
      {
        continue;
      }
      vtkSmartPointer<vtkCompositeDataIterator> leaves;
      leaves.TakeReference(blocks->NewIterator());
      for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
      {
        if (vtkPolyData* poly = vtkPolyData::SafeDownCast(leaves->GetCurrentDataObject()))
        {
          added += this->Impl->AddPolyData(poly, matrix, smooth) ? 1 : 0;
        }
      }
    }
    else if (auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper()))
    {
      mapper->Update();
      if (vtkPolyData* poly = mapper->GetInput())
      {
        added += this->Impl->AddPolyData(poly, matrix, smooth) ? 1 : 0;
      }
    }
    if (added == addedBefore)
    {
      this->Skipped.push_back(actor->GetMapper()->GetClassName());
    }
  }
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  volumes->InitTraversal(it);
  while (vtkVolume* volume = volumes->GetNextVolume(it))
  {
    if (volume->GetVisibility())
    {
      this->Skipped.push_back(volume->GetClassName());
    }
  }
  rtcCommitScene(this->Impl->Scene);
  if (rtcGetDeviceError(this->Impl->Device) != RTC_ERROR_NONE)
  {
    error = "Embree failed to build the scene";
    return false;
  }
  if (added == 0)
  {
    error = "no geometry the reference can trace";
    return false;
  }
  return true;
}

void vtkFXReferenceAO::PixelRay(vtkMatrix4x4* inverse, int x, int y, int width, int height,
  double origin[3], double direction[3])
{
  const double ndcX = 2.0 * (x + 0.5) / width - 1.0;
  const double ndcY = 2.0 * (y + 0.5) / height - 1.0;
  double p0[4] = { ndcX, ndcY, -1.0, 1.0 }, p1[4] = { ndcX, ndcY, 1.0, 1.0 };
  double w0[4], w1[4];
  inverse->MultiplyPoint(p0, w0);
  inverse->MultiplyPoint(p1, w1);
  for (int i = 0; i < 3; ++i)
  {
    origin[i] = w0[i] / w0[3];
    direction[i] = w1[i] / w1[3] - origin[i];
  }
  vtkMath::Normalize(direction);
}

namespace
{
// Per-pixel, per-ray hash (PCG-style) to [0,1): deterministic jitter.
double Hash(unsigned int a, unsigned int b)
{
  unsigned int h = a * 747796405u + b * 2891336453u + 12345u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  h = (h >> 22u) ^ h;
  return (h & 0xffffffu) / 16777216.0;
}

// What a ray hit: its length, the facet's normal (unnormalised), and
// where on which primitive of which geometry.
struct Hit
{
  double T = 0.0;
  double Normal[3] = { 0.0, 0.0, 0.0 };
  unsigned int Geometry = RTC_INVALID_GEOMETRY_ID;
  unsigned int Primitive = 0;
  float U = 0.0f, V = 0.0f;
};

bool Intersect(RTCScene scene, const double o[3], const double d[3], double tnear, double tfar,
  Hit& hit)
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = static_cast<float>(o[0]);
  rh.ray.org_y = static_cast<float>(o[1]);
  rh.ray.org_z = static_cast<float>(o[2]);
  rh.ray.dir_x = static_cast<float>(d[0]);
  rh.ray.dir_y = static_cast<float>(d[1]);
  rh.ray.dir_z = static_cast<float>(d[2]);
  rh.ray.tnear = static_cast<float>(tnear);
  rh.ray.tfar = static_cast<float>(tfar);
  rh.ray.mask = 0xffffffffu;
  rh.ray.flags = 0;
  rh.ray.time = 0.0f;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return false;
  }
  hit.T = rh.ray.tfar;
  hit.Geometry = rh.hit.geomID;
  hit.Primitive = rh.hit.primID;
  hit.U = rh.hit.u;
  hit.V = rh.hit.v;
  hit.Normal[0] = rh.hit.Ng_x;
  hit.Normal[1] = rh.hit.Ng_y;
  hit.Normal[2] = rh.hit.Ng_z;
  return true;
}

// Turns unit vector v to the side of unit vector reference.
void TurnTo(const double reference[3], double v[3])
{
  if (vtkMath::Dot(v, reference) < 0.0)
  {
    v[0] = -v[0], v[1] = -v[1], v[2] = -v[2];
  }
}

// The normals of a hit, on the side that ray direction d sees: the facet's,
// and the one VTK shades with there, the geometry's point normals
// interpolated where it carries them (VTK turns a back face's normal to
// the viewer), else the facet's. Returns false for a degenerate facet.
bool SeenNormals(const std::vector<RTCGeometry>& normals, const Hit& hit, const double d[3],
  double facet[3], double shading[3])
{
  std::copy(hit.Normal, hit.Normal + 3, facet);
  if (vtkMath::Normalize(facet) == 0.0)
  {
    return false;
  }
  const double towardsRay[3] = { -d[0], -d[1], -d[2] };
  TurnTo(towardsRay, facet);
  std::copy(facet, facet + 3, shading);
  if (hit.Geometry < normals.size() && normals[hit.Geometry])
  {
    float n[3];
    rtcInterpolate0(normals[hit.Geometry], hit.Primitive, hit.U, hit.V,
      RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, n, 3);
    double s[3] = { n[0], n[1], n[2] };
    if (vtkMath::Normalize(s) > 0.0 && std::isfinite(s[0] + s[1] + s[2]))
    {
      TurnTo(facet, s);
      std::copy(s, s + 3, shading);
    }
  }
  return true;
}

// The surface a pixel shows, as every traced pixel starts from it: point,
// geometric (facet) normal faced towards the viewer, the normal VTK shades
// it with (SeenNormals), the primary ray's length, and the point its rays
// leave from.
struct VisibleSurface
{
  double Point[3];
  double Normal[3];
  double Shading[3];
  double Distance;
  double Start[3];
};

bool FindVisibleSurface(RTCScene scene, const std::vector<RTCGeometry>& normals,
  vtkMatrix4x4* inverse, int x, int y, int width, int height, double radius, VisibleSurface& v)
{
  double o[3], d[3];
  vtkFXReferenceAO::PixelRay(inverse, x, y, width, height, o, d);
  Hit hit;
  if (!Intersect(scene, o, d, 0.0, 1e30, hit) || !SeenNormals(normals, hit, d, v.Normal, v.Shading))
  {
    return false;
  }
  v.Distance = hit.T;
  for (int c = 0; c < 3; ++c)
  {
    v.Point[c] = o[c] + v.Distance * d[c];
  }
  // Leave the surface by a hair to avoid hitting it again: the hit point
  // carries float error growing with its coordinates and with the distance
  // travelled.
  const double offset = 1e-4 * radius + 1e-6 * (v.Distance + std::max(std::fabs(v.Point[0]),
    std::max(std::fabs(v.Point[1]), std::fabs(v.Point[2]))));
  for (int c = 0; c < 3; ++c)
  {
    v.Start[c] = v.Point[c] + offset * v.Normal[c];
  }
  return true;
}

// Stratified cosine-weighted directions around an axis (Malley's method on
// a side x side grid, jittered by a per-pixel hash: deterministic).
class CosineLobe
{
public:
  CosineLobe(const double axis[3], int side, unsigned int pixel)
    : Side(side)
    , Pixel(pixel)
  {
    double helper[3] = { 0, 0, 1 };
    if (std::fabs(axis[2]) > 0.9)
    {
      helper[0] = 1, helper[2] = 0;
    }
    std::copy(axis, axis + 3, this->Axis);
    vtkMath::Cross(helper, axis, this->Tx);
    vtkMath::Normalize(this->Tx);
    vtkMath::Cross(axis, this->Tx, this->Ty);
  }

  void Direction(int s, double w[3]) const
  {
    const double u1 = ((s % this->Side) + Hash(this->Pixel, 2 * s)) / this->Side;
    const double u2 = ((s / this->Side) + Hash(this->Pixel, 2 * s + 1)) / this->Side;
    const double r = std::sqrt(u1), phi = 2.0 * vtkMath::Pi() * u2;
    const double lx = r * std::cos(phi), ly = r * std::sin(phi);
    const double lz = std::sqrt(std::max(0.0, 1.0 - u1));
    for (int c = 0; c < 3; ++c)
    {
      w[c] = lx * this->Tx[c] + ly * this->Ty[c] + lz * this->Axis[c];
    }
  }

private:
  double Axis[3], Tx[3], Ty[3];
  int Side;
  unsigned int Pixel;
};

// The camera's inverse composite projection for a width x height image.
void InverseProjection(vtkRenderer* renderer, int width, int height, vtkMatrix4x4* inverse)
{
  inverse->DeepCopy(renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    static_cast<double>(width) / height, -1, 1));
  inverse->Invert();
}

// Runs row(y) for every row, rows handed out to `threads` threads.
template <typename Row>
void ForEachRow(int height, int threads, Row row)
{
  std::atomic<int> nextRow(0);
  auto work = [&]() {
    for (int y = nextRow++; y < height; y = nextRow++)
    {
      row(y);
    }
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < std::max(1, threads); ++i)
  {
    pool.emplace_back(work);
  }
  for (auto& thread : pool)
  {
    thread.join();
  }
}
}

vtkFXReferenceAO::Result vtkFXReferenceAO::Trace(
  vtkRenderer* renderer, int width, int height, double radius, int raysPerPixel, int falloff,
  int threads, const std::vector<float>* shadingNormals) const
{
  if (falloff != Binary && falloff != CubeRoot)
  {
    std::cerr << "vtkFXReferenceAO: falloff " << falloff
              << " is neither Binary (0) nor CubeRoot (1); tracing Binary\n";
    falloff = Binary;
  }
  Result result;
  result.Width = width;
  result.Height = height;
  result.Occlusion.assign(static_cast<size_t>(width) * height, -1.0f);
  result.StandardError.assign(result.Occlusion.size(), 0.0f);
  if (!this->Impl->Scene)
  {
    return result;
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkNew<vtkMatrix4x4> inverse;
  InverseProjection(renderer, width, height, inverse);
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(raysPerPixel))));
  const int rays = side * side;
  std::vector<double> variance(result.Occlusion.size(), 0.0);
  RTCScene scene = this->Impl->Scene;
  const std::vector<RTCGeometry>& normals = this->Impl->Normals;
  ForEachRow(height, threads, [&](int y) {
    for (int x = 0; x < width; ++x)
    {
      VisibleSurface v;
      if (!FindVisibleSurface(scene, normals, inverse, x, y, width, height, radius, v))
      {
        continue;
      }
      const double* n = v.Normal;
      const unsigned int pixel = static_cast<unsigned int>(y * width + x);
      // The lobe's axis: the shading normal when given (turned to the
      // geometric normal's side), else the normal the mesh is shaded with
      // (its interpolated point normals, as the G-buffer's geometric
      // normal; the facet's where it has none). Rays below the facet are
      // left out of both sums: an open surface is 1 whatever its normals.
      double axis[3] = { v.Shading[0], v.Shading[1], v.Shading[2] };
      if (shadingNormals && shadingNormals->size() >= 3 * (static_cast<size_t>(pixel) + 1))
      {
        double s[3] = { (*shadingNormals)[3 * pixel], (*shadingNormals)[3 * pixel + 1],
          (*shadingNormals)[3 * pixel + 2] };
        if (vtkMath::Normalize(s) > 0.0 && std::isfinite(s[0] + s[1] + s[2]))
        {
          TurnTo(n, s);
          std::copy(s, s + 3, axis);
        }
      }
      const CosineLobe lobe(axis, side, pixel);
      double sum = 0.0, sum2 = 0.0;
      int counted = 0;
      for (int s = 0; s < rays; ++s)
      {
        double w[3];
        lobe.Direction(s, w);
        if (vtkMath::Dot(w, n) <= 0.0)
        {
          continue; // into the surface: outside the geometric hemisphere
        }
        ++counted;
        Hit hit;
        double f = 0.0;
        if (Intersect(scene, v.Start, w, 0.0, radius, hit))
        {
          f = falloff == Binary ? 1.0
                                : 1.0 - std::cbrt(std::min(1.0, std::max(0.0, hit.T / radius)));
        }
        sum += f;
        sum2 += f * f;
      }
      // (the axis lies in the geometric hemisphere, so most rays count)
      const int used = std::max(1, counted);
      const double mean = sum / used;
      result.Occlusion[pixel] = static_cast<float>(1.0 - mean);
      variance[pixel] = std::max(0.0, sum2 / used - mean * mean) / used;
      result.StandardError[pixel] = static_cast<float>(std::sqrt(variance[pixel]));
    }
  });
  double total = 0.0;
  for (size_t i = 0; i < variance.size(); ++i)
  {
    if (result.Occlusion[i] >= 0.0f)
    {
      total += variance[i];
      ++result.CoveredPixels;
    }
  }
  result.StandardErrorRMS = result.CoveredPixels ? std::sqrt(total / result.CoveredPixels) : 0.0;
  timer->StopTimer();
  result.Seconds = timer->GetElapsedTime();
  return result;
}

namespace
{
// A light as VTK's Phong model applies it (vtkFXLightingFS.glsl), in world
// coordinates: colour x intensity, direction from the light, position,
// attenuation and cone.
struct WorldLight
{
  double Color[3];
  double Direction[3];
  double Position[3];
  double Attenuation[3];
  double ConeAngle;
  double Exponent;
  bool Positional;
};

std::vector<WorldLight> WorldLights(vtkRenderer* renderer)
{
  std::vector<WorldLight> lights;
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (light->GetSwitch() <= 0)
    {
      continue;
    }
    WorldLight l;
    double color[3], focal[3];
    light->GetDiffuseColor(color);
    light->GetTransformedPosition(l.Position);
    light->GetTransformedFocalPoint(focal);
    for (int c = 0; c < 3; ++c)
    {
      l.Color[c] = light->GetIntensity() * color[c];
      l.Direction[c] = focal[c] - l.Position[c];
    }
    vtkMath::Normalize(l.Direction);
    light->GetAttenuationValues(l.Attenuation);
    l.ConeAngle = light->GetConeAngle();
    l.Exponent = light->GetExponent();
    l.Positional = light->GetPositional() != 0;
    lights.push_back(l);
  }
  return lights;
}

// VTK's diffuse light at a point of normal n (no shadows).
void DirectLight(const std::vector<WorldLight>& lights, const double p[3], const double n[3],
  double out[3])
{
  out[0] = out[1] = out[2] = 0.0;
  for (const WorldLight& l : lights)
  {
    double toSurface[3] = { l.Direction[0], l.Direction[1], l.Direction[2] };
    double attenuation = 1.0;
    if (l.Positional)
    {
      for (int c = 0; c < 3; ++c)
      {
        toSurface[c] = p[c] - l.Position[c];
      }
      const double d = vtkMath::Normalize(toSurface);
      attenuation = 1.0 / (l.Attenuation[0] + l.Attenuation[1] * d + l.Attenuation[2] * d * d);
      if (l.ConeAngle < 90.0)
      {
        const double coneDot = vtkMath::Dot(toSurface, l.Direction);
        attenuation = coneDot >= std::cos(vtkMath::RadiansFromDegrees(l.ConeAngle))
          ? attenuation * std::pow(coneDot, l.Exponent)
          : 0.0;
      }
    }
    const double df = std::max(0.0, -attenuation * vtkMath::Dot(n, toSurface));
    for (int c = 0; c < 3; ++c)
    {
      out[c] += df * l.Color[c];
    }
  }
}
}

std::vector<float> vtkFXReferenceAO::TraceBleeding(
  vtkRenderer* renderer, int width, int height, double radius, int raysPerPixel, int threads) const
{
  std::vector<float> result(3 * static_cast<size_t>(width) * height, -1.0f);
  if (!this->Impl->Scene)
  {
    return result;
  }
  const std::vector<WorldLight> lights = WorldLights(renderer);
  vtkNew<vtkMatrix4x4> inverse;
  InverseProjection(renderer, width, height, inverse);
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(raysPerPixel))));
  const int rays = side * side;
  RTCScene scene = this->Impl->Scene;
  const auto& albedo = this->Impl->Albedo;
  const std::vector<RTCGeometry>& normals = this->Impl->Normals;
  ForEachRow(height, threads, [&](int y) {
    for (int x = 0; x < width; ++x)
    {
      VisibleSurface v;
      if (!FindVisibleSurface(scene, normals, inverse, x, y, width, height, radius, v))
      {
        continue;
      }
      const unsigned int pixel = static_cast<unsigned int>(y * width + x);
      const CosineLobe lobe(v.Shading, side, pixel);
      double sum[3] = { 0.0, 0.0, 0.0 };
      int counted = 0; // (rays above the facet, as Trace counts them)
      for (int s = 0; s < rays; ++s)
      {
        double w[3];
        lobe.Direction(s, w);
        if (vtkMath::Dot(w, v.Normal) <= 0.0)
        {
          continue;
        }
        ++counted;
        Hit hit;
        double facet[3], shading[3];
        if (!Intersect(scene, v.Start, w, 0.0, radius, hit) || hit.Geometry >= albedo.size() ||
          !SeenNormals(normals, hit, w, facet, shading))
        {
          continue;
        }
        const double at[3] = { v.Start[0] + hit.T * w[0], v.Start[1] + hit.T * w[1],
          v.Start[2] + hit.T * w[2] };
        double light[3];
        DirectLight(lights, at, shading, light);
        for (int c = 0; c < 3; ++c)
        {
          sum[c] += albedo[hit.Geometry][c] * light[c];
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        result[3 * pixel + c] = static_cast<float>(sum[c] / std::max(1, counted));
      }
    }
  });
  return result;
}
