/**
 * vtkFXSetClampMacro: VTK's vtkSetClampMacro for floating-point parameters,
 * except that NaN is refused with an error and the value kept. VTK's
 * clamp compares, and every comparison with NaN is false, so NaN would be
 * stored and reach the shaders. The generated methods are the same as
 * VTK's (Set, GetMinValue, GetMaxValue), so wrapping sees no difference.
 */
#ifndef vtkFXSetGet_h
#define vtkFXSetGet_h

#include "vtkSetGet.h"

#define vtkFXSetClampMacro(name, type, min, max)                                                   \
  virtual void Set##name(type _arg)                                                                \
  {                                                                                                \
    if (_arg != _arg)                                                                              \
    {                                                                                              \
      vtkErrorMacro(<< #name " NaN refused; keeping " << this->name << ".");                     \
      return;                                                                                      \
    }                                                                                              \
    vtkDebugMacro(<< this->GetClassName() << " (" << this << "): setting " << #name " to "         \
                  << _arg);                                                                        \
    if (this->name != (_arg < min ? min : (_arg > max ? max : _arg)))                              \
    {                                                                                              \
      this->name = (_arg < min ? min : (_arg > max ? max : _arg));                                 \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  virtual type Get##name##MinValue() { return min; }                                               \
  virtual type Get##name##MaxValue() { return max; }

#endif
// VTK-HeaderTest-Exclude: vtkFXSetGet.h
