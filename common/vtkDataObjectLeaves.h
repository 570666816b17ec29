// SPDX-License-Identifier: BSD-3-Clause
// The leaves of a data object as a list: the blocks of a composite dataset (what ParaView hands a
// composite mapper), or the object itself. The composite mappers look for attached textures there.
#ifndef vtkDataObjectLeaves_h
#define vtkDataObjectLeaves_h

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkSmartPointer.h"

#include <vector>

// Not for the wrappers (C++ code only).
#ifndef __VTK_WRAP__
namespace mesolight
{
inline std::vector<vtkDataObject*> DataObjectLeaves(vtkDataObject* input)
{
  std::vector<vtkDataObject*> leaves;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      leaves.push_back(it->GetCurrentDataObject());
    }
  }
  else if (input)
  {
    leaves.push_back(input);
  }
  return leaves;
}
} // namespace mesolight
#endif

#endif
