// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldReliefs.h"

#include "CommandLine.h"
#include "ReliefScene.h" // BuildReliefTextures
#include "VlfRelief.h"   // ReadDepthImage
#include "vtkMessageCollector.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "WalkthroughTracer.h" // TracedReliefs
#include "vtkLightFieldReliefMapper.h"
#include "vtkLightFieldReliefSurface.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include "EmbreeScene.h"
#include "EmitterLights.h"
#include "LightField.h"
#include "ReliefOcclusion.h" // EmitterLightVisibility
#include "ReliefShading.h"
#include "ReliefSurface.h"
#include "TriangleScene.h"
#include "vtkIrradianceProbesTexture.h" // the visible share's array names
#include <vtkTextureObject.h>    // for vtkIrradianceProbesTexture's inline getter

#include <vtkActor.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkActorCollection.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <iostream>
#include <memory>

namespace mesolight
{

void AddReliefOptions(CommandLine& cl)
{
  cl.AddValue("--relief", "SURFACE=DEPTH_IMAGE",
    "repeatable: draw the named surface of the field's scene as a relief (depth image, 0 = top, "
    "1 = deepest) by the relief mapper, lit by the field: indirect light as SH9 probes, the "
    "emitters as lights");
  cl.AddValue("--relief-depth-scale", "K",
    "world depth of depth 1 over the world width of the relief's texture", "0.05");
  cl.AddFlag("--relief-no-occlusion",
    "the relief mapper without the relief's occlusion of its indirect light, its "
    "inter-reflection and the scene's shadows of the emitter lights (for comparison)");
}

std::vector<std::string> ReliefInputs(const CommandLine& cl)
{
  std::vector<std::string> inputs;
  for (const std::string& item : cl.GetAll("--relief"))
  {
    const std::size_t equals = item.find('=');
    if (equals != std::string::npos)
    {
      inputs.push_back(item.substr(equals + 1));
    }
  }
  return inputs;
}

namespace
{
// Texels per side of the relief's visible-share map at most: V varies at the scale of the
// relief's features, and the map costs OcclusionDirections exact marches per texel, once.
constexpr int MaxVisibleShareSide = 256;

// The probes of `surface` with what the relief mapper needs to draw the relief's occlusion, its
// inter-reflection and the scene's shadows of the emitter lights at near-zero cost per pixel
// (vtkIrradianceProbesTexture): the relief's visible share over its texture, precomputed on the
// exact height-field intersector with the CPU renderer's directions (ReliefVisibleShareMap), and
// per probe the scene's visibility of each emitter light (EmitterLightVisibility), in the order
// the relief layer's renderer has them (vtkLightFieldReliefSurface::GetEmitterLights). Throws
// ReliefSetupError for an unreadable depth image.
vtkSmartPointer<vtkImageData> OccludedProbes(const vlf::LightField& field,
  const EmbreeScene& embree, const std::string& name, const std::string& depthImage,
  double depthScale, vtkImageData* probes)
{
  const vlf::ReliefSurface surface = vlf::FindReliefSurface(field, name);
  const HeightField height = ReadDepthImage(depthImage);
  ReliefFrame frame;
  frame.Origin = surface.Origin;
  frame.AxisU = surface.AxisU;
  frame.AxisV = surface.AxisV;
  frame.Normal = surface.Normal;
  frame.DepthScale = depthScale;
  const int w = std::min(height.Width(), MaxVisibleShareSide);
  const int h = std::min(height.Height(), MaxVisibleShareSide);
  const std::vector<float> share =
    ReliefVisibleShareMap(height, frame, w, h, ReliefLighting().OcclusionDirections);

  int dims[3];
  probes->GetDimensions(dims);
  const int nu = dims[0] / 9, nv = dims[1];
  std::vector<glm::vec3> lights;
  for (const vlf::EmitterLight& light : vlf::EstimateEmitterLights(field).Lights)
  {
    lights.push_back(light.Position);
  }
  const std::vector<float> visible =
    vlf::EmitterLightVisibility(field, embree, surface, lights, nu, nv);

  auto result = vtkSmartPointer<vtkImageData>::New();
  result->DeepCopy(probes);
  vtkDataArray* in = probes->GetPointData()->GetScalars();
  vtkNew<vtkFloatArray> out;
  out->SetName(in->GetName());
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(in->GetNumberOfTuples());
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < 9 * nu; ++i)
    {
      const vtkIdType pixel = static_cast<vtkIdType>(j) * dims[0] + i;
      const std::size_t k = static_cast<std::size_t>(i % 9);
      const std::size_t probe = static_cast<std::size_t>(j) * nu + i / 9;
      const float tuple[4] = { static_cast<float>(in->GetComponent(pixel, 0)),
        static_cast<float>(in->GetComponent(pixel, 1)),
        static_cast<float>(in->GetComponent(pixel, 2)),
        k < lights.size() ? visible[probe * lights.size() + k] : 1.0f };
      out->SetTypedTuple(pixel, tuple);
    }
  }
  result->GetPointData()->SetScalars(out);
  vtkNew<vtkFloatArray> shareArray;
  shareArray->SetName(vtkIrradianceProbesTexture::GetVisibleShareName());
  shareArray->SetNumberOfComponents(2);
  shareArray->SetNumberOfTuples(static_cast<vtkIdType>(share.size() / 2));
  std::copy(share.begin(), share.end(), shareArray->GetPointer(0));
  vtkNew<vtkIntArray> shareSize;
  shareSize->SetName(vtkIrradianceProbesTexture::GetVisibleShareSizeName());
  shareSize->InsertNextValue(w);
  shareSize->InsertNextValue(h);
  result->GetFieldData()->AddArray(shareArray);
  result->GetFieldData()->AddArray(shareSize);
  return result;
}

