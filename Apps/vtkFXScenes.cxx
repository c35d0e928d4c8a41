#include "vtkFXScenes.h"

#include "vtkFXGBufferPass.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkContourFilter.h"
#include "vtkCamera.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkColorTransferFunction.h"
#include "vtkConeSource.h"
#include "vtkCylinderSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRTAnalyticSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkCubeSource.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkElevationFilter.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMolecule.h"
#include "vtkMoleculeMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPDBReader.h"
#include "vtkPLYReader.h"
#include "vtkPNGReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataTangents.h"
#include "vtkTriangleFilter.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#ifndef VTKFX_SOURCE_DATA_DIR
#define VTKFX_SOURCE_DATA_DIR "Data"
#endif

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string Extension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  return dot == std::string::npos ? std::string() : Lower(path.substr(dot + 1));
}

bool FileReadable(const std::string& path)
{
  std::ifstream f(path.c_str());
  return f.good();
}

// Numbers in [0, 1) from a fixed seed (a linear congruential generator):
// scenes built from them are the same on every run and machine.
class Uniform
{
public:
  explicit Uniform(unsigned int seed)
    : State(seed)
  {
  }
  double operator()()
  {
    this->State = this->State * 1664525u + 1013904223u;
    return (this->State >> 8) / 16777216.0;
  }

private:
  unsigned int State;
};

vtkSmartPointer<vtkActor> MakeActor(vtkPolyData* data, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

// Point normals for a mesh that has none: smooth everywhere, or, with
// `splitAtFeatures`, split at edges sharper than 30 degrees
// (vtkPolyDataNormals' and ParaView's Generate Surface Normals defaults), so
// that a CAD part's edges stay sharp: normals averaged across a 90 degree
// edge smear its shading and tilt the tangent plane that screen-space
// occlusion measures from (the fandisk's convex edges came out dark, where
// the ray-traced reference, from the geometric normal, has none).
vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* in, bool splitAtFeatures = false)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(in);
  normals->SetSplitting(splitAtFeatures);
  normals->SetFeatureAngle(30.0);
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->Update();
  return normals->GetOutput();
}

vtkSmartPointer<vtkPolyData> Sphere(double cx, double cy, double cz, double radius, int res = 48)
{
  vtkNew<vtkSphereSource> s;
  s->SetCenter(cx, cy, cz);
  s->SetRadius(radius);
  s->SetThetaResolution(res);
  s->SetPhiResolution(res / 2 + 1);
  s->Update();
  return s->GetOutput();
}

vtkSmartPointer<vtkPolyData> ReadPolyData(const std::string& path, std::string& error)
{
  const std::string ext = Extension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == "obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "vtk")
  {
    auto r = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    error = "unsupported file type '." + ext + "' (use .obj, .ply, .stl, .vtp, .vtk or .pdb)";
    return nullptr;
  }
  reader->Update();
  vtkDataObject* out = reader->GetOutputDataObject(0);
  vtkSmartPointer<vtkPolyData> poly = vtkPolyData::SafeDownCast(out);
  if (!poly && vtkDataSet::SafeDownCast(out))
  {
    vtkNew<vtkDataSetSurfaceFilter> surface;
    surface->SetInputData(out);
    surface->Update();
    poly = surface->GetOutput();
  }
  if (!poly)
  {
    error = "could not read '" + path + "' as a dataset";
    return nullptr;
  }
  if (poly->GetNumberOfCells() == 0 || poly->GetNumberOfPoints() == 0)
  {
    error = "'" + path + "' holds no geometry (empty dataset or unreadable file)";
    return nullptr;
  }
  return poly;
}

// A ground plane just under the bounds, in the plane perpendicular to +y.
void AddGround(vtkRenderer* renderer, const double b[6])
{
  const double dx = b[1] - b[0], dy = b[3] - b[2], dz = b[5] - b[4];
  const double size = 0.9 * std::max(std::max(dx, dz), 0.5 * dy) + 1e-30;
  const double cx = 0.5 * (b[0] + b[1]), cz = 0.5 * (b[4] + b[5]);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(cx - size, b[2], cz - size);
  plane->SetPoint1(cx + size, b[2], cz - size);
  plane->SetPoint2(cx - size, b[2], cz + size);
  plane->SetResolution(1, 1);
  plane->Update();
  auto actor = MakeActor(plane->GetOutput(), 0.8, 0.8, 0.78);
  renderer->AddActor(actor);
}

// Frames `bounds` (the data, not the ground) from above and to the side.
void FrameCamera(vtkRenderer* renderer, const double bounds[6])
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCamera(bounds);
  camera->Azimuth(30);
  camera->Elevation(25);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera(bounds);
  camera->Zoom(1.2);
  renderer->ResetCameraClippingRange();
}

void SceneSpheres(vtkRenderer* renderer)
{
  const double colors[5][3] = { { 0.9, 0.3, 0.2 }, { 0.2, 0.6, 0.9 }, { 0.3, 0.8, 0.3 },
    { 0.95, 0.8, 0.2 }, { 0.7, 0.4, 0.8 } };
  for (int i = 0; i < 5; ++i)
  {
    const double angle = 2.0 * vtkMath::Pi() * i / 5.0;
    const double r = 0.35 + 0.1 * i;
    auto actor = MakeActor(Sphere(1.3 * std::cos(angle), r, 1.3 * std::sin(angle), r),
      colors[i][0], colors[i][1], colors[i][2]);
    if (i % 2 == 0)
    {
      actor->GetProperty()->SetSpecular(0.4);
      actor->GetProperty()->SetSpecularPower(30.0);
    }
    renderer->AddActor(actor);
  }
}

