// A VTK application that renders a mesh through vtkFX: the only vtkFX line
// needed is renderer->SetPass(pipeline); the ambient occlusion settings
// after it are optional.
//
//   vtkfx-example MESH.obj OUT.png
#include "vtkFXPipelinePass.h"
#include "vtkFXSSAOPass.h"

#include "vtkActor.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: vtkfx-example MESH.obj OUT.png\n";
    return 2;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.8, 0.7);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(40);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.2, 0.25, 0.3);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);

  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline); // the one line that installs vtkFX

  // Optional: ambient occlusion, with the three settings users reach for.
  pipeline->AmbientOcclusionOn();
  pipeline->SetAmbientOcclusionQuality(vtkFXPipelinePass::Medium); // Low, Medium, High
  pipeline->SetAmbientOcclusionFalloff(vtkFXSSAOPass::Binary); // visibility within the radius
  pipeline->GetSSAOPass()->SetRadiusFraction(0.1); // of the data's diagonal (or SetRadius)
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(argv[2]);
  writer->Write();

  std::cout << "passes:";
  for (int i = 0; i < pipeline->GetNumberOfPassesThatRan(); ++i)
  {
    std::cout << " " << pipeline->GetPassThatRan(i);
  }
  std::cout << "\nG-buffer: " << pipeline->GetGBufferBytesPerPixel() << " bytes/pixel\n";
  return writer->GetErrorCode() == 0 && pipeline->GetGBufferBytesPerPixel() > 0 ? 0 : 1;
}
