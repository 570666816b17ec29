// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldCameraView
 * @brief   the renderer's camera as a view of the light field (mesolight::vlf::ViewFrame in the
 *          field's unit sphere), and the warnings about views the field cannot show
 *
 * Private to Mesolight::LightFieldActor (header not installed). Update() reads the viewport and
 * the camera each frame and keeps the last view (the progressive worker traces it once it
 * rests). It warns, on behalf of the actor, once about a parallel projection (the walkthrough
 * needs a perspective camera), about a camera that defines no view, and once per stay about an
 * eye behind the field's one-sided surfaces (inside a wall).
 */
#ifndef vtkLightFieldCameraView_h
#define vtkLightFieldCameraView_h

#include "WalkthroughTracer.h" // For ViewFrame

class vtkObject;
class vtkRenderer;

class vtkLightFieldCameraView
{
public:
  /** owner: the object warnings are reported for (the actor). */
  explicit vtkLightFieldCameraView(vtkObject* owner);

  /**
   * The view of the renderer's active camera over its viewport. False (and no last view) for a
   * zero-size viewport, a parallel projection or a camera that defines no view.
   */
  bool Update(vtkRenderer* renderer, const mesolight::vlf::LightField& field,
    const mesolight::vlf::WalkthroughTracer& tracer);
  /** Forgets the last view (a new field). */
  void Forget() { this->HaveLast = false; }

  bool HasView() const { return this->HaveLast; }
  const mesolight::vlf::ViewFrame& GetView() const { return this->Last; }
  /** The last Update gave a view other than the one before. */
  bool IsNew() const { return this->New; }
  /** The viewport of the last Update: size and window origin in pixels. */
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }
  const int* GetOrigin() const { return this->Origin; }

private:
  // Says once per stay if the eye sits behind surfaces (inside a wall or a block), where the
  // one-sided field shows black.
  void CheckInsideWall(
    const mesolight::vlf::ViewFrame& view, const mesolight::vlf::WalkthroughTracer& tracer);

  vtkObject* Owner;
  mesolight::vlf::ViewFrame Last;
  bool HaveLast = false;
  bool New = false;
  int Width = 0;
  int Height = 0;
  int Origin[2] = { 0, 0 };
  bool WarnedParallel = false;
  bool WarnedInsideWall = false;
};

#endif
