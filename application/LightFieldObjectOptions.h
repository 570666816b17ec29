// SPDX-License-Identifier: BSD-3-Clause
// The movable object of `mesolight vlf render --mode` and `mesolight vlf view` (--object, its
// placement, shading and --path): the options, their parsing, and the object actor with its
// vtkLightFieldObjectMapper in the walkthrough's renderer (Wither 2005, "Interactive dynamic
// objects in a virtual light field", chapter 3; docs/walkthrough.md "A movable object").
#ifndef mesolight_LightFieldObjectOptions_h
#define mesolight_LightFieldObjectOptions_h

#include "LightFieldObjectRelief.h" // ObjectRelief
#include "ObjectPath.h"             // ObjectPlacement, ParsePlacement, ReadPath
#include "vtkLightFieldObjectMapper.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkLightFieldActor;
class vtkRenderer;

namespace mesolight
{
namespace vlf
{
struct ObjectMesh;
}
}

namespace mesolight
{
class CommandLine;

// --object, --object-transform, --object-colour, --shading, --shadows, --subdivision,
// --gather-directions, --object-relief, --object-relief-depth-scale.
void AddObjectOptions(CommandLine& cl);

// The polydata of an object mesh (points, triangles, normals when it has them).
vtkSmartPointer<vtkPolyData> ObjectPolyData(const mesolight::vlf::ObjectMesh& mesh);

void ApplyPlacement(vtkActor* object, const ObjectPlacement& p);

// The object of the command line in the walkthrough's renderer.
struct MovableObject
{
  vtkNew<vtkActor> Actor;
  vtkNew<vtkLightFieldObjectMapper> Mapper;
  bool Active = false;
  ObjectPlacement Placement; // the one --object-transform (or the default) gave
  double Step = 1.0;         // world units per key press (a twentieth of the field)
  ObjectRelief Relief;       // --object-relief: the charts' relief actors draw the object
};

// 0 when set up (or no --object), else the command's exit code (the message is printed).
// `inputs` gathers the files read, so no output overwrites them.
int SetUpObject(const CommandLine& cl, const char* command, vtkLightFieldActor* scene,
  vtkRenderer* renderer, MovableObject& object, std::vector<std::string>* inputs = nullptr);

} // namespace mesolight

#endif
