// SPDX-License-Identifier: BSD-3-Clause
/**
 * The viewer's mouse (`mesolight vlf view`): the trackball camera, except that a left-button drag
 * that starts on the movable object moves the object in the plane through its centre parallel
 * to the view, as vtkInteractorStyleTrackballActor pans an actor. The object is found by a
 * geometric pick (vtkCellPicker on the object alone): vtkLightFieldObjectMapper draws a private
 * shaded copy, which hardware picking would not report as the user's actor.
 */
#ifndef mesolight_ObjectDragStyle_h
#define mesolight_ObjectDragStyle_h

#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkWeakPointer.h>

class vtkActor;
class vtkCellPicker;

class vtkRenderer;

namespace mesolight
{

class ObjectDragStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static ObjectDragStyle* New();
  vtkTypeMacro(ObjectDragStyle, vtkInteractorStyleTrackballCamera);

  /** The actor a left drag may move (none: the plain trackball camera). */
  void SetObject(vtkActor* object);
  /**
   * An actor drawn in the object's place (a relief chart) by `renderer` (the reliefs' layer,
   * which takes no events): a pick on it picks the object.
   */
  void AddStandIn(vtkActor* actor, vtkRenderer* renderer);

  void OnLeftButtonDown() override;
  void OnLeftButtonUp() override;
  void OnMouseMove() override;

  /** Whether a drag of the object is under way. */
  bool IsDragging() const { return this->Dragging; }

protected:
  ObjectDragStyle();
  ~ObjectDragStyle() override;

private:
  ObjectDragStyle(const ObjectDragStyle&) = delete;
  void operator=(const ObjectDragStyle&) = delete;

  vtkWeakPointer<vtkActor> Object;
  vtkNew<vtkCellPicker> Picker;
  vtkWeakPointer<vtkRenderer> StandInRenderer;
  bool Dragging = false;
};

} // namespace mesolight

#endif