void SceneCorner(vtkRenderer* renderer)
{
  // A wall meeting the ground at a right angle, a box in the corner.
  vtkNew<vtkPlaneSource> wall;
  wall->SetOrigin(-2, 0, -1);
  wall->SetPoint1(2, 0, -1);
  wall->SetPoint2(-2, 2.5, -1);
  wall->Update();
  renderer->AddActor(MakeActor(wall->GetOutput(), 0.85, 0.85, 0.85));
  vtkNew<vtkCubeSource> box;
  // (clear of the wall and the ground by 1% of its size: coplanar faces
  // would z-fight, differently at every scale)
  box->SetBounds(-0.5, 0.3, 0.008, 0.8, -0.992, -0.2);
  box->Update();
  renderer->AddActor(MakeActor(box->GetOutput(), 0.9, 0.6, 0.3));
  renderer->AddActor(MakeActor(Sphere(1.0, 0.5, 0.0, 0.5), 0.3, 0.5, 0.9));
}

// Point scalar `name` = height(point) on `poly`, in world units.
template <typename HeightFunction>
void AddHeight(vtkPolyData* poly, const char* name, HeightFunction height)
{
  vtkNew<vtkFloatArray> values;
  values->SetName(name);
  values->SetNumberOfTuples(poly->GetNumberOfPoints());
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
  {
    double p[3];
    poly->GetPoint(i, p);
    values->SetValue(i, static_cast<float>(height(p)));
  }
  poly->GetPointData()->AddArray(values);
}

void SceneBumps(vtkRenderer* renderer)
{
  // Scalar bumps (vtkFXGBufferPass::SetBump) on flat and curved geometry,
  // near occluders: what directional occlusion shows and plain AO cannot.
  // A wall of rivets (domes 0.04 high on a 0.4 grid) meeting the ground,
  vtkNew<vtkPlaneSource> wall;
  wall->SetOrigin(-2, 0, -1);
  wall->SetPoint1(2, 0, -1);
  wall->SetPoint2(-2, 2.5, -1);
  wall->SetResolution(320, 200);
  wall->Update();
  vtkSmartPointer<vtkPolyData> wallData = wall->GetOutput();
  AddHeight(wallData, "height", [](const double p[3]) {
    const double cell = 0.4, radius = 0.13;
    const double dx = p[0] - cell * std::floor(p[0] / cell) - 0.5 * cell;
    const double dy = p[1] - cell * std::floor(p[1] / cell) - 0.5 * cell;
    const double r2 = (dx * dx + dy * dy) / (radius * radius);
    return r2 < 1.0 ? 0.04 * std::sqrt(1.0 - r2) : 0.0;
  });
  auto wallActor = MakeActor(wallData, 0.85, 0.85, 0.85);
  vtkFXGBufferPass::SetBump(wallActor, "height", 1.0);
  renderer->AddActor(wallActor);
  // a sphere with horizontal ridges (a scalar field's bumps on a curved
  // surface),
  vtkSmartPointer<vtkPolyData> ball = Sphere(0.7, 0.6, -0.2, 0.6, 160);
  AddHeight(ball, "ridges", [](const double p[3]) { return 0.012 * std::sin(40.0 * p[1]); });
  auto ballActor = MakeActor(ball, 0.3, 0.5, 0.9);
  vtkFXGBufferPass::SetBump(ballActor, "ridges", 1.0);
  renderer->AddActor(ballActor);
  // and a box without a bump in the corner.
  vtkNew<vtkCubeSource> box;
  box->SetBounds(-1.3, -0.6, 0.008, 0.7, -0.992, -0.3);
  box->Update();
  renderer->AddActor(MakeActor(box->GetOutput(), 0.9, 0.6, 0.3));
}

void SceneTerrain(vtkRenderer* renderer)
{
  // A scalar-bumped terrain: smooth hills as geometry (y up), and a finer
  // "detail" elevation field, gullies a few hundredths deep, that is not in
  // the mesh but shades it through vtkFXGBufferPass::SetBump, as a
  // high-resolution elevation over a coarse grid would.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3, 0, -3);
  plane->SetPoint1(-3, 0, 3); // (normal +y)
  plane->SetPoint2(3, 0, -3);
  plane->SetResolution(240, 240);
  plane->Update();
  vtkSmartPointer<vtkPolyData> land = plane->GetOutput();
  const auto hill = [](double x, double z, double cx, double cz, double height, double width) {
    return height * std::exp(-((x - cx) * (x - cx) + (z - cz) * (z - cz)) / width);
  };
  vtkPoints* points = land->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    p[1] = hill(p[0], p[2], 1.0, 0.5, 0.9, 0.9) + hill(p[0], p[2], -1.2, -1.0, 0.6, 0.5) +
      hill(p[0], p[2], -0.6, 1.6, 0.5, 0.4);
    points->SetPoint(i, p);
  }
  land = WithNormals(land);
  AddHeight(land, "detail", [](const double p[3]) {
    const double a = std::sin(9.0 * p[0] + 2.0 * std::sin(5.0 * p[2]));
    const double b = std::sin(7.0 * p[2] + 2.0 * std::sin(4.0 * p[0]));
    return -0.02 * (1.0 - std::fabs(a)) * (1.0 - std::fabs(b));
  });
  auto actor = MakeActor(land, 0.72, 0.66, 0.55);
  vtkFXGBufferPass::SetBump(actor, "detail", 1.0);
  renderer->AddActor(actor);
  // The block it tops, as a relief model stands on a table (a sheet
  // floating over the ground would cast an overhang shadow no screen-space
  // estimator sees, which is not what this scene is for).
  vtkNew<vtkCubeSource> block;
  block->SetBounds(-3, 3, -0.6, -0.005, -3, 3);
  block->Update();
  renderer->AddActor(MakeActor(block->GetOutput(), 0.55, 0.5, 0.42));
}

