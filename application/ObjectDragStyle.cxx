// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectDragStyle.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCellPicker.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

namespace mesolight
{

vtkStandardNewMacro(ObjectDragStyle);

ObjectDragStyle::ObjectDragStyle()
{
  this->Picker->PickFromListOn();
  this->Picker->SetTolerance(0.0005);
}

ObjectDragStyle::~ObjectDragStyle() = default;

void ObjectDragStyle::SetObject(vtkActor* object)
{
  this->Object = object;
  this->Picker->InitializePickList();
  if (object)
  {
    this->Picker->AddPickList(object);
  }
}

void ObjectDragStyle::AddStandIn(vtkActor* actor, vtkRenderer* renderer)
{
  if (actor)
  {
    this->Picker->AddPickList(actor);
    this->StandInRenderer = renderer;
  }
}

void ObjectDragStyle::OnLeftButtonDown()
{
  const int* position = this->Interactor->GetEventPosition();
  this->FindPokedRenderer(position[0], position[1]);
  // The pick list holds the object and its stand-ins, which may be drawn by another renderer.
  const auto picked = [&](vtkRenderer* renderer)
  {
    return renderer && this->Picker->Pick(position[0], position[1], 0.0, renderer) &&
      this->Picker->GetActor() != nullptr;
  };
  if (this->Object && this->CurrentRenderer &&
    (picked(this->CurrentRenderer) || picked(this->StandInRenderer)))
  {
    this->Dragging = true;
    this->GrabFocus(this->EventCallbackCommand);
    return;
  }
  this->Superclass::OnLeftButtonDown();
}

void ObjectDragStyle::OnLeftButtonUp()
{
  if (this->Dragging)
  {
    this->Dragging = false;
    this->ReleaseFocus();
    return;
  }
  this->Superclass::OnLeftButtonUp();
}

void ObjectDragStyle::OnMouseMove()
{
  if (!this->Dragging || !this->Object || !this->CurrentRenderer)
  {
    this->Superclass::OnMouseMove();
    return;
  }
  // The pointer's motion at the depth of the object's centre, in world coordinates.
  const double* centre = this->Object->GetCenter();
  double display[3];
  this->ComputeWorldToDisplay(centre[0], centre[1], centre[2], display);
  const int* now = this->Interactor->GetEventPosition();
  const int* last = this->Interactor->GetLastEventPosition();
  double to[4], from[4];
  this->ComputeDisplayToWorld(now[0], now[1], display[2], to);
  this->ComputeDisplayToWorld(last[0], last[1], display[2], from);
  this->Object->AddPosition(to[0] - from[0], to[1] - from[1], to[2] - from[2]);
  this->Interactor->Render();
}

} // namespace mesolight
