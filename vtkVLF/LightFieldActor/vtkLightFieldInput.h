// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldInput
 * @brief   where vtkLightFieldActor's field comes from: borrowed, loaded from a snapshot, or
 *          taken from a vtkVirtualLightField brought up to date
 *
 * Private to Mesolight::LightFieldActor (header not installed). It owns a loaded snapshot, holds
 * the filter, and says when the filter's field is a new one (a new field may sit at the old
 * one's address: its output's modification time tells). The actor builds what it draws from
 * the field this gives (vtkLightFieldSceneCache).
 */
#ifndef vtkLightFieldInput_h
#define vtkLightFieldInput_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <functional>
#include <memory>
#include <string>

namespace mesolight
{
namespace vlf
{
class LightField;
}
}
class vtkVirtualLightField;

class vtkLightFieldInput
{
public:
  vtkLightFieldInput();
  ~vtkLightFieldInput();
  vtkLightFieldInput(const vtkLightFieldInput&) = delete;
  vtkLightFieldInput& operator=(const vtkLightFieldInput&) = delete;

  /** Forgets the filter and any loaded snapshot (a borrowed field follows). */
  void Borrow();
  /** Holds the filter (forgetting any snapshot); false when it is the one already held. */
  bool SetFilter(vtkVirtualLightField* filter);
  vtkVirtualLightField* GetFilter() const;
  /**
   * Reads a snapshot; on success it is owned and returned, on failure nullptr with the reason in
   * error (and the field loaded before, if any, is kept). Forgets the filter either way.
   */
  const mesolight::vlf::LightField* Load(const std::string& fileName, std::string& error);
  /**
   * Updates the filter, if any. stopReaders runs first when the update will execute (it frees
   * the field the progressive worker may be reading). True when the filter's field is not
   * `shown` any more or was rebuilt: then GetFilterField() is the field to show.
   */
  bool Refresh(const mesolight::vlf::LightField* shown, const std::function<void()>& stopReaders);
  const mesolight::vlf::LightField* GetFilterField() const;

private:
  std::unique_ptr<mesolight::vlf::LightField> Owned; // Load's
  vtkSmartPointer<vtkVirtualLightField> Filter;
  vtkMTimeType FilterUpstreamTime = 0; // the filter's upstream modification at its last update
  vtkMTimeType FilterOutputTime = 0;   // its output's modification when its field was taken
};

#endif
