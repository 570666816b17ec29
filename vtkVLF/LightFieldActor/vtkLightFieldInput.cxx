// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldInput.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkVirtualLightFieldCore.h"

#include "LightField.h"
#include "Snapshot.h"

#include <algorithm>
#include <exception>

namespace
{
// Latest modification of an algorithm, its input data and everything upstream: what decides
// whether an Update() executes.
vtkMTimeType UpstreamModifiedTime(vtkAlgorithm* algorithm)
{
  vtkMTimeType time = algorithm->GetMTime();
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < algorithm->GetNumberOfInputConnections(port); ++c)
    {
      if (vtkAlgorithm* producer = algorithm->GetInputAlgorithm(port, c))
      {
        time = std::max(time, UpstreamModifiedTime(producer));
      }
      if (vtkDataObject* data = algorithm->GetInputDataObject(port, c))
      {
        time = std::max(time, data->GetMTime());
      }
    }
  }
  return time;
}
} // namespace

//------------------------------------------------------------------------------
vtkLightFieldInput::vtkLightFieldInput() = default;

//------------------------------------------------------------------------------
vtkLightFieldInput::~vtkLightFieldInput() = default;

//------------------------------------------------------------------------------
void vtkLightFieldInput::Borrow()
{
  this->Filter = nullptr;
  this->Owned.reset();
}

//------------------------------------------------------------------------------
bool vtkLightFieldInput::SetFilter(vtkVirtualLightField* filter)
{
  if (this->Filter == filter)
  {
    return false;
  }
  this->Owned.reset();
  this->Filter = filter;
  this->FilterUpstreamTime = 0;
  this->FilterOutputTime = 0;
  return true;
}

//------------------------------------------------------------------------------
vtkVirtualLightField* vtkLightFieldInput::GetFilter() const
{
  return this->Filter;
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightField* vtkLightFieldInput::Load(
  const std::string& fileName, std::string& error)
{
  this->Filter = nullptr;
  std::unique_ptr<mesolight::vlf::LightField> field;
  try
  {
    field = mesolight::vlf::ReadSnapshot(fileName);
  }
  catch (const std::exception& e)
  {
    error = std::string("cannot use light field '") + fileName + "': " + e.what();
    return nullptr;
  }
  this->Owned = std::move(field);
  return this->Owned.get();
}

//------------------------------------------------------------------------------
bool vtkLightFieldInput::Refresh(
  const mesolight::vlf::LightField* shown, const std::function<void()>& stopReaders)
{
  if (!this->Filter)
  {
    return false;
  }
  // Stop the readers only when the filter will execute, so a settled pipeline never cancels a
  // trace.
  const vtkMTimeType upstream = UpstreamModifiedTime(this->Filter);
  if (upstream > this->FilterUpstreamTime)
  {
    stopReaders();
  }
  this->Filter->Update();
  this->FilterUpstreamTime = upstream;
  const vtkMTimeType output =
    this->Filter->GetOutputDataObject(0) ? this->Filter->GetOutputDataObject(0)->GetMTime() : 0;
  if (vtkVirtualLightFieldCore::GetLightField(this->Filter) != shown ||
    output != this->FilterOutputTime)
  {
    this->FilterOutputTime = output;
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightField* vtkLightFieldInput::GetFilterField() const
{
  return vtkVirtualLightFieldCore::GetLightField(this->Filter);
}
