// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefSurface.h"
#include "vtkLightFieldReliefSurfaceCore.h"
#include "vtkLightFieldReliefSurfaceProbes.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldReducer.h"
#include "vtkVirtualLightField.h"
#include "vtkVirtualLightFieldCore.h"

#include "vtkAlgorithmOutput.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReliefMapper.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIrradianceProbesTexture.h" // the visible share map

#include "Distribution.h" // Agree
#include "EmbreeScene.h"
#include "EmitterLights.h"
#include "HeightFieldTracer.h"
#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "Progress.h"
#include "ReliefOcclusion.h"
#include "ReliefShading.h"
#include "ReliefSurface.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <exception>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vlf = mesolight::vlf;

namespace
{
// The probes image's extent is known once RequestData has chosen the probe count (the automatic
// one depends on the surface); the pipeline is told the extent the data has.
void ProbesWholeExtentFromData(vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(1);
  vtkImageData* probes = vtkImageData::GetData(info);
  if (probes && probes->GetNumberOfPoints() > 0)
  {
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), probes->GetExtent(), 6);
  }
}
} // namespace
using namespace mesolight::vlf::reliefsurface;

// What the last update of a surface of input port 1 computed, and from what.
struct vtkLightFieldReliefSurface::vtkInternals
{
  SurfaceResult Result;
  bool HasResult = false;
  const void* Producer = nullptr;
  int Propagation = -1;
  vtkMTimeType SurfaceTime = 0;
  int Probes = 0;
  bool SceneOcclusion = false;

  vtkSmartPointer<vtkImageData> ReliefTexture;
  // The last visible-share map and what it was made from.
  std::vector<float> Share;
  std::vector<float> WallShare; // the side walls' cells of a walled relief (ReliefWallShareMap)
  int ShareSize[2] = { 0, 0 };
  // The texture's texels (an attached texture comes as a new image sharing the same array).
  vtkDataArray* ShareTexture = nullptr; // compared only
  vtkMTimeType ShareTextureTime = 0;
  double ShareKey[19] = {}; // frame (12), depth scale, walled, light 0's samples (count, sum),
                            // the probes' sum (the walls' radiance weighting)
  // The emitter samples the renderer's light 0 stands for (EmitterSamplesOfLight), whose
  // shadow by the relief the map holds as a fourth value; empty: not in the map (the relief
  // mapper marches one shadow ray to the light).
  std::vector<mesolight::ReliefEmitterSample> LightSamples;

  // An Embree scene of LentFor's scene, lent (vtkLightFieldReliefSurfaceCore::LendEmbreeScene).
  std::shared_ptr<const mesolight::EmbreeScene> LentEmbree;
  const vlf::LightField* LentFor = nullptr; // compared only
};

vtkStandardNewMacro(vtkLightFieldReliefSurface);
vtkCxxSetObjectMacro(vtkLightFieldReliefSurface, LightFieldActor, vtkLightFieldActor);
vtkCxxSetObjectMacro(vtkLightFieldReliefSurface, LightFieldProducer, vtkVirtualLightField);

