// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVirtualLightField
 * @brief   propagates a scene's light into a virtual light field (Wither 2005 §2.4)
 *
 * Input: a scene as vtkPolyData with the material cell arrays of vtkTriangleSceneConverter
 * ("Diffuse", "Specular", "Emission", "MaterialId"), e.g. from vtkCornellBoxSource or
 * vtkOBJSceneReader. The filter builds the light field (Directions parallel subfields of
 * RaysPerSide x RaysPerSide lines in Tiles x Tiles tiles, mesolight::vlf::LightField) and shoots
 * until at most ConvergenceTolerance of the emitted flux is left unshot
 * (mesolight::vlf::PropagateToTolerance), or a fixed count of Iterations when that is 0 or more,
 * on vtkSMPTools threads.
 *
 * Output: the scene's triangles (world coordinates, material arrays kept) with the diffuse
 * radiance leaving each surface -- the per-surface total diffuse textures, the walkthrough's
 * progressive mode (Wither 2005 §2.4.2.2.3) -- as cell data "Radiance" (mean over the triangle's
 * corners and centre) and point data "Radiance" (at each vertex), 3 components, linear radiance.
 * The same textures also travel whole, for drawing them per pixel (ParaView's "Light Field"
 * representation, vtkCompositeLightFieldMapper): the field's TextureAtlas as field data
 * (GetAtlasName(): RGBA floats, row 0 = v near 0; GetAtlasSizeName(): width and height) and each
 * vertex's atlas coordinates as point data (GetAtlasCoordinatesName(), 2 components). Field
 * data travels with every piece and into state files. For the shadows a movable object casts on
 * the scene (vtkCompositeLightFieldMapper), each vertex also carries its place in the field's
 * unit sphere, its surface's normal and reflectance (GetReceiverPointName(),
 * GetReceiverNormalName(), GetReceiverDiffuseName(): 3 components each). The field's world to
 * unit sphere normalisation travels as field data too (GetToUnitSphereName(): centre x, y, z,
 * scale), as on Light Field Gather's output: what tells a movable object gathered from this
 * field from one gathered from another (vtkLightFieldCasterShadows::SetFieldUnitSphere).
 *
 * Memory is estimated before anything is allocated; above MemoryBudget the filter fails with a
 * message saying how much it would need. With a SnapshotFileName a snapshot is written after
 * every iteration (atomically); with ResumeFromSnapshot an existing snapshot of that name is
 * read and propagation continues from it (to the tolerance, or up to Iterations). The filter
 * refuses to replace a file that is not a light field snapshot. Progress goes through
 * UpdateProgress; AbortExecute stops between rounds of subfields.
 *
 * Under MPI (pieces > 1, vtkMultiProcessController's global controller, e.g. `mpiexec -n N
 * pvbatch`) every rank gets the whole scene and the directions are split between the ranks
 * (DistributeDirections, mesolight::vlf Distribution.h): each traces and shoots its share, one
 * sum per iteration gives every rank the whole diffuse textures, and each rank keeps its own
 * directions' maps only (no rank holds the whole field). Every rank's output is its piece of the
 * scene's triangles (piece p of n: the p-th n-th of them), each with the whole diffuse textures
 * (the atlas), so that ParaView draws the pieces on their ranks and composites them;
 * vtkLightFieldGatherFilter gathers from every rank's directions (one sum). Snapshots are
 * written by rank 0, receiving the other ranks' maps one direction at a time. With
 * DistributeDirections off, rank 0 alone propagates and holds the output (the other pieces are
 * empty; vtkLightFieldGatherFilter broadcasts rank 0's field).
 *
 * After an update, ComputeIrradiance() gives the irradiance at any world point and normal (the
 * movable-object query). Code built in this tree reaches the field itself (for lookups,
 * mesolight::vlf::Lookup) through vtkVirtualLightFieldCore, whose header is not installed, as
 * the field's is not.
 */
#ifndef vtkVirtualLightField_h
#define vtkVirtualLightField_h

#include "MesolightLightFieldModule.h" // For export macro
#include "vtkClampedSetter.h"          // For mesolightSetClampMacro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkFloatArray;
class vtkTriangleSceneConverter;

namespace mesolight
{
namespace vlf
{
class LightField;
struct LightFieldSettings;
class Reducer;
}
}

class MESOLIGHTLIGHTFIELD_EXPORT vtkVirtualLightField : public vtkPolyDataAlgorithm
{
public:
  static vtkVirtualLightField* New();
  vtkTypeMacro(vtkVirtualLightField, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Directions of the subfields: 2 n^2 + 1 (513, 2049, 8193), or 0 (default): automatic, from the
   * lines per side (mesolight::vlf::ResolveAutomaticSettings, AutomaticSettings.h).
   */
  mesolightSetClampMacro(Directions, int, 0, VTK_INT_MAX);
  vtkGetMacro(Directions, int);
  ///@}

  ///@{
  /**
   * Lines per subfield side, or 0 (default): automatic, from the scene's small features within a
   * line count and MemoryBudget (2049 x 64 x 64 when the scene asks for no more and it fits).
   */
  mesolightSetClampMacro(RaysPerSide, int, 0, VTK_INT_MAX);
  vtkGetMacro(RaysPerSide, int);
  ///@}

  ///@{
  /** Tiles per subfield side; RaysPerSide must be a multiple. 0 (default) = RaysPerSide / 8. */
  mesolightSetClampMacro(Tiles, int, 0, VTK_INT_MAX);
  vtkGetMacro(Tiles, int);
  ///@}

  ///@{
  /**
   * Shooting iterations: -1 (default) iterates until at most ConvergenceTolerance of the emitted
   * flux is left unshot (at most MaxIterations); 0 or more is that fixed count.
   */
  mesolightSetClampMacro(Iterations, int, -1, VTK_INT_MAX);
  vtkGetMacro(Iterations, int);
  ///@}
  ///@{
  /** Share of the emitted flux left unshot at which propagation stops (default 0.01). */
  mesolightSetClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}
  ///@{
  /** Most iterations the tolerance may take (default 100): a safety cap. */
  mesolightSetClampMacro(MaxIterations, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaxIterations, int);
  ///@}

  ///@{
  /**
   * Final gather after the propagation (default on; mesolight::vlf::FinalGather): every texel
   * of the diffuse textures recomputed from exact shadow rays to the emitters and
   * FinalGatherRays cosine-distributed rays reading the propagated field at their hits, so
   * visibility resolves per texel rather than per line spacing. Off: the propagated textures.
   */
  vtkSetMacro(FinalGather, bool);
  vtkGetMacro(FinalGather, bool);
  vtkBooleanMacro(FinalGather, bool);
  ///@}
  ///@{
  /** Indirect rays per texel of the final gather (default 1024). */
  vtkSetMacro(FinalGatherRays, int);
  vtkGetMacro(FinalGatherRays, int);
  ///@}

  ///@{
  /**
   * Finer texels where surfaces meet (mesolight::vlf::LightFieldSettings::ContactTexelHalvings):
   * on the surfaces other surfaces stand on (a floor under a box, a wall behind a rib) the texels
   * are halved this many times (0-3), so a contact shadow narrower than a texel is not smeared
   * into the light beside it. -1 (default): automatic, as `mesolight vlf propagate
   * --contact-texels auto` (mesolight::vlf::ResolveAutomaticSettings): one halving with
   * FinalGather, 2049 directions or more and automatic lines, when it fits half the
   * MemoryBudget; none otherwise. 0-3 is kept whatever the rest; anything else fails the update
   * with an error. A resumed snapshot keeps the texels it was traced with.
   */
  vtkSetMacro(ContactTexelHalvings, int);
  vtkGetMacro(ContactTexelHalvings, int);
  ///@}

  ///@{
  /**
   * Texels refined from the light (default off; mesolight::vlf::ChooseAdaptiveTexels, as
   * `mesolight vlf propagate --adaptive-texels`): with automatic RaysPerSide and FinalGather, a
   * cheap first pass measures per surface how much its light varies between texels, and the
   * surfaces where it varies get texels a half or a quarter of the others', on top of the contact
   * texels (ContactTexelHalvings). Off: the contact texels alone. Not with given RaysPerSide,
   * without FinalGather, when resuming a snapshot or with DistributeDirections over several
   * processes (the first pass runs in one).
   */
  vtkSetMacro(AdaptiveTexels, bool);
  vtkGetMacro(AdaptiveTexels, bool);
  vtkBooleanMacro(AdaptiveTexels, bool);
  ///@}

  ///@{
  /**
   * With AdaptiveTexels, the refinements beyond the contact texels add at most this fraction of
   * the contact texels' gathered texels (the final gather's rays grow with them), best gain per
   * texel first (mesolight::vlf::AdaptiveTexelOptions::GatherBudget, default 0.5, as
   * `mesolight vlf propagate --adaptive-budget`); negative: unbounded.
   */
  vtkSetMacro(AdaptiveTexelsBudget, double);
  vtkGetMacro(AdaptiveTexelsBudget, double);
  ///@}

  ///@{
  /** Memory budget in bytes (default 4 GiB). */
  vtkSetMacro(MemoryBudget, vtkTypeInt64);
  vtkGetMacro(MemoryBudget, vtkTypeInt64);
  ///@}

  ///@{
  /**
   * The same budget in MiB (2^20 bytes), for ParaView's panel: it has no widget for 64-bit
   * integer properties, and MiB keep the values in 32-bit range. Negative or NaN is 0.
   */
  void SetMemoryBudgetMiB(double mebibytes);
  double GetMemoryBudgetMiB();
  ///@}

  ///@{
  /** Snapshot written after every iteration (none when empty). */
  vtkSetStdStringFromCharMacro(SnapshotFileName);
  vtkGetCharFromStdStringMacro(SnapshotFileName);
  ///@}

  ///@{
  /** Continue from an existing snapshot of SnapshotFileName (default off). */
  vtkSetMacro(ResumeFromSnapshot, bool);
  vtkGetMacro(ResumeFromSnapshot, bool);
  vtkBooleanMacro(ResumeFromSnapshot, bool);
  ///@}

  ///@{
  /**
   * Under MPI, split the directions between the ranks (default on); off: rank 0 propagates
   * alone. One rank is the serial path either way.
   */
  vtkSetMacro(DistributeDirections, bool);
  vtkGetMacro(DistributeDirections, bool);
  vtkBooleanMacro(DistributeDirections, bool);
  ///@}

  /**
   * Directions whose subfields this process shot in the last update: all of them in one process,
   * its share under MPI with DistributeDirections, 0 on a rank that did not propagate.
   */
  vtkGetMacro(DirectionsPropagated, int);

  /**
   * Irradiance at a world point with a unit normal, gathered from the field (Wither 2005 §3.6).
   * False before a successful update, and on a field distributed over ranks (a rank holds part
   * of the directions: gather with vtkLightFieldGatherFilter, which sums over the ranks).
   */
  bool ComputeIrradiance(const double point[3], const double normal[3], double irradiance[3]) const;

  ///@{
  /** Names of the output's atlas arrays (see the class description). */
  static const char* GetAtlasName() { return "LightFieldAtlas"; }
  static const char* GetAtlasSizeName() { return "LightFieldAtlasSize"; }
  static const char* GetAtlasCoordinatesName() { return "LightFieldAtlasTC"; }
  static const char* GetReceiverPointName() { return "LightFieldUnitPoint"; }
  static const char* GetReceiverNormalName() { return "LightFieldNormal"; }
  static const char* GetReceiverDiffuseName() { return "LightFieldDiffuse"; }
  static const char* GetToUnitSphereName() { return "LightFieldToUnitSphere"; }
  ///@}

  /**
   * Fields this instance has built or read since it was created (each update that makes a field
   * counts one): how tests check that, under MPI, one rank propagates and the others receive
   * the field (vtkLightFieldGatherFilter).
   */
  vtkGetMacro(PropagationCount, int);

  /**
   * The atlas a light field output carries (null when it has none or the arrays do not agree);
   * size receives its width and height.
   */
  static vtkFloatArray* GetAttachedAtlas(vtkDataObject* data, int size[2]);

  ///@{
  /**
   * The field's world to unit sphere normalisation (p -> (p - centre) x scale, Wither 2005 §2.2:
   * the field's lines live in the unit sphere about the scene) as field data of `data`
   * (GetToUnitSphereName()), the form of this filter's and Light Field Gather's outputs. Get
   * returns false when `data` carries none (or a malformed one).
   */
  static void AttachUnitSphere(vtkDataObject* data, const double centre[3], double scale);
  static bool GetAttachedUnitSphere(vtkDataObject* data, double centre[3], double* scale);
  ///@}

  /**
   * The vtkVirtualLightField whose output reaches `algorithm`: itself, or the first one found
   * walking up through the first input of pass-through filters (ParaView's post filter); null if
   * none. How consumers of the output (Light Field Gather, a relief lit by the field) find the
   * field, which does not travel with the data.
   */
  static vtkVirtualLightField* FindUpstream(vtkAlgorithm* algorithm);

  /** Bytes the last update's field needs (its memory estimate), 0 before. */
  vtkTypeInt64 GetEstimatedBytes() const;

protected:
  vtkVirtualLightField();
  ~vtkVirtualLightField() override;

  // Piece 0 asks its input for the whole scene; the other pieces pass the request on and make
  // no field (their output is empty).
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkVirtualLightField(const vtkVirtualLightField&) = delete;
  void operator=(const vtkVirtualLightField&) = delete;
  friend class vtkVirtualLightFieldCore;

  int Directions = 0;  // automatic
  int RaysPerSide = 0; // automatic
  int Tiles = 0;
  int Iterations = -1;
  double ConvergenceTolerance = 0.01; // mesolight::vlf::DefaultTolerance
  int MaxIterations = 100;            // mesolight::vlf::DefaultMaxIterations
  vtkTypeInt64 MemoryBudget = vtkTypeInt64(4) << 30;
  std::string SnapshotFileName;
  // Under MPI with the directions split (see the class description).
  bool Distributed(int pieces) const;
  int RequestDistributedData(vtkPolyData* input, vtkPolyData* output);
  // The output from this->Field.
  int FillOutput(vtkTriangleSceneConverter* converter, vtkPolyData* output);
  // Keeps piece `piece` of `pieces` of the output's triangles (a contiguous range), their points
  // and data; the field data (the atlas) stays whole.
  static void KeepPiece(vtkPolyData* output, int piece, int pieces);

  bool ResumeFromSnapshot = false;
  bool DistributeDirections = true;
  bool FinalGather = true;
  int FinalGatherRays = 1024;    // mesolight::vlf::FinalGatherOptions::IndirectRays
  int ContactTexelHalvings = -1; // mesolight::vlf::AutomaticContactTexelHalvings
  bool AdaptiveTexels = false;
  double AdaptiveTexelsBudget = 0.5; // mesolight::vlf::AdaptiveTexelOptions::GatherBudget
  // The sentence refusing ContactTexelHalvings outside [-1, 3], empty when it is in range.
  std::string CheckContactTexelHalvings() const;
  // After resuming a snapshot: a warning naming each setting given here (Directions, RaysPerSide,
  // Tiles, ContactTexelHalvings; automatic ones excepted) that differs from the snapshot's, which
  // the resumed field keeps.
  void WarnAboutSettingsNotResumed(const mesolight::vlf::LightFieldSettings& stored);
  // The final gather (when on) with progress from `begin` to 1, then the snapshot written again;
  // with a reducer (a distributed field) split over the ranks (collective).
  void GatherIfAsked(
    mesolight::vlf::LightField& field, double begin, mesolight::vlf::Reducer* reducer = nullptr);
  int DirectionsPropagated = 0;
  int PropagationCount = 0;
  std::unique_ptr<mesolight::vlf::LightField> Field;
};

#endif
