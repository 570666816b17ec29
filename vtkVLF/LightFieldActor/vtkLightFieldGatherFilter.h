// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldGatherFilter
 * @brief   shades any surface by the irradiance a virtual light field gathers at its points
 *
 * Input 0: any vtkPolyData with polygons (other datasets: Extract Surface first); its point
 * normals are used when it has them, else computed (vtkPolyDataNormals, no splitting, so the
 * points stay the input's). Input 1 (SetLightFieldConnection): the output of a
 * vtkVirtualLightField. The field itself does not travel with the data: the filter takes it from
 * the nearest vtkVirtualLightField upstream of input 1 (after that filter has
 * run), walking through pass-through filters such as ParaView's post filter. In ParaView's
 * builtin and client/server modes the filter and its producer share the server process, so this
 * works there too. With several MPI ranks (vtkMultiProcessController's global controller) the
 * field is made once: input 1 is asked for the same piece as this filter's output. By default
 * (vtkVirtualLightField's DistributeDirections) the ranks propagate it together and each keeps
 * its own directions' maps: every rank then gathers the whole surface (every rank's piece,
 * gathered onto each rank) from its own directions, one sum over the ranks (12 bytes a point)
 * completes the irradiance, and each rank keeps its own piece's points; no rank holds the whole
 * field. With DistributeDirections off rank 0 makes the whole field, broadcasts it (as
 * snapshot bytes; again only when it changed) and every rank gathers only its own piece of the
 * surface. A surface piece sees all of the scene's light.
 *
 * Output: the input (with the computed normals as its point normals when it had none) and
 * point arrays "Irradiance" (the irradiance E gathered at each point
 * with its normal, Wither 2005 §3.6: every direction's lines through the point, solid-angle
 * weights, projected-area normalisation) and "Radiance" (Reflectance / pi x E, the radiance
 * a diffuse surface of that reflectance leaves there), 3-component float, in the field's
 * radiance units, world coordinates. The surface is not part of the propagated field: it
 * receives the scene's light, shadows and colour bleeding, but casts nothing onto the field
 * itself. Its shadow on the scene is drawn by ParaView's Light Field representation, whose
 * Shadow Caster input this output can be: for that the output's field data carries the field's
 * significant emitters (GetEmittersName(), mesolight::vlf::PackEmitters), the world -> unit
 * sphere normalisation (GetToUnitSphereName(): centre x, y, z, scale) and the field's log-average
 * luminance (GetLogAverageName(), the scene's automatic exposure, so the surface drawn as
 * Light Field is exposed like the scene) and the field's indirect light where this surface's
 * shadow falls (GetAmbientName(), RGB per unit reflectance, mesolight::vlf::EstimateShadowIndirect:
 * the shadows' ObjectShadows::SetAmbient).
 *
 * Each point's position when gathered goes with it (point array GetGatheredAtName(): x, y, z, 1;
 * four components so that a Transform after the gather, which moves the points and transforms
 * every 3-component array as a vector, Radiance included, leaves it alone):
 * vtkCompositeLightFieldMapper warns when the surface it draws was moved after the gather.
 *
 * Points outside the field's bounding sphere are gathered on its boundary (a warning gives how
 * many); GetOutsidePoints() tells after an update. Progress goes through UpdateProgress;
 * AbortExecute stops between batches of points (the output is then empty).
 */
#ifndef vtkLightFieldGatherFilter_h
#define vtkLightFieldGatherFilter_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkVirtualLightField.h" // For GetToUnitSphereName

#include <memory> // For std::unique_ptr

namespace mesolight
{
namespace vlf
{
class LightField;
}
}

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldGatherFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLightFieldGatherFilter* New();
  vtkTypeMacro(vtkLightFieldGatherFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The light field: the output of a vtkVirtualLightField (input port 1). */
  void SetLightFieldConnection(vtkAlgorithmOutput* output);

  ///@{
  /** Diffuse reflectance (RGB in [0, 1]) of the surface for "Radiance" (default 0.7). */
  vtkSetVector3Macro(Reflectance, double);
  vtkGetVector3Macro(Reflectance, double);
  ///@}

  enum DirectionSets
  {
    ALL_DIRECTIONS = 0,
    HALF_DIRECTIONS = 1,
    IMPORTANCE_DIRECTIONS = 2
  };
  ///@{
  /**
   * Which of the field's directions every point gathers along: all (default), every other
   * (half the time), or half of them drawn by the radiance the field carries along each
   * direction (importance sampling).
   */
  vtkSetClampMacro(DirectionSet, int, ALL_DIRECTIONS, IMPORTANCE_DIRECTIONS);
  vtkGetMacro(DirectionSet, int);
  ///@}

  /** Points of the last update outside the field's bounding sphere. */
  vtkGetMacro(OutsidePoints, vtkIdType);

  /**
   * Fields the Virtual Light Field producers of all ranks have made so far (each rank's
   * vtkVirtualLightField::GetPropagationCount(), summed over ranks at the last update): 1 after
   * the first update of a new field, whatever the number of ranks.
   */
  vtkGetMacro(FieldPropagations, int);
  /** Times rank 0 has sent the field to the other ranks (0 in a serial run or when the field is
   * distributed over the ranks). */
  vtkGetMacro(FieldBroadcasts, int);
  /** Whether the last update gathered from a field distributed over the ranks (each rank its
   * own directions, the irradiance summed over the ranks). */
  vtkGetMacro(FieldDistributed, bool);

  ///@{
  /** Names of the output's field data arrays (see the class description). */
  static const char* GetEmittersName() { return "LightFieldEmitters"; }
  // vtkVirtualLightField::AttachUnitSphere's array, as on the field's own output.
  static const char* GetToUnitSphereName() { return vtkVirtualLightField::GetToUnitSphereName(); }
  static const char* GetLogAverageName() { return "LightFieldLogAverage"; }
  static const char* GetAmbientName() { return "LightFieldAmbient"; }
  static const char* GetGatheredAtName() { return "LightFieldGatheredAt"; }
  ///@}

protected:
  vtkLightFieldGatherFilter();
  ~vtkLightFieldGatherFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  // Asks input 1 for this output's piece: the field filters make the field once (all ranks
  // together, or rank 0 alone with DistributeDirections off).
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLightFieldGatherFilter(const vtkLightFieldGatherFilter&) = delete;
  void operator=(const vtkLightFieldGatherFilter&) = delete;

  double Reflectance[3] = { 0.7, 0.7, 0.7 };
  int DirectionSet = ALL_DIRECTIONS;
  vtkIdType OutsidePoints = 0;
  int FieldPropagations = 0;
  int FieldBroadcasts = 0;
  bool FieldDistributed = false;

  // Gathers the whole surface (every rank's piece) from a distributed field: see the class
  // description. Collective.
  int GatherDistributed(
    const mesolight::vlf::LightField& field, vtkPolyData* input, vtkPolyData* output);
  // The field on this rank: the producer's (serial runs, rank 0, every rank's share when
  // distributed: FieldDistributed) or the one received.
  const mesolight::vlf::LightField* AcquireField(vtkAlgorithm* producer);
  std::unique_ptr<mesolight::vlf::LightField> Received;
  const void* SentProducer = nullptr; // rank 0: the producer and version last broadcast
  int SentVersion = -1;
};

#endif
