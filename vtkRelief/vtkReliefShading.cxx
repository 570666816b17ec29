#include "vtkReliefShading.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkOpenGLError.h"
#include "vtkVariant.h"
#include "vtk_glew.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataTangents.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTriangleFilter.h"

// GLSL sources embedded at build time (vtk_encode_string).
#include "vtkReliefHeightFieldFS.h"
#include "vtkReliefImplFS.h"
#include "vtkReliefLightSetFS.h"
#include "vtkReliefLightingFS.h"
#include "vtkReliefMarchFS.h"
#include "vtkReliefMaxMipmapFS.h"

#include "ConeMaps.h" // Mesolight::Filters core: the min-depth pyramid

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkReliefShading);

namespace
{
const char* const MethodNames[] = { "texture", "bump", "parallax", "parallax-limit",
  "parallax-slope", "iterative-parallax", "binary", "secant", "linear", "pom", "relief", "interval",
  "relaxed-cone", "relaxed-cone-interval", "cone", "max-mipmap" };
static_assert(sizeof(MethodNames) / sizeof(MethodNames[0]) == vtkReliefShading::NumberOfMethods,
  "one name per method");
const char* const ReliefTCoordsName = "vtkReliefMapperTCoords";

// Compile-time refinement of the march per method (see vtkReliefMarchFS.glsl, ML_REFINE).
int RefinementKind(int method)
{
  switch (method)
  {
    case vtkReliefShading::Relief:
      return 2; // binary search
    case vtkReliefShading::ParallaxOcclusion:
      return 1; // one secant step
    default:
      return 0;
  }
}

// GLSL names of the methods, so the shader reads "#if ML_METHOD == ML_RELIEF".
std::string MethodDefines()
{
  const char* const glslNames[] = { "ML_TEXTURE_MAPPING", "ML_BUMP", "ML_PARALLAX",
    "ML_PARALLAX_OFFSET_LIMITING", "ML_PARALLAX_SLOPE", "ML_ITERATIVE_PARALLAX",
    "ML_BINARY_SEARCH", "ML_SECANT", "ML_LINEAR_SEARCH", "ML_PARALLAX_OCCLUSION", "ML_RELIEF",
    "ML_INTERVAL", "ML_RELAXED_CONE_BINARY", "ML_RELAXED_CONE_INTERVAL", "ML_CONSERVATIVE_CONE",
    "ML_MAXIMUM_MIPMAP" };
  static_assert(sizeof(glslNames) / sizeof(glslNames[0]) == vtkReliefShading::NumberOfMethods,
    "one GLSL name per method");
  std::string defines;
  for (int m = 0; m < vtkReliefShading::NumberOfMethods; ++m)
  {
    defines += std::string("#define ") + glslNames[m] + " " + std::to_string(m) + "\n";
  }
  return defines;
}

// "relaxed" / "conservative" (or 1 / 2) from the cone map's field data; 0 if not cone packed.
int ConeTypeOf(vtkImageData* image)
{
  vtkAbstractArray* type = image->GetFieldData()->GetAbstractArray("MesolightConeType");
  if (!type || type->GetNumberOfValues() < 1)
  {
    return vtkReliefShading::NoConeMap;
  }
  std::string text = type->GetVariantValue(0).ToString();
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return (text.find("conserv") != std::string::npos || text == "2")
    ? vtkReliefShading::ConservativeConeMap
    : vtkReliefShading::RelaxedConeMap;
}

bool AllTriangles(vtkPolyData* poly)
{
  if (poly->GetNumberOfStrips() > 0)
  {
    return false;
  }
  vtkCellArray* polys = poly->GetPolys();
  return polys->IsHomogeneous() == 3;
}

bool UsableDirection(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) &&
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) > 1e-20;
}

