// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVirtualLightField.h"
#include "Progress.h"
#include "vtkVirtualLightFieldCore.h"

#include "AdaptiveTexels.h"
#include "AutomaticSettings.h"
#include "Distribution.h"
#include "FinalGather.h"
#include "LightField.h"
#include "Lookup.h"
#include "PatchComparison.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TextureAtlas.h"
#include "TriangleScene.h"
#include "vtkLightFieldReducer.h"
#include "vtkTriangleSceneConverter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkVirtualLightField);

namespace
{
// A fixed count of iterations (iterations >= 0) or until the tolerance; the share of the emitted
// flux still unshot when MaxIterations stopped it first, else 0. Under MPI every rank decides
// alike: the unshot flux is summed over the ranks each iteration.
double PropagateAsConfigured(mesolight::vlf::LightField& field, int iterations, double tolerance,
  int maxIterations, const mesolight::vlf::PropagationOptions& options,
  const std::function<void(const mesolight::vlf::LightField&)>& afterIteration)
{
  namespace vlf = mesolight::vlf;
  if (iterations >= 0)
  {
    vlf::Propagate(field, iterations, options, afterIteration);
    return 0.0;
  }
  return vlf::PropagateToTolerance(field, tolerance, maxIterations, options, afterIteration)
    ? 0.0
    : vlf::UnshotFraction(field);
}
} // namespace

vtkVirtualLightField::vtkVirtualLightField() = default;
vtkVirtualLightField::~vtkVirtualLightField() = default;

void vtkVirtualLightField::SetMemoryBudgetMiB(double mebibytes)
{
  constexpr double bytesPerMiB = 1048576.0;
  // 2^63 bytes is 2^43 MiB: clamp there so the conversion never overflows.
  const double clamped = mebibytes > 0.0 ? std::min(mebibytes, 8.0e12) : 0.0;
  this->SetMemoryBudget(static_cast<vtkTypeInt64>(clamped * bytesPerMiB));
}

double vtkVirtualLightField::GetMemoryBudgetMiB()
{
  return static_cast<double>(this->MemoryBudget) / 1048576.0;
}

const mesolight::vlf::LightField* vtkVirtualLightFieldCore::GetLightField(
  const vtkVirtualLightField* filter)
{
  return filter ? filter->Field.get() : nullptr;
}

vtkVirtualLightField* vtkVirtualLightField::FindUpstream(vtkAlgorithm* algorithm)
{
  for (int depth = 0; algorithm && depth < 16; ++depth)
  {
    if (auto* field = vtkVirtualLightField::SafeDownCast(algorithm))
    {
      return field;
    }
    if (algorithm->GetNumberOfInputPorts() < 1 || algorithm->GetNumberOfInputConnections(0) < 1)
    {
      return nullptr;
    }
    algorithm = algorithm->GetInputAlgorithm(0, 0);
  }
  return nullptr;
}

vtkTypeInt64 vtkVirtualLightField::GetEstimatedBytes() const
{
  return this->Field ? static_cast<vtkTypeInt64>(this->Field->Estimate().TotalBytes) : 0;
}

bool vtkVirtualLightField::ComputeIrradiance(
  const double point[3], const double normal[3], double irradiance[3]) const
{
  if (!this->Field || !this->Field->OwnedSubfields.empty())
  {
    return false; // none, or distributed: this rank holds part of the directions
  }
  const glm::vec3 n(
    static_cast<float>(normal[0]), static_cast<float>(normal[1]), static_cast<float>(normal[2]));
  if (!(glm::length(n) > 0.0f))
  {
    return false;
  }
  const glm::vec3 p = mesolight::vlf::ToUnit(*this->Field,
    glm::vec3(
      static_cast<float>(point[0]), static_cast<float>(point[1]), static_cast<float>(point[2])));
  const glm::vec3 e = mesolight::vlf::Lookup(*this->Field).Irradiance(p, glm::normalize(n));
  for (int c = 0; c < 3; ++c)
  {
    irradiance[c] = static_cast<double>(e[c]);
  }
  return true;
}

