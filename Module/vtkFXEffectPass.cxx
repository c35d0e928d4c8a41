#include "vtkFXEffectPass.h"

#include "vtkFXGBufferPass.h"
#include "vtkFXRenderUtilities.h"

vtkCxxSetObjectMacro(vtkFXEffectPass, GBuffer, vtkFXGBufferPass);

vtkFXEffectPass::~vtkFXEffectPass()
{
  this->SetGBuffer(nullptr);
}

void vtkFXEffectPass::WarnIfDrawnInTiles(vtkRenderer* renderer, const char* missed)
{
  if (!this->WarnedTiles && vtkFXRenderUtilities::IsRenderingTiles(renderer))
  {
    vtkWarningMacro("This image is drawn tile by tile (vtkWindowToImageFilter's scale above 1): "
      << missed << " across a tile's border, which leaves seams. Render offscreen at the "
                   "image's full size instead.");
    this->WarnedTiles = true;
  }
}

const char* vtkFXEffectPass::GetStageName(int stage)
{
  static const char* const names[NumberOfStages] = { "light-space", "after-gbuffer",
    "composite", "post-process" };
  return (stage >= 0 && stage < NumberOfStages) ? names[stage] : "unknown";
}

bool vtkFXEffectPass::HasWork(const vtkFXSceneInfo& scene)
{
  return !scene.OpaqueProps.empty();
}

void vtkFXEffectPass::DeclareInput(const char* name, bool optional, bool readInComposite)
{
  InputPort port;
  port.Name = name;
  port.Optional = optional;
  port.ReadInComposite = readInComposite;
  this->Inputs.push_back(port);
}

void vtkFXEffectPass::DeclareOutput(const char* name)
{
  this->Outputs.emplace_back(name);
}

int vtkFXEffectPass::GetNumberOfOutputs() const
{
  return static_cast<int>(this->Outputs.size());
}

const char* vtkFXEffectPass::GetOutputName(int i) const
{
  return (i >= 0 && i < this->GetNumberOfOutputs()) ? this->Outputs[i].c_str() : nullptr;
}

bool vtkFXEffectPass::HasOutput(const char* name) const
{
  for (const std::string& output : this->Outputs)
  {
    if (name && output == name)
    {
      return true;
    }
  }
  return false;
}

vtkFXEffectPass::Output vtkFXEffectPass::GetOutput(const char*)
{
  return Output();
}

vtkTextureObject* vtkFXEffectPass::GetOutputTexture(const char* name)
{
  if (!name)
  {
    name = this->GetOutputName(0);
  }
  return name ? this->GetOutput(name).Texture : nullptr;
}

int vtkFXEffectPass::GetNumberOfInputs() const
{
  return static_cast<int>(this->Inputs.size());
}

const char* vtkFXEffectPass::GetInputName(int i) const
{
  return (i >= 0 && i < this->GetNumberOfInputs()) ? this->Inputs[i].Name.c_str() : nullptr;
}

bool vtkFXEffectPass::IsInputOptional(int i) const
{
  return i >= 0 && i < this->GetNumberOfInputs() && this->Inputs[i].Optional;
}

bool vtkFXEffectPass::IsInputReadInComposite(int i) const
{
  return i >= 0 && i < this->GetNumberOfInputs() && this->Inputs[i].ReadInComposite;
}

const vtkFXEffectPass::InputPort* vtkFXEffectPass::FindInput(const char* name) const
{
  for (const InputPort& port : this->Inputs)
  {
    if (name && port.Name == name)
    {
      return &port;
    }
  }
  return nullptr;
}

vtkFXEffectPass::InputPort* vtkFXEffectPass::InputToChange(const char* name)
{
  InputPort* port = const_cast<InputPort*>(this->FindInput(name));
  if (!port)
  {
    vtkErrorMacro(<< this->GetClassName() << " has no input named '" << (name ? name : "")
                  << "'.");
  }
  return port;
}

void vtkFXEffectPass::SetInputConnection(const char* input, const char* source)
{
  InputPort* port = this->InputToChange(input);
  if (!port)
  {
    return;
  }
  const std::string connection = source ? source : "";
  if (port->Connection != connection)
  {
    port->Connection = connection;
    this->Modified();
  }
}

const char* vtkFXEffectPass::GetInputConnection(const char* input) const
{
  const InputPort* port = this->FindInput(input);
  return port ? port->Connection.c_str() : nullptr;
}

void vtkFXEffectPass::SetInputProducer(
  const char* input, vtkFXEffectPass* producer, const char* output)
{
  InputPort* port = this->InputToChange(input);
  if (!port)
  {
    return;
  }
  if (producer && (!output || !producer->HasOutput(output)))
  {
    vtkErrorMacro(<< producer->GetClassName() << " has no output named '"
                  << (output ? output : "") << "'.");
    producer = nullptr;
  }
  port->Producer = producer;
  port->ProducerOutput = producer ? output : "";
}

vtkFXEffectPass* vtkFXEffectPass::GetInputProducer(const char* input) const
{
  const InputPort* port = this->FindInput(input);
  return port ? port->Producer.GetPointer() : nullptr;
}

vtkFXEffectPass::Output vtkFXEffectPass::GetInput(const char* input) const
{
  const InputPort* port = this->FindInput(input);
  if (!port || !port->Producer)
  {
    return Output();
  }
  return port->Producer->GetOutput(port->ProducerOutput.c_str());
}

std::string vtkFXEffectPass::GetCompositeCode(int)
{
  return std::string();
}

void vtkFXEffectPass::BindCompositeResources(vtkShaderProgram*, const std::string&) {}

void vtkFXEffectPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Stage: " << GetStageName(this->Stage) << "\n";
  os << indent << "Enabled: " << this->Enabled << "\n";
  os << indent << "GBuffer: " << this->GBuffer << "\n";
  for (const InputPort& port : this->Inputs)
  {
    os << indent << "Input " << port.Name << (port.Optional ? " (optional)" : "")
       << (port.ReadInComposite ? " (read in the composite)" : "") << ": "
       << (port.Connection.empty() ? "not connected" : port.Connection);
    if (port.Producer)
    {
      os << " -> " << port.Producer->GetClassName() << "." << port.ProducerOutput;
    }
    os << "\n";
  }
  for (const std::string& output : this->Outputs)
  {
    os << indent << "Output " << output << "\n";
  }
}
