#include "vtkFXTimedSequencePass.h"

#include "vtkFXGBufferPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkRenderState.h"
#include "vtkSmartPointer.h"

#include <map>

vtkStandardNewMacro(vtkFXTimedSequencePass);

struct vtkFXTimedSequencePass::Internals
{
  struct Entry
  {
    std::string Name;
    vtkSmartPointer<vtkRenderPass> Pass;
    vtkFXGBufferPass* Reads; // (owned by whoever added the pass)
  };
  struct Timing
  {
    // Timers per pass used in turn, so that the queries of frames the GPU
    // has not finished yet stay in flight while later frames start their
    // own (with two, a driver running two frames behind, with vsync or
    // triple buffering, dropped every result and the times stayed -1).
    static constexpr int TimersPerPass = 4;
    vtkOpenGLRenderTimer Timers[TimersPerPass];
    int Next = 0;
    double LastMilliseconds = -1.0;
  };
  std::vector<Entry> Passes;
  std::vector<std::string> Ran;
  std::map<std::string, std::unique_ptr<Timing>> Timings;

  Timing& TimingFor(const std::string& name)
  {
    auto& slot = this->Timings[name];
    if (!slot)
    {
      slot.reset(new Timing);
    }
    return *slot;
  }

  // Collects the finished measurements, oldest first (the ring from the
  // next timer on), so that the newest is the one kept.
  static void Harvest(Timing& t)
  {
    for (int k = 0; k < Timing::TimersPerPass; ++k)
    {
      vtkOpenGLRenderTimer& timer = t.Timers[(t.Next + k) % Timing::TimersPerPass];
      if (timer.Started() && timer.Stopped() && timer.Ready())
      {
        t.LastMilliseconds = timer.GetElapsedMilliseconds();
        timer.Reset();
      }
    }
  }

  // Collects any finished measurement, then starts the next one.
  static void Begin(Timing& t)
  {
    Harvest(t);
    vtkOpenGLRenderTimer& timer = t.Timers[t.Next];
    if (timer.Started())
    {
      // Still pending after a full cycle: drop it rather than block.
      timer.Reset();
    }
    timer.Start();
  }

  static void End(Timing& t)
  {
    t.Timers[t.Next].Stop();
    t.Next = (t.Next + 1) % Timing::TimersPerPass;
  }
};

vtkFXTimedSequencePass::vtkFXTimedSequencePass()
  : Impl(new Internals)
{
}

vtkFXTimedSequencePass::~vtkFXTimedSequencePass() = default;

void vtkFXTimedSequencePass::ClearPasses()
{
  this->Impl->Passes.clear();
}

void vtkFXTimedSequencePass::AddPass(const char* name, vtkRenderPass* pass, vtkFXGBufferPass* reads)
{
  if (!name || !pass)
  {
    vtkErrorMacro("AddPass needs a name and a pass.");
    return;
  }
  this->Impl->Passes.push_back({ name, pass, reads });
}

void vtkFXTimedSequencePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->Impl->Ran.clear();
  for (auto& entry : this->Impl->Passes)
  {
    if (entry.Reads && !entry.Reads->GetFrameComplete())
    {
      continue; // (its input could not be made this frame)
    }
    Internals::Timing* timing = this->Timing ? &this->Impl->TimingFor(entry.Name) : nullptr;
    if (timing)
    {
      Internals::Begin(*timing);
    }
    entry.Pass->Render(s);
    if (timing)
    {
      Internals::End(*timing);
    }
    this->NumberOfRenderedProps += entry.Pass->GetNumberOfRenderedProps();
    this->Impl->Ran.push_back(entry.Name);
  }
}

double vtkFXTimedSequencePass::GetPassMilliseconds(const char* name)
{
  auto it = name ? this->Impl->Timings.find(name) : this->Impl->Timings.end();
  if (it == this->Impl->Timings.end())
  {
    return -1.0;
  }
  // (results that completed since the last frame)
  Internals::Harvest(*it->second);
  return it->second->LastMilliseconds;
}

std::vector<std::string> vtkFXTimedSequencePass::GetPassesThatRan() const
{
  return this->Impl->Ran;
}

void vtkFXTimedSequencePass::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& entry : this->Impl->Passes)
  {
    entry.Pass->ReleaseGraphicsResources(w);
  }
  for (auto& timing : this->Impl->Timings)
  {
    for (auto& timer : timing.second->Timers)
    {
      timer.ReleaseGraphicsResources();
    }
  }
  this->Impl->Timings.clear();
}

void vtkFXTimedSequencePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Timing: " << this->Timing << "\n";
  for (const auto& entry : this->Impl->Passes)
  {
    os << indent << "Pass: " << entry.Name << " (" << entry.Pass->GetClassName() << ")\n";
  }
}