int vtkVirtualLightField::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* out = outputVector->GetInformationObject(0);
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  if (!in)
  {
    return 1;
  }
  // Piece 0 propagates the whole scene (a split scene would give each rank a wrong field); with
  // the directions distributed every rank needs the whole scene.
  const bool first = out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) == 0 ||
    this->Distributed(out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
    first ? 0 : out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
    first ? 1 : out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

int vtkVirtualLightField::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  namespace vlf = mesolight::vlf;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->Field.reset();
  this->DirectionsPropagated = 0;
  if (!input)
  {
    vtkErrorMacro("No input scene.");
    return 0;
  }
  // In parallel (ParaView under MPI) piece 0 (rank 0) gets the whole scene and makes the field
  // once; the other pieces are empty, not an error (Light Field Gather broadcasts the field).
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (this->Distributed(pieces))
  {
    const int result = this->RequestDistributedData(input, output);
    if (result && output->GetNumberOfCells() > 0)
    {
      KeepPiece(
        output, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()), pieces);
    }
    return result;
  }
  if (pieces > 1 &&
    (outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0 ||
      input->GetNumberOfCells() == 0))
  {
    return 1;
  }
  vtkNew<vtkTriangleSceneConverter> converter;
  mesolight::TriangleScene scene;
  if (!converter->ToTriangleScene(input, scene))
  {
    vtkErrorMacro("The input cannot be used as a light field scene (see the converter's message).");
    return 0;
  }
  if (this->Iterations < -1 || this->Iterations > 10000)
  {
    vtkErrorMacro("Iterations " << this->Iterations
                                << " is outside [-1, 10000] (-1: until ConvergenceTolerance).");
    return 0;
  }
  if (this->Iterations < 0 &&
    (!(this->ConvergenceTolerance > 0.0 && this->ConvergenceTolerance < 1.0) ||
      this->MaxIterations < 1 || this->MaxIterations > 10000))
  {
    vtkErrorMacro("ConvergenceTolerance (" << this->ConvergenceTolerance
                                           << ") must be in (0, 1) and MaxIterations ("
                                           << this->MaxIterations << ") in [1, 10000].");
    return 0;
  }
  if (this->Directions < 0 || this->RaysPerSide < 0)
  {
    vtkErrorMacro("Directions (" << this->Directions << ") and RaysPerSide (" << this->RaysPerSide
                                 << ") must be positive or 0 (automatic).");
    return 0;
  }
  if (this->MemoryBudget <= 0)
  {
    vtkErrorMacro(
      "The memory budget must be positive (it is " << this->GetMemoryBudgetMiB() << " MiB).");
    return 0;
  }
  const std::string contactProblem = this->CheckContactTexelHalvings();
  if (!contactProblem.empty())
  {
    vtkErrorMacro(<< contactProblem);
    return 0;
  }
  vlf::LightFieldSettings settings;
  settings.Directions = static_cast<std::size_t>(this->Directions);
  settings.RaysPerSide = this->RaysPerSide;
  settings.TilesPerSide = this->Tiles;
  settings.MemoryBudget = static_cast<std::uint64_t>(this->MemoryBudget);

  const bool snapshots = !this->SnapshotFileName.empty();
  try
  {
    if (snapshots && vlf::FileExists(this->SnapshotFileName) &&
      !vlf::IsSnapshotFile(this->SnapshotFileName))
    {
      vtkErrorMacro("'" << this->SnapshotFileName
                        << "' exists and is not a light field snapshot: it is left alone; choose "
                           "another SnapshotFileName.");
      return 0;
    }
    std::unique_ptr<vlf::LightField> field;
    const double buildShare = 0.3;
    if (snapshots && this->ResumeFromSnapshot && vlf::FileExists(this->SnapshotFileName))
    {
      field = vlf::ReadSnapshot(this->SnapshotFileName, settings.MemoryBudget);
      this->WarnAboutSettingsNotResumed(field->Settings());
    }
    else
    {
      const vlf::AutomaticChoice choice = vlf::ResolveAutomaticSettings(
        scene, settings, this->FinalGather, this->ContactTexelHalvings);
      const bool automaticLines = settings.RaysPerSide == 0;
      settings = choice.Settings;
      double begin = 0.0;
      if (this->AdaptiveTexels && automaticLines && this->FinalGather)
      {
        begin = 0.5 * buildShare;
        vlf::AdaptiveTexelOptions adaptive;
        adaptive.Progress = mesolight::AlgorithmProgress(this, 0.0, begin);
        adaptive.GatherBudget = this->AdaptiveTexelsBudget;
        settings = vlf::ChooseAdaptiveTexels(scene, settings, adaptive);
      }
      field = vlf::LightField::Build(
        scene, settings, mesolight::AlgorithmProgress(this, begin, buildShare));
    }
    vlf::PropagationOptions options;
    const double gatherShare = this->FinalGather ? 0.9 : 1.0;
    options.Progress = mesolight::AlgorithmProgress(this, buildShare, gatherShare);
    const auto afterIteration = [&](const vlf::LightField& f)
    {
      if (snapshots)
      {
        vlf::WriteSnapshot(f, this->SnapshotFileName);
      }
    };
    const double unshot = PropagateAsConfigured(*field, this->Iterations,
      this->ConvergenceTolerance, this->MaxIterations, options, afterIteration);
    this->GatherIfAsked(*field, gatherShare);
    if (snapshots && this->FinalGather)
    {
      vlf::WriteSnapshot(*field, this->SnapshotFileName);
    }
    if (unshot > 0.0)
    {
      vtkWarningMacro("The light field still holds "
        << 100.0 * unshot << "% of its emitted flux unshot after " << this->MaxIterations
        << " iterations (MaxIterations).");
    }
    this->DirectionsPropagated = static_cast<int>(field->SubfieldCount());
    this->Field = std::move(field);
    ++this->PropagationCount;
  }
  catch (const vlf::AbortedError&)
  {
    vtkWarningMacro("Light field propagation aborted.");
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }

  return this->FillOutput(converter, output);
}

