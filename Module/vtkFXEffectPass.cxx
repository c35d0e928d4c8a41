#include "vtkFXEffectPass.h"

#include "vtkFXGBufferPass.h"

vtkCxxSetObjectMacro(vtkFXEffectPass, GBuffer, vtkFXGBufferPass);

vtkCxxSetObjectMacro(vtkFXEffectPass, InputEffect, vtkFXEffectPass);

vtkFXEffectPass::~vtkFXEffectPass()
{
  this->SetGBuffer(nullptr);
  this->SetInputEffect(nullptr);
}

bool vtkFXEffectPass::HasWork(int opaqueProps, int)
{
  return opaqueProps > 0;
}

void vtkFXEffectPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Stage: " << this->Stage << "\n";
  os << indent << "Enabled: " << this->Enabled << "\n";
  os << indent << "GBuffer: " << this->GBuffer << "\n";
}
