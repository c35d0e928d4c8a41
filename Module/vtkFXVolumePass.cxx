#include "vtkFXVolumePass.h"

#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkVolumetricPass.h"

#include <vector>

vtkStandardNewMacro(vtkFXVolumePass);

vtkFXVolumePass::vtkFXVolumePass()
  : Volumes(vtkSmartPointer<vtkVolumetricPass>::New())
{
}

vtkFXVolumePass::~vtkFXVolumePass() = default;

namespace
{
// The props whose mappers draw volumes: each vtkVolume on a prop's paths
// (itself, or an assembly's part), and vtkLODProp3D, which hands its keys
// to the level it draws.
std::vector<vtkProp*> VolumesDrawn(const vtkRenderState* s)
{
  std::vector<vtkProp*> volumes;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (prop->IsA("vtkLODProp3D"))
    {
      volumes.push_back(prop);
      continue;
    }
    prop->InitPathTraversal();
    while (vtkAssemblyPath* path = prop->GetNextPath())
    {
      vtkProp* part = path->GetLastNode()->GetViewProp();
      if (part && part->IsA("vtkVolume"))
      {
        volumes.push_back(part);
      }
    }
  }
  return volumes;
}
}

void vtkFXVolumePass::Render(const vtkRenderState* s)
{
  std::vector<vtkProp*> volumes = VolumesDrawn(s);
  vtkRenderState keyed(s->GetRenderer());
  keyed.SetPropArrayAndCount(volumes.data(), static_cast<int>(volumes.size()));
  keyed.SetFrameBuffer(s->GetFrameBuffer());
  this->PreRender(&keyed);
  this->Volumes->Render(s);
  this->PostRender(&keyed);
  this->NumberOfRenderedProps = this->Volumes->GetNumberOfRenderedProps();
}

void vtkFXVolumePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Volumes->ReleaseGraphicsResources(w);
}
