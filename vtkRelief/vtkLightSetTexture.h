// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightSetTexture
 * @brief   An image-based light set on the GPU, sorted strongest first, for relief shading.
 *
 * The light set is an N x 2 image with 3 or 4 components (vtkMedianCutLights' light texture):
 * row 0 the directions toward the lights in world coordinates, row 1 the irradiance each
 * delivers at normal incidence (RGB). It is uploaded as an N x 2 float RGBA texture: unit
 * directions in row 0, irradiance in row 1, each light's luminance in A, sorted by luminance
 * (strongest first) so the shader can stop at the first negligible light. Uploads are keyed by
 * the scalar array and its modification time.
 */

#ifndef vtkLightSetTexture_h
#define vtkLightSetTexture_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for TextureObject

class vtkDataArray;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkLightSetTexture : public vtkObject
{
public:
  static vtkLightSetTexture* New();
  vtkTypeMacro(vtkLightSetTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Uploads the light set unless it is already on the GPU of this window; null means no light
   * set (true). False (with an error) for a malformed light set or a failed upload: the relief
   * is then lit as without one (HasLightSet false), as a malformed set of probes is.
   */
  bool Update(vtkOpenGLRenderWindow* renWin, vtkImageData* lights);

  /** Whether the last Update was given a light set and uploaded it. */
  vtkGetMacro(HasLightSet, bool);

  /** Number of lights uploaded. */
  vtkGetMacro(NumberOfLights, int);

  /** Luminance of the strongest light uploaded. */
  vtkGetMacro(MaximumLuminance, float);

  /** The texture; null before the first upload. */
  vtkTextureObject* GetTextureObject() { return this->TextureObject; }

  void ReleaseGraphicsResources(vtkWindow* win);

protected:
  vtkLightSetTexture();
  ~vtkLightSetTexture() override;

  bool Upload(vtkOpenGLRenderWindow* renWin, vtkImageData* lights);

  vtkSmartPointer<vtkTextureObject> TextureObject;
  vtkDataArray* Uploaded = nullptr; // not referenced: only compared
  vtkMTimeType UploadTime = 0;
  int NumberOfLights = 0;
  float MaximumLuminance = 0.0f;
  bool HasLightSet = false;

private:
  vtkLightSetTexture(const vtkLightSetTexture&) = delete;
  void operator=(const vtkLightSetTexture&) = delete;
};

#endif
