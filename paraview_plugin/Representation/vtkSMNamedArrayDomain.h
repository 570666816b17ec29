// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMNamedArrayDomain
 * @brief   an input property's domain: outputs whose data carries an array of a given name
 *
 * ParaView's input selector (the Properties panel's `panel_widget="input_selector"`,
 * pqInputSelectorWidget) lists every pipeline output for which the property's domains hold.
 * DataTypeDomain alone lets the relief's Light Field list every polydata (the box, the patch, a
 * sphere), and each of them gives an error when picked. This domain keeps the outputs whose data
 * carries the array that makes them what the property needs, e.g. a Virtual Light Field's
 * receiver points (`LightFieldUnitPoint`) or Light Field Gather's emitters
 * (`LightFieldEmitters`), in point, cell or field data, directly or through filters that pass
 * it on. Only outputs that have executed have data to look at: a source not yet applied is not
 * listed until it is. Python and state files set the property without asking the domain.
 *
 * XML: `<NamedArrayDomain name="..." array_name="LightFieldUnitPoint"/>`.
 */
#ifndef vtkSMNamedArrayDomain_h
#define vtkSMNamedArrayDomain_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkSMDomain.h"

#include <string> // for std::string

class vtkSMSourceProxy;

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkSMNamedArrayDomain : public vtkSMDomain
{
public:
  static vtkSMNamedArrayDomain* New();
  vtkTypeMacro(vtkSMNamedArrayDomain, vtkSMDomain);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** IN_DOMAIN when every (unchecked) input of the property carries the array. */
  int IsInDomain(vtkSMProperty* property) override;
  /** Whether output port `port` of `source` carries the array (point, cell or field data). */
  bool IsInDomain(vtkSMSourceProxy* source, unsigned int port);

  /** The array's name (XML attribute array_name). */
  const char* GetArrayName() const { return this->ArrayName.c_str(); }

protected:
  vtkSMNamedArrayDomain();
  ~vtkSMNamedArrayDomain() override;

  int ReadXMLAttributes(vtkSMProperty* prop, vtkPVXMLElement* element) override;

private:
  vtkSMNamedArrayDomain(const vtkSMNamedArrayDomain&) = delete;
  void operator=(const vtkSMNamedArrayDomain&) = delete;

  std::string ArrayName;
};

#endif
