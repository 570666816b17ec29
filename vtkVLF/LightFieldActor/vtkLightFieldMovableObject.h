// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldMovableObject
 * @brief   vtkLightFieldActor's movable object: an ordinary actor placed in the light field,
 *          its gathered shading and its instance in the tracer
 *
 * Private to Mesolight::LightFieldActor (header not installed). Wither 2005, "Interactive
 * dynamic objects in a virtual light field", chapter 3. Update() reads the actor's polydata when
 * it changed (triangulated, normals completed, Kd from its property), places it in the field's
 * unit sphere by the actor's matrix, gathers the field's light at its points when anything moved
 * (mesolight::vlf::ObjectGatherer, optionally from an irradiance volume), sets its instance in
 * the tracer's Embree scene (only the transform changes when it only moves), hands its
 * unit-sphere mesh to the shadows, and checks what a user wants to hear about (outside the
 * field, through a wall). The actor is held weakly.
 */
#ifndef vtkLightFieldMovableObject_h
#define vtkLightFieldMovableObject_h

#include "vtkType.h"
#include "vtkWeakPointer.h"

#include "ObjectMesh.h" // For ObjectMesh

#include <glm/mat4x4.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace mesolight
{
namespace vlf
{
class IrradianceVolume;
class LightField;
class ObjectGatherer;
class WalkthroughTracer;
struct ShadedObject;
}
}
class vtkActor;
class vtkLightFieldObjectShadows;
class vtkObject;
class vtkPolyData;

class vtkLightFieldMovableObject
{
public:
  /** owner: the object errors and warnings are reported for (the actor). */
  explicit vtkLightFieldMovableObject(vtkObject* owner);
  ~vtkLightFieldMovableObject();
  vtkLightFieldMovableObject(const vtkLightFieldMovableObject&) = delete;
  vtkLightFieldMovableObject& operator=(const vtkLightFieldMovableObject&) = delete;

  /** How the object is gathered and traced (vtkLightFieldActor's Object* settings). */
  struct Settings
  {
    int Subdivision = 0;
    int Directions = 0;       // vtkLightFieldActor::GatherDirectionSets
    int IrradianceVolume = 0; // grid points along the longest side; 0: gather per vertex
    bool Ignore = false;      // negative tests only: keep it out of the tracer
  };

  /** A new object (the tracer must not hold the old one any more); forgets everything. */
  void SetActor(vtkActor* object);
  vtkActor* GetActor() const { return this->Object; }
  /** Forgets the placement, the gather and the instance (a new tracer); the mesh is reread. */
  void Forget();
  /** Forget(), and the irradiance volume too (it was the old field's). */
  void ForgetField();

  /**
   * Brings the object up to date (see vtkLightFieldActor::UpdateMovableObject). stopReaders
   * runs before the tracer's instance or radiance changes; start is when the caller began the
   * update (GetLastSeconds counts from it).
   */
  bool Update(const mesolight::vlf::LightField* field, mesolight::vlf::WalkthroughTracer* tracer,
    const Settings& settings, vtkLightFieldObjectShadows& shadows,
    const std::function<void()>& stopReaders, std::chrono::steady_clock::time_point start);

  /** The object as last gathered (unit sphere, per-point radiance), or nullptr. */
  const mesolight::vlf::ShadedObject* GetShaded() const;
  /** Bumped whenever the mesh, placement or shading changed. */
  unsigned long GetVersion() const { return this->Version; }
  /** Whether the version changed since the last call (a frame's question: did it move?). */
  bool ChangedSinceLastFrame();
  double GetLastSeconds() const { return this->LastSeconds; }
  double GetLastGatherSeconds() const { return this->LastGatherSeconds; }

private:
  // Takes the object out of the tracer (the mesh stays read: a later placement may work).
  void Drop(mesolight::vlf::WalkthroughTracer& tracer, vtkLightFieldObjectShadows& shadows,
    const std::function<void()>& stopReaders);
  // Drop(), and reports why (an error once per problem); returns false.
  bool Fail(const std::string& why, mesolight::vlf::WalkthroughTracer& tracer,
    vtkLightFieldObjectShadows& shadows, const std::function<void()>& stopReaders);
  // Step 1: the mesh, reread only when the data (or the reflectance) changed.
  bool ReadMesh(vtkPolyData* data, std::string& problem);
  // Step 3: the gather (from the irradiance volume when asked for).
  void Gather(
    const mesolight::vlf::LightField& field, const glm::mat4& placement, const Settings& settings);
  // Step 4: the tracer's instance.
  void Trace(mesolight::vlf::WalkthroughTracer& tracer, const glm::mat4& placement,
    const Settings& settings);
  // Step 5: outside the field or through a wall ("" when neither).
  static std::string Check(
    const mesolight::vlf::ObjectMesh& unit, const mesolight::vlf::WalkthroughTracer& tracer);

  vtkObject* Owner;
  vtkWeakPointer<vtkActor> Object;
  vtkPolyData* Data = nullptr; // identity only, never dereferenced after it changes
  vtkMTimeType DataTime = 0;
  mesolight::vlf::ObjectMesh Model; // model coordinates, as last read
  unsigned long MeshVersion = 0;    // bumped when Model is reread
  bool Usable = false;
  bool Placed = false;
  glm::mat4 Placement{ 1.0f }; // model -> unit sphere
  // The mesh version and settings of the last gather.
  unsigned long GatheredMesh = 0;
  int GatheredSubdivision = -1;
  int GatheredDirections = -1;
  int GatheredVolume = -1;
  bool Ignored = false;
  unsigned long TracedMesh = 0; // (mesh version, subdivision) the tracer's instance holds
  int TracedSubdivision = -1;
  unsigned long Version = 1;
  unsigned long VersionAtLastFrame = 0;
  std::unique_ptr<mesolight::vlf::ObjectGatherer> Gatherer;
  bool Gathered = false;
  // The irradiance volume of Settings::IrradianceVolume, for the field it was built from.
  std::unique_ptr<mesolight::vlf::IrradianceVolume> Volume;
  const mesolight::vlf::LightField* VolumeField = nullptr;
  int VolumeResolution = 0;
  std::string ProblemWarned; // reported once, until the object or its problem changes
  double LastSeconds = 0.0;
  double LastGatherSeconds = 0.0;
};

#endif