int vtkVirtualLightField::FillOutput(vtkTriangleSceneConverter* converter, vtkPolyData* output)
{
  namespace vlf = mesolight::vlf;
  // Output: the scene in world coordinates with the diffuse radiance leaving each surface.
  const vlf::LightField& field = *this->Field;
  const mesolight::TriangleScene& unit = field.Scene();
  // A vertex shared by two surfaces (a wall and the floor along their edge) is duplicated, one
  // copy per surface, so one surface's point "Radiance" never bleeds into the other's.
  mesolight::TriangleScene world = unit;
  world.Positions.clear();
  world.Normals.clear();
  world.TextureCoordinates.clear();
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> copyOf;
  for (std::size_t t = 0; t < unit.TriangleCount(); ++t)
  {
    const std::uint32_t surface = field.SurfaceOfTriangle(t);
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t original = unit.Triangles[t][c];
      auto inserted = copyOf.emplace(
        std::make_pair(surface, original), static_cast<std::uint32_t>(world.Positions.size()));
      if (inserted.second)
      {
        world.Positions.push_back(vlf::ToWorld(field, unit.Positions[original]));
        if (unit.Normals.size() == unit.Positions.size())
        {
          world.Normals.push_back(unit.Normals[original]);
        }
        if (unit.TextureCoordinates.size() == unit.Positions.size())
        {
          world.TextureCoordinates.push_back(unit.TextureCoordinates[original]);
        }
      }
      world.Triangles[t][c] = inserted.first->second;
    }
  }
  converter->ToPolyData(world, output);
  // No active scalars: a display (ParaView's on Apply) would otherwise colour by Diffuse instead
  // of showing the light.
  output->GetCellData()->SetActiveAttribute(-1, vtkDataSetAttributes::SCALARS);
  const vtkIdType triangles = static_cast<vtkIdType>(world.TriangleCount());
  vtkNew<vtkFloatArray> cellRadiance;
  cellRadiance->SetName("Radiance");
  cellRadiance->SetNumberOfComponents(3);
  cellRadiance->SetNumberOfTuples(triangles);
  vtkNew<vtkFloatArray> pointRadiance;
  pointRadiance->SetName("Radiance");
  pointRadiance->SetNumberOfComponents(3);
  pointRadiance->SetNumberOfTuples(static_cast<vtkIdType>(world.Positions.size()));
  pointRadiance->Fill(0.0);
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(static_cast<std::size_t>(t));
    glm::vec3 mean(0.0f);
    if (s != vlf::NoSurface)
    {
      const glm::vec3 centre = (unit.Vertex(t, 0) + unit.Vertex(t, 1) + unit.Vertex(t, 2)) / 3.0f;
      mean = field.SampleTexture(field.TotalDiffuse, s, centre);
      for (int c = 0; c < 3; ++c)
      {
        const glm::vec3 corner = field.SampleTexture(field.TotalDiffuse, s, unit.Vertex(t, c));
        mean += corner;
        const float rgb[3] = { corner.x, corner.y, corner.z };
        pointRadiance->SetTypedTuple(static_cast<vtkIdType>(world.Triangles[t][c]), rgb);
      }
      mean /= 4.0f;
    }
    const float rgb[3] = { mean.x, mean.y, mean.z };
    cellRadiance->SetTypedTuple(t, rgb);
  }
  output->GetCellData()->AddArray(cellRadiance);
  output->GetPointData()->AddArray(pointRadiance);

  // Shadow receivers (vtkCompositeLightFieldMapper): each vertex's unit-sphere point and its
  // surface's normal and reflectance, what vtkLightFieldShadowFS.glsl reads per fragment.
  const vtkIdType vertices = static_cast<vtkIdType>(world.Positions.size());
  vtkNew<vtkFloatArray> receiverPoint, receiverNormal, receiverDiffuse;
  receiverPoint->SetName(GetReceiverPointName());
  receiverNormal->SetName(GetReceiverNormalName());
  receiverDiffuse->SetName(GetReceiverDiffuseName());
  for (vtkFloatArray* array : { receiverPoint.Get(), receiverNormal.Get(), receiverDiffuse.Get() })
  {
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(vertices);
    array->Fill(0.0);
  }
  for (std::size_t t = 0; t < unit.TriangleCount(); ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(t);
    if (s == vlf::NoSurface)
    {
      continue;
    }
    const glm::vec3 n = field.Surfaces()[s].Normal;
    const glm::vec3 kd = field.MaterialOf(s).Diffuse;
    for (int c = 0; c < 3; ++c)
    {
      const vtkIdType id = static_cast<vtkIdType>(world.Triangles[t][c]);
      const glm::vec3 p = unit.Vertex(t, c);
      receiverPoint->SetTypedTuple(id, &p[0]);
      receiverNormal->SetTypedTuple(id, &n[0]);
      receiverDiffuse->SetTypedTuple(id, &kd[0]);
    }
  }
  output->GetPointData()->AddArray(receiverPoint);
  output->GetPointData()->AddArray(receiverNormal);
  output->GetPointData()->AddArray(receiverDiffuse);
  const glm::vec3 centre = field.NormalizationCentre();
  const double unitCentre[3] = { centre.x, centre.y, centre.z };
  AttachUnitSphere(output, unitCentre, field.NormalizationScale());

  // The total diffuse textures whole, for drawing them per pixel (bilinear, no seams: the
  // atlas' gutters), and each vertex's place in them. Every vertex belongs to one surface.
  try
  {
    const vlf::TextureAtlas atlas(field);
    vtkNew<vtkFloatArray> pixels;
    pixels->SetName(GetAtlasName());
    pixels->SetNumberOfComponents(4);
    pixels->SetNumberOfTuples(static_cast<vtkIdType>(atlas.Width()) * atlas.Height());
    std::copy(atlas.Pixels().begin(), atlas.Pixels().end(), pixels->GetPointer(0));
    vtkNew<vtkIntArray> size;
    size->SetName(GetAtlasSizeName());
    size->SetNumberOfValues(2);
    size->SetValue(0, atlas.Width());
    size->SetValue(1, atlas.Height());
    vtkNew<vtkFloatArray> coordinates;
    coordinates->SetName(GetAtlasCoordinatesName());
    coordinates->SetNumberOfComponents(2);
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(world.Positions.size()));
    coordinates->Fill(0.0);
    for (std::size_t t = 0; t < unit.TriangleCount(); ++t)
    {
      const std::uint32_t s = field.SurfaceOfTriangle(t);
      if (s == vlf::NoSurface)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        const glm::vec2 tc = atlas.TextureCoordinates(s, unit.Vertex(t, c));
        coordinates->SetTypedTuple(static_cast<vtkIdType>(world.Triangles[t][c]), &tc[0]);
      }
    }
    output->GetFieldData()->AddArray(pixels);
    output->GetFieldData()->AddArray(size);
    output->GetPointData()->AddArray(coordinates);
  }
  catch (const std::exception& e)
  {
    vtkWarningMacro(<< "No radiance atlas in the output (" << e.what()
                    << "): the Light Field representation cannot draw it.");
  }
  return 1;
}

