// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefShaderSource.h"

#include "vtkMinDepthPyramidTexture.h"
#include "vtkObjectFactory.h"
#include "vtkReliefProperty.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h" // for vtkMinDepthPyramidTexture's smart pointer

// GLSL sources embedded at build time (vtk_encode_string).
#include "mlEncodeSrgbFS.h"
#include "vtkReliefHeightFieldFS.h"
#include "vtkReliefImplFS.h"
#include "vtkReliefIrradianceProbesFS.h"
#include "vtkReliefLightSetFS.h"
#include "vtkReliefLightingFS.h"
#include "vtkReliefMarchFS.h"
#include "vtkReliefMaxMipmapFS.h"

#include <cstdlib>
#include <functional> // std::hash of a radiance hook's source
#include <iostream>
#include <string>

vtkStandardNewMacro(vtkReliefShaderSource);

namespace
{
// Compile-time refinement of the march per method (see vtkReliefMarchFS.glsl, ML_REFINE).
int RefinementKind(int method)
{
  switch (method)
  {
    case vtkReliefProperty::Relief:
      return 2; // binary search
    case vtkReliefProperty::ParallaxOcclusion:
      return 1; // one secant step
    default:
      return 0;
  }
}

// GLSL names of the methods, so the shader reads "#if ML_METHOD == ML_RELIEF".
std::string MethodDefines()
{
  const char* const glslNames[] = { "ML_TEXTURE_MAPPING", "ML_BUMP", "ML_PARALLAX",
    "ML_PARALLAX_OFFSET_LIMITING", "ML_PARALLAX_SLOPE", "ML_ITERATIVE_PARALLAX", "ML_BINARY_SEARCH",
    "ML_SECANT", "ML_LINEAR_SEARCH", "ML_PARALLAX_OCCLUSION", "ML_RELIEF", "ML_INTERVAL",
    "ML_RELAXED_CONE_BINARY", "ML_RELAXED_CONE_INTERVAL", "ML_CONSERVATIVE_CONE",
    "ML_MAXIMUM_MIPMAP" };
  static_assert(sizeof(glslNames) / sizeof(glslNames[0]) == vtkReliefProperty::NumberOfMethods,
    "one GLSL name per method");
  std::string defines;
  for (int m = 0; m < vtkReliefProperty::NumberOfMethods; ++m)
  {
    defines += std::string("#define ") + glslNames[m] + " " + std::to_string(m) + "\n";
  }
  return defines;
}
} // namespace

//------------------------------------------------------------------------------
vtkReliefShaderSource::vtkReliefShaderSource()
{
  this->Property = vtkSmartPointer<vtkReliefProperty>::New();
}

//------------------------------------------------------------------------------
vtkReliefShaderSource::~vtkReliefShaderSource() = default;

//------------------------------------------------------------------------------
void vtkReliefShaderSource::Configure(vtkReliefProperty* property, bool albedoTexture,
  bool conePacked, bool lightSet, bool irradianceProbes)
{
  this->Property = property;
  this->HasAlbedoTexture = albedoTexture;
  this->ConePacked = conePacked;
  this->HasLightSet = lightSet;
  this->HasIrradianceProbes = irradianceProbes;
}

//------------------------------------------------------------------------------
void vtkReliefShaderSource::SetTextureLayout(
  bool floatTextures, bool storedNormals, bool moments, bool normalsFromDepth)
{
  this->NormalsFromDepth = normalsFromDepth;
  this->NormalMoments = moments;
  this->FloatTextures = floatTextures;
  this->StoredNormals = storedNormals;
}

//------------------------------------------------------------------------------
int vtkReliefShaderSource::GetMarchMethod(vtkReliefProperty* property, bool curvedGeometry)
{
  const int method = property->GetMethod();
  return method == vtkReliefProperty::MaximumMipmap && curvedGeometry &&
      property->GetSurfaceCurvature()
    ? vtkReliefProperty::Relief
    : method;
}

