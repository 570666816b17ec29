// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAttachReliefTexture
 * @brief   Attaches a relief texture (and optionally a light set) to a dataset as field data,
 *          for relief mappers that only see the geometry (ParaView's Relief Surface).
 *
 * Input port 0: any vtkDataSet (the surface to draw; it needs point texture coordinates).
 * Input port 1: the relief texture, a 4-component vtkImageData (vtkReliefTextureFilter or
 * vtkConeMapFilter output). Input port 2 (optional): a light set, vtkMedianCutLights' N x 2
 * light texture (its output port 1). Input port 3 (optional): a colour (albedo) image in the same
 * texture coordinates, e.g. vtkDepthHallucinationFilter's albedo.
 *
 * The output is the input (shallow copy) with field data arrays
 *  - "MesolightReliefTexture" (the texels, shared with the image) and
 *    "MesolightReliefTextureSize" (width, height), "MesolightReliefTextureDepthScale" and
 *    "MesolightReliefTextureConeType" when the image carries them;
 *  - "MesolightLightSet" and "MesolightLightSetSize" when a light set is connected;
 *  - "MesolightColorTexture" and "MesolightColorTextureSize" when a colour image is connected
 *    (ParaView's Relief Surface representation uses it as the actor's texture unless the user
 *    chose a Texture).
 * GetAttachedReliefTexture() / GetAttachedLightSet() / GetAttachedColorTexture() turn them back
 * into images.
 *
 * A flat polygonal surface whose texture coordinates draw the map more than 2% out of its
 * proportions on the ground (vtkReliefPlaneFilter::GetGroundProportions; a vtkPlaneSource is
 * square whatever the map) stretches every feature of the relief: a warning says by how much and
 * names vtkReliefPlaneFilter (ParaView's Mesolight Relief Plane), once until the stretch changes.
 * Curved surfaces are not judged:
 * their parametrisation has a stretch of its own (mesolight::TextureProportions).
 *
 * Why field data: a ParaView representation has one input, and field data travels with every
 * piece of a distributed dataset (each MPI rank draws its piece with the whole texture), through
 * state files and pvbatch, where a second pipeline input of the representation would not.
 * The images are requested whole whatever piece the surface is.
 */
#ifndef vtkAttachReliefTexture_h
#define vtkAttachReliefTexture_h

#include "MesolightReliefTexturesModule.h" // For export macro
#include "vtkPassInputTypeAlgorithm.h"
#include "vtkSmartPointer.h" // For the returned images

#include <string> // For std::string

class vtkAlgorithmOutput;
class vtkDataArray;
class vtkDataObject;
class vtkFieldData;
class vtkImageData;

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkAttachReliefTexture : public vtkPassInputTypeAlgorithm
{
public:
  static vtkAttachReliefTexture* New();
  vtkTypeMacro(vtkAttachReliefTexture, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The relief texture (input port 1). */
  void SetReliefTextureConnection(vtkAlgorithmOutput* output);
  /** The light set (input port 2, optional). */
  void SetLightSetConnection(vtkAlgorithmOutput* output);

  /** The colour (albedo) image (input port 3, optional). */
  void SetColorTextureConnection(vtkAlgorithmOutput* output);

  /** The relief texture attached to a dataset's field data as an image; null if none. */
  static vtkSmartPointer<vtkImageData> GetAttachedReliefTexture(vtkDataObject* data);
  /** The light set attached to a dataset's field data as an image; null if none. */
  static vtkSmartPointer<vtkImageData> GetAttachedLightSet(vtkDataObject* data);

  /** The colour image attached to a dataset's field data as an image; null if none. */
  static vtkSmartPointer<vtkImageData> GetAttachedColorTexture(vtkDataObject* data);

protected:
  vtkAttachReliefTexture();
  ~vtkAttachReliefTexture() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkAttachReliefTexture(const vtkAttachReliefTexture&) = delete;
  void operator=(const vtkAttachReliefTexture&) = delete;

  // Adds the image's scalars (shared, not copied) and size under prefix; false if it has none.
  // The array attached for input `port` is the same object while the image's scalars are: a
  // consumer that keeps work per texture (the Relief Surface's visible-share map) tells a new
  // texture from a re-execution for another input (e.g. a colour texture attached).
  bool Attach(vtkImageData* image, int port, const char* prefix, vtkFieldData* field);
  struct AttachedArray
  {
    vtkDataArray* Source = nullptr; // the image's scalars; compared only (with their time)
    vtkMTimeType SourceTime = 0;
    vtkSmartPointer<vtkDataArray> Attached;
  };
  AttachedArray AttachedArrays[4]; // per input port (1-3 used)
  std::string LastStretchWarning;  // said once until the stretch changes
};

#endif