bool vtkVirtualLightField::Distributed(int pieces) const
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return this->DistributeDirections && pieces > 1 && controller &&
    controller->GetNumberOfProcesses() > 1;
}

int vtkVirtualLightField::RequestDistributedData(vtkPolyData* input, vtkPolyData* output)
{
  namespace vlf = mesolight::vlf;
  // Every rank runs every step below; a step that fails on one rank is agreed (Distribution.h),
  // so every rank reports the failing rank's message instead of waiting for it.
  vlf::ControllerReducer reducer;
  vtkNew<vtkTriangleSceneConverter> converter;
  mesolight::TriangleScene scene;
  vlf::LightFieldSettings settings;
  const bool snapshots = !this->SnapshotFileName.empty();
  std::unique_ptr<vlf::LightField> field;
  try
  {
    double resume = 0.0;
    vlf::Agree(reducer,
      [&]()
      {
        if (input->GetNumberOfCells() == 0 || !converter->ToTriangleScene(input, scene))
        {
          throw std::invalid_argument(
            "the input cannot be used as a light field scene (see the converter's message)");
        }
        if (this->Iterations < -1 || this->Iterations > 10000)
        {
          throw std::invalid_argument("Iterations " + std::to_string(this->Iterations) +
            " is outside [-1 (until the tolerance), 10000]");
        }
        if (this->Iterations < 0 &&
          (!(this->ConvergenceTolerance > 0.0 && this->ConvergenceTolerance < 1.0) ||
            this->MaxIterations < 1 || this->MaxIterations > 10000))
        {
          throw std::invalid_argument("ConvergenceTolerance must be in (0, 1) and MaxIterations "
                                      "in [1, 10000]");
        }
        if (this->Directions < 0 || this->RaysPerSide < 0 || this->MemoryBudget <= 0)
        {
          throw std::invalid_argument("Directions and RaysPerSide must be positive or 0 "
                                      "(automatic), MemoryBudget positive");
        }
        const std::string contactProblem = this->CheckContactTexelHalvings();
        if (!contactProblem.empty())
        {
          throw std::invalid_argument(contactProblem);
        }
        settings.Directions = static_cast<std::size_t>(this->Directions);
        settings.RaysPerSide = this->RaysPerSide;
        settings.TilesPerSide = this->Tiles;
        settings.MemoryBudget = static_cast<std::uint64_t>(this->MemoryBudget);
        // Every rank has the whole scene here and chooses alike.
        const vlf::AutomaticChoice choice = vlf::ResolveAutomaticSettings(
          scene, settings, this->FinalGather, this->ContactTexelHalvings);
        settings = choice.Settings;
        if (snapshots && vlf::FileExists(this->SnapshotFileName) &&
          !vlf::IsSnapshotFile(this->SnapshotFileName))
        {
          throw std::invalid_argument("'" + this->SnapshotFileName +
            "' exists and is not a light field snapshot: it is left alone; choose another "
            "SnapshotFileName");
        }
        resume = snapshots && this->ResumeFromSnapshot && vlf::FileExists(this->SnapshotFileName)
          ? 1.0
          : 0.0;
      });
    reducer.SumInPlace(&resume, 1); // every rank decides alike
    if (resume > 0.0 && resume < static_cast<double>(reducer.Size()))
    {
      throw vlf::DistributedError(
        "'" + this->SnapshotFileName + "' is visible to some ranks only: resume needs it on all");
    }
    const double buildShare = 0.3;
    if (resume > 0.0)
    {
      vlf::Agree(reducer,
        [&]()
        {
          field = vlf::ReadSnapshot(this->SnapshotFileName, settings.MemoryBudget);
          vlf::KeepOwnedSubfields(*field, reducer);
        });
      if (reducer.Rank() == 0)
      {
        this->WarnAboutSettingsNotResumed(field->Settings());
      }
    }
    else
    {
      field = vlf::LightField::Build(
        scene, settings, mesolight::AlgorithmProgress(this, 0.0, buildShare), &reducer);
    }
    vlf::PropagationOptions options;
    const double gatherShare = this->FinalGather ? 0.9 : 1.0;
    options.Progress = mesolight::AlgorithmProgress(this, buildShare, gatherShare);
    options.Reduce = &reducer;
    const auto afterIteration = [&](const vlf::LightField&)
    {
      if (snapshots)
      {
        vlf::WriteDistributedSnapshot(*field, this->SnapshotFileName, reducer);
      }
    };
    const double unshot = PropagateAsConfigured(*field, this->Iterations,
      this->ConvergenceTolerance, this->MaxIterations, options, afterIteration);
    // The diffuse textures are whole on every rank: each gathers its share of the texels and
    // one sum gives every rank all of them, the serial result (FinalGather.h).
    this->GatherIfAsked(*field, gatherShare, &reducer);
    if (snapshots && this->FinalGather)
    {
      vlf::WriteDistributedSnapshot(*field, this->SnapshotFileName, reducer);
    }
    if (unshot > 0.0 && reducer.Rank() == 0)
    {
      vtkWarningMacro("The light field still holds "
        << 100.0 * unshot << "% of its emitted flux unshot after " << this->MaxIterations
        << " iterations (MaxIterations).");
    }
    for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
    {
      this->DirectionsPropagated += field->OwnsSubfield(k) ? 1 : 0;
    }
    // Every rank keeps its own directions' maps: downstream asks their owners (Distribution.h:
    // the gather's sum, the mirrors' lookups); the diffuse textures are whole on every rank.
  }
  catch (const vlf::AbortedError&)
  {
    vtkWarningMacro("Light field propagation aborted.");
    return 0;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  this->Field = std::move(field);
  ++this->PropagationCount;
  return this->FillOutput(converter, output);
}

void vtkVirtualLightField::KeepPiece(vtkPolyData* output, int piece, int pieces)
{
  vtkCellArray* polys = output->GetPolys();
  const vtkIdType cells = polys ? polys->GetNumberOfCells() : 0;
  if (pieces <= 1 || cells == 0 || output->GetNumberOfCells() != cells)
  {
    return; // the output is triangles only (FillOutput); anything else stays whole
  }
  const vtkIdType first = cells * piece / pieces, last = cells * (piece + 1) / pieces;
  vtkNew<vtkPolyData> part;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> kept;
  part->GetPointData()->CopyAllocate(output->GetPointData());
  part->GetCellData()->CopyAllocate(output->GetCellData());
  std::vector<vtkIdType> newId(static_cast<std::size_t>(output->GetNumberOfPoints()), -1);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = first; c < last; ++c)
  {
    polys->GetCellAtId(c, ids);
    for (vtkIdType q = 0; q < ids->GetNumberOfIds(); ++q)
    {
      vtkIdType& id = newId[static_cast<std::size_t>(ids->GetId(q))];
      if (id < 0)
      {
        id = points->InsertNextPoint(output->GetPoint(ids->GetId(q)));
        part->GetPointData()->CopyData(output->GetPointData(), ids->GetId(q), id);
      }
      ids->SetId(q, id);
    }
    const vtkIdType cell = kept->InsertNextCell(ids);
    part->GetCellData()->CopyData(output->GetCellData(), c, cell);
  }
  part->SetPoints(points);
  part->SetPolys(kept);
  part->GetFieldData()->ShallowCopy(output->GetFieldData());
  output->ShallowCopy(part);
}

