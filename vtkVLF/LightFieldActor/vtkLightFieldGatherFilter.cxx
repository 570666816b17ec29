// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldGatherFilter.h"

#include "vtkAlgorithmOutput.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightFieldReducer.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleSceneConverter.h"
#include "vtkVirtualLightFieldCore.h"

#include "Distribution.h"
#include "LightField.h"
#include "ObjectGatherer.h"
#include "ObjectShadows.h"
#include "PatchComparison.h" // ToUnit
#include "Progress.h"
#include "Snapshot.h"
#include "TextureAtlas.h"
#include "WalkthroughImage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

vtkStandardNewMacro(vtkLightFieldGatherFilter);

namespace
{
// A file name of this process' own in the temporary directory (the field travels between ranks
// as snapshot bytes, written and read by the snapshot code).
std::string TemporarySnapshotName(int rank)
{
  const char* directory = std::getenv("TMPDIR");
  return std::string(directory && *directory ? directory : "/tmp") + "/mesolight-field-" +
    std::to_string(static_cast<long>(::getpid())) + "-" + std::to_string(rank) + ".vlf";
}
} // namespace

//------------------------------------------------------------------------------
vtkLightFieldGatherFilter::vtkLightFieldGatherFilter()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkLightFieldGatherFilter::~vtkLightFieldGatherFilter() = default;

//------------------------------------------------------------------------------
void vtkLightFieldGatherFilter::SetLightFieldConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  (void)port;
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* out = outputVector->GetInformationObject(0);
  vtkInformation* surface = inputVector[0]->GetInformationObject(0);
  if (surface)
  {
    // The surface: the piece asked of this filter.
    surface->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
    surface->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    surface->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()));
  }
  if (vtkInformation* field = inputVector[1]->GetInformationObject(0))
  {
    // The piece the field's own display asks for: the field is made once (all ranks together,
    // or on rank 0 with DistributeDirections off) and not made again for this filter.
    field->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
    field->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    field->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
namespace
{
// The shadows' indirect term where the caster's shadow falls
// (mesolight::vlf::ObjectShadows::SetAmbient, EstimateShadowIndirect), from the points of
// `caster` (in the unit sphere: all the estimate reads of it), into `output`'s field data. Under
// MPI every rank must pass the whole caster, not its piece, so that every rank draws alike.
void AttachShadowAmbient(const mesolight::vlf::LightField& field,
  const std::vector<mesolight::vlf::ShadowEmitter>& significant, vtkPolyData* caster,
  vtkPolyData* output)
{
  namespace vlf = mesolight::vlf;
  vlf::ObjectMesh unit;
  unit.Positions.reserve(static_cast<std::size_t>(caster->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < caster->GetNumberOfPoints(); ++i)
  {
    double p[3];
    caster->GetPoint(i, p);
    unit.Positions.push_back(vlf::ToUnit(field,
      glm::vec3(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]))));
  }
  vtkNew<vtkDoubleArray> ambient;
  ambient->SetName(vtkLightFieldGatherFilter::GetAmbientName());
  const glm::vec3 a = vlf::EstimateShadowIndirect(field, significant, unit);
  for (const float v : { a.x, a.y, a.z })
  {
    ambient->InsertNextValue(static_cast<double>(v));
  }
  output->GetFieldData()->RemoveArray(vtkLightFieldGatherFilter::GetAmbientName());
  output->GetFieldData()->AddArray(ambient);
}

// The object's reflectance, each channel clamped to [0, 1].
glm::vec3 ClampedReflectance(const double reflectance[3])
{
  glm::vec3 diffuse;
  for (int c = 0; c < 3; ++c)
  {
    diffuse[c] = static_cast<float>(std::min(1.0, std::max(0.0, reflectance[c])));
  }
  return diffuse;
}

// The gather's settings from the filter's (serial and distributed paths alike).
mesolight::vlf::GatherSettings MakeGatherSettings(vtkAlgorithm* filter, int directionSet)
{
  namespace vlf = mesolight::vlf;
  vlf::GatherSettings settings;
  settings.UseCache = false;
  settings.Directions = directionSet == vtkLightFieldGatherFilter::HALF_DIRECTIONS
    ? vlf::DirectionSampling::Half
    : directionSet == vtkLightFieldGatherFilter::IMPORTANCE_DIRECTIONS
    ? vlf::DirectionSampling::Importance
    : vlf::DirectionSampling::All;
  settings.Progress = mesolight::AlgorithmProgress(filter);
  return settings;
}

// The surface's point normals: the input's, else computed without splitting (the points stay
// the input's) by `filter`, which holds them; null when they cannot be computed.
vtkDataArray* PointNormals(vtkPolyData* input, vtkPolyDataNormals* filter, bool& computed)
{
  computed = false;
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == input->GetNumberOfPoints())
  {
    return normals;
  }
  vtkNew<vtkPolyData> copy;
  copy->CopyStructure(input);
  filter->SetInputData(copy);
  filter->SplittingOff();
  filter->ConsistencyOff();
  filter->ComputePointNormalsOn();
  filter->ComputeCellNormalsOff();
  filter->Update();
  normals = filter->GetOutput()->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return nullptr;
  }
  computed = true;
  return normals;
}