// The walkthrough's display settings on every relief of the relief layer (static surfaces and
// a relief-mapped movable object alike).
void CopyDisplay(vtkLightFieldActor* actor, const WalkthroughReliefs& reliefs)
{
  vtkActorCollection* actors = reliefs.Renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* relief = actors->GetNextActor())
  {
    if (vtkReliefMapper* mapper = vtkReliefMapper::SafeDownCast(relief->GetMapper()))
    {
      CopyWalkthroughDisplay(actor, mapper->GetReliefProperty());
    }
  }
}

void OnActorModified(vtkObject* caller, unsigned long, void* clientData, void*)
{
  CopyDisplay(static_cast<vtkLightFieldActor*>(caller),
    *static_cast<const WalkthroughReliefs*>(clientData));
}

// The reliefs as the walkthrough's mirrors show them: a reflected ray that reaches a relief's
// wall is shaded by the CPU reference (`vlf render --relief`: SetUpFieldReliefs, ReliefRadiance,
// the exact height-field intersection and the same probes and emitters), so the mirror shows the
// relief the relief mapper draws where it is seen directly.
class MirroredReliefs : public vlf::TracedReliefs
{
public:
  MirroredReliefs(const vlf::LightField& field, const std::vector<std::string>& items,
    double depthScale)
    : Embree(field.Scene())
  {
    FieldReliefOptions options;
    options.DepthScale = depthScale;
    this->Reliefs = SetUpFieldReliefs(field, this->Embree, items, options);
    this->ReliefOf = ReliefOfTriangle(field, this->Reliefs);
  }
  bool Covers(std::size_t triangle) const override
  {
    return triangle < this->ReliefOf.size() && this->ReliefOf[triangle] >= 0;
  }
  bool Radiance(std::size_t triangle, const glm::vec3& origin, const glm::vec3& direction,
    glm::vec3& radiance) const override
  {
    return this->Covers(triangle) &&
      ReliefRadiance(this->Reliefs[static_cast<std::size_t>(this->ReliefOf[triangle])], origin,
        direction, radiance);
  }

private:
  EmbreeScene Embree; // the scene's occlusion of the emitters (the reliefs' lighting)
  std::vector<FieldRelief> Reliefs;
  std::vector<int> ReliefOf; // per scene triangle
};
} // namespace

WalkthroughReliefs::~WalkthroughReliefs()
{
  if (this->Followed)
  {
    this->Followed->RemoveObserver(this->FollowTag);
  }
}

void CopyWalkthroughDisplay(vtkLightFieldActor* actor, vtkReliefProperty* property)
{
  property->SetExposure(actor->GetExposure());
  property->SetToneMapping(actor->GetToneMap() == vtkLightFieldActor::Reinhard);
  property->EncodeSRGBOn(); // the walkthrough's radiance is sRGB-encoded (vtkLightFieldActor)
}

vtkRenderer* ReliefLayer(vtkLightFieldActor* actor, vtkRenderer* walkthrough,
  vtkRenderWindow* window, WalkthroughReliefs& reliefs)
{
  vtkRenderer* renderer = reliefs.Renderer;
  if (reliefs.Followed)
  {
    return renderer;
  }
  // Above the walkthrough, its depth kept, the same camera; its lights are the field's emitters
  // (no headlight), so they light the reliefs only.
  window->SetNumberOfLayers(std::max(2, window->GetNumberOfLayers()));
  renderer->SetLayer(1);
  renderer->PreserveDepthBufferOn();
  renderer->InteractiveOff();
  renderer->AutomaticLightCreationOff();
  renderer->SetActiveCamera(walkthrough->GetActiveCamera());
  window->AddRenderer(renderer);
  vtkLightFieldReliefSurface::GetEmitterLights(actor, renderer->GetLights());
  reliefs.FollowDisplay->SetCallback(OnActorModified);
  reliefs.FollowDisplay->SetClientData(&reliefs);
  reliefs.FollowTag = actor->AddObserver(vtkCommand::ModifiedEvent, reliefs.FollowDisplay);
  reliefs.Followed = actor;
  return renderer;
}