vtkFloatArray* vtkVirtualLightField::GetAttachedAtlas(vtkDataObject* data, int size[2])
{
  vtkFieldData* fields = data ? data->GetFieldData() : nullptr;
  if (!fields)
  {
    return nullptr;
  }
  auto* pixels = vtkFloatArray::SafeDownCast(fields->GetAbstractArray(GetAtlasName()));
  vtkDataArray* dimensions =
    vtkArrayDownCast<vtkDataArray>(fields->GetAbstractArray(GetAtlasSizeName()));
  if (!pixels || !dimensions || pixels->GetNumberOfComponents() != 4 ||
    dimensions->GetNumberOfValues() != 2)
  {
    return nullptr;
  }
  size[0] = static_cast<int>(dimensions->GetComponent(0, 0));
  size[1] = static_cast<int>(dimensions->GetComponent(1, 0));
  if (size[0] < 1 || size[1] < 1 ||
    static_cast<vtkIdType>(size[0]) * size[1] != pixels->GetNumberOfTuples())
  {
    return nullptr;
  }
  return pixels;
}

void vtkVirtualLightField::AttachUnitSphere(
  vtkDataObject* data, const double centre[3], double scale)
{
  if (!data || !data->GetFieldData())
  {
    return;
  }
  vtkNew<vtkDoubleArray> normalisation;
  normalisation->SetName(GetToUnitSphereName());
  for (const double v : { centre[0], centre[1], centre[2], scale })
  {
    normalisation->InsertNextValue(v);
  }
  data->GetFieldData()->AddArray(normalisation);
}

