// Hardware picking keeps working while the pipeline is installed: a
// vtkHardwareSelector area selection and a vtkPropPicker pick find the prop
// under the cursor, and the next ordinary frame is deferred again.
#include "vtkFXPipelinePass.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkHardwareSelector.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkPropPicker.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"
#include "vtkInformation.h"

namespace
{
vtkSmartPointer<vtkActor> Sphere(vtkRenderer* renderer, double x, double opacity)
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(x, 0, 0);
  source->SetRadius(0.8);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(opacity);
  renderer->AddActor(actor);
  return actor;
}
}

int TestPicking(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(300, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  auto left = Sphere(renderer, -1.0, 1.0);
  auto right = Sphere(renderer, 1.0, 0.6); // translucent props are pickable too
  renderer->ResetCamera();
  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);
  window->Render();
  FX_CHECK(std::string(pipeline->GetPassThatRan(1)) == "gbuffer", "deferred frame");

  // Project the sphere centres to display coordinates.
  double display[2][3];
  const double centres[2][3] = { { -1, 0, 0 }, { 1, 0, 0 } };
  for (int i = 0; i < 2; ++i)
  {
    renderer->SetWorldPoint(centres[i][0], centres[i][1], centres[i][2], 1.0);
    renderer->WorldToDisplay();
    renderer->GetDisplayPoint(display[i]);
  }

  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  const int x = static_cast<int>(display[0][0]), y = static_cast<int>(display[0][1]);
  selector->SetArea(x - 2, y - 2, x + 2, y + 2);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  FX_CHECK(selection && selection->GetNumberOfNodes() == 1, "one prop selected");
  vtkSelectionNode* node = selection->GetNode(0);
  FX_CHECK(node->GetProperties()->Get(vtkSelectionNode::PROP()) == left,
    "the hardware selector selects the left sphere's cells");

  vtkNew<vtkPropPicker> picker;

  FX_CHECK(picker->Pick(display[0][0], display[0][1], 0, renderer), "a prop under the left sphere");
  FX_CHECK(picker->GetViewProp() == left, "vtkPropPicker finds the left sphere");
  FX_CHECK(picker->Pick(display[1][0], display[1][1], 0, renderer), "a prop under the right sphere");
  FX_CHECK(picker->GetViewProp() == right, "vtkPropPicker finds the right sphere");
  FX_CHECK(!picker->Pick(2, 2, 0, renderer), "nothing in the corner");

  window->Render();
  FX_CHECK(std::string(pipeline->GetPassThatRan(1)) == "gbuffer",
    "the frame after picking is deferred again");
  return EXIT_SUCCESS;
}