// What the Light Field representation needs of the field to draw this surface's shadow on the
// scene and to expose it like the scene (see the header).
void AttachShadowCasterData(const mesolight::vlf::LightField& field, vtkPolyData* output)
{
  namespace vlf = mesolight::vlf;
  const std::vector<vlf::ShadowEmitter> significant =
    vlf::SignificantEmitters(field, vlf::ShadowSettings());
  const std::vector<float> packed = vlf::PackEmitters(significant);
  vtkNew<vtkFloatArray> emitters;
  emitters->SetName(vtkLightFieldGatherFilter::GetEmittersName());
  emitters->SetNumberOfValues(static_cast<vtkIdType>(packed.size()));
  std::copy(packed.begin(), packed.end(), emitters->GetPointer(0));
  vtkNew<vtkDoubleArray> logAverage;
  logAverage->SetName(vtkLightFieldGatherFilter::GetLogAverageName());
  double average = 0.0;
  try
  {
    const vlf::TextureAtlas atlas(field);
    average = vlf::LogAverageLuminance(atlas.Pixels().data(), atlas.Pixels().size() / 4);
  }
  catch (const std::exception&)
  {
    average = 0.0; // no atlas: the representation falls back to its Exposure alone
  }
  logAverage->InsertNextValue(average);
  AttachShadowAmbient(field, significant, output, output);
  output->GetFieldData()->AddArray(emitters);
  const glm::vec3 centre = field.NormalizationCentre();
  const double unitCentre[3] = { centre.x, centre.y, centre.z };
  vtkVirtualLightField::AttachUnitSphere(output, unitCentre, field.NormalizationScale());
  output->GetFieldData()->AddArray(logAverage);
}

// Each point's position as gathered, as x, y, z, 1 (see the header: not 3 components, so that a
// Transform after the gather leaves it alone).
void AttachGatheredAt(vtkPolyData* output)
{
  vtkNew<vtkFloatArray> at;
  at->SetName(vtkLightFieldGatherFilter::GetGatheredAtName());
  at->SetNumberOfComponents(4);
  at->SetNumberOfTuples(output->GetNumberOfPoints());
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    const float tuple[4] = { static_cast<float>(p[0]), static_cast<float>(p[1]),
      static_cast<float>(p[2]), 1.0f };
    at->SetTypedTuple(i, tuple);
  }
  output->GetPointData()->AddArray(at);
}
} // namespace