//------------------------------------------------------------------------------
vtkLightFieldReliefSurface::vtkLightFieldReliefSurface()
  : ProbesPerSide(vlf::AutomaticReliefProbes)
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(2); // 0: the field, 1: a surface of its own (optional)
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkLightFieldReliefSurface::~vtkLightFieldReliefSurface()
{
  this->SetLightFieldActor(nullptr);
  this->SetLightFieldProducer(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::SetLightFieldConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(0, output);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::SetSurfaceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::SetSurfaceData(vtkPolyData* surface)
{
  this->SetInputDataObject(1, surface);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::SetReliefTextureData(vtkImageData* texture)
{
  if (this->Internals->ReliefTexture != texture)
  {
    this->Internals->ReliefTexture = texture;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldReliefSurface::GetReliefTextureData()
{
  return this->Internals->ReliefTexture;
}

//------------------------------------------------------------------------------
double vtkLightFieldReliefSurface::MapProgress() const
{
  return this->Internals->ReliefTexture && this->ReliefDepthScale > 0.0 ? 0.5 : 1.0;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefSurface::AddVisibleShare(
  vtkImageData* probesOutput, const double frame[12], vtkMultiProcessController* controller)
{
  vtkInternals& in = *this->Internals;
  vtkImageData* texture = in.ReliefTexture;
  // Under MPI the ranks split the map's rows when every rank has the same map to make: the
  // texture of the same size (each rank's comes with its piece of the data) and the frame, depth
  // scale and edge, alike on every rank. Otherwise (a rank without the texture, say) each rank
  // makes its own, as one process does.
  int dims[3] = { 0, 0, 0 };
  if (texture)
  {
    texture->GetDimensions(dims);
  }
  const bool wanted = texture && this->ReliefDepthScale > 0.0;
  vtkMultiProcessController* split = nullptr;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    const int mine[3] = { wanted ? 1 : 0, wanted ? dims[0] : -1, wanted ? dims[1] : -1 };
    const int negated[3] = { -mine[0], -mine[1], -mine[2] };
    int most[3] = { 0, 0, 0 }, least[3] = { 0, 0, 0 };
    controller->AllReduce(mine, most, 3, vtkCommunicator::MAX_OP);
    controller->AllReduce(negated, least, 3, vtkCommunicator::MAX_OP);
    if (most[0] == 1 && -least[0] == 1 && most[1] == -least[1] && most[2] == -least[2])
    {
      split = controller;
    }
  }
  // A flat relief (depth scale 0) hides nothing of the room: V = 1, no map (the relief frame
  // would have no depth axis to march along).
  if (!wanted)
  {
    return true;
  }
  // The probes (SH9 of pixel (9 i + k, j)), which weight the side walls' share of their light.
  mesolight::ReliefLighting probes;
  double probeSum = 0.0;
  if (vtkDataArray* coefficients = probesOutput->GetPointData()->GetScalars())
  {
    int probeDims[3] = { 0, 0, 0 };
    probesOutput->GetDimensions(probeDims);
    if (probeDims[0] % 9 == 0 && probeDims[0] > 0 && coefficients->GetNumberOfComponents() >= 3 &&
      coefficients->GetNumberOfTuples() == static_cast<vtkIdType>(probeDims[0]) * probeDims[1])
    {
      probes.ProbesU = probeDims[0] / 9;
      probes.ProbesV = probeDims[1];
      probes.Probes.resize(static_cast<std::size_t>(probes.ProbesU) * probes.ProbesV);
      for (int j = 0; j < probes.ProbesV; ++j)
      {
        for (int i = 0; i < probes.ProbesU; ++i)
        {
          for (int k = 0; k < 9; ++k)
          {
            for (int c = 0; c < 3; ++c)
            {
              const double value =
                coefficients->GetComponent(static_cast<vtkIdType>(j) * probeDims[0] + 9 * i + k, c);
              probes.Probes[static_cast<std::size_t>(j) * probes.ProbesU + i].L[k][c] = value;
              probeSum += value * (1.0 + 0.01 * k);
            }
          }
        }
      }
    }
  }
  double key[19] = {};
  std::copy(frame, frame + 12, key);
  key[12] = this->ReliefDepthScale;
  key[13] = this->WalledRelief ? 1.0 : 0.0;
  key[14] = static_cast<double>(in.LightSamples.size());
  for (const mesolight::ReliefEmitterSample& sample : in.LightSamples)
  {
    key[15] += sample.Position.x;
    key[16] += sample.Position.y;
    key[17] += sample.Position.z;
  }
  key[18] = probeSum;
  vtkDataArray* texels = texture->GetPointData()->GetScalars();
  const vtkMTimeType texelsTime = texels ? texels->GetMTime() : texture->GetMTime();
  int stale = (texels != in.ShareTexture || texelsTime != in.ShareTextureTime ||
                std::memcmp(key, in.ShareKey, sizeof(key)) != 0 || in.Share.empty())
    ? 1
    : 0;
  if (split)
  {
    int any = stale; // every rank computes its rows, or none does
    split->AllReduce(&stale, &any, 1, vtkCommunicator::MAX_OP);
    stale = any;
  }
  if (stale)
  {
    in.Share.clear();
    in.WallShare.clear();
    in.ShareTexture = texels;
    in.ShareTextureTime = texelsTime;
    std::copy(key, key + 19, in.ShareKey);
    std::unique_ptr<vlf::ControllerReducer> reducer;
    if (split)
    {
      reducer = std::make_unique<vlf::ControllerReducer>(split);
    }
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    try
    {
      std::unique_ptr<mesolight::HeightField> height;
      const auto makeHeight = [&]()
      {
        height =
          std::make_unique<mesolight::HeightField>(ReliefHeightField(texture, this->WalledRelief));
      };
      if (reducer)
      {
        vlf::Agree(*reducer, makeHeight); // no rank left waiting in the map's sums
      }
      else
      {
        makeHeight();
      }
      vlf::ReliefSurface surface;
      surface.Origin = glm::dvec3(frame[0], frame[1], frame[2]);
      surface.AxisU = glm::dvec3(frame[3], frame[4], frame[5]);
      surface.AxisV = glm::dvec3(frame[6], frame[7], frame[8]);
      surface.Normal = glm::dvec3(frame[9], frame[10], frame[11]);
      in.Share = vlf::ReliefVisibleShareGrid(*height,
        vlf::ReliefFrameOf(surface, this->ReliefDepthScale), in.ShareSize[0], in.ShareSize[1],
        mesolight::AlgorithmProgress(this, this->MapProgress(), 1.0), in.LightSamples,
        reducer.get(), &in.WallShare, &probes);
      ++this->VisibleShareComputations;
      this->VisibleShareRanks = reducer ? reducer->Size() : 1;
      this->VisibleShareSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      this->VisibleShareCpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    }
    catch (const vlf::AbortedError&)
    {
      in.ShareTexture = nullptr;
      return false;
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< e.what() << "; the relief is drawn without its occlusion");
      return true; // the same texture is not tried again until it changes
    }
  }
  if (in.Share.empty())
  {
    return true;
  }
  // The values per cell are ReliefVisibleShareGrid's (V, V over the share above the plane, the
  // seen relief's share, and with light samples light 0's share past the relief's shadow).
  const std::size_t cells = static_cast<std::size_t>(in.ShareSize[0]) * in.ShareSize[1];
  vtkNew<vtkFloatArray> share;
  share->SetNumberOfComponents(static_cast<int>(in.Share.size() / cells));
  share->SetNumberOfTuples(static_cast<vtkIdType>(cells));
  std::copy(in.Share.begin(), in.Share.end(), share->GetPointer(0));
  vtkIrradianceProbesTexture::AttachVisibleShare(
    probesOutput, share, in.ShareSize[0], in.ShareSize[1]);
  if (!in.WallShare.empty())
  {
    // The side walls' cells, as many values each (vtkIrradianceProbesTexture::GetWallShareName).
    vtkNew<vtkFloatArray> walls;
    walls->SetName(vtkIrradianceProbesTexture::GetWallShareName());
    walls->SetNumberOfComponents(share->GetNumberOfComponents());
    walls->SetNumberOfTuples(
      static_cast<vtkIdType>(in.WallShare.size() / share->GetNumberOfComponents()));
    std::copy(in.WallShare.begin(), in.WallShare.end(), walls->GetPointer(0));
    probesOutput->GetFieldData()->AddArray(walls);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldReliefSurface::GetProbesOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightFieldReliefSurface::GetMTime()
{
  // The actor changes with every setting and camera-driven update; only a new field (loaded or
  // lent) makes the outputs stale, and the probes are too costly to recompute for less.
  if (this->LightFieldActor &&
    vtkLightFieldActorCore::GetLightField(this->LightFieldActor) != this->ExecutedField)
  {
    this->Modified();
  }
  return this->Superclass::GetMTime();
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // The automatic count is known once the surface is (RequestData sets the extent it chose).
  const int n = this->ProbesPerSide > 0 ? this->ProbesPerSide
    : this->ProbesPerSideUsed > 0       ? this->ProbesPerSideUsed
                                        : vlf::DefaultReliefProbesPerSide;
  const int extent[6] = { 0, 9 * n - 1, 0, n - 1, 0, 0 };
  vtkInformation* info = outputVector->GetInformationObject(1);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, this->SceneOcclusion ? 4 : 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* probesOutput = vtkImageData::GetData(outputVector, 1);
  this->EmitterLights->RemoveAllItems();
  this->NamedProbes.reset();
  std::fill(this->DepthLimit, this->DepthLimit + 7, 0.0);
  std::fill(this->FieldUnitSphere, this->FieldUnitSphere + 4, 0.0);
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    const int done =
      this->RequestSurfaceData(vtkPolyData::GetData(inputVector[1], 0), output, probesOutput);
    ProbesWholeExtentFromData(outputVector);
    return done;
  }
  const vlf::LightField* field = nullptr;
  if (this->LightFieldActor)
  {
    field = vtkLightFieldActorCore::GetLightField(this->LightFieldActor);
    this->ExecutedField = field;
  }
  else if (auto* producer = vtkVirtualLightField::FindUpstream(this->GetInputAlgorithm(0, 0)))
  {
    field = vtkVirtualLightFieldCore::GetLightField(producer);
  }
  if (!field)
  {
    vtkErrorMacro("a relief surface needs a light field: a vtkLightFieldActor showing one, or a "
                  "vtkVirtualLightField that has propagated connected to input port 0");
    return 0;
  }
  vlf::ReliefSurface surface;
  std::vector<mesolight::SH9> probes;
  int n = vlf::DefaultReliefProbesPerSide;
  try
  {
    surface = vlf::FindReliefSurface(*field, this->SurfaceName);
    n = vlf::ReliefProbesPerSide(*field, surface, this->ProbesPerSide);
    probes = vlf::ReliefSurfaceProbes(
      *field, surface, n, n, mesolight::AlgorithmProgress(this, 0.0, this->MapProgress()));
  }
  catch (const vlf::AbortedError&)
  {
    return 1; // stopped: empty outputs
  }
  catch (const std::exception& e)
  {
    if (!this->LightFieldActor && mesolight::SurfaceNameList(field->Scene()) == "(none)")
    {
      // Polydata names its surfaces only with vtkTriangleSceneConverter's SurfaceId array.
      vtkErrorMacro(<< e.what()
                    << "; a field propagated from polydata has no surface names when the polydata "
                       "has no SurfaceId cell array (the Mesolight OBJ reader's and Cornell box "
                       "source's have one): read the scene with them, or load a snapshot of a "
                       "named scene into a vtkLightFieldActor and give that actor");
      return 0;
    }
    vtkErrorMacro(<< e.what());
    return 0;
  }
  for (int c = 0; c < 3; ++c)
  {
    this->SurfaceDiffuse[c] = surface.Diffuse[c];
    this->SurfaceEmission[c] = surface.Emission[c];
  }

  // Port 0: the triangles, three points each (the surface's own normal and texture map).
  const mesolight::TriangleScene& scene = field->Scene();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> polys;
  for (const std::size_t t : surface.Triangles)
  {
    vtkIdType ids[3];
    for (int corner = 0; corner < 3; ++corner)
    {
      const glm::vec3 unit = scene.Vertex(t, corner);
      const glm::vec3 world = vlf::ToWorld(*field, unit);
      ids[corner] = points->InsertNextPoint(world.x, world.y, world.z);
      const glm::dvec3 uvw = surface.TextureOf(glm::dvec3(unit));
      tcoords->InsertNextTuple2(uvw.x, uvw.y);
      normals->InsertNextTuple3(surface.Normal.x, surface.Normal.y, surface.Normal.z);
    }
    // Counter-clockwise about the front normal (the relief lies behind the front side).
    const glm::dvec3 a(scene.Vertex(t, 0)), b(scene.Vertex(t, 1)), c(scene.Vertex(t, 2));
    if (glm::dot(glm::cross(b - a, c - a), surface.Normal) < 0.0)
    {
      std::swap(ids[1], ids[2]);
    }
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->SetTCoords(tcoords);

  // Port 1: the probes, pixel (9 i + k, j), with the emitter lights' factors and the relief's
  // visible share when asked for.
  std::vector<float> factors;
  const std::vector<vlf::EmitterLight> emitters = ReliefEmitterLights(*field, &surface);
  this->Internals->LightSamples.clear();
  if (this->SceneOcclusion)
  {
    factors = LightFactors(*field, surface, emitters, n,
      this->Internals->LentFor == field ? this->Internals->LentEmbree.get() : nullptr);
    this->Internals->LightSamples = FirstLightSamples(*field, emitters);
  }
  FillProbesImage(probesOutput, PackProbes(probes, n), n, this->SceneOcclusion ? &factors : nullptr,
    emitters.size());
  this->ProbesPerSideUsed = n;
  ProbesWholeExtentFromData(outputVector);
  this->NamedProbes = std::make_unique<std::vector<mesolight::SH9>>(std::move(probes));
  ++this->ProbeComputations;
  const double frame[12] = { surface.Origin.x, surface.Origin.y, surface.Origin.z, surface.AxisU.x,
    surface.AxisU.y, surface.AxisU.z, surface.AxisV.x, surface.AxisV.y, surface.AxisV.z,
    surface.Normal.x, surface.Normal.y, surface.Normal.z };
  if (!this->AddVisibleShare(probesOutput, frame))
  {
    output->Initialize();
    probesOutput->Initialize();
    return 1; // stopped: empty outputs
  }

  AddEmitterLights(*field, emitters, this->EmitterLights);
  const glm::vec3 centre = field->NormalizationCentre();
  std::copy(&centre.x, &centre.x + 3, this->FieldUnitSphere);
  this->FieldUnitSphere[3] = field->NormalizationScale();
  return 1;
}

//------------------------------------------------------------------------------
const std::vector<mesolight::SH9>* vtkLightFieldReliefSurfaceCore::GetProbes(
  const vtkLightFieldReliefSurface* surface)
{
  return surface ? surface->NamedProbes.get() : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurfaceCore::LendEmbreeScene(vtkLightFieldReliefSurface* surface,
  const mesolight::vlf::LightField* field, std::shared_ptr<const mesolight::EmbreeScene> scene)
{
  if (surface)
  {
    surface->Internals->LentFor = scene ? field : nullptr;
    surface->Internals->LentEmbree = std::move(scene);
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkLightFieldReliefSurface::GatherWholeSurface(
  vtkPolyData* local, vtkMultiProcessController* controller)
{
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return local;
  }
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(local, pieces);
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : pieces)
  {
    auto* poly = vtkPolyData::SafeDownCast(piece);
    if (poly && poly->GetNumberOfPolys() > 0)
    {
      append->AddInputData(poly);
    }
  }
  auto whole = vtkSmartPointer<vtkPolyData>::New();
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    whole->ShallowCopy(append->GetOutput());
  }
  return whole;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::RequestSurfaceData(
  vtkPolyData* input, vtkPolyData* output, vtkImageData* probesOutput)
{
  vtkVirtualLightField* producer = this->LightFieldProducer;
  if (!producer && this->GetNumberOfInputConnections(0) > 0)
  {
    producer = vtkVirtualLightField::FindUpstream(this->GetInputAlgorithm(0, 0));
  }
  const vlf::LightField* field =
    producer ? vtkVirtualLightFieldCore::GetLightField(producer) : nullptr;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  const int rank = ranks > 1 ? controller->GetLocalProcessId() : 0;
  const int requested = this->ProbesPerSide;

  // The whole surface on every rank (one texture frame for all pieces). Every rank reaches each
  // collective below: nothing returns before the last one.
  vtkNew<vtkPolyData> local;
  if (input)
  {
    local->ShallowCopy(input);
  }
  vtkSmartPointer<vtkPolyData> whole = GatherWholeSurface(local, controller);

  // Who computes: the lowest rank holding the whole field, else (a field whose directions are
  // split) every rank its share, summed.
  const bool partial = field && !field->OwnedSubfields.empty();
  int local2[2] = { field && !partial ? rank : ranks, partial ? 1 : 0 };
  int reduced[2] = { local2[0], local2[1] };
  if (ranks > 1)
  {
    controller->AllReduce(&local2[0], &reduced[0], 1, vtkCommunicator::MIN_OP);
    controller->AllReduce(&local2[1], &reduced[1], 1, vtkCommunicator::SUM_OP);
  }
  const int root = reduced[0];
  const bool summed = root == ranks && reduced[1] == ranks;
  const bool computes = (root < ranks && rank == root) || summed;

  // The probes of an unchanged field and surface are kept (a new relief texture or depth scale
  // recomputes the visible-share map only); every rank decides alike.
  vtkInternals& in = *this->Internals;
  const int propagation = producer ? producer->GetPropagationCount() : -1;
  const vtkMTimeType surfaceTime = input ? input->GetMTime() : 0;
  int stale = (!in.HasResult || in.Producer != producer || in.Propagation != propagation ||
                in.SurfaceTime != surfaceTime || in.Probes != requested ||
                in.SceneOcclusion != this->SceneOcclusion)
    ? 1
    : 0;
  if (ranks > 1)
  {
    int any = stale;
    controller->AllReduce(&stale, &any, 1, vtkCommunicator::MAX_OP);
    stale = any;
  }
  in.HasResult = in.HasResult && !stale;

  // status: 1 done, 0 error (reported by the rank that met it), -1 aborted.
  int status = 1;
  SurfaceResult result;
  if (!stale)
  {
    result = in.Result;
  }
  else if (root == ranks && !summed)
  {
    status = 0;
    if (rank == 0)
    {
      vtkErrorMacro("a relief surface lit by a light field needs the output of a Virtual Light "
                    "Field that has propagated successfully connected to input port 0");
    }
  }
  else if (computes)
  {
    if (whole->GetNumberOfPolys() == 0)
    {
      status = 0;
      if (rank == 0 || !summed)
      {
        vtkErrorMacro("a relief surface lit by a light field needs a surface with polygons "
                      "(input port 1 has none)");
      }
    }
    else
    {
      try
      {
        result = ComputeSurface(*field, whole, requested, this->SceneOcclusion,
          mesolight::AlgorithmProgress(this, 0.0, this->MapProgress()));
        if (!result.Warning.empty() && (rank == 0 || !summed))
        {
          vtkWarningMacro(<< result.Warning);
        }
      }
      catch (const vlf::AbortedError&)
      {
        status = -1;
      }
      catch (const std::exception& e)
      {
        status = 0;
        if (rank == 0 || !summed)
        {
          vtkErrorMacro(<< e.what());
        }
      }
    }
  }
  if (ranks > 1 && stale)
  {
    // Everyone learns the worst status: the computing ranks', or the root's.
    int worst = status;
    if (summed)
    {
      controller->AllReduce(&status, &worst, 1, vtkCommunicator::MIN_OP);
    }
    else
    {
      controller->Broadcast(&worst, 1, root);
    }
    status = worst;
    if (status == 1 && summed)
    {
      std::vector<float> sum(result.Probes.size());
      controller->AllReduce(result.Probes.data(), sum.data(), static_cast<vtkIdType>(sum.size()),
        vtkCommunicator::SUM_OP);
      result.Probes = sum;
    }
    else if (status == 1)
    {
      vtkIdType lights = static_cast<vtkIdType>(result.Lights.size());
      controller->Broadcast(&lights, 1, root);
      controller->Broadcast(&result.ProbesPerSide, 1, root);
      const int n = result.ProbesPerSide;
      result.Probes.resize(static_cast<std::size_t>(27) * n * n);
      result.Lights.resize(static_cast<std::size_t>(lights));
      controller->Broadcast(
        result.Probes.data(), static_cast<vtkIdType>(result.Probes.size()), root);
      controller->Broadcast(result.Frame, 16, root);
      controller->Broadcast(result.Diffuse, 3, root);
      controller->Broadcast(result.Emission, 3, root);
      controller->Broadcast(result.Limit, 7, root);
      if (lights > 0)
      {
        controller->Broadcast(result.Lights.data(), lights, root);
      }
      if (this->SceneOcclusion)
      {
        result.Factors.resize(static_cast<std::size_t>(n) * n * (lights / 9));
        controller->Broadcast(
          result.Factors.data(), static_cast<vtkIdType>(result.Factors.size()), root);
        vtkIdType samples = static_cast<vtkIdType>(result.LightSamples.size());
        controller->Broadcast(&samples, 1, root);
        result.LightSamples.resize(static_cast<std::size_t>(samples));
        if (samples > 0)
        {
          controller->Broadcast(result.LightSamples.data(), samples, root);
        }
      }
    }
  }
  if (status != 1)
  {
    return status < 0 ? 1 : 0; // aborted: empty outputs, no error
  }
  if (stale)
  {
    in.Result = result;
    in.HasResult = true;
    in.Producer = producer;
    in.Propagation = propagation;
    in.SurfaceTime = surfaceTime;
    in.Probes = requested;
    in.SceneOcclusion = this->SceneOcclusion;
    ++this->ProbeComputations;
  }

  FillProbesImage(probesOutput, result.Probes, result.ProbesPerSide,
    this->SceneOcclusion ? &result.Factors : nullptr, result.Lights.size() / 9);
  this->ProbesPerSideUsed = result.ProbesPerSide;
  // Light 0's area shadow in the map, as for a named surface (every rank has the samples: its own
  // or the computing rank's).
  in.LightSamples = UnpackEmitterSamples(result.LightSamples);
  if (!this->AddVisibleShare(probesOutput, result.Frame, ranks > 1 ? controller : nullptr))
  {
    probesOutput->Initialize();
    return 1; // stopped: empty outputs
  }
  AddPackedLights(result.Lights, this->EmitterLights);
  std::copy(result.Diffuse, result.Diffuse + 3, this->SurfaceDiffuse);
  std::copy(result.Emission, result.Emission + 3, this->SurfaceEmission);
  std::copy(result.Limit, result.Limit + 7, this->DepthLimit);
  std::copy(result.Frame + 12, result.Frame + 16, this->FieldUnitSphere);

  // Port 0: this rank's piece, with normals and, when it has none, the plane's texture
  // coordinates (u, v of the frame at each point: world -> unit sphere -> texture).
  output->ShallowCopy(local);
  if (local->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  const glm::dvec3 axisU(result.Frame[3], result.Frame[4], result.Frame[5]);
  const glm::dvec3 axisV(result.Frame[6], result.Frame[7], result.Frame[8]);
  const glm::dvec3 normal(result.Frame[9], result.Frame[10], result.Frame[11]);
  if (!output->GetPointData()->GetNormals())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(output->GetNumberOfPoints());
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      normals->SetTuple3(i, normal.x, normal.y, normal.z);
    }
    output->GetPointData()->SetNormals(normals);
  }
  if (!output->GetPointData()->GetTCoords())
  {
    const glm::dvec3 centre(result.Frame[12], result.Frame[13], result.Frame[14]);
    vlf::ReliefSurface frame;
    frame.Origin = glm::dvec3(result.Frame[0], result.Frame[1], result.Frame[2]);
    frame.AxisU = axisU;
    frame.AxisV = axisV;
    frame.Normal = normal;
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("TextureCoordinates");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(output->GetNumberOfPoints());
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      output->GetPoint(i, p);
      const glm::dvec3 uvw =
        frame.TextureOf((glm::dvec3(p[0], p[1], p[2]) - centre) * result.Frame[15]);
      tcoords->SetTuple2(i, uvw.x, uvw.y);
    }
    output->GetPointData()->SetTCoords(tcoords);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefSurface::GetDepthLimitPlane(double origin[3], double normal[3]) const
{
  std::copy(this->DepthLimit, this->DepthLimit + 3, origin);
  std::copy(this->DepthLimit + 3, this->DepthLimit + 6, normal);
  return this->DepthLimit[6] > 0.0;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefSurface::GetFieldUnitSphere(double centre[3], double* scale) const
{
  std::copy(this->FieldUnitSphere, this->FieldUnitSphere + 3, centre);
  *scale = this->FieldUnitSphere[3];
  return this->FieldUnitSphere[3] > 0.0;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefSurface::GetEmitterLights(
  vtkLightFieldActor* actor, vtkLightCollection* lights)
{
  const vlf::LightField* field = actor ? vtkLightFieldActorCore::GetLightField(actor) : nullptr;
  if (!field || !lights)
  {
    return false;
  }
  AddEmitterLights(*field, ReliefEmitterLights(*field), lights);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << this->LightFieldActor << "\n";
  os << indent << "LightFieldProducer: " << this->LightFieldProducer << "\n";
  os << indent << "SurfaceName: " << this->SurfaceName << "\n";
  os << indent << "ProbesPerSide: " << this->ProbesPerSide << "\n";
  os << indent << "ProbesPerSideUsed: " << this->ProbesPerSideUsed << "\n";
  os << indent << "EmitterLights: " << this->EmitterLights->GetNumberOfItems() << "\n";
  os << indent << "ReliefTextureData: " << this->Internals->ReliefTexture.Get() << "\n";
  os << indent << "ReliefDepthScale: " << this->ReliefDepthScale << "\n";
  os << indent << "WalledRelief: " << this->WalledRelief << "\n";
  os << indent << "SceneOcclusion: " << this->SceneOcclusion << "\n";
  os << indent << "ProbeComputations: " << this->ProbeComputations << "\n";
  os << indent << "VisibleShareComputations: " << this->VisibleShareComputations << "\n";
  os << indent << "VisibleShareRanks: " << this->VisibleShareRanks << "\n";
  os << indent << "VisibleShareSeconds: " << this->VisibleShareSeconds << "\n";
  os << indent << "VisibleShareCpuSeconds: " << this->VisibleShareCpuSeconds << "\n";
}