void SceneScalars(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(96);
  source->SetPhiResolution(64);
  source->Update();
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputData(source->GetOutput());
  elevation->SetLowPoint(0, -0.5, 0);
  elevation->SetHighPoint(0, 0.5, 0);
  elevation->Update();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(vtkPolyData::SafeDownCast(elevation->GetOutput()));
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0, 1);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);

  // The same data with scalars interpolated before mapping (colour texture).
  vtkNew<vtkPolyDataMapper> textured;
  textured->SetInputData(vtkPolyData::SafeDownCast(elevation->GetOutput()));
  textured->SetLookupTable(lut);
  textured->SetScalarRange(0, 1);
  textured->InterpolateScalarsBeforeMappingOn();
  vtkNew<vtkActor> actor2;
  actor2->SetMapper(textured);
  actor2->SetPosition(1.2, 0, 0);
  renderer->AddActor(actor2);
}

bool SceneTextured(vtkRenderer* renderer, std::string& error)
{
  const std::string dir = vtkFXScenes::DataDirectory();
  auto poly = ReadPolyData(dir + "/spot.obj", error);
  vtkNew<vtkPNGReader> png;
  png->SetFileName((dir + "/spot_texture.png").c_str());
  if (!poly || !FileReadable(dir + "/spot_texture.png"))
  {
    error = "scene:textured needs spot.obj and spot_texture.png in " + dir;
    return false;
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(png->GetOutputPort());
  texture->InterpolateOn();
  auto actor = MakeActor(poly, 1, 1, 1);
  actor->SetTexture(texture);
  renderer->AddActor(actor);
  return true;
}

// A tangent-space normal map (RGB = n / 2 + 1/2, blue up) of a height
// field of rounded scales on a 24 x 24 grid over the texture square,
// `size` texels wide: dh/du and dh/dv by central differences.
vtkSmartPointer<vtkImageData> ScalesNormalMap(int size)
{
  const auto height = [](double u, double v) {
    const double cells = 24.0;
    const double x = u * cells - std::floor(u * cells) - 0.5;
    const double y = v * cells - std::floor(v * cells) - 0.5;
    const double r2 = 4.0 * (x * x + y * y);
    return r2 < 1.0 ? std::sqrt(1.0 - r2) : 0.0;
  };
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  const double h = 1.0 / size, strength = 0.02 / h; // slope per texel scale
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const double u = (i + 0.5) * h, v = (j + 0.5) * h;
      double n[3] = { -(height(u + h, v) - height(u - h, v)) * 0.5 * strength,
        -(height(u, v + h) - height(u, v - h)) * 0.5 * strength, 1.0 };
      vtkMath::Normalize(n);
      for (int c = 0; c < 3; ++c)
      {
        texels[3 * (j * size + i) + c] =
          static_cast<unsigned char>(std::lround(127.5 * (n[c] + 1.0)));
      }
    }
  }
  return image;
}

bool SceneNormalMap(vtkRenderer* renderer, std::string& error)
{
  // Spot with a normal texture generated from a height map of scales,
  // tangents from vtkPolyDataTangents: VTK 9.1 applies the map in its own
  // lighting, and directional occlusion resolves with it.
  const std::string dir = vtkFXScenes::DataDirectory();
  auto poly = ReadPolyData(dir + "/spot.obj", error);
  if (!poly || !poly->GetPointData()->GetTCoords())
  {
    error = "scene:normalmap needs spot.obj (with texture coordinates) in " + dir;
    return false;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(poly->GetPointData()->GetNormals() ? poly.GetPointer()
                                                             : WithNormals(poly).GetPointer());
  vtkNew<vtkPolyDataTangents> tangents;
  tangents->SetInputConnection(triangles->GetOutputPort());
  tangents->Update();
  vtkNew<vtkTexture> normalMap;
  normalMap->SetInputData(ScalesNormalMap(1024));
  normalMap->InterpolateOn();
  normalMap->MipmapOn();
  auto actor = MakeActor(tangents->GetOutput(), 0.9, 0.85, 0.8);
  actor->GetProperty()->SetNormalTexture(normalMap);
  renderer->AddActor(actor);
  return true;
}

// n points spread evenly on a sphere around (0, height, 0) (Fibonacci
// spiral), deterministic so that baselines do not depend on a random seed.
vtkSmartPointer<vtkPolyData> SpherePoints(int n, double radius, double height)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double y = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(1.0 - y * y);
    const double phi = golden * i;
    const vtkIdType id = points->InsertNextPoint(
      radius * r * std::cos(phi), height + radius * y, radius * r * std::sin(phi));
    verts->InsertNextCell(1, &id);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  return poly;
}

