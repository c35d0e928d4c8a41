#include "vtkFXVolumePass.h"

#include "vtkFXRenderUtilities.h"

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

void vtkFXVolumePass::Render(const vtkRenderState* s)
{
  std::vector<vtkProp*> volumes;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    const std::vector<vtkProp*> drawn = vtkFXRenderUtilities::GetVolumesDrawn(s->GetPropArray()[i]);
    volumes.insert(volumes.end(), drawn.begin(), drawn.end());
  }
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