bool vtkVirtualLightField::GetAttachedUnitSphere(
  vtkDataObject* data, double centre[3], double* scale)
{
  vtkFieldData* fields = data ? data->GetFieldData() : nullptr;
  vtkDataArray* normalisation = fields
    ? vtkArrayDownCast<vtkDataArray>(fields->GetAbstractArray(GetToUnitSphereName()))
    : nullptr;
  if (!normalisation || normalisation->GetNumberOfValues() != 4 ||
    normalisation->GetNumberOfComponents() != 1 || !(normalisation->GetComponent(3, 0) > 0.0))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    centre[i] = normalisation->GetComponent(i, 0);
  }
  *scale = normalisation->GetComponent(3, 0);
  return true;
}

std::string vtkVirtualLightField::CheckContactTexelHalvings() const
{
  namespace vlf = mesolight::vlf;
  if (this->ContactTexelHalvings >= vlf::AutomaticContactTexelHalvings &&
    this->ContactTexelHalvings <= vlf::MaxContactTexelHalvings)
  {
    return std::string();
  }
  return "ContactTexelHalvings " + std::to_string(this->ContactTexelHalvings) + " is outside [0, " +
    std::to_string(vlf::MaxContactTexelHalvings) +
    "] (texels halved that many times where surfaces meet; -1: automatic).";
}