void SceneGlyphs(vtkRenderer* renderer)
{
  auto points = SpherePoints(60, 1.0, 1.0);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(16);
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputData(points);
  mapper->SetSourceConnection(cone->GetOutputPort());
  mapper->SetScaleFactor(0.25);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.5, 0.2);
  renderer->AddActor(actor);
}

void SceneComposite(vtkRenderer* renderer)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  for (int i = 0; i < 4; ++i)
  {
    blocks->SetBlock(i, Sphere(i * 0.9, 0.4, 0, 0.4, 32));
  }
  vtkNew<vtkCompositePolyDataMapper2> mapper;
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  mapper->SetCompositeDataDisplayAttributes(attributes);
  mapper->SetInputDataObject(blocks);
  mapper->SetBlockColor(1, 0.9, 0.2, 0.2);
  mapper->SetBlockColor(3, 0.2, 0.3, 0.9);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.8, 0.3);
  renderer->AddActor(actor);
  // A per-actor transform.
  auto moved = MakeActor(Sphere(0, 0.3, 0, 0.3), 0.4, 0.8, 0.5);
  moved->SetPosition(1.3, 0.0, 1.0);
  moved->SetScale(1.0, 2.0, 1.0);
  moved->RotateZ(20);
  renderer->AddActor(moved);
}

void SceneSplats(vtkRenderer* renderer)
{
  auto points = SpherePoints(400, 1.0, 1.0);
  vtkNew<vtkPointGaussianMapper> mapper;
  mapper->SetInputData(points);
  mapper->EmissiveOff();
  mapper->SetScaleFactor(0.06);
  // Opaque round splats: discard outside the unit disc.
  mapper->SetSplatShaderCode("//VTK::Color::Impl\n"
                             "  float dist = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
                             "  if (dist > 1.0) { discard; }\n");
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.2, 0.7, 0.9);
  renderer->AddActor(actor);
}

// Emissive data for glow: three lit spheres carrying an EMISSIVE_COLOR
// (one above 1, an HDR emission), among the plain spheres of scene:spheres.
void SceneGlow(vtkRenderer* renderer)
{
  SceneSpheres(renderer);
  const double emissive[3][4] = { { -0.6, 0.2, 0.9, 0.2 }, { 0.5, 0.15, 0.2, 0.15 },
    { 0.0, 0.25, -0.5, 0.25 } };
  const double emission[3][3] = { { 4.0, 1.2, 0.3 }, { 0.2, 0.9, 1.0 }, { 0.9, 0.9, 0.3 } };
  for (int i = 0; i < 3; ++i)
  {
    auto actor = MakeActor(Sphere(emissive[i][0], emissive[i][1], emissive[i][2], emissive[i][3]),
      0.2, 0.2, 0.2);
    vtkNew<vtkInformation> keys;
    keys->Set(vtkFXGBufferPass::EMISSIVE_COLOR(), emission[i], 3);
    actor->SetPropertyKeys(keys);
    renderer->AddActor(actor);
  }
}

// A translucent isosurface (a blob of three spheres' summed fields, opacity
// 0.45) floating over scene:spheres: shadows from translucent data.
void SceneIsoShadow(vtkRenderer* renderer)
{
  SceneSpheres(renderer);
  vtkNew<vtkImageData> field;
  const int n = 48;
  field->SetDimensions(n, n, n);
  field->SetOrigin(-1.6, 1.2, -1.2);
  field->SetSpacing(3.2 / (n - 1), 1.4 / (n - 1), 2.4 / (n - 1));
  field->AllocateScalars(VTK_FLOAT, 1);
  const double centers[3][3] = { { -0.7, 1.9, 0.0 }, { 0.4, 1.85, 0.3 }, { 0.1, 1.95, -0.5 } };
  auto* values = static_cast<float*>(field->GetScalarPointer());
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        double p[3];
        field->GetPoint(field->ComputePointId(std::array<int, 3>{ i, j, k }.data()), p);
        double v = 0.0;
        for (const auto& c : centers)
        {
          v += 0.12 / (vtkMath::Distance2BetweenPoints(p, c) + 1e-3);
        }
        values[(k * n + j) * n + i] = static_cast<float>(v);
      }
    }
  }
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(field);
  contour->SetValue(0, 1.0);
  contour->Update();
  auto actor = MakeActor(contour->GetOutput(), 0.3, 0.6, 0.9);
  actor->GetProperty()->SetOpacity(0.45);
  renderer->AddActor(actor);
}