// Degenerate triangles (zero area, or coinciding texture coordinates) give zero or NaN normals
// and tangents. Replace them by a usable frame so the shader never receives NaN.
void SanitizeFrame(vtkPolyData* mesh)
{
  vtkPointData* pd = mesh->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  auto* tangents = vtkFloatArray::SafeDownCast(pd->GetTangents());
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkSmartPointer<vtkDataArray> ownNormals;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double nrm[3];
    normals->GetTuple(i, nrm);
    if (!UsableDirection(nrm))
    {
      if (!ownNormals) // the normals may be the user's: change a copy
      {
        ownNormals = vtkSmartPointer<vtkDataArray>::Take(normals->NewInstance());
        ownNormals->DeepCopy(normals);
        pd->SetNormals(ownNormals);
        normals = ownNormals;
      }
      normals->SetTuple3(i, 0.0, 0.0, 1.0);
      nrm[0] = nrm[1] = 0.0;
      nrm[2] = 1.0;
    }
    float* t = tangents->GetPointer(3 * i);
    const double tangent[3] = { t[0], t[1], t[2] };
    if (UsableDirection(tangent))
    {
      continue;
    }
    double perp[3];
    vtkMath::Perpendiculars(nrm, perp, nullptr, 0.0);
    if (!UsableDirection(perp))
    {
      perp[0] = 1.0;
      perp[1] = perp[2] = 0.0;
    }
    t[0] = static_cast<float>(perp[0]);
    t[1] = static_cast<float>(perp[1]);
    t[2] = static_cast<float>(perp[2]);
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkReliefShading::vtkReliefShading()
{
  this->ReliefTextureObject = vtkSmartPointer<vtkTextureObject>::New();
}

//------------------------------------------------------------------------------
vtkReliefShading::~vtkReliefShading() = default;

//------------------------------------------------------------------------------
void vtkReliefShading::SetMessageOwner(vtkObject* owner)
{
  if (!this->MessageOwner)
  {
    vtkNew<vtkCallbackCommand> forward;
    forward->SetCallback(&vtkReliefShading::ForwardMessage);
    forward->SetClientData(this);
    this->AddObserver(vtkCommand::ErrorEvent, forward);
    this->AddObserver(vtkCommand::WarningEvent, forward);
  }
  this->MessageOwner = owner;
}

//------------------------------------------------------------------------------
void vtkReliefShading::ForwardMessage(vtkObject*, unsigned long event, void* self, void* text)
{
  vtkObject* owner = static_cast<vtkReliefShading*>(self)->MessageOwner;
  if (owner && owner->HasObserver(event))
  {
    owner->InvokeEvent(event, text);
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(static_cast<const char*>(text));
  }
  else
  {
    vtkOutputWindowDisplayWarningText(static_cast<const char*>(text));
  }
}

//------------------------------------------------------------------------------
const char* vtkReliefShading::GetReliefTCoordsName()
{
  return ReliefTCoordsName;
}

//------------------------------------------------------------------------------
const char* vtkReliefShading::GetMethodName(int method)
{
  if (method < 0 || method >= NumberOfMethods)
  {
    return "unknown";
  }
  return MethodNames[method];
}

//------------------------------------------------------------------------------
void vtkReliefShading::SetDepthScale(double depthScale)
{
  if (std::isnan(depthScale))
  {
    vtkErrorMacro(<< "SetDepthScale: NaN is not a depth scale; keeping " << this->DepthScale << ".");
    return;
  }
  depthScale = vtkMath::ClampValue(depthScale, 0.0, 10.0);
  if (depthScale != this->DepthScale)
  {
    this->DepthScale = depthScale;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkReliefShading::GetRequiredConeMap(int method)
{
  switch (method)
  {
    case RelaxedConeBinary:
    case RelaxedConeInterval:
      return RelaxedConeMap;
    case ConservativeCone:
      return ConservativeConeMap;
    default:
      return NoConeMap;
  }
}

//------------------------------------------------------------------------------
bool vtkReliefShading::SetMethodByName(const char* name)
{
  if (!name)
  {
    return false;
  }
  const std::string n(name);
  if (n == "steep")
  {
    this->SetMethod(LinearSearch);
    return true;
  }
  for (int m = 0; m < NumberOfMethods; ++m)
  {
    if (n == MethodNames[m])
    {
      this->SetMethod(m);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkReliefShading::UpdateLightSet(vtkOpenGLRenderWindow* renWin, vtkImageData* lights)
{
  this->HasLightSet = lights != nullptr;
  if (!lights)
  {
    return true;
  }
  vtkDataArray* values = lights->GetPointData()->GetScalars();
  if (values && values == this->LightSetUploaded &&
    values->GetMTime() <= this->LightSetUploadTime && this->LightSetTextureObject &&
    this->LightSetTextureObject->GetHandle() != 0 &&
    this->LightSetTextureObject->GetContext() == renWin)
  {
    return this->LightSetCount > 0;
  }
  this->LightSetUploaded = values;
  this->LightSetUploadTime = values ? values->GetMTime() : 0;
  this->LightSetCount = 0;
  int dims[3];
  lights->GetDimensions(dims);
  if (!values || dims[1] != 2 || dims[0] < 1 || values->GetNumberOfComponents() < 3)
  {
    vtkErrorMacro(<< "The light set must be an N x 2 image with 3 or 4 components (row 0 "
                     "directions, row 1 irradiance), as vtkMedianCutLights makes it.");
    return false;
  }
  // Sorted by luminance, strongest first, so the shader can stop at the first negligible light.
  struct Light
  {
    float Direction[3];
    float Irradiance[3];
    float Luminance;
  };
  std::vector<Light> sorted(static_cast<size_t>(dims[0]));
  for (int i = 0; i < dims[0]; ++i)
  {
    Light& light = sorted[static_cast<size_t>(i)];
    double direction[3];
    for (int c = 0; c < 3; ++c)
    {
      direction[c] = values->GetComponent(i, c);
      light.Irradiance[c] = static_cast<float>(values->GetComponent(dims[0] + i, c));
      if (!std::isfinite(direction[c]) || !std::isfinite(light.Irradiance[c]) ||
        light.Irradiance[c] < 0.0f)
      {
        vtkErrorMacro(<< "Light " << i << " of the light set has a non-finite direction or a "
                         "negative or non-finite irradiance.");
        return false;
      }
    }
    if (vtkMath::Normalize(direction) <= 0.0)
    {
      vtkErrorMacro(<< "Light " << i << " of the light set has a zero direction.");
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      light.Direction[c] = static_cast<float>(direction[c]);
    }
    light.Luminance = 0.2125f * light.Irradiance[0] + 0.7154f * light.Irradiance[1] +
      0.0721f * light.Irradiance[2];
  }
  std::sort(sorted.begin(), sorted.end(),
    [](const Light& a, const Light& b) { return a.Luminance > b.Luminance; });
  std::vector<float> texels(static_cast<size_t>(dims[0]) * 8);
  for (int i = 0; i < dims[0]; ++i)
  {
    const Light& light = sorted[static_cast<size_t>(i)];
    float* d = &texels[static_cast<size_t>(i) * 4];
    float* e = &texels[(static_cast<size_t>(dims[0]) + i) * 4];
    for (int c = 0; c < 3; ++c)
    {
      d[c] = light.Direction[c];
      e[c] = light.Irradiance[c];
    }
    d[3] = light.Luminance;
    e[3] = light.Luminance;
  }
  if (!this->LightSetTextureObject)
  {
    this->LightSetTextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->LightSetTextureObject->SetContext(renWin);
  this->LightSetTextureObject->SetMinificationFilter(vtkTextureObject::Nearest);
  this->LightSetTextureObject->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!this->LightSetTextureObject->Create2DFromRaw(
        static_cast<unsigned int>(dims[0]), 2, 4, VTK_FLOAT, texels.data()))
  {
    vtkErrorMacro(<< "Could not create the light-set texture (" << dims[0] << " lights).");
    return false;
  }
  this->LightSetCount = dims[0];
  this->LightSetMaximum = sorted.empty() ? 0.0f : sorted.front().Luminance;
  return true;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkReliefShading::PrepareInput(vtkPolyData* input)
{
  if (!input)
  {
    return nullptr;
  }
  PreparedGeometry& cached = this->Prepared[input];
  if (cached.Prepared && input->GetMTime() <= cached.SourceTime)
  {
    return cached.Prepared;
  }
  cached.Prepared = nullptr;
  cached.SourceTime = input->GetMTime();

  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro(<< "The input has no point texture coordinates (2 components). A relief surface "
                     "is addressed by texture coordinates: give the mesh tcoords, e.g. with "
                     "vtkTextureMapToPlane or from the mesh file.");
    return nullptr;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< "The input has no polygons; vtkReliefMapper draws surfaces only.");
    return nullptr;
  }
  for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
  {
    if (!std::isfinite(tcoords->GetComponent(i, 0)) || !std::isfinite(tcoords->GetComponent(i, 1)))
    {
      vtkErrorMacro(<< "Texture coordinate " << i << " is not finite (NaN or Inf).");
      return nullptr;
    }
  }

  vtkSmartPointer<vtkPolyData> mesh = input;
  if (!AllTriangles(mesh))
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(mesh);
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    mesh = triangles->GetOutput();
  }
  if (!mesh->GetPointData()->GetNormals())
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(mesh);
    normals->SplittingOff();
    normals->ConsistencyOff();
    normals->AutoOrientNormalsOff();
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->Update();
    mesh = normals->GetOutput();
  }
  vtkFloatArray* tangents = vtkFloatArray::SafeDownCast(mesh->GetPointData()->GetTangents());
  if (!tangents || tangents->GetNumberOfComponents() != 3)
  {
    vtkNew<vtkPolyDataTangents> tangentFilter;
    tangentFilter->SetInputData(mesh);
    tangentFilter->ComputePointTangentsOn();
    tangentFilter->ComputeCellTangentsOff();
    tangentFilter->Update();
    mesh = tangentFilter->GetOutput();
    vtkDataArray* computed = mesh->GetPointData()->GetTangents();
    if (!computed)
    {
      vtkErrorMacro(<< "Could not compute tangents for the input.");
      return nullptr;
    }
    // The OpenGL mapper uploads tangents only as floats.
    vtkNew<vtkFloatArray> asFloat;
    asFloat->DeepCopy(computed);
    asFloat->SetName("Tangents");
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(mesh);
    copy->GetPointData()->SetTangents(asFloat);
    mesh = copy;
  }
  else
  {
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(mesh);
    vtkNew<vtkFloatArray> own;
    own->DeepCopy(tangents);
    copy->GetPointData()->SetTangents(own);
    mesh = copy;
  }
  SanitizeFrame(mesh);
  vtkNew<vtkFloatArray> reliefTCoords;
  reliefTCoords->SetName(ReliefTCoordsName);
  reliefTCoords->SetNumberOfComponents(2);
  vtkDataArray* meshTCoords = mesh->GetPointData()->GetTCoords();
  reliefTCoords->SetNumberOfTuples(meshTCoords->GetNumberOfTuples());
  for (vtkIdType i = 0; i < meshTCoords->GetNumberOfTuples(); ++i)
  {
    reliefTCoords->SetTypedComponent(i, 0, static_cast<float>(meshTCoords->GetComponent(i, 0)));
    reliefTCoords->SetTypedComponent(i, 1, static_cast<float>(meshTCoords->GetComponent(i, 1)));
  }
  mesh->GetPointData()->AddArray(reliefTCoords);
  cached.Prepared = mesh;
  return mesh;
}

//------------------------------------------------------------------------------
void vtkReliefShading::KeepPreparedInputs(const std::vector<vtkPolyData*>& inputs)
{
  for (auto it = this->Prepared.begin(); it != this->Prepared.end();)
  {
    if (std::find(inputs.begin(), inputs.end(), it->first) == inputs.end())
    {
      it = this->Prepared.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkReliefShading::UpdateReliefTexture(vtkOpenGLRenderWindow* renWin, vtkImageData* image)
{
  // Upload again when the image changed, or when mipmaps or the pyramid are newly needed.
  const bool needPyramid = this->Method == MaximumMipmap;
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (scalars && scalars == this->ReliefTextureUploaded &&
    scalars->GetMTime() <= this->ReliefTextureUploadTime &&
    this->ReliefTextureObject->GetHandle() != 0 &&
    this->ReliefTextureObject->GetContext() == renWin &&
    this->UploadedWithMipmaps == this->LevelOfDetail && (!needPyramid || this->PyramidLevels > 0))
  {
    return this->ReliefTextureReady;
  }
  this->ReliefTextureUploaded = scalars;
  this->ReliefTextureUploadTime = scalars ? scalars->GetMTime() : 0;
  this->ReliefTextureReady = false;

  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 1 || dims[1] < 1 || !scalars || scalars->GetNumberOfTuples() < 1)
  {
    vtkErrorMacro(<< "The relief texture is empty.");
    return false;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro(<< "The relief texture must be a 2D image; it has " << dims[2] << " slices.");
    return false;
  }
  if (scalars->GetNumberOfComponents() != 4)
  {
    vtkErrorMacro(<< "The relief texture needs 4 components (normal RGB, depth A) as made by "
                     "vtkReliefTextureFilter; it has "
                  << scalars->GetNumberOfComponents() << ".");
    return false;
  }
  const bool bytes = scalars->GetDataType() == VTK_UNSIGNED_CHAR;
  this->ConeType = ConeTypeOf(image);
  this->ConePacked = this->ConeType != NoConeMap;
  const vtkIdType count = static_cast<vtkIdType>(dims[0]) * dims[1];
  std::vector<float> texels(static_cast<size_t>(count) * 4);
  std::vector<float> depth(needPyramid ? static_cast<size_t>(count) : 0);
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      double value = scalars->GetComponent(i, c);
      if (bytes)
      {
        value /= 255.0;
      }
      if (!std::isfinite(value))
      {
        vtkErrorMacro(<< "The relief texture has a non-finite value at texel " << i
                      << " (component " << c << "); NaN or Inf cannot be rendered.");
        return false;
      }
      if (c == 2 && this->ConePacked)
      {
        // Cone ratio: raw in float maps, stored as c / (1 + c) in 8-bit ones (never widened).
        value = bytes ? value / (1.0 - std::min(value, 0.999)) : std::max(value, 0.0);
      }
      else
      {
        value = vtkMath::ClampValue(value, 0.0, 1.0);
      }
      texels[static_cast<size_t>(i) * 4 + c] = static_cast<float>(value);
    }
    if (needPyramid)
    {
      depth[static_cast<size_t>(i)] = texels[static_cast<size_t>(i) * 4 + 3];
    }
  }

  this->ReliefTextureObject->SetContext(renWin);
  this->ReliefTextureObject->SetGenerateMipmap(this->LevelOfDetail);
  this->ReliefTextureObject->SetMinificationFilter(
    this->LevelOfDetail ? vtkTextureObject::LinearMipmapLinear : vtkTextureObject::Linear);
  this->ReliefTextureObject->SetMagnificationFilter(vtkTextureObject::Linear);
  this->UploadedWithMipmaps = this->LevelOfDetail;
  if (!this->ReliefTextureObject->Create2DFromRaw(
        static_cast<unsigned int>(dims[0]), static_cast<unsigned int>(dims[1]), 4, VTK_FLOAT,
        texels.data()))
  {
    vtkErrorMacro(<< "Could not create a " << dims[0] << "x" << dims[1]
                  << " float RGBA texture (too large for this OpenGL implementation?).");
    return false;
  }
  this->ReliefTextureSize[0] = dims[0];
  this->ReliefTextureSize[1] = dims[1];
  this->BakedDepthScale = -1.0;
  if (vtkDataArray* baked = image->GetFieldData()->GetArray("MesolightDepthScale"))
  {
    if (baked->GetNumberOfTuples() > 0)
    {
      this->BakedDepthScale = baked->GetComponent(0, 0);
    }
  }
  this->PyramidLevels = 0;
  if (needPyramid && !this->UpdatePyramid(renWin, depth))
  {
    return false;
  }
  this->ReliefTextureReady = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkReliefShading::UpdatePyramid(vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth)
{
  // The min-depth pyramid (filters/core/ConeMaps.h): level sizes halve rounding down, a complete
  // OpenGL mipmap, so the coarser levels upload as mip levels of one texture.
  const std::vector<std::vector<float>> levels = mesolight::ComputeMinDepthPyramid(
    depth.data(), this->ReliefTextureSize[0], this->ReliefTextureSize[1]);
  std::vector<std::pair<int, int>> sizes;
  for (size_t l = 0; l < levels.size(); ++l)
  {
    int lw = 0, lh = 0;
    mesolight::MinDepthPyramidLevelSize(
      this->ReliefTextureSize[0], this->ReliefTextureSize[1], static_cast<int>(l), lw, lh);
    sizes.emplace_back(lw, lh);
  }
  if (!this->PyramidTextureObject)
  {
    this->PyramidTextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTextureObject* pyramid = this->PyramidTextureObject;
  pyramid->SetContext(renWin);
  pyramid->SetMinificationFilter(vtkTextureObject::NearestMipmapNearest);
  pyramid->SetMagnificationFilter(vtkTextureObject::Nearest);
  pyramid->SetWrapS(vtkTextureObject::ClampToEdge);
  pyramid->SetWrapT(vtkTextureObject::ClampToEdge);
  pyramid->SetBaseLevel(0);
  pyramid->SetMaxLevel(static_cast<int>(levels.size()) - 1);
  if (!pyramid->Create2DFromRaw(static_cast<unsigned int>(sizes[0].first),
        static_cast<unsigned int>(sizes[0].second), 1, VTK_FLOAT,
        const_cast<float*>(levels[0].data())))
  {
    vtkErrorMacro(<< "Could not create the min-depth pyramid texture.");
    return false;
  }
  // vtkTextureObject uploads one level; the coarser ones are ours (minima, not averages).
  pyramid->Bind();
  // Tightly packed rows, whatever pixel-store state earlier uploads left behind.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t l = 1; l < levels.size(); ++l)
  {
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(l), GL_R32F, sizes[l].first, sizes[l].second, 0,
      GL_RED, GL_FLOAT, levels[l].data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
  if (levels.size() > 16)
  {
    vtkErrorMacro(<< "Relief textures above 32768 texels per side are not supported.");
    return false;
  }
  vtkOpenGLCheckErrorMacro("failed uploading the min-depth pyramid");
  this->PyramidLevels = static_cast<int>(levels.size());
  this->PyramidSizes.clear();
  for (const auto& size : sizes)
  {
    this->PyramidSizes.push_back(size.first);
    this->PyramidSizes.push_back(size.second);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkReliefShading::StartDraw(
  vtkOpenGLRenderWindow* renWin, vtkImageData* relief, vtkImageData* lights, vtkActor* actor)
{
  this->Drawing = false;
  if (!relief)
  {
    vtkErrorMacro(<< "No relief texture: give the mapper the output of vtkReliefTextureFilter "
                     "(or attach it to the polydata with vtkAttachReliefTexture).");
    return false;
  }
  if (!this->UpdateReliefTexture(renWin, relief) || !this->UpdateLightSet(renWin, lights))
  {
    return false;
  }
  const int requiredCones = GetRequiredConeMap(this->Method);
  if (requiredCones != NoConeMap && !this->ConePacked)
  {
    vtkErrorMacro(<< "Method '" << GetMethodName(this->Method)
                  << "' needs a relief texture with cone ratios: use vtkConeMapFilter's output.");
    return false;
  }
  if (requiredCones == ConservativeConeMap && this->ConeType == RelaxedConeMap)
  {
    vtkWarningMacro(<< "Conservative cone stepping with relaxed cones may step through the "
                       "surface; bake conservative cones for method 'cone'.");
  }
  this->HasAlbedoTexture = actor->GetTexture() != nullptr;
  const int wrap = this->RepeatTexture ? vtkTextureObject::Repeat : vtkTextureObject::ClampToEdge;
  this->ReliefTextureObject->SetWrapS(wrap);
  this->ReliefTextureObject->SetWrapT(wrap);
  this->ReliefTextureObject->Activate();
  if (this->Method == MaximumMipmap)
  {
    this->PyramidTextureObject->Activate();
  }
  if (this->HasLightSet)
  {
    this->LightSetTextureObject->Activate();
  }
  this->Drawing = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefShading::FinishDraw()
{
  if (!this->Drawing)
  {
    return;
  }
  this->ReliefTextureObject->Deactivate();
  if (this->Method == MaximumMipmap && this->PyramidTextureObject)
  {
    this->PyramidTextureObject->Deactivate();
  }
  if (this->HasLightSet)
  {
    this->LightSetTextureObject->Deactivate();
  }
  this->Drawing = false;
}

//------------------------------------------------------------------------------
std::string vtkReliefShading::ShaderKey() const
{
  return std::to_string(this->Method) + (this->SelfShadowing ? "S" : "s") +
    (this->Silhouettes ? "E" : "e") + (this->WriteDepth ? "D" : "d") +
    (this->HasAlbedoTexture ? "A" : "a") + std::to_string(this->Output) +
    (this->ConePacked ? "C" : "c") + (this->AdaptiveSteps ? "V" : "v") +
    (this->LevelOfDetail ? "L" : "l") + (this->HasLightSet ? "I" : "i") +
    (this->ToneMapping ? "T" : "t") + (this->ShadowCulling ? "K" : "k");
}

//------------------------------------------------------------------------------
bool vtkReliefShading::ShaderKeyChanged(const void* cellBO) const
{
  auto it = this->ShaderKeys.find(cellBO);
  return it == this->ShaderKeys.end() || it->second != this->ShaderKey();
}

//------------------------------------------------------------------------------
void vtkReliefShading::ReplaceShaderValuesBefore(std::string& vs, std::string& fs, bool noVTKLights)
{
  // Reserve our places before VTK fills its tags. VTK's lighting and its texture modulation at
  // the undisplaced coordinate are replaced by the relief implementation.
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
    "in vec3 tangentMC;\nuniform mat3 mlTangentMatrix;\nout vec3 mlTangentVC;\n"
    "in vec2 mlTCoordMC;\nout vec2 mlTCoordVC;\n//VTK::Normal::Dec");
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
    "mlTangentVC = mlTangentMatrix * tangentMC;\n  mlTCoordVC = mlTCoordMC;\n  //VTK::Normal::Impl");
  vtkShaderProgram::Substitute(
    fs, "//VTK::CustomUniforms::Dec", "//VTK::CustomUniforms::Dec\n//MESOLIGHT::Dec");
  vtkShaderProgram::Substitute(
    fs, "//VTK::UniformFlow::Impl", "//MESOLIGHT::UniformFlow::Impl\n  //VTK::UniformFlow::Impl");
  vtkShaderProgram::Substitute(fs, "//VTK::Light::Impl", "//MESOLIGHT::Relief::Impl");
  if (noVTKLights)
  {
    // Without VTK lights (e.g. lit only by a light set) VTK declares no normal and no view-space
    // position; the relief needs both. VTK fills these uniforms whenever a shader uses them.
    vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
      "in vec3 normalMC;\nuniform mat3 normalMatrix;\nout vec3 normalVCVSOutput;\n"
      "uniform mat4 MCVCMatrix;\nout vec4 vertexVCVSOutput;\n//VTK::Normal::Dec");
    vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
      "normalVCVSOutput = normalMatrix * normalMC;\n"
      "  vertexVCVSOutput = MCVCMatrix * vertexMC;\n  //VTK::Normal::Impl");
    vtkShaderProgram::Substitute(fs, "//VTK::Normal::Dec",
      "in vec3 normalVCVSOutput;\nin vec4 vertexVCVSOutput;\n//VTK::Normal::Dec");
    vtkShaderProgram::Substitute(fs, "//MESOLIGHT::UniformFlow::Impl",
      "vec4 vertexVC = vertexVCVSOutput;\n  //MESOLIGHT::UniformFlow::Impl");
    vtkShaderProgram::Substitute(fs, "//MESOLIGHT::Relief::Impl",
      "vec3 normalVCVSOutput = normalize(normalVCVSOutput);\n"
      "  if (gl_FrontFacing == false) { normalVCVSOutput = -normalVCVSOutput; }\n"
      "  //MESOLIGHT::Relief::Impl");
  }
  vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Impl", "");
}

//------------------------------------------------------------------------------
void vtkReliefShading::ReplaceShaderValuesAfter(std::string& fs, const void* cellBO)
{
  std::string defines = MethodDefines() + "#define ML_METHOD " + std::to_string(this->Method) + "\n" +
    "#define ML_REFINE " + std::to_string(RefinementKind(this->Method)) + "\n" +
    "#define ML_OUTPUT " + std::to_string(this->Output) + "\n";
  if (this->SelfShadowing)
  {
    defines += "#define ML_SELF_SHADOWING\n";
  }
  if (this->Silhouettes)
  {
    defines += "#define ML_SILHOUETTES\n";
  }
  if (this->WriteDepth)
  {
    defines += "#define ML_WRITE_DEPTH\n";
  }
  if (this->HasAlbedoTexture)
  {
    defines += "#define ML_ALBEDO_SAMPLER actortexture\n";
  }
  if (this->ConePacked)
  {
    defines += "#define ML_CONE_PACKED\n";
  }
  if (this->AdaptiveSteps)
  {
    defines += "#define ML_ADAPTIVE_STEPS\n";
  }
  if (this->LevelOfDetail)
  {
    defines += "#define ML_LEVEL_OF_DETAIL\n";
  }
  if (this->HasLightSet)
  {
    defines += "#define ML_LIGHT_SET\n";
  }
  if (this->ToneMapping)
  {
    defines += "#define ML_TONE_MAPPING\n";
  }
  if (!this->ShadowCulling)
  {
    defines += "#define ML_NO_SHADOW_CULLING\n";
  }
  const std::string declarations = defines +
    "in vec3 mlTangentVC;\n"
    "in vec2 mlTCoordVC;\n"
    "uniform int mlCameraParallel;\n"
    "uniform mat4 mlViewToClip;\n" +
    vtkReliefHeightFieldFS + (this->Method == MaximumMipmap ? vtkReliefMaxMipmapFS : "") +
    vtkReliefMarchFS + vtkReliefLightingFS + (this->HasLightSet ? vtkReliefLightSetFS : "");
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::Dec", declarations);
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::UniformFlow::Impl",
    "vec3 mlDPdx = dFdx(vertexVC.xyz);\n"
    "  vec3 mlDPdy = dFdy(vertexVC.xyz);\n"
    "  vec2 mlDUVdx = dFdx(mlTCoordVC);\n"
    "  vec2 mlDUVdy = dFdy(mlTCoordVC);" +
      std::string(this->LevelOfDetail
          ? "\n  mlMarchLod = max(0.0, log2(max(length(mlDUVdx * mlTextureSize), "
            "length(mlDUVdy * mlTextureSize))));"
          : ""));
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::Relief::Impl", vtkReliefImplFS);

  this->ShaderKeys[cellBO] = this->ShaderKey();

  if (const char* dump = std::getenv("MESOLIGHT_DUMP_SHADERS"))
  {
    if (dump[0] != '\0' && dump[0] != '0')
    {
      std::cerr << "==== relief fragment shader ====\n" << fs << std::endl;
    }
  }
}

//------------------------------------------------------------------------------
void vtkReliefShading::SetShaderParameters(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor)
{
  if (!program)
  {
    return;
  }
  program->SetUniformi("mlReliefTexture", this->ReliefTextureObject->GetTextureUnit());
  program->SetUniformf("mlDepthScale", static_cast<float>(this->DepthScale));
  // Normals baked with another depth scale are rescaled through the depth gradient.
  const double baked = this->BakedDepthScale >= 0.0 ? this->BakedDepthScale : this->DepthScale;
  program->SetUniformf("mlGradientScale", baked > 0.0 ? static_cast<float>(1.0 / baked) : 0.0f);
  program->SetUniformf("mlTexelAspect",
    this->ReliefTextureSize[0] > 0
      ? static_cast<float>(this->ReliefTextureSize[1]) / this->ReliefTextureSize[0]
      : 1.0f);
  program->SetUniformi("mlLinearSteps", this->LinearSteps);
  program->SetUniformi("mlRefinementSteps", this->RefinementSteps);
  program->SetUniformi("mlMinimumSteps", std::min(this->MinimumSteps, this->LinearSteps));
  const float textureSize[2] = { static_cast<float>(this->ReliefTextureSize[0]),
    static_cast<float>(this->ReliefTextureSize[1]) };
  program->SetUniform2f("mlTextureSize", textureSize);
  if (this->Method == MaximumMipmap && this->PyramidTextureObject)
  {
    program->SetUniformi("mlMinDepthPyramid", this->PyramidTextureObject->GetTextureUnit());
    program->SetUniformi("mlPyramidLevels", this->PyramidLevels);
    program->SetUniform1iv("mlPyramidSizes", static_cast<int>(this->PyramidSizes.size()),
      this->PyramidSizes.data());
  }

  vtkCamera* camera = ren->GetActiveCamera();
  program->SetUniformi("mlCameraParallel", camera->GetParallelProjection());
  vtkMatrix4x4* projection =
    camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1);
  float columnMajor[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[c * 4 + r] = static_cast<float>(projection->GetElement(r, c));
    }
  }
  program->SetUniformMatrix4x4("mlViewToClip", columnMajor);

  // Tangents are surface directions: transform them with the linear part of model-view.
  vtkNew<vtkMatrix4x4> modelView;
  vtkMatrix4x4::Multiply4x4(camera->GetViewTransformMatrix(), actor->GetMatrix(), modelView);
  float tangentMatrix[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      tangentMatrix[c * 3 + r] = static_cast<float>(modelView->GetElement(r, c));
    }
  }
  program->SetUniformMatrix3x3("mlTangentMatrix", tangentMatrix);

  vtkProperty* property = actor->GetProperty();
  const double* sc = property->GetSpecularColor();
  const float specular[3] = { static_cast<float>(property->GetSpecular() * sc[0]),
    static_cast<float>(property->GetSpecular() * sc[1]),
    static_cast<float>(property->GetSpecular() * sc[2]) };
  program->SetUniform3f("mlSpecularColor", specular);
  program->SetUniformf("mlSpecularPower", static_cast<float>(property->GetSpecularPower()));
  program->SetUniformf("mlExposure", static_cast<float>(this->Exposure));
  if (this->HasLightSet)
  {
    program->SetUniformi("mlLightSet", this->LightSetTextureObject->GetTextureUnit());
    program->SetUniformi("mlLightSetCount", this->LightSetCount);
    program->SetUniformf("mlLightSetCutoff",
      static_cast<float>(this->LightSetThreshold * this->LightSetMaximum));
    program->SetUniformi("mlShadowedLights", this->ShadowedLights);
    float worldToView[9];
    vtkMatrix4x4* view = camera->GetViewTransformMatrix();
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        worldToView[c * 3 + r] = static_cast<float>(view->GetElement(r, c));
      }
    }
    program->SetUniformMatrix3x3("mlWorldToView", worldToView);
  }

  this->SetLightUniforms(program, ren);
}