//------------------------------------------------------------------------------
void vtkVirtualLightField::WarnAboutSettingsNotResumed(
  const mesolight::vlf::LightFieldSettings& stored)
{
  // What a user set that the resumed field does not use would otherwise be ignored without a
  // word (`mesolight vlf propagate --resume` refuses such options instead).
  const struct
  {
    const char* Name;
    bool Given;
    long long Asked;
    long long Stored;
  } settings[] = {
    { "Directions", this->Directions > 0, this->Directions,
      static_cast<long long>(stored.Directions) },
    { "RaysPerSide", this->RaysPerSide > 0, this->RaysPerSide, stored.RaysPerSide },
    { "Tiles", this->Tiles > 0, this->Tiles, stored.TilesPerSide },
    { "ContactTexelHalvings", this->ContactTexelHalvings >= 0, this->ContactTexelHalvings,
      stored.ContactTexelHalvings },
  };
  std::ostringstream differing;
  for (const auto& setting : settings)
  {
    if (setting.Given && setting.Asked != setting.Stored)
    {
      differing << (differing.tellp() > 0 ? ", " : "") << setting.Name << " " << setting.Stored
                << " (asked: " << setting.Asked << ")";
    }
  }
  if (differing.tellp() > 0)
  {
    vtkWarningMacro("Resumed '" << this->SnapshotFileName
                                << "' with the settings it was propagated with: " << differing.str()
                                << ". A resumed field keeps its own; turn ResumeFromSnapshot off "
                                   "to start over with yours.");
  }
}