// A cloud of 240 small translucent spheres (opacity 0.3) over
// scene:spheres: particle-like casters, up to some 20 surfaces along a
// light ray, where the AVSM's compression shows.
void SceneCloud(vtkRenderer* renderer)
{
  SceneSpheres(renderer);
  vtkNew<vtkAppendPolyData> cloud;
  Uniform random(2024u); // every run builds the same cloud
  for (int i = 0; i < 240; ++i)
  {
    // Denser towards the middle: the sum of two uniform numbers.
    const double x = 1.8 * (random() + random() - 1.0);
    const double y = 1.6 + 0.5 * (random() + random() - 1.0);
    const double z = 1.4 * (random() + random() - 1.0);
    cloud->AddInputData(Sphere(x, y, z, 0.09 + 0.06 * random(), 8));
  }
  cloud->Update();
  auto actor = MakeActor(cloud->GetOutput(), 0.85, 0.88, 0.95);
  actor->GetProperty()->SetOpacity(0.3);
  renderer->AddActor(actor);
}

// A particle cloud of 2000 point-gaussian splats (VTK's gaussian, scale
// 0.06, opacity 0.25; a quarter of their colour ambient, which a shadow
// leaves) over scene:spheres, spread as scene:cloud's spheres: the
// particle data AVSM is made for; each splat casts as a sphere.
void SceneParticles(vtkRenderer* renderer)
{
  SceneSpheres(renderer);
  vtkNew<vtkPoints> points;
  Uniform random(2025u); // every run builds the same cloud
  for (int i = 0; i < 2000; ++i)
  {
    const double x = 1.8 * (random() + random() - 1.0);
    const double y = 1.6 + 0.5 * (random() + random() - 1.0);
    const double z = 1.4 * (random() + random() - 1.0);
    points->InsertNextPoint(x, y, z);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkPointGaussianMapper> mapper;
  mapper->SetInputData(cloud);
  mapper->EmissiveOff();
  mapper->SetScaleFactor(0.06);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.88, 0.95);
  actor->GetProperty()->SetOpacity(0.25);
  actor->GetProperty()->SetAmbient(0.25);
  actor->GetProperty()->SetDiffuse(0.75);
  renderer->AddActor(actor);
}

void SceneLights(vtkRenderer* renderer)
{
  SceneSpheres(renderer);
  // Scene lights: a positional spot with cone and attenuation, a directional
  // light, and a camera light.
  vtkNew<vtkLight> spot;
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(0, 4, 2);
  spot->SetFocalPoint(0, 0, 0);
  spot->SetConeAngle(35);
  spot->SetExponent(2);
  spot->SetAttenuationValues(1, 0.1, 0.02);
  spot->SetColor(1.0, 0.9, 0.8);
  spot->SetIntensity(0.9);
  renderer->AddLight(spot);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(-3, 2, 1);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetColor(0.6, 0.7, 1.0);
  sun->SetIntensity(0.4);
  renderer->AddLight(sun);
  vtkNew<vtkLight> cameraLight;
  cameraLight->SetLightTypeToCameraLight();
  cameraLight->SetPosition(1, 1, 1);
  cameraLight->SetFocalPoint(0, 0, 0);
  cameraLight->SetIntensity(0.3);
  renderer->AddLight(cameraLight);
}

void SceneMixed(vtkRenderer* renderer)
{
  // Opaque, translucent and 2D overlay props together, two-sided lighting
  // seen on an open surface, an unlit prop and ambient/specular terms.
  SceneScalars(renderer);
  auto glass = MakeActor(Sphere(0.6, 0.2, 0.9, 0.45), 0.3, 0.9, 0.6);
  glass->GetProperty()->SetOpacity(0.4);
  renderer->AddActor(glass);
  vtkNew<vtkSphereSource> half;
  half->SetCenter(-1.2, 0.5, 0);
  half->SetRadius(0.5);
  half->SetThetaResolution(48);
  half->SetEndPhi(110); // open: the inside shows back faces
  half->Update();
  auto bowl = MakeActor(half->GetOutput(), 0.9, 0.7, 0.4);
  bowl->GetProperty()->SetAmbient(0.2);
  bowl->GetProperty()->SetSpecular(0.5);
  bowl->GetProperty()->SetSpecularPower(60);
  renderer->AddActor(bowl);
  auto unlit = MakeActor(Sphere(0.0, 0.2, 1.2, 0.2), 1.0, 0.9, 0.2);
  unlit->GetProperty()->LightingOff();
  renderer->AddActor(unlit);
  vtkNew<vtkTextActor> text;
  text->SetInput("vtkFX");
  text->GetTextProperty()->SetFontSize(24);
  text->GetTextProperty()->SetColor(1, 1, 1);
  text->SetPosition(10, 10);
  renderer->AddViewProp(text);
  vtkNew<vtkScalarBarActor> bar;
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  bar->SetLookupTable(lut);
  bar->SetWidth(0.08);
  bar->SetHeight(0.5);
  bar->SetPosition(0.9, 0.3);
  renderer->AddViewProp(bar);
}

void SceneVolume(vtkRenderer* renderer)
{
  // A ray-cast volume crossing an opaque sphere: the volume must stop at
  // the sphere's surface, i.e. be depth-tested against the G-buffer depth.
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-16, 16, -16, 16, -16, 16);
  source->Update();
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(40, 0.1, 0.2, 0.9);
  color->AddRGBPoint(160, 0.9, 0.9, 0.2);
  color->AddRGBPoint(280, 0.9, 0.1, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(280, 0.08);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->GetProperty()->SetColor(color);
  volume->GetProperty()->SetScalarOpacity(opacity);
  volume->GetProperty()->SetInterpolationTypeToLinear();
  volume->SetScale(1.0 / 16.0);
  volume->SetPosition(0, 1.0, 0);
  renderer->AddVolume(volume);
  renderer->AddActor(MakeActor(Sphere(0.4, 1.0, 0.3, 0.6), 0.9, 0.9, 0.9));
}