//------------------------------------------------------------------------------
bool vtkReliefShaderSource::GetCurved() const
{
  // The methods whose search steps along the ray (linear or cone steps, then refinement): the
  // quadric lowers the ray at every step and a ray that leaves the layer is known as a miss.
  switch (GetMarchMethod(this->Property, this->CurvedGeometry))
  {
    case vtkReliefProperty::LinearSearch:
    case vtkReliefProperty::ParallaxOcclusion:
    case vtkReliefProperty::Relief:
    case vtkReliefProperty::Interval:
    case vtkReliefProperty::RelaxedConeBinary:
    case vtkReliefProperty::RelaxedConeInterval:
    case vtkReliefProperty::ConservativeCone:
      return this->CurvedGeometry && this->Property->GetSurfaceCurvature();
    default:
      return false;
  }
}

//------------------------------------------------------------------------------
std::string vtkReliefShaderSource::Key() const
{
  vtkReliefProperty* p = this->Property;
  return std::to_string(p->GetMethod()) + (p->GetSelfShadowing() ? "S" : "s") +
    (p->GetSilhouettes() ? "E" : "e") +
    (p->GetWriteDepth() ? (p->GetHasDepthLimitPlane() ? "Z" : "D") : "d") +
    (this->HasAlbedoTexture ? "A" : "a") + std::to_string(p->GetOutput()) +
    (this->ConePacked ? "C" : "c") + (p->GetAdaptiveSteps() ? "V" : "v") +
    (p->GetLevelOfDetail() ? "L" : "l") + (this->HasLightSet ? "I" : "i") +
    (p->GetToneMapping() ? "T" : "t") + (p->GetShadowCulling() ? "K" : "k") +
    (this->HasIrradianceProbes ? "P" : "p") + (p->GetEncodeSRGB() ? "G" : "g") +
    (this->NormalMoments && p->GetLevelOfDetail()
        ? (p->GetNormalFilter() == vtkReliefProperty::MaskedNormalFilter       ? "H"
              : p->GetNormalFilter() == vtkReliefProperty::VisibleNormalFilter ? "M"
                                                                               : "W") +
          std::to_string(p->GetFarViewRays())
        : "m") +
    (this->GetCurved() ? "Q" : "q") +
    (this->FloatTextures      ? "F"
        : this->StoredNormals ? "N"
                              : "f") +
    (this->NormalsFromDepth ? "S" : "s") + this->RadianceHookKey;
}

//------------------------------------------------------------------------------
void vtkReliefShaderSource::SetRadianceHookSource(const std::string& source)
{
  // Called on every draw: the copy and its hash only when the source changes.
  if (source != this->RadianceHookSource)
  {
    this->RadianceHookSource = source;
    this->RadianceHookKey =
      source.empty() ? std::string("r") : "R" + std::to_string(std::hash<std::string>()(source));
  }
}

//------------------------------------------------------------------------------
bool vtkReliefShaderSource::KeyChanged(const void* cellBO) const
{
  auto it = this->Keys.find(cellBO);
  return it == this->Keys.end() || it->second != this->Key();
}

//------------------------------------------------------------------------------
void vtkReliefShaderSource::ReplaceValuesBefore(std::string& vs, std::string& fs, bool noVTKLights)
{
  // Reserve our places before VTK fills its tags. VTK's lighting and its texture modulation at
  // the undisplaced coordinate are replaced by the relief implementation.
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
    "in vec3 tangentMC;\nuniform mat3 mlTangentMatrix;\nout vec3 mlTangentVC;\n"
    "in vec2 mlTCoordMC;\nout vec2 mlTCoordVC;\n//VTK::Normal::Dec");
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
    "mlTangentVC = mlTangentMatrix * tangentMC;\n  mlTCoordVC = mlTCoordMC;\n  "
    "//VTK::Normal::Impl");
  // A radiance hook's declarations come after the relief's own (which they may use), before main.
  vtkShaderProgram::Substitute(fs, "//VTK::CustomUniforms::Dec",
    "//VTK::CustomUniforms::Dec\n//MESOLIGHT::Dec\n" + this->RadianceHookSource);
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
  if (this->GetCurved())
  {
    // The per-vertex quadric (a, b) of the curved mesh, interpolated like the tangent.
    vtkShaderProgram::Substitute(
      vs, "//VTK::Normal::Dec", "in vec2 mlQuadricMC;\nout vec2 mlQuadricVC;\n//VTK::Normal::Dec");
    vtkShaderProgram::Substitute(
      vs, "//VTK::Normal::Impl", "mlQuadricVC = mlQuadricMC;\n  //VTK::Normal::Impl");
  }
  vtkShaderProgram::Substitute(fs, "//VTK::TCoord::Impl", "");
}

