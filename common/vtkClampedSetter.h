// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkClampedSetter.h
 * @brief mesolightSetClampMacro: vtkSetClampMacro that says what it did with a wrong value.
 *
 * VTK's vtkSetClampMacro clamps without a word, so SetLinearSteps(1000000000) silently became
 * 1024 and SetExposure(-1) became 0. The Mesolight convention (docs/dev/conventions.md, "Setters
 * say what they do with a wrong value"): a value clamped into range is a warning naming the value
 * used; NaN is an error and the old value stays. Same Set/GetMinValue/GetMaxValue members as
 * vtkSetClampMacro, so wrappers and ParaView's XML see no difference.
 */
#ifndef vtkClampedSetter_h
#define vtkClampedSetter_h

#include "vtkObject.h" // vtkWarningMacro, vtkErrorMacro

#define mesolightSetClampMacro(name, type, min, max)                                               \
  virtual void Set##name(type _arg)                                                                \
  {                                                                                                \
    if (_arg != _arg) /* NaN */                                                                    \
    {                                                                                              \
      vtkErrorMacro(<< "Set" #name ": NaN is not a value; keeping " << this->name << ".");         \
      return;                                                                                      \
    }                                                                                              \
    const type _clamped = (_arg < (min) ? (min) : (_arg > (max) ? (max) : _arg));                  \
    if (_clamped != _arg)                                                                          \
    {                                                                                              \
      vtkWarningMacro(<< "Set" #name ": " << _arg << " is outside [" << (min) << ", " << (max)     \
                      << "]; using " << _clamped << ".");                                          \
    }                                                                                              \
    if (this->name != _clamped)                                                                    \
    {                                                                                              \
      this->name = _clamped;                                                                       \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  virtual type Get##name##MinValue()                                                               \
  {                                                                                                \
    return (min);                                                                                  \
  }                                                                                                \
  virtual type Get##name##MaxValue()                                                               \
  {                                                                                                \
    return (max);                                                                                  \
  }

#endif