void SceneEdges(vtkRenderer* renderer)
{
  // Everything VTK shades through paths other than plain surfaces: surface
  // edges (colour in the ambient term), a lit wireframe, points drawn as
  // spheres and lines drawn as tubes (impostors that write their own depth),
  // and an open tube whose inside shows a backface property.
  auto edged = MakeActor(Sphere(-1.2, 0.5, 0, 0.5, 16), 0.8, 0.8, 0.9);
  edged->GetProperty()->EdgeVisibilityOn();
  edged->GetProperty()->SetEdgeColor(0.9, 0.1, 0.1);
  renderer->AddActor(edged);
  auto wire = MakeActor(Sphere(0, 0.5, -0.8, 0.5, 20), 0.3, 0.9, 0.4);
  wire->GetProperty()->SetRepresentationToWireframe();
  renderer->AddActor(wire);
  auto points = MakeActor(SpherePoints(40, 0.4, 0.5), 0.9, 0.6, 0.2);
  points->SetPosition(0.0, 0.0, 0.8);
  points->GetProperty()->SetRepresentationToPoints();
  points->GetProperty()->RenderPointsAsSpheresOn();
  points->GetProperty()->SetPointSize(9);
  renderer->AddActor(points);
  auto tubes = MakeActor(Sphere(1.2, 0.5, 0.6, 0.35, 10), 0.2, 0.5, 0.9);
  tubes->GetProperty()->SetRepresentationToWireframe();
  tubes->GetProperty()->RenderLinesAsTubesOn();
  tubes->GetProperty()->SetLineWidth(4);
  renderer->AddActor(tubes);
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetCenter(1.1, 0.4, -0.6);
  cylinder->SetRadius(0.35);
  cylinder->SetHeight(0.8);
  cylinder->SetResolution(32);
  cylinder->CappingOff();
  cylinder->Update();
  auto open = MakeActor(cylinder->GetOutput(), 0.9, 0.9, 0.3);
  vtkNew<vtkProperty> inside;
  inside->SetColor(0.6, 0.2, 0.7);
  inside->SetSpecular(0.4);
  inside->SetSpecularPower(20);
  open->SetBackfaceProperty(inside);
  renderer->AddActor(open);
}

bool PopulateMolecule(vtkRenderer* renderer, const std::string& path, std::string& error)
{
  vtkNew<vtkPDBReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkMolecule* molecule = vtkMolecule::SafeDownCast(reader->GetOutputDataObject(1));
  if (!molecule || molecule->GetNumberOfAtoms() == 0)
  {
    error = "'" + path + "' holds no atoms";
    return false;
  }
  vtkNew<vtkMoleculeMapper> mapper;
  mapper->SetInputData(molecule);
  mapper->UseBallAndStickSettings();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  return true;
}

bool PopulateBuiltIn(vtkRenderer* renderer, const std::string& name, std::string& error)
{
  if (name == "scene:spheres")
    SceneSpheres(renderer);
  else if (name == "scene:corner")
    SceneCorner(renderer);
  else if (name == "scene:bumps")
    SceneBumps(renderer);
  else if (name == "scene:normalmap")
    return SceneNormalMap(renderer, error);
  else if (name == "scene:terrain")
    SceneTerrain(renderer);
  else if (name == "scene:scalars")
    SceneScalars(renderer);
  else if (name == "scene:textured")
    return SceneTextured(renderer, error);
  else if (name == "scene:glyphs")
    SceneGlyphs(renderer);
  else if (name == "scene:composite")
    SceneComposite(renderer);
  else if (name == "scene:splats")
    SceneSplats(renderer);
  else if (name == "scene:lights")
    SceneLights(renderer);
  else if (name == "scene:glow")
    SceneGlow(renderer);
  else if (name == "scene:isoshadow")
    SceneIsoShadow(renderer);
  else if (name == "scene:cloud")
    SceneCloud(renderer);
  else if (name == "scene:particles")
    SceneParticles(renderer);
  else if (name == "scene:pointlights")
    SceneSpheres(renderer); // Populate adds the lights over the ground
  else if (name == "scene:mixed")
    SceneMixed(renderer);
  else if (name == "scene:volume")
    SceneVolume(renderer);
  else if (name == "scene:edges")
    SceneEdges(renderer);
  else if (name == "scene:molecule")
    return PopulateMolecule(renderer, vtkFXScenes::DataDirectory() + "/1crn.pdb", error);
  else
  {
    // (CheckInput words the message; a listed name never gets here)
    if (vtkFXScenes::CheckInput(name, error))
    {
      error = "scene '" + name + "' is listed but not built";
    }
    return false;
  }
  return true;
}
}

std::string vtkFXScenes::DataDirectory()
{
  const char* env = std::getenv("VTKFX_DATA");
  return (env && *env) ? std::string(env) : std::string(VTKFX_SOURCE_DATA_DIR);
}