//------------------------------------------------------------------------------
const mesolight::vlf::LightField* vtkLightFieldGatherFilter::AcquireField(vtkAlgorithm* input)
{
  namespace vlf = mesolight::vlf;
  vtkVirtualLightField* producer = vtkVirtualLightField::FindUpstream(input);
  const vlf::LightField* own =
    producer ? vtkVirtualLightFieldCore::GetLightField(producer) : nullptr;
  int count = producer ? producer->GetPropagationCount() : 0;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (ranks < 2)
  {
    this->FieldPropagations = count;
    return own;
  }
  // Every rank reaches this point (nothing above returns early), so the collectives match.
  // [propagations, ranks holding a distributed field]
  int local[2] = { count, own && !own->OwnedSubfields.empty() ? 1 : 0 }, total[2] = { 0, 0 };
  controller->AllReduce(local, total, 2, vtkCommunicator::SUM_OP);
  if (total[1] == ranks)
  {
    // Propagated by all ranks together, each holding its own directions: nothing to send.
    this->FieldPropagations = count;
    this->FieldDistributed = true;
    return own;
  }
  this->FieldPropagations = total[0];
  const int rank = controller->GetLocalProcessId();
  // Rank 0 sends [bytes, version]: bytes -1 = no field there, 0 = the one sent before.
  vtkIdType header[2] = { -1, 0 };
  std::vector<char> bytes;
  if (rank == 0 && own)
  {
    header[1] = producer->GetPropagationCount();
    if (producer == this->SentProducer && header[1] == this->SentVersion)
    {
      header[0] = 0;
    }
    else
    {
      const std::string file = TemporarySnapshotName(rank);
      try
      {
        vlf::WriteSnapshot(*own, file);
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }
      catch (const std::exception& e)
      {
        vtkErrorMacro(
          "Light Field Gather cannot send the light field to the other ranks: " << e.what());
        bytes.clear();
      }
      std::remove(file.c_str());
      header[0] = bytes.empty() ? -1 : static_cast<vtkIdType>(bytes.size());
      this->SentProducer = header[0] > 0 ? producer : nullptr;
      this->SentVersion = static_cast<int>(header[1]);
    }
  }
  controller->Broadcast(header, 2, 0);
  if (header[0] > 0)
  {
    bytes.resize(static_cast<std::size_t>(header[0]));
    controller->Broadcast(bytes.data(), header[0], 0);
    ++this->FieldBroadcasts;
  }
  if (rank == 0)
  {
    return own;
  }
  if (header[0] < 0)
  {
    this->Received.reset();
  }
  else if (header[0] > 0)
  {
    const std::string file = TemporarySnapshotName(rank);
    try
    {
      {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      }
      this->Received = vlf::ReadSnapshot(file);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro("Light Field Gather cannot read the light field rank 0 sent: " << e.what());
      this->Received.reset();
    }
    std::remove(file.c_str());
  }
  return this->Received.get();
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  using namespace mesolight;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->OutsidePoints = 0;
  if (!input || !output)
  {
    vtkErrorMacro("Light Field Gather needs a surface (polygonal data) as its Input.");
    return 0;
  }
  output->ShallowCopy(input);
  // First, on every rank: the field (under MPI a collective step: each rank's share of a
  // distributed field, or rank 0's whole field broadcast).
  this->FieldDistributed = false;
  const vlf::LightField* field = AcquireField(this->GetInputAlgorithm(1, 0));
  if (field)
  {
    AttachShadowCasterData(*field, output); // every piece, empty ones too
  }
  if (field && this->FieldDistributed)
  {
    return this->GatherDistributed(*field, input, output);
  }
  if (input->GetNumberOfPoints() == 0)
  {
    return 1; // an empty piece (e.g. another rank's): nothing to gather
  }
  if (!field)
  {
    vtkErrorMacro("Light Field Gather needs the output of a Virtual Light Field filter that has "
                  "propagated successfully as its Light Field input.");
    return 0;
  }
  if (input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("Light Field Gather needs a surface with polygons (the input has none): apply "
                  "Extract Surface or Triangulate first.");
    return 0;
  }

  vtkNew<vtkPolyDataNormals> normalFilter;
  bool computed = false;
  vtkDataArray* normals = PointNormals(input, normalFilter, computed);
  if (!normals)
  {
    vtkErrorMacro("Light Field Gather could not compute normals for the surface.");
    return 0;
  }
  if (computed)
  {
    output->GetPointData()->SetNormals(normals); // what the irradiance was gathered with
  }

  // The surface's points and triangles (only the normals repair and the placement checks use
  // the triangles), gathered with the normals above.
  const vtkIdType n = input->GetNumberOfPoints();
  vlf::ObjectMesh mesh;
  vtkTriangleSceneConverter::ToTriangleMesh(input, mesh);
  mesh.TextureCoordinates.clear();
  mesh.Normals.resize(mesh.Positions.size());
  for (vtkIdType i = 0; i < n; ++i)
  {
    double m[3];
    normals->GetTuple(i, m);
    mesh.Normals[i] = glm::vec3(m[0], m[1], m[2]);
  }
  mesh.Diffuse = ClampedReflectance(this->Reflectance);

  const vlf::GatherSettings settings = MakeGatherSettings(this, this->DirectionSet);
  try
  {
    vlf::ObjectGatherer gatherer(*field);
    const vlf::ShadedObject& shaded =
      gatherer.Gather(mesh, vlf::WorldToUnitSphere(*field), settings);
    vtkNew<vtkFloatArray> irradiance, radiance;
    irradiance->SetName("Irradiance");
    radiance->SetName("Radiance");
    irradiance->SetNumberOfComponents(3);
    radiance->SetNumberOfComponents(3);
    irradiance->SetNumberOfTuples(n);
    radiance->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        irradiance->SetTypedComponent(i, c, shaded.Irradiance[i][c]);
        radiance->SetTypedComponent(i, c, shaded.Radiance[i][c]);
      }
    }
    output->GetPointData()->AddArray(irradiance);
    output->GetPointData()->AddArray(radiance);
    AttachGatheredAt(output);
    // No active scalars: ParaView shows the output as Light Field (its radiance exposed and
    // tone-mapped like the scene) rather than through a colour map.
    this->OutsidePoints = static_cast<vtkIdType>(shaded.OutsidePoints);
    if (shaded.OutsidePoints > 0)
    {
      vtkWarningMacro(<< shaded.OutsidePoints << " of " << n
                      << " points lie outside the light field's bounding sphere; they were "
                         "gathered on its boundary.");
    }
  }
  catch (const vlf::AbortedError&)
  {
    output->Initialize();
    vtkWarningMacro("Light Field Gather aborted.");
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Light Field Gather cannot shade this surface: " << e.what() << ".");
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::GatherDistributed(
  const mesolight::vlf::LightField& field, vtkPolyData* input, vtkPolyData* output)
{
  using namespace mesolight;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  // This rank's piece with its normals (the input's, else computed on the piece as in the
  // broadcast path); a piece that cannot be used is reported here and joins as empty, so that
  // every rank reaches the collectives below.
  vtkNew<vtkPolyData> local;
  bool usable = true;
  if (input->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkPolyDataNormals> normalFilter;
    bool computed = false;
    vtkDataArray* normals = nullptr;
    if (input->GetNumberOfPolys() == 0)
    {
      vtkErrorMacro("Light Field Gather needs a surface with polygons (the input has none): apply "
                    "Extract Surface or Triangulate first.");
      usable = false;
    }
    else if (!(normals = PointNormals(input, normalFilter, computed)))
    {
      vtkErrorMacro("Light Field Gather could not compute normals for the surface.");
      usable = false;
    }
    else if (computed)
    {
      output->GetPointData()->SetNormals(normals); // what the irradiance was gathered with
    }
    if (usable)
    {
      local->SetPoints(input->GetPoints());
      local->SetPolys(input->GetPolys());
      vtkNew<vtkFloatArray> copied;
      copied->DeepCopy(normals);
      copied->SetName("Normals");
      local->GetPointData()->SetNormals(copied);
    }
  }
  // Every rank's piece onto every rank, in rank order: the mesh is the same everywhere.
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(local, pieces);
  const int rank = controller->GetLocalProcessId();
  vtkNew<vtkAppendPolyData> append;
  vtkIdType offset = 0;
  for (std::size_t r = 0; r < pieces.size(); ++r)
  {
    auto* poly = vtkPolyData::SafeDownCast(pieces[r]);
    if (!poly || poly->GetNumberOfPoints() == 0)
    {
      continue;
    }
    if (static_cast<int>(r) < rank)
    {
      offset += poly->GetNumberOfPoints();
    }
    append->AddInputData(poly);
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return 1; // no rank has a surface (the same everywhere): nothing to gather
  }
  append->Update();
  vtkPolyData* whole = append->GetOutput();
  AttachShadowAmbient(field, vlf::SignificantEmitters(field, vlf::ShadowSettings()), whole, output);
  vtkDataArray* normals = whole->GetPointData()->GetNormals();
  vlf::ObjectMesh mesh;
  vtkTriangleSceneConverter::ToTriangleMesh(whole, mesh);
  mesh.TextureCoordinates.clear();
  mesh.Normals.resize(mesh.Positions.size());
  for (vtkIdType i = 0; i < whole->GetNumberOfPoints() && normals; ++i)
  {
    double m[3];
    normals->GetTuple(i, m);
    mesh.Normals[i] = glm::vec3(m[0], m[1], m[2]);
  }
  mesh.Diffuse = ClampedReflectance(this->Reflectance);
  const vlf::GatherSettings settings = MakeGatherSettings(this, this->DirectionSet);
  const vtkIdType n = usable ? input->GetNumberOfPoints() : 0;
  try
  {
    vlf::ControllerReducer reducer(controller);
    vlf::ObjectGatherer gatherer(field, &reducer);
    const vlf::ShadedObject& shaded =
      gatherer.Gather(mesh, vlf::WorldToUnitSphere(field), settings);
    if (n > 0)
    {
      vtkNew<vtkFloatArray> irradiance, radiance;
      irradiance->SetName("Irradiance");
      radiance->SetName("Radiance");
      irradiance->SetNumberOfComponents(3);
      radiance->SetNumberOfComponents(3);
      irradiance->SetNumberOfTuples(n);
      radiance->SetNumberOfTuples(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        const std::size_t at = static_cast<std::size_t>(offset + i);
        for (int c = 0; c < 3; ++c)
        {
          irradiance->SetTypedComponent(i, c, shaded.Irradiance[at][c]);
          radiance->SetTypedComponent(i, c, shaded.Radiance[at][c]);
        }
        const glm::vec3& p = shaded.Mesh.Positions[at];
        this->OutsidePoints += glm::dot(p, p) > 1.0f ? 1 : 0;
      }
      output->GetPointData()->AddArray(irradiance);
      output->GetPointData()->AddArray(radiance);
      AttachGatheredAt(output);
    }
    if (this->OutsidePoints > 0)
    {
      vtkWarningMacro(<< this->OutsidePoints << " of " << n
                      << " points lie outside the light field's bounding sphere; they were "
                         "gathered on its boundary.");
    }
  }
  catch (const vlf::AbortedError&)
  {
    output->Initialize();
    vtkWarningMacro("Light Field Gather aborted.");
    return 1;
  }
  catch (const vlf::DistributedError& e)
  {
    output->Initialize();
    vtkWarningMacro("Light Field Gather stopped: " << e.what());
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Light Field Gather cannot shade this surface: " << e.what() << ".");
    return 0;
  }
  return usable ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkLightFieldGatherFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Reflectance: " << this->Reflectance[0] << " " << this->Reflectance[1] << " "
     << this->Reflectance[2] << "\n";
  os << indent << "DirectionSet: " << this->DirectionSet << "\n";
  os << indent << "OutsidePoints: " << this->OutsidePoints << "\n";
  os << indent << "FieldPropagations: " << this->FieldPropagations << "\n";
  os << indent << "FieldBroadcasts: " << this->FieldBroadcasts << "\n";
  os << indent << "FieldDistributed: " << this->FieldDistributed << "\n";
}
