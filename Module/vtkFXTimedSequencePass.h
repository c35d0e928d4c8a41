/**
 * @class   vtkFXTimedSequencePass
 * @brief   Runs a list of named render passes in order and GPU-times each one.
 *
 * Reads and writes whatever its passes do; it owns no texture.
 * Each pass is bracketed by a vtkOpenGLRenderTimer (GL timestamp queries).
 * Query results arrive one or more frames late, so GetPassMilliseconds()
 * returns the most recent *completed* measurement of a pass, or -1 when none
 * has arrived yet. Cost: two timestamp queries per pass and frame.
 *
 * The list of passes that ran in the last frame (GetPassesThatRan()) is what
 * vtkFXPipelinePass reports to show which effects the scene needed.
 */
#ifndef vtkFXTimedSequencePass_h
#define vtkFXTimedSequencePass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"

class vtkFXGBufferPass;

#include <memory>
#include <string>
#include <vector>

class VTKFX_EXPORT vtkFXTimedSequencePass : public vtkRenderPass
{
public:
  static vtkFXTimedSequencePass* New();
  vtkTypeMacro(vtkFXTimedSequencePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Replace the list of passes run by the next Render(). Names identify the
   * passes in timings; timers persist per name across frames. A pass given
   * a G-buffer reads it, and is left out of a frame whose G-buffer could
   * not be made (vtkFXGBufferPass::GetFrameComplete).
   */
  void ClearPasses();
  void AddPass(const char* name, vtkRenderPass* pass, vtkFXGBufferPass* reads = nullptr);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /**
   * Most recent completed GPU time of the named pass in milliseconds, or -1
   * when none has completed yet (timer results arrive frames late).
   */
  double GetPassMilliseconds(const char* name);

  /**
   * Names of the passes run by the last Render(), in order.
   */
  std::vector<std::string> GetPassesThatRan() const;

  /**
   * Enable GPU timing (on by default). When off, no query objects are used.
   */
  vtkSetMacro(Timing, bool);
  vtkGetMacro(Timing, bool);
  vtkBooleanMacro(Timing, bool);

protected:
  vtkFXTimedSequencePass();
  ~vtkFXTimedSequencePass() override;

  bool Timing = true;

private:
  vtkFXTimedSequencePass(const vtkFXTimedSequencePass&) = delete;
  void operator=(const vtkFXTimedSequencePass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