std::vector<std::string> vtkFXScenes::BuiltInSceneNames()
{
  return { "scene:spheres", "scene:corner", "scene:scalars", "scene:textured", "scene:glyphs",
    "scene:composite", "scene:splats", "scene:lights", "scene:mixed", "scene:volume", "scene:edges",
    "scene:molecule", "scene:glow", "scene:pointlights", "scene:isoshadow", "scene:cloud",
    "scene:particles", "scene:bumps", "scene:normalmap", "scene:terrain" };
}

bool vtkFXScenes::CheckInput(const std::string& input, std::string& error)
{
  if (input.rfind("scene:", 0) == 0)
  {
    const auto names = BuiltInSceneNames();
    if (std::find(names.begin(), names.end(), input) != names.end())
    {
      return true;
    }
    error = "unknown scene '" + input + "'; built-in scenes:";
    for (const auto& n : names)
    {
      error += " " + n;
    }
    return false;
  }
  if (!FileReadable(input))
  {
    error = "cannot open '" + input + "'";
    return false;
  }
  return true;
}

bool vtkFXScenes::Populate(vtkRenderer* renderer, const std::string& input,
  const Options& options, std::string& error, double dataBounds[6])
{
  bool ok = false;
  const bool lightKitScene = input != "scene:lights" && input != "scene:pointlights";
  if (input.rfind("scene:", 0) == 0)
  {
    ok = PopulateBuiltIn(renderer, input, error);
  }
  else if (!FileReadable(input))
  {
    error = "cannot open '" + input + "'";
  }
  else if (Extension(input) == "pdb")
  {
    ok = PopulateMolecule(renderer, input, error);
  }
  else
  {
    auto poly = ReadPolyData(input, error);
    if (poly)
    {
      const bool hasNormals = poly->GetPointData()->GetNormals() != nullptr;
      renderer->AddActor(
        MakeActor(hasNormals ? poly.GetPointer() : WithNormals(poly, true).GetPointer(),
        0.85, 0.82, 0.75));
      ok = true;
    }
  }
  if (!ok)
  {
    renderer->RemoveAllViewProps();
    return false;
  }
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    error = "'" + input + "' has nothing visible";
    renderer->RemoveAllViewProps();
    return false;
  }
  if (dataBounds)
  {
    std::copy(bounds, bounds + 6, dataBounds);
  }
  if (options.Ground)
  {
    AddGround(renderer, bounds);
  }
  if (options.LightKit && lightKitScene)
  {
    renderer->RemoveAllLights();
    vtkNew<vtkLightKit> kit;
    kit->AddLightsToRenderer(renderer);
  }
  if (input == "scene:pointlights")
  {
    vtkFXScenes::AddPointLights(renderer, 256, bounds);
  }
  renderer->SetBackground(0.32, 0.34, 0.43);
  FrameCamera(renderer, bounds);
  return true;
}

double vtkFXScenes::AddPointLights(
  vtkRenderer* renderer, int count, const double b[6], double reach)
{
  renderer->RemoveAllLights();
  // The ground of AddGround: a square of half-size `size` at height b[2].
  const double dx = b[1] - b[0], dy = b[3] - b[2], dz = b[5] - b[4];
  const double size = 0.9 * std::max(std::max(dx, dz), 0.5 * dy) + 1e-30;
  const double cx = 0.5 * (b[0] + b[1]), cz = 0.5 * (b[4] + b[5]);
  const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)))));
  const double spacing = 2.0 * size / side;
  const double range = reach * spacing;
  const double cutoff = 1.0 / 512.0;
  Uniform random(12345u); // every run places the same lights
  for (int i = 0; i < count; ++i)
  {
    const double x = cx - size + spacing * (i % side + random());
    const double z = cz - size + spacing * (i / side + random());
    const double hue = random();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->PositionalOn();
    light->SetConeAngle(180.0);
    light->SetPosition(x, b[2] + 0.05 * spacing, z);
    light->SetFocalPoint(x, b[2], z);
    double rgb[3];
    vtkMath::HSVToRGB(hue, 0.6, 1.0, rgb, rgb + 1, rgb + 2);
    light->SetColor(rgb);
    light->SetIntensity(1.0);
    const double brightest = std::max(rgb[0], std::max(rgb[1], rgb[2]));
    light->SetAttenuationValues(1.0, 0.0, (2.0 * brightest / cutoff - 1.0) / (range * range));
    renderer->AddLight(light);
  }
  return spacing;
}

std::vector<unsigned char> vtkFXScenes::Capture(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  std::vector<unsigned char> pixels(static_cast<size_t>(size[0]) * size[1] * 3);
  unsigned char* data = window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0);
  std::copy(data, data + pixels.size(), pixels.begin());
  delete[] data;
  return pixels;
}

double vtkFXScenes::PSNR(const std::vector<unsigned char>& a,
  const std::vector<unsigned char>& b, const unsigned char* background)
{
  if (a.size() != b.size() || a.empty())
  {
    return -1.0;
  }
  auto isBackground = [background](const unsigned char* p) {
    return background && std::abs(p[0] - background[0]) <= 1 &&
      std::abs(p[1] - background[1]) <= 1 && std::abs(p[2] - background[2]) <= 1;
  };
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i + 2 < a.size(); i += 3)
  {
    if (isBackground(&a[i]) && isBackground(&b[i]))
    {
      continue;
    }
    for (size_t c = 0; c < 3; ++c)
    {
      const double d = static_cast<double>(a[i + c]) - static_cast<double>(b[i + c]);
      sum += d * d;
    }
    count += 3;
  }
  if (count == 0)
  {
    return -1.0; // nothing compared: no agreement to claim
  }
  if (sum == 0.0)
  {
    return std::numeric_limits<double>::infinity();
  }
  return 10.0 * std::log10(255.0 * 255.0 * count / sum);
}

