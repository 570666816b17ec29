// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMNamedArrayDomain.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataInformation.h"
#include "vtkPVXMLElement.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMUncheckedPropertyHelper.h"

vtkStandardNewMacro(vtkSMNamedArrayDomain);

//------------------------------------------------------------------------------
vtkSMNamedArrayDomain::vtkSMNamedArrayDomain() = default;
vtkSMNamedArrayDomain::~vtkSMNamedArrayDomain() = default;

//------------------------------------------------------------------------------
int vtkSMNamedArrayDomain::ReadXMLAttributes(vtkSMProperty* prop, vtkPVXMLElement* element)
{
  if (!this->Superclass::ReadXMLAttributes(prop, element))
  {
    return 0;
  }
  const char* name = element->GetAttribute("array_name");
  if (!name || !*name)
  {
    vtkErrorMacro("NamedArrayDomain needs an array_name attribute.");
    return 0;
  }
  this->ArrayName = name;
  return 1;
}

//------------------------------------------------------------------------------
int vtkSMNamedArrayDomain::IsInDomain(vtkSMProperty* property)
{
  if (this->IsOptional)
  {
    return IN_DOMAIN;
  }
  if (!property)
  {
    return NOT_IN_DOMAIN;
  }
  vtkSMUncheckedPropertyHelper helper(property);
  if (helper.GetNumberOfElements() == 0)
  {
    return NOT_IN_DOMAIN;
  }
  for (unsigned int i = 0; i < helper.GetNumberOfElements(); ++i)
  {
    if (!this->IsInDomain(
          vtkSMSourceProxy::SafeDownCast(helper.GetAsProxy(i)), helper.GetOutputPort(i)))
    {
      return NOT_IN_DOMAIN;
    }
  }
  return IN_DOMAIN;
}

//------------------------------------------------------------------------------
bool vtkSMNamedArrayDomain::IsInDomain(vtkSMSourceProxy* source, unsigned int port)
{
  if (!source || this->ArrayName.empty())
  {
    return false;
  }
  // The data information already gathered: looking must not execute anyone's pipeline.
  source->CreateOutputPorts();
  vtkPVDataInformation* info = source->GetDataInformation(port);
  if (!info)
  {
    return false;
  }
  for (const int association : { vtkDataObject::FIELD_ASSOCIATION_POINTS,
         vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkDataObject::FIELD_ASSOCIATION_NONE })
  {
    if (info->GetArrayInformation(this->ArrayName.c_str(), association))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkSMNamedArrayDomain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayName: " << this->ArrayName << "\n";
}