int SetUpWalkthroughReliefs(const CommandLine& cl, const char* command, vtkLightFieldActor* actor,
  vtkRenderer* walkthrough, vtkRenderWindow* window, WalkthroughReliefs& reliefs)
{
  const std::vector<std::string> items = cl.GetAll("--relief");
  if (items.empty())
  {
    return 0;
  }
  double depthScale = 0.05;
  std::string error;
  if (!cl.GetDouble("--relief-depth-scale", 0.0, 10.0, depthScale, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  const vlf::LightField* field = vtkLightFieldActorCore::GetLightField(actor);
  if (!field)
  {
    return 1; // the actor reported why
  }
  const auto quoted = [](const std::string& text) { return "'" + text + "'"; };
  std::vector<std::string> names;
  for (const std::string& item : items)
  {
    // The CPU reference's messages (application/VlfRelief.cxx, SetUpFieldReliefs).
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == item.size())
    {
      std::cerr << command << ": --relief " << quoted(item)
                << ": give SURFACE=DEPTH_IMAGE (the field's surfaces: "
                << SurfaceNameList(field->Scene()) << ")\n";
      return 2;
    }
    const std::string name = item.substr(0, equals);
    if (std::find(names.begin(), names.end(), name) != names.end())
    {
      std::cerr << command << ": --relief names surface " << quoted(name) << " twice\n";
      return 2;
    }
    names.push_back(name);
  }

  vtkRenderer* renderer = ReliefLayer(actor, walkthrough, window, reliefs);
  const bool occlusion = !cl.Has("--relief-no-occlusion");
  std::unique_ptr<EmbreeScene> embree;
  if (occlusion)
  {
    embree = std::make_unique<EmbreeScene>(field->Scene());
  }

  for (std::size_t r = 0; r < names.size(); ++r)
  {
    const std::string& name = names[r];
    const std::string depthImage = items[r].substr(items[r].find('=') + 1);
    vtkNew<MessageCollector> messages;
    vtkNew<vtkLightFieldReliefSurface> surface;
    messages->Watch(surface);
    vtkNew<MessageCollector> executiveNoise; // its "returned failure" follow-up
    executiveNoise->Watch(surface->GetExecutive());
    surface->SetLightFieldActor(actor);
    surface->SetSurfaceName(name.c_str());
    surface->Update();
    if (!messages->Errors.empty())
    {
      std::cerr << command << ": --relief: " << messages->ErrorText() << "\n";
      return 2;
    }
    ReliefSceneOptions textureOptions;
    textureOptions.DepthFile = depthImage;
    textureOptions.DepthScale = depthScale;
    vtkSmartPointer<vtkImageData> texture;
    vtkSmartPointer<vtkTexture> albedo;
    if (!BuildReliefTextures(textureOptions, texture, albedo, error))
    {
      std::cerr << command << ": --relief: " << error << "\n";
      return 2;
    }
    // A vtkReliefMapper that also draws the movable object's shadow as the walls show it.
    vtkNew<vtkLightFieldReliefMapper> mapper;
    mapper->SetLightFieldActor(actor);
    mapper->SetInputConnection(surface->GetOutputPort(0));
    mapper->SetReliefTextureData(texture);
    if (occlusion)
    {
      try
      {
        mapper->SetIrradianceProbesData(OccludedProbes(*field, *embree, name, depthImage,
          depthScale, vtkImageData::SafeDownCast(surface->GetOutputDataObject(1))));
      }
      catch (const std::exception& e)
      {
        std::cerr << command << ": --relief: " << e.what() << "\n";
        return 2;
      }
    }
    else
    {
      mapper->SetIrradianceProbesConnection(surface->GetOutputPort(1));
    }
    vtkReliefProperty* property = mapper->GetReliefProperty();
    property->SetDepthScale(depthScale);
    property->SetSelfShadowing(true);
    // A wall of a closed room has no silhouette: a view ray leaving the texture at its edge
    // would show the background through the hidden wall (the CPU reference keeps the wall there).
    property->SilhouettesOff();
    vtkNew<vtkActor> relief;
    relief->SetMapper(mapper);
    const double* kd = surface->GetSurfaceDiffuse();
    relief->GetProperty()->SetColor(kd[0], kd[1], kd[2]);
    relief->GetProperty()->SetAmbient(0.0);
    relief->GetProperty()->SetDiffuse(1.0);
    relief->GetProperty()->SetSpecular(0.0);
    renderer->AddActor(relief);
    actor->AddHiddenSurface(name);
    reliefs.Surfaces.emplace_back(surface);
    reliefs.Actors.emplace_back(relief);
  }
  // Mirrors show the reliefs (not the flat walls the tracer keeps) where their rays land.
  bool mirrors = false;
  for (std::uint32_t surface = 0; surface < field->Surfaces().size(); ++surface)
  {
    const glm::vec3 ks = field->MaterialOf(surface).Specular;
    mirrors = mirrors || ks.x > 0.0f || ks.y > 0.0f || ks.z > 0.0f;
  }
  if (mirrors)
  {
    try
    {
      vtkLightFieldActorCore::SetTracedReliefs(
        actor, std::make_shared<MirroredReliefs>(*field, items, depthScale));
    }
    catch (const std::exception& e)
    {
      std::cerr << command << ": --relief: " << e.what() << "\n";
      return 2;
    }
  }
  CopyDisplay(actor, reliefs);
  return 0;
}

} // namespace mesolight