namespace
{
// Gaussian blur (sigma in pixels) of `values` over the pixels where `mask`
// is set, normalised by the blurred mask: background never leaks in.
std::vector<double> MaskedGaussian(const std::vector<double>& values,
  const std::vector<char>& mask, int width, int height, double sigma)
{
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> kernel(2 * radius + 1);
  for (int k = -radius; k <= radius; ++k)
  {
    kernel[k + radius] = std::exp(-0.5 * k * k / (sigma * sigma));
  }
  const size_t n = values.size();
  std::vector<double> v(n), m(n), tv(n), tm(n);
  for (size_t i = 0; i < n; ++i)
  {
    m[i] = mask[i] ? 1.0 : 0.0;
    v[i] = mask[i] ? values[i] : 0.0;
  }
  for (int pass = 0; pass < 2; ++pass)
  {
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        double sv = 0.0, sm = 0.0;
        for (int k = -radius; k <= radius; ++k)
        {
          const int xx = pass == 0 ? x + k : x;
          const int yy = pass == 0 ? y : y + k;
          if (xx < 0 || yy < 0 || xx >= width || yy >= height)
          {
            continue;
          }
          const size_t j = static_cast<size_t>(yy) * width + xx;
          sv += kernel[k + radius] * v[j];
          sm += kernel[k + radius] * m[j];
        }
        const size_t i = static_cast<size_t>(y) * width + x;
        tv[i] = sv;
        tm[i] = sm;
      }
    }
    v.swap(tv);
    m.swap(tm);
  }
  std::vector<double> blurred(n, 0.0);
  for (size_t i = 0; i < n; ++i)
  {
    blurred[i] = m[i] > 1e-12 ? v[i] / m[i] : 0.0;
  }
  return blurred;
}
}

double vtkFXScenes::DetailScore(const std::vector<float>& image,
  const std::vector<float>& reference, int width, int height)
{
  const size_t n = static_cast<size_t>(width) * height;
  if (image.size() != n || reference.size() != n)
  {
    return 0.0;
  }
  std::vector<char> geometry(n);
  std::vector<double> a(n), b(n);
  for (size_t i = 0; i < n; ++i)
  {
    geometry[i] = reference[i] >= 0.0f;
    a[i] = image[i];
    b[i] = reference[i];
  }
  const auto blurA = MaskedGaussian(a, geometry, width, height, 3.0);
  const auto blurB = MaskedGaussian(b, geometry, width, height, 3.0);
  // Pixels at least 8 from the background and from the border.
  const int reach = 8;
  double sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
  size_t count = 0;
  for (int y = reach; y < height - reach; ++y)
  {
    for (int x = reach; x < width - reach; ++x)
    {
      bool inside = true;
      for (int dy = -reach; dy <= reach && inside; ++dy)
      {
        for (int dx = -reach; dx <= reach && inside; ++dx)
        {
          inside = dx * dx + dy * dy >= reach * reach ||
            geometry[static_cast<size_t>(y + dy) * width + (x + dx)];
        }
      }
      if (!inside)
      {
        continue;
      }
      const size_t i = static_cast<size_t>(y) * width + x;
      const double fa = a[i] - blurA[i], fb = b[i] - blurB[i];
      sa += fa;
      sb += fb;
      saa += fa * fa;
      sbb += fb * fb;
      sab += fa * fb;
      ++count;
    }
  }
  if (count < 2)
  {
    return 0.0;
  }
  const double varA = saa / count - (sa / count) * (sa / count);
  const double varB = sbb / count - (sb / count) * (sb / count);
  const double cov = sab / count - (sa / count) * (sb / count);
  // A fine band without variance carries no structure (a flat image, or
  // one whose detail the blur took): no detail kept.
  if (varA <= 1e-12 || varB <= 1e-12)
  {
    return 0.0;
  }
  return cov / std::sqrt(varA * varB);
}

int vtkFXScenes::MaxDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int largest = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    largest = std::max(largest, std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i])));
  }
  return largest;
}

void vtkFXScenes::BackgroundBytes(vtkRenderer* renderer, unsigned char rgb[3])
{
  const double* bg = renderer->GetBackground();
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, bg[c]))));
  }
}

bool vtkFXScenes::LoadRGB(const std::string& path, std::vector<unsigned char>& rgb, int size[2])
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return false;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  vtkUnsignedCharArray* scalars =
    vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!scalars)
  {
    return false;
  }
  // Grey (1 component) or grey and alpha (2): the grey in all three
  // channels; RGB or RGBA: the colour (alpha is not compared).
  const int comps = scalars->GetNumberOfComponents();
  size[0] = image->GetDimensions()[0];
  size[1] = image->GetDimensions()[1];
  rgb.clear();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb.push_back(scalars->GetValue(i * comps + (comps < 3 ? 0 : c)));
    }
  }
  return true;
}
