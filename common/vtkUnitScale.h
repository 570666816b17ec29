// SPDX-License-Identifier: BSD-3-Clause
// The factor that takes an array's stored samples to unit values, for code that reads samples
// one by one (GetComponent) instead of through the typed ToUnitValue (ScalarConversion.h):
// integer images store [0, 1] as [0, max of the type], floating-point ones as they are.
#ifndef vtkUnitScale_h
#define vtkUnitScale_h

#include "vtkDataArray.h"
#include "vtkType.h"

#include <limits>
#include <type_traits>

namespace mesolight
{
template <typename T>
constexpr double UnitScaleOf()
{
  if constexpr (std::is_floating_point<T>::value)
  {
    return 1.0;
  }
  else
  {
    return 1.0 / static_cast<double>(std::numeric_limits<T>::max());
  }
}

/** 1 / the type's maximum for integer arrays (uchar 1/255, ushort 1/65535, short 1/32767...),
 *  1 for float and double (and for no array). */
inline double UnitScale(vtkDataArray* array)
{
  switch (array ? array->GetDataType() : VTK_FLOAT)
  {
    vtkTemplateMacro(return UnitScaleOf<VTK_TT>());
    default:
      return 1.0;
  }
}
} // namespace mesolight

#endif