//------------------------------------------------------------------------------
void vtkVirtualLightField::GatherIfAsked(
  mesolight::vlf::LightField& field, double begin, mesolight::vlf::Reducer* reducer)
{
  if (!this->FinalGather)
  {
    mesolight::vlf::RestorePropagatedDiffuse(field); // a gathered snapshot resumed: as propagated
    return;
  }
  mesolight::vlf::FinalGatherOptions options;
  options.IndirectRays = this->FinalGatherRays;
  options.Progress = mesolight::AlgorithmProgress(this, begin, 1.0);
  options.Reduce = reducer;
  mesolight::vlf::FinalGather(field, options);
}

void vtkVirtualLightField::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Directions: " << this->Directions
     << (this->Directions == 0 ? " (automatic)" : "") << "\n";
  os << indent << "RaysPerSide: " << this->RaysPerSide
     << (this->RaysPerSide == 0 ? " (automatic)" : "") << "\n";
  os << indent << "Tiles: " << this->Tiles << (this->Tiles == 0 ? " (RaysPerSide / 8)" : "")
     << "\n";
  os << indent << "Iterations: " << this->Iterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "MaxIterations: " << this->MaxIterations << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << " bytes\n";
  os << indent
     << "SnapshotFileName: " << (this->SnapshotFileName.empty() ? "(none)" : this->SnapshotFileName)
     << "\n";
  os << indent << "ResumeFromSnapshot: " << this->ResumeFromSnapshot << "\n";
  os << indent << "DistributeDirections: " << this->DistributeDirections << "\n";
  os << indent << "FinalGather: " << this->FinalGather << "\n";
  os << indent << "FinalGatherRays: " << this->FinalGatherRays << "\n";
  os << indent << "ContactTexelHalvings: " << this->ContactTexelHalvings
     << (this->ContactTexelHalvings == mesolight::vlf::AutomaticContactTexelHalvings
            ? " (automatic)"
            : "")
     << "\n";
  os << indent << "AdaptiveTexels: " << this->AdaptiveTexels << "\n";
  os << indent << "AdaptiveTexelsBudget: " << this->AdaptiveTexelsBudget << "\n";
  os << indent << "PropagationCount: " << this->PropagationCount << "\n";
  os << indent << "LightField: "
     << (this->Field ? std::to_string(this->Field->IterationsDone) + " iterations done" : "(none)")
     << "\n";
}
