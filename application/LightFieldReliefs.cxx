// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldReliefs.h"

#include "CommandLine.h"
#include "ReliefScene.h" // BuildReliefTextures
#include "Timing.h"
#include "VlfRelief.h" // SetUpFieldReliefs, ReliefRadiance
#include "vtkMessageCollector.h"

#include "WalkthroughTracer.h" // TracedReliefs
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldReliefActor.h"
#include "vtkLightFieldReliefSurface.h"
#include "vtkLightFieldReliefSurfaceCore.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include "EmbreeScene.h"
#include "LightField.h"
#include "TriangleScene.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <utility>

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
  cl.AddFlag("--relief-height", "the relief images store height (white = high), not depth");
  cl.AddFlag("--relief-no-occlusion",
    "the relief mapper without the relief's occlusion of its indirect light, its "
    "inter-reflection and the scene's shadows of the emitter lights (for comparison)");
  cl.AddFlag("--relief-normalize", CommandLine::ReliefNormalizeHelp);
  cl.AddValue("--relief-probes", "N", ReliefProbesHelp(), "0");
  for (const char* option : { "--relief-depth-scale", "--relief-height", "--relief-normalize",
         "--relief-no-occlusion", "--relief-probes" })
  {
    cl.AppliesOnlyWith(option, { "--relief" });
  }
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
      vtkLightFieldReliefActor::CopyDisplay(actor, mapper->GetReliefProperty());
    }
  }
}

void OnActorModified(vtkObject* caller, unsigned long, void* clientData, void*)
{
  CopyDisplay(
    static_cast<vtkLightFieldActor*>(caller), *static_cast<const WalkthroughReliefs*>(clientData));
}

// The reliefs as the walkthrough's mirrors show them: a reflected ray that reaches a relief's
// wall is shaded by the CPU reference (`vlf render --relief`: SetUpFieldReliefs, ReliefRadiance,
// the exact height-field intersection and the same probes and emitters), so the mirror shows the
// relief the relief mapper draws where it is seen directly. Its probes are the relief surfaces'
// (`probes`, per item: vtkLightFieldReliefSurface computed them, at the CPU reference's default
// count), not computed again.
class MirroredReliefs : public vlf::TracedReliefs
{
public:
  MirroredReliefs(const vlf::LightField& field, std::shared_ptr<const EmbreeScene> embree,
    const std::vector<std::string>& items, const FieldReliefOptions& options)
    : Embree(std::move(embree))
  {
    this->Reliefs = SetUpFieldReliefs(field, *this->Embree, items, options);
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
  std::shared_ptr<const EmbreeScene> Embree; // the scene's occlusion of the emitters
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

vtkRenderer* ReliefLayer(vtkLightFieldActor* actor, vtkRenderer* walkthrough,
  vtkRenderWindow* window, WalkthroughReliefs& reliefs)
{
  vtkRenderer* renderer = reliefs.Renderer;
  if (reliefs.Followed)
  {
    return renderer;
  }
  // Above the walkthrough, its depth kept, the same camera; its lights are the field's emitters
  // (no headlight), so they light nothing of the walkthrough (each relief shades its own
  // surface's list, vtkReliefProperty::SetLights).
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
  int probesPerSide = vlf::AutomaticReliefProbes;
  std::string error;
  if (!cl.GetDouble("--relief-depth-scale", 0.0, 10.0, depthScale, error) ||
    !cl.GetInt("--relief-probes", 0, 256, probesPerSide, error))
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
  // Mirrors show the reliefs (not the flat walls the tracer keeps) where their rays land.
  bool mirrors = false;
  for (std::uint32_t surface = 0; surface < field->Surfaces().size(); ++surface)
  {
    const glm::vec3 ks = field->MaterialOf(surface).Specular;
    mirrors = mirrors || ks.x > 0.0f || ks.y > 0.0f || ks.z > 0.0f;
  }
  // One Embree scene of the field's scene for the reliefs' scene occlusion and the mirrors'
  // relief tracing, built once here rather than by each relief surface's update and again for
  // the mirrors.
  std::shared_ptr<const EmbreeScene> embree;
  if (mirrors || occlusion)
  {
    embree = std::make_shared<const EmbreeScene>(field->Scene());
  }

  for (std::size_t r = 0; r < names.size(); ++r)
  {
    const std::string& name = names[r];
    const std::string depthImage = items[r].substr(items[r].find('=') + 1);
    ReliefSceneOptions textureOptions;
    textureOptions.DepthFile = depthImage;
    textureOptions.DepthScale = depthScale;
    textureOptions.DepthFileIsHeight = cl.Has("--relief-height");
    textureOptions.NormalizeDepthFile = cl.Has("--relief-normalize");
    vtkSmartPointer<vtkImageData> texture;
    vtkSmartPointer<vtkTexture> albedo;
    if (!BuildReliefTextures(textureOptions, texture, albedo, error))
    {
      std::cerr << command << ": --relief: " << error << "\n";
      return 2;
    }
    // The relief actor VTK pipelines use (vtkLightFieldReliefActor), its surface filter lent the
    // Embree scene built above and updated here so that its errors end the command.
    vtkNew<vtkLightFieldReliefActor> relief;
    relief->SetLightFieldActor(actor);
    relief->SetSurfaceName(name.c_str());
    relief->SetReliefTextureData(texture);
    relief->SetDepthScale(depthScale);
    relief->SetProbesPerSide(probesPerSide);
    relief->SetOcclusion(occlusion);
    vtkLightFieldReliefSurface* surface = relief->GetReliefSurface();
    if (occlusion)
    {
      vtkLightFieldReliefSurfaceCore::LendEmbreeScene(surface, field, embree);
    }
    vtkNew<MessageCollector> messages;
    messages->Watch(relief); // its surface filter's messages are the actor's
    const auto start = std::chrono::steady_clock::now();
    relief->GetBounds(); // updates the surface
    if (!messages->Errors.empty())
    {
      std::cerr << command << ": --relief: " << messages->ErrorText() << "\n";
      return 2;
    }
    // What the set-up cost, once per field and surface (scripts/bench-relief-probes.sh reads it).
    const int probes = surface->GetProbesPerSideUsed();
    std::cout << "relief on '" << name << "': " << probes << " x " << probes
              << " SH9 probes, set up in " << SecondsSince(start) << " s\n";
    renderer->AddActor(relief);
    reliefs.Surfaces.emplace_back(surface);
    reliefs.Actors.emplace_back(relief);
  }
  if (mirrors)
  {
    // The CPU reference's reading of the same images, with the relief surfaces' probes.
    FieldReliefOptions mirrorOptions;
    mirrorOptions.DepthScale = depthScale;
    mirrorOptions.DepthIsHeight = cl.Has("--relief-height");
    mirrorOptions.NormalizeDepth = cl.Has("--relief-normalize");
    mirrorOptions.Probes = probesPerSide;
    for (const auto& surface : reliefs.Surfaces)
    {
      const std::vector<SH9>* computed = vtkLightFieldReliefSurfaceCore::GetProbes(surface);
      mirrorOptions.KnownProbes.push_back(computed ? *computed : std::vector<SH9>());
    }
    try
    {
      vtkLightFieldActorCore::SetTracedReliefs(
        actor, std::make_shared<MirroredReliefs>(*field, embree, items, mirrorOptions));
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