//------------------------------------------------------------------------------
void vtkReliefShading::SetLightUniforms(vtkShaderProgram* program, vtkRenderer* ren)
{
  float color[MaximumNumberOfLights][3] = {};
  float direction[MaximumNumberOfLights][3] = {};
  float position[MaximumNumberOfLights][3] = {};
  float attenuation[MaximumNumberOfLights][3] = {};
  float coneAngle[MaximumNumberOfLights] = {};
  float exponent[MaximumNumberOfLights] = {};
  int positional[MaximumNumberOfLights] = {};

  vtkMatrix4x4* view = ren->GetActiveCamera()->GetViewTransformMatrix();
  int count = 0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* lights = ren->GetLights();
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    if (count == MaximumNumberOfLights)
    {
      if (!this->WarnedTooManyLights)
      {
        vtkWarningMacro(<< "More than " << MaximumNumberOfLights
                        << " lights are switched on; vtkReliefMapper shades the first "
                        << MaximumNumberOfLights << ".");
        this->WarnedTooManyLights = true;
      }
      break;
    }
    const double intensity = light->GetIntensity();
    const double* diffuse = light->GetDiffuseColor();
    double lp[4] = { 0, 0, 0, 1 };
    double lfp[3];
    light->GetTransformedPosition(lp);
    light->GetTransformedFocalPoint(lfp);
    double dirWC[3] = { lfp[0] - lp[0], lfp[1] - lp[1], lfp[2] - lp[2] };
    vtkMath::Normalize(dirWC);
    double posVC[4];
    view->MultiplyPoint(lp, posVC);
    for (int k = 0; k < 3; ++k)
    {
      color[count][k] = static_cast<float>(diffuse[k] * intensity);
      direction[count][k] = static_cast<float>(view->GetElement(k, 0) * dirWC[0] +
        view->GetElement(k, 1) * dirWC[1] + view->GetElement(k, 2) * dirWC[2]);
      position[count][k] = static_cast<float>(posVC[k]);
      attenuation[count][k] = static_cast<float>(light->GetAttenuationValues()[k]);
    }
    coneAngle[count] = static_cast<float>(light->GetConeAngle());
    exponent[count] = static_cast<float>(light->GetExponent());
    positional[count] = light->GetPositional();
    ++count;
  }
  program->SetUniformi("mlNumberOfLights", count);
  program->SetUniform3fv("mlLightColor", MaximumNumberOfLights, color);
  program->SetUniform3fv("mlLightDirectionVC", MaximumNumberOfLights, direction);
  program->SetUniform3fv("mlLightPositionVC", MaximumNumberOfLights, position);
  program->SetUniform3fv("mlLightAttenuation", MaximumNumberOfLights, attenuation);
  program->SetUniform1fv("mlLightConeAngle", MaximumNumberOfLights, coneAngle);
  program->SetUniform1fv("mlLightExponent", MaximumNumberOfLights, exponent);
  program->SetUniform1iv("mlLightPositional", MaximumNumberOfLights, positional);
}