//------------------------------------------------------------------------------
void vtkReliefShaderSource::ReplaceValuesAfter(std::string& fs, const void* cellBO)
{
  vtkReliefProperty* p = this->Property;
  const int method = GetMarchMethod(p, this->CurvedGeometry);
  std::string defines = MethodDefines() + "#define ML_METHOD " + std::to_string(method) +
    "\n#define ML_REFINE " + std::to_string(RefinementKind(method)) + "\n" + "#define ML_OUTPUT " +
    std::to_string(p->GetOutput()) + "\n";
  if (method == vtkReliefProperty::MaximumMipmap)
  {
    defines += "#define ML_PYRAMID_FIRST_LEVEL " +
      std::to_string(vtkMinDepthPyramidTexture::FirstLevel) + "\n";
  }
  if (!this->FloatTextures &&
    (method == vtkReliefProperty::MaximumMipmap || this->NormalsFromDepth))
  {
    // mlTexelQuad gathers four depth texels at once (GLSL 4.00; VTK declares 1.50): the
    // maximum-mipmap march's cell corners, the surface's cells and gradient.
    vtkShaderProgram::Substitute(
      fs, "//VTK::System::Dec", "//VTK::System::Dec\n#extension GL_ARB_texture_gather : require\n");
    defines += "#define ML_TEXEL_GATHER\n";
  }
  if (p->GetSelfShadowing())
  {
    defines += "#define ML_SELF_SHADOWING\n";
  }
  if (p->GetSilhouettes())
  {
    defines += "#define ML_SILHOUETTES\n";
  }
  if (p->GetWriteDepth())
  {
    defines += "#define ML_WRITE_DEPTH\n";
    if (p->GetHasDepthLimitPlane())
    {
      defines += "#define ML_DEPTH_LIMIT\n";
    }
  }
  if (this->GetCurved())
  {
    defines += "#define ML_CURVED\nin vec2 mlQuadricVC;\n";
  }
  if (this->HasAlbedoTexture)
  {
    defines += "#define ML_ALBEDO_SAMPLER actortexture\n";
  }
  if (this->ConePacked)
  {
    defines += "#define ML_CONE_PACKED\n";
  }
  if (this->FloatTextures)
  {
    defines += "#define ML_FLOAT_TEXTURES\n";
  }
  else if (this->StoredNormals)
  {
    defines += "#define ML_STORED_NORMALS\n";
  }
  if (this->NormalsFromDepth)
  {
    defines += "#define ML_SURFACE_NORMALS\n";
  }
  if (p->GetAdaptiveSteps())
  {
    defines += "#define ML_ADAPTIVE_STEPS\n";
  }
  if (p->GetLevelOfDetail())
  {
    defines += "#define ML_LEVEL_OF_DETAIL\n";
    if (this->NormalMoments)
    {
      // Every normal filter reads the footprint's normals from their moments: the mean filter
      // their plain mean (Toksvig's, ML_MEAN_NORMALS), the others the visible one.
      defines += "#define ML_NORMAL_MOMENTS\n";
      const int filter = p->GetNormalFilter();
      if (filter == vtkReliefProperty::MeanNormalFilter)
      {
        defines += "#define ML_MEAN_NORMALS\n";
      }
      else if (filter == vtkReliefProperty::MaskedNormalFilter)
      {
        defines += "#define ML_MASKED_FACETS\n";
      }
      const int output = p->GetOutput();
      // An odd count, so that one ray passes through the pixel's centre; with the visible
      // filters (FarViewRays), the mean filter keeping one ray as Toksvig's filter does.
      const int rays =
        filter == vtkReliefProperty::MeanNormalFilter ? 1 : (p->GetFarViewRays() - 1) | 1;
      if (rays > 1 &&
        (output == vtkReliefProperty::ShadedOutput ||
          output == vtkReliefProperty::SampleCountOutput))
      {
        // Several view rays per far pixel (vtkReliefImplFS.glsl), their colours averaged: only
        // where the output is a colour (or the samples it costs), not a hit coordinate.
        defines += "#define ML_FAR_RAYS " + std::to_string(rays) + "\n";
      }
    }
  }
  if (this->HasLightSet)
  {
    defines += "#define ML_LIGHT_SET\n";
  }
  if (this->HasIrradianceProbes)
  {
    defines += "#define ML_IRRADIANCE_PROBES\n";
  }
  if (p->GetToneMapping())
  {
    defines += "#define ML_TONE_MAPPING\n";
  }
  if (p->GetEncodeSRGB())
  {
    defines += "#define ML_ENCODE_SRGB\n";
  }
  if (!p->GetShadowCulling())
  {
    defines += "#define ML_NO_SHADOW_CULLING\n";
  }
  const std::string declarations = defines +
    "in vec3 mlTangentVC;\n"
    "in vec2 mlTCoordVC;\n"
    "uniform int mlCameraParallel;\n"
    "uniform mat4 mlViewToClip;\n" +
    std::string(p->GetWriteDepth() && p->GetHasDepthLimitPlane()
        ? "uniform vec4 mlDepthLimitVC; // view coordinates: normal, offset (n . x + w = 0)\n"
        : "") +
    vtkReliefHeightFieldFS +
    (method == vtkReliefProperty::MaximumMipmap ? vtkReliefMaxMipmapFS : "") + vtkReliefMarchFS +
    vtkReliefLightingFS + (this->HasLightSet ? vtkReliefLightSetFS : "") +
    (this->HasIrradianceProbes ? vtkReliefIrradianceProbesFS : "") +
    (p->GetEncodeSRGB() ? mlEncodeSrgbFS : "");
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::Dec", declarations);
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::UniformFlow::Impl",
    "vec3 mlDPdx = dFdx(vertexVC.xyz);\n"
    "  vec3 mlDPdy = dFdy(vertexVC.xyz);\n"
    "  vec2 mlDUVdx = dFdx(mlTCoordVC);\n"
    "  vec2 mlDUVdy = dFdy(mlTCoordVC);" +
      std::string(p->GetLevelOfDetail()
          // Mean normal filter: footprint area -> level, one level finer than the area's, as
          // trilinear filtering blends in the next coarser level (measured best of -2..0 on
          // Stone and Bricks). Anisotropic taps along the footprint's major axis were measured
          // worse at 80 degrees (4.03 against 3.42 levels): at grazing views the texels facing
          // away are hidden, and the longer average takes them in. Visible normal filter: the
          // level of the footprint's minor axis (area over the longer screen axis), half a level
          // finer; measured on two real maps at 45 and 80 degrees against the area's level
          // -1.5..0 (docs/relief-methods.md, "Aliasing").
          ? "\n  mlFootprint = sqrt(abs(mlDUVdx.x * mlDUVdy.y - mlDUVdx.y * mlDUVdy.x) * "
            "mlTextureSize.x * mlTextureSize.y);" +
            std::string(
              this->NormalMoments && p->GetNormalFilter() != vtkReliefProperty::MeanNormalFilter
                ? "\n  mlShadeLod = max(0.0, -0.5 + log2(max(mlFootprint * mlFootprint / "
                  "max(max(length(mlDUVdx * mlTextureSize), length(mlDUVdy * mlTextureSize)), "
                  "1e-30), 1e-30)));"
                : "\n  mlShadeLod = max(0.0, -1.0 + log2(max(mlFootprint, 1e-30)));")
          : ""));
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::Relief::Impl", vtkReliefImplFS);

  this->Keys[cellBO] = this->Key();

  if (const char* dump = std::getenv("MESOLIGHT_DUMP_SHADERS"))
  {
    if (dump[0] != '\0' && dump[0] != '0')
    {
      std::cerr << "==== relief fragment shader ====\n" << fs << std::endl;
    }
  }
}

//------------------------------------------------------------------------------
void vtkReliefShaderSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Variant: " << this->Key() << "\n";
  os << indent << "Shaders: " << this->Keys.size() << "\n";
}
