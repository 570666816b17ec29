// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkGeometryImageToMeshCore
 * @brief   vtkGeometryImageToMesh's conversion to the core's mesolight::GeometryImage, for code
 *          built in this tree
 *
 * Private to Mesolight::GeometryImages (header not installed: the core's headers are not
 * either), as vtkLightFieldActorCore is for the light field actor. The evaluation scenes build
 * their dense reference meshes from it.
 */
#ifndef vtkGeometryImageToMeshCore_h
#define vtkGeometryImageToMeshCore_h

#include "MesolightGeometryImagesModule.h" // For export macro

#include <string>

class vtkImageData;
namespace mesolight
{
struct GeometryImage;
}

class MESOLIGHTGEOMETRYIMAGES_EXPORT vtkGeometryImageToMeshCore
{
public:
  /**
   * The positions (and normals, from normalImage or a "Normals" array of image) of a VTK image
   * as a core geometry image. False with a message for unusable input.
   */
  static bool ToGeometryImage(vtkImageData* image, vtkImageData* normalImage,
    mesolight::GeometryImage& geometry, std::string& error);
};

#endif
