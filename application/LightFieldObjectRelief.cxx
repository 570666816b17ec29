// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldObjectRelief.h"

#include "LightFieldReliefs.h"

#include "CommandLine.h"
#include "vtkMessageCollector.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldReliefActor.h"
#include "vtkOIIOImageReader.h"
#include "vtkReliefMapper.h"
#include "vtkReliefTextureFilter.h"

#include "Snapshot.h" // FileExists

#include <vtkMatrix4x4.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <iostream>

namespace mesolight
{

namespace
{
// Before the renderer draws: the probes at the object's placement (regathered when it moved),
// the relief actors at its matrix, the scene's exposure.
void SyncObjectRelief(vtkObject*, unsigned long, void* clientData, void*)
{
  ObjectRelief& relief = *static_cast<ObjectRelief*>(clientData);
  if (!relief.Active || !relief.Object)
  {
    return;
  }
  const vtkMTimeType before = relief.Probes->GetMTime();
  if (relief.Probes->Update() && relief.Probes->GetMTime() != before)
  {
    relief.ProbeSeconds += relief.Probes->GetLastSeconds();
    relief.GatheredProbes += relief.Probes->GetLastGatheredProbes();
    ++relief.Moves;
  }
  vtkMatrix4x4* matrix = relief.Object->GetMatrix();
  vtkLightFieldActor* scene = relief.Probes->GetLightFieldActor();
  for (vtkActor* actor : relief.Actors)
  {
    vtkMatrix4x4* user = actor->GetUserMatrix();
    bool same = true;
    for (int e = 0; e < 16; ++e)
    {
      same = same && user->GetElement(e / 4, e % 4) == matrix->GetElement(e / 4, e % 4);
    }
    if (!same)
    {
      user->DeepCopy(matrix);
    }
    if (scene)
    {
      vtkLightFieldReliefActor::CopyDisplay(
        scene, vtkReliefMapper::SafeDownCast(actor->GetMapper())->GetReliefProperty());
    }
  }
}
} // namespace

void AddObjectReliefOptions(CommandLine& cl)
{
  cl.AddValue("--object-relief", "DEPTH_IMAGE",
    "with --object cube or FILE.obj with texture coordinates: draw the object as a relief of this "
    "depth image (0 = top, 1 = deepest) over its texture, lit per pixel by the field at the "
    "relief's perturbed normal (SH9 probes of the field's indirect light per chart of the "
    "texture, regathered when the object moves); its shadow stays the object's");
  cl.AddValue("--object-relief-depth-scale", "K",
    "world depth of depth 1 over the world width of the object's texture", "0.05");
  cl.AppliesOnlyWith("--object-relief-depth-scale", { "--object-relief" });
}

int CheckObjectRelief(const CommandLine& cl, const char* command, const std::string& objectName,
  bool hasTextureCoordinates)
{
  if (!cl.Has("--object-relief"))
  {
    return 0;
  }
  double scale = 0.0;
  std::string error;
  if (!cl.GetDouble("--object-relief-depth-scale", 0.0, 10.0, scale, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  if (!hasTextureCoordinates)
  {
    std::cerr << command << ": --object-relief: "
              << (objectName == "sphere" ? std::string("the built-in sphere")
                                         : "'" + objectName + "'")
              << " has no texture coordinates, which a relief is laid out by: use --object cube "
                 "(each face maps the whole depth image), or an OBJ file with a 'vt' coordinate "
                 "on every face corner (e.g. unwrap it in Blender, UV > Smart UV Project, and "
                 "export with UVs)\n";
    return 2;
  }
  const std::string depth = cl.Get("--object-relief");
  if (!vlf::FileExists(depth))
  {
    std::cerr << command << ": --object-relief: cannot read the depth image '" << depth
              << "': no such file\n";
    return 2;
  }
  return 0;
}

int SetUpObjectRelief(const CommandLine& cl, const char* command, vtkLightFieldActor* scene,
  vtkRenderer* renderer, vtkActor* object, ObjectRelief& relief)
{
  if (!cl.Has("--object-relief"))
  {
    return 0;
  }
  double scale = 0.05;
  std::string error;
  cl.GetDouble("--object-relief-depth-scale", 0.0, 10.0, scale, error); // checked before
  const std::string depth = cl.Get("--object-relief");
  vtkNew<MessageCollector> messages;
  vtkNew<vtkOIIOImageReader> reader;
  messages->Watch(reader);
  reader->SetFileName(depth.c_str());
  vtkNew<vtkReliefTextureFilter> bake;
  messages->Watch(bake);
  bake->SetInputConnection(reader->GetOutputPort());
  bake->SetDepthScale(scale);
  bake->Update();
  int dims[3] = { 0, 0, 0 };
  if (bake->GetOutput())
  {
    bake->GetOutput()->GetDimensions(dims);
  }
  if (!messages->Errors.empty() || dims[0] < 2 || dims[1] < 2)
  {
    std::cerr << command << ": --object-relief: cannot read the depth image '" << depth << "'"
              << (messages->Errors.empty() ? std::string(": it has fewer than 2 x 2 pixels")
                                           : ": " + messages->ErrorText())
              << "\n";
    return 2;
  }
  relief.Texture = vtkSmartPointer<vtkImageData>::New();
  relief.Texture->DeepCopy(bake->GetOutput());

  messages->Errors.clear();
  messages->Watch(relief.Probes);
  relief.Probes->SetLightFieldActor(scene);
  if (!relief.Probes->Update())
  {
    std::cerr << command << ": --object-relief: " << messages->ErrorText() << "\n";
    return 2;
  }
  relief.Object = object;
  vtkNew<vtkMatrix4x4> matrix;
  matrix->DeepCopy(object->GetMatrix());
  for (int c = 0; c < relief.Probes->GetNumberOfCharts(); ++c)
  {
    vtkNew<vtkReliefMapper> mapper;
    mapper->SetInputData(relief.Probes->GetChart(c));
    mapper->SetReliefTextureData(relief.Texture);
    mapper->SetIrradianceProbesData(relief.Probes->GetProbes(c));
    vtkReliefProperty* property = mapper->GetReliefProperty();
    property->SetDepthScale(scale);
    // A closed object: a face's relief is cut at the face's edge, not opened into the object.
    property->SetSilhouettes(false);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->SetUserMatrix(matrix); // shared: one update moves every chart
    vtkProperty* p = actor->GetProperty();
    p->SetDiffuseColor(object->GetProperty()->GetDiffuseColor());
    p->SetDiffuse(1.0);
    p->SetAmbient(0.0);
    p->SetSpecular(0.0);
    renderer->AddActor(actor);
    relief.Actors.push_back(actor);
  }
  // The object stays the scene's movable object (shadow, reflections), drawn by the charts.
  object->VisibilityOff();
  relief.Sync->SetCallback(SyncObjectRelief);
  relief.Sync->SetClientData(&relief);
  renderer->AddObserver(vtkCommand::StartEvent, relief.Sync);
  relief.Active = true;
  return 0;
}

} // namespace mesolight
