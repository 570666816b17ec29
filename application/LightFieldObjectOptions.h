// SPDX-License-Identifier: BSD-3-Clause
// The movable object of `mesolight vlf render --mode` and `mesolight vlf view` (--object, its
// placement, shading and --path): the options, their parsing, and the object actor with its
// vtkLightFieldObjectMapper in the walkthrough's renderer (Wither 2005, "Interactive dynamic
// objects in a virtual light field", chapter 3; docs/walkthrough.md "A movable object").
#ifndef mesolight_LightFieldObjectOptions_h
#define mesolight_LightFieldObjectOptions_h

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
// --gather-directions.
void AddObjectOptions(CommandLine& cl);

struct ObjectPlacement
{
  double Position[3] = { 0.0, 0.0, 0.0 };
  double Orientation[3] = { 0.0, 0.0, 0.0 };
  double Scale = 1.0;
};

// The polydata of an object mesh (points, triangles, normals when it has them).
vtkSmartPointer<vtkPolyData> ObjectPolyData(const mesolight::vlf::ObjectMesh& mesh);

// "tx,ty,tz[,rx,ry,rz[,s]]" over the defaults in `placement`; "" or why not.
std::string ParsePlacement(const std::string& text, ObjectPlacement& placement);
void ApplyPlacement(vtkActor* object, const ObjectPlacement& p);

// The object of the command line in the walkthrough's renderer.
struct MovableObject
{
  vtkNew<vtkActor> Actor;
  vtkNew<vtkLightFieldObjectMapper> Mapper;
  bool Active = false;
  ObjectPlacement Placement; // the one --object-transform (or the default) gave
  double Step = 1.0;         // world units per key press (a twentieth of the field)
};

// 0 when set up (or no --object), else the command's exit code (the message is printed).
// `inputs` gathers the files read, so no output overwrites them.
int SetUpObject(const CommandLine& cl, const char* command, vtkLightFieldActor* scene,
  vtkRenderer* renderer, MovableObject& object, std::vector<std::string>* inputs = nullptr);

// --path FILE: one placement per line ("tx,ty,tz[,rx,ry,rz[,s]]"; '#' comments and a header
// line of names are skipped); rows without a scale keep `base`'s.
bool ReadPath(const std::string& file, const ObjectPlacement& base,
  std::vector<ObjectPlacement>& path, std::string& error);

// One line on the object after a frame: timings and anything wrong with its placement.
void PrintObjectNote(vtkLightFieldActor* actor, const MovableObject& object);

} // namespace mesolight

#endif