//------------------------------------------------------------------------------
void vtkReliefShading::ReleaseGraphicsResources(vtkWindow* win)
{
  this->ReliefTextureObject->ReleaseGraphicsResources(win);
  if (this->PyramidTextureObject)
  {
    this->PyramidTextureObject->ReleaseGraphicsResources(win);
  }
  if (this->LightSetTextureObject)
  {
    this->LightSetTextureObject->ReleaseGraphicsResources(win);
  }
  this->PyramidLevels = 0;
  this->ReliefTextureUploaded = nullptr;
  this->LightSetUploaded = nullptr;
  this->ShaderKeys.clear();
}

//------------------------------------------------------------------------------
void vtkReliefShading::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "LinearSteps: " << this->LinearSteps << "\n";
  os << indent << "RefinementSteps: " << this->RefinementSteps << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "SelfShadowing: " << (this->SelfShadowing ? "On" : "Off") << "\n";
  os << indent << "Silhouettes: " << (this->Silhouettes ? "On" : "Off") << "\n";
  os << indent << "WriteDepth: " << (this->WriteDepth ? "On" : "Off") << "\n";
  os << indent << "RepeatTexture: " << (this->RepeatTexture ? "On" : "Off") << "\n";
  os << indent << "Output: " << this->Output << "\n";
  os << indent << "AdaptiveSteps: " << (this->AdaptiveSteps ? "On" : "Off") << "\n";
  os << indent << "MinimumSteps: " << this->MinimumSteps << "\n";
  os << indent << "LevelOfDetail: " << (this->LevelOfDetail ? "On" : "Off") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << (this->ToneMapping ? "On" : "Off") << "\n";
  os << indent << "LightSetThreshold: " << this->LightSetThreshold << "\n";
  os << indent << "ShadowedLights: " << this->ShadowedLights << "\n";
  os << indent << "ShadowCulling: " << (this->ShadowCulling ? "On" : "Off") << "\n";
}
