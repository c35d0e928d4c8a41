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

/**
 * vtkFXSetClampVector3Macro: VTK's vtkSetVector3Macro for a floating-point
 * triple whose components are bounded: each clamped to [min, max], and a
 * triple with a NaN component refused with an error, the value kept. The
 * same two setters as VTK's (three values, or an array of three).
 */
#define vtkFXSetClampVector3Macro(name, type, min, max)                                            \
  virtual void Set##name(type _arg1, type _arg2, type _arg3)                                       \
  {                                                                                                \
    if (_arg1 != _arg1 || _arg2 != _arg2 || _arg3 != _arg3)                                        \
    {                                                                                              \
      vtkErrorMacro(<< #name " with NaN refused; keeping " << this->name[0] << " "                 \
                    << this->name[1] << " " << this->name[2] << ".");                              \
      return;                                                                                      \
    }                                                                                              \
    const type _clamped[3] = { _arg1 < min ? min : (_arg1 > max ? max : _arg1),                    \
      _arg2 < min ? min : (_arg2 > max ? max : _arg2),                                             \
      _arg3 < min ? min : (_arg3 > max ? max : _arg3) };                                           \
    if (this->name[0] != _clamped[0] || this->name[1] != _clamped[1] ||                            \
      this->name[2] != _clamped[2])                                                                \
    {                                                                                              \
      this->name[0] = _clamped[0];                                                                 \
      this->name[1] = _clamped[1];                                                                 \
      this->name[2] = _clamped[2];                                                                 \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  virtual void Set##name(const type _arg[3]) { this->Set##name(_arg[0], _arg[1], _arg[2]); }

#endif
// VTK-HeaderTest-Exclude: vtkFXSetGet.h
