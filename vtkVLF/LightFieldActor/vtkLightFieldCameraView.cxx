// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldCameraView.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkObject.h"
#include "vtkRenderer.h"

#include "PatchComparison.h" // ToUnit

#include <cmath>

namespace vlf = mesolight::vlf;

//------------------------------------------------------------------------------
vtkLightFieldCameraView::vtkLightFieldCameraView(vtkObject* owner)
  : Owner(owner)
{
}

//------------------------------------------------------------------------------
bool vtkLightFieldCameraView::Update(
  vtkRenderer* renderer, const vlf::LightField& field, const vlf::WalkthroughTracer& tracer)
{
  renderer->GetTiledSizeAndOrigin(&this->Width, &this->Height, &this->Origin[0], &this->Origin[1]);
  const int width = this->Width, height = this->Height;
  vtkCamera* camera = renderer->GetActiveCamera();
  if (width < 1 || height < 1 || !camera)
  {
    this->HaveLast = false;
    return false; // a zero-size viewport: nothing to compute, nothing drawn from the screen
  }
  if (camera->GetParallelProjection())
  {
    if (!this->WarnedParallel)
    {
      vtkWarningWithObjectMacro(
        this->Owner, << "the light field walkthrough needs a perspective camera; mirrors and "
                        "raytrace pixels show only the diffuse textures under parallel projection");
      this->WarnedParallel = true;
    }
    this->HaveLast = false;
    return false;
  }
  double position[3], focal[3], up[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  double angle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle())
  {
    const double half =
      std::atan(std::tan(0.5 * vtkMath::RadiansFromDegrees(angle)) * height / width);
    angle = 2.0 * vtkMath::DegreesFromRadians(half);
  }
  vlf::ViewFrame view;
  if (!vlf::ViewFrame::Make(vlf::ToUnit(field, glm::vec3(position[0], position[1], position[2])),
        vlf::ToUnit(field, glm::vec3(focal[0], focal[1], focal[2])), glm::vec3(up[0], up[1], up[2]),
        static_cast<float>(angle), width, height, view))
  {
    vtkWarningWithObjectMacro(
      this->Owner, << "the camera does not define a view (position on the focal point or view up "
                      "along the view direction): nothing traced");
    this->HaveLast = false;
    return false;
  }
  this->New = !this->HaveLast || view != this->Last;
  if (this->New)
  {
    this->CheckInsideWall(view, tracer);
  }
  this->Last = view;
  this->HaveLast = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldCameraView::CheckInsideWall(
  const vlf::ViewFrame& view, const vlf::WalkthroughTracer& tracer)
{
  int back = 0;
  for (int q = 0; q < 9; ++q)
  {
    const mesolight::SceneRay ray =
      view.Ray((0.5f + static_cast<float>(q % 3)) * this->Width / 3.0f,
        (0.5f + static_cast<float>(q / 3)) * this->Height / 3.0f);
    std::uint32_t s;
    if (tracer.Classify(ray, tracer.Embree().Intersect(ray), s) == vlf::PixelClass::BackFace)
    {
      ++back;
    }
  }
  // Once per stay behind the surfaces, not once per frame of a moving camera.
  const bool warn = back >= 5 && !this->WarnedInsideWall;
  this->WarnedInsideWall = back >= 5;
  if (warn)
  {
    vtkWarningWithObjectMacro(this->Owner,
      << "the camera sees the back of the light field's surfaces (is it inside a wall, or "
         "outside a closed room?): "
         "the field is one-sided, so they show black");
  }
}
