// SPDX-License-Identifier: BSD-3-Clause
#include "ImageCommands.h"

#include "CommandLine.h"
#include "OutputFile.h"
#include "Timing.h"

#include "EnvironmentMaps.h"
#include "SrtmHeightFile.h"
#include "vtkConeMapFilter.h"
#include "vtkLightProbeToLatLong.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"
#include "vtkReliefTextureFilter.h"
#include "vtkUnitScale.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace mesolight
{

namespace
{
RgbImage ToRgb(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  RgbImage rgb(dims[0], dims[1]);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(dims[0]) * dims[1]; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb.Rgb[3 * p + c] = static_cast<float>(
        values->GetComponent(p, std::min(c, values->GetNumberOfComponents() - 1)));
    }
  }
  return rgb;
}
} // namespace

int RunBakeCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bake",
    "mesolight bake DEPTH_IMAGE --out RELIEF_IMAGE [options]\n\nBakes a relief "
    "texture: Sobel normals (packed (n+1)/2) in RGB, depth in A\n(0 = top, 1 = "
    "deepest).\n");
  cl.AddValue("--out", "RELIEF_IMAGE", "relief texture to write (.exr/.tif float, .png 8/16-bit)");
  cl.AddValue("--depth-scale", "K", "relief depth as a fraction of the texture width", "0.04");
  cl.AddValue("--border", "MODE", "clamp or wrap (tiling maps)", "clamp");
  cl.AddFlag("--height", "the input stores height (white = high) rather than depth");
  cl.AddFlag("--normalize", "stretch the input's value range to [0, 1]");
  cl.AddValue("--no-data", "VALUE", CommandLine::NoDataHelp);
  cl.AddValue("--vertical-exaggeration", "E", CommandLine::VerticalExaggerationHelp);
  cl.AddValue("--bits", "N", "8 or 16 bits per channel for PNG/TIFF output", "8");
  cl.AddValue("--memory-budget", "GIB", "refuse images needing more memory (0: all there is)", "0");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (cl.Positional().size() != 1 || !cl.Has("--out"))
  {
    return cl.UsageError("usage: mesolight bake DEPTH_IMAGE --out RELIEF_IMAGE");
  }
  const std::string in = cl.Positional()[0];
  const std::string out = cl.Get("--out");
  double depthScale = 0.04;
  int bits = 8;
  double budget = 0.0;
  CommandLine::NoDataOption noData;
  double exaggeration = 0.0;
  if (!cl.GetDouble("--depth-scale", 0.0, 100.0, depthScale, error) ||
    !cl.GetInt("--bits", 8, 16, bits, error) ||
    !cl.GetDouble("--memory-budget", 0.0, 1e6, budget, error) ||
    !cl.GetNoData("--no-data", noData, error) ||
    (cl.Has("--vertical-exaggeration") &&
      (!cl.GetDouble("--vertical-exaggeration", 1e-6, 1000.0, exaggeration, error) ||
        !CommandLine::CheckVerticalExaggeration(cl, error))))
  {
    return cl.UsageError(error);
  }
  if (bits != 8 && bits != 16)
  {
    return cl.UsageError("--bits must be 8 or 16");
  }
  const std::string border = cl.Get("--border");
  if (border != "clamp" && border != "wrap")
  {
    return cl.UsageError("--border must be clamp or wrap");
  }
  const std::string problem = CheckOutputFile(out, { in });
  if (!problem.empty())
  {
    return cl.UsageError("--out: " + problem);
  }
  const std::string format =
    CheckOutputExtension(cl, { "--out" }, { ".exr", ".tif", ".tiff", ".png" },
      "a relief texture holds its depth in alpha, which JPEG and the like drop");
  if (!format.empty())
  {
    return cl.UsageError(format);
  }

  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(in.c_str());
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputConnection(reader->GetOutputPort());
  bake->SetDepthScale(depthScale);
  bake->SetInvertInput(cl.Has("--height"));
  bake->SetNormalizeRange(cl.Has("--normalize"));
  bake->SetUseNoDataValue(noData.Use);
  bake->SetNoDataValue(noData.Value);
  bake->SetUseInputNoDataValue(noData.UseFileValue);
  bake->SetUseTrueDepthScale(exaggeration > 0.0);
  bake->SetVerticalExaggeration(exaggeration);
  bake->SetMemoryBudget(static_cast<vtkTypeInt64>(budget * 1073741824.0));
  if (border == "wrap")
  {
    bake->SetBorderModeToWrap();
  }
  else
  {
    bake->SetBorderModeToClamp();
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(bake->GetOutputPort());
  writer->SetFileName(out.c_str());
  writer->SetBitDepth(bits);
  // Errors from any stage are reported by VTK on stderr; the exit code tells the caller.
  bake->Update();
  if (bake->GetOutput()->GetNumberOfPoints() == 0 || reader->GetErrorCode() != 0)
  {
    std::cerr << "mesolight bake: could not bake " << in << "\n";
    return 1;
  }
  if (!writer->Write())
  {
    std::cerr << "mesolight bake: could not write " << out << "\n";
    return 1;
  }
  ReportFileNoDataValue(in, !noData.Use && noData.UseFileValue);
  ReportTrueDepthScale(in, bake->GetOutput());
  int dims[3];
  bake->GetOutput()->GetDimensions(dims);
  std::cout << "wrote " << out << " (" << dims[0] << "x" << dims[1]
            << " relief texture, depth scale " << bake->GetAppliedDepthScale() << ")\n";
  return 0;
}

void ReportFileNoDataValue(const std::string& file, bool applied)
{
  if (!applied || file.empty())
  {
    return;
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.c_str());
  reader->UpdateInformation();
  if (reader->GetHasNoDataValue())
  {
    std::cout << file << " names the no-data value " << reader->GetNoDataValue()
              << (IsSrtmHeightFileName(file) ? " (SRTM voids)" : " (GDAL_NODATA)")
              << ": its texels are drawn as the lowest ground (--no-data none: as elevations)\n";
  }
}

void ReportTrueDepthScale(const std::string& file, vtkImageData* relief)
{
  vtkFieldData* fields = relief ? relief->GetFieldData() : nullptr;
  vtkDataArray* trueScale = fields ? fields->GetArray("MesolightTrueDepthScale") : nullptr;
  vtkDataArray* drawn = fields ? fields->GetArray("MesolightDepthScale") : nullptr;
  if (!trueScale || !drawn || trueScale->GetNumberOfTuples() != 1 ||
    drawn->GetNumberOfTuples() != 1)
  {
    return;
  }
  const double t = trueScale->GetComponent(0, 0);
  const double d = drawn->GetComponent(0, 0);
  std::ostringstream text;
  text << std::setprecision(3) << file
       << " is georeferenced: its true vertical scale is depth scale " << t << "; drawn at " << d
       << ", " << d / t
       << " times exaggerated (--vertical-exaggeration E: E times the true scale)\n";
  std::cout << text.str();
}

int RunConeCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight cone",
    "mesolight cone DEPTH_IMAGE --out FILE.exr [options]\n\nBakes a cone-packed relief "
    "texture for cone stepping: R,G normal x, y packed (n+1)/2,\nB cone ratio "
    "(width / height), A depth (0 top .. 1 deepest).\n");
  cl.AddValue(
    "--out", "FILE", "cone map to write (.exr: float RGBA = normal x, y; cone ratio; depth)");
  cl.AddValue("--type", "TYPE", "relaxed or conservative", "relaxed");
  cl.AddValue("--depth-scale", "K", "relief depth as a fraction of the texture width", "0.04");
  cl.AddValue("--border", "MODE", "clamp or wrap (tiling maps)", "clamp");
  cl.AddFlag("--height", "the input stores height (white = high) rather than depth");
  cl.AddFlag("--normalize", "stretch the input's value range to [0, 1]");
  cl.AddValue("--no-data", "VALUE", CommandLine::NoDataHelp);
  cl.AddFlag("--8bit", "the relief thesis' 8-bit packing (cone as c / (1 + c)) instead of float");
  cl.AddValue("--memory-budget", "GIB", "refuse images needing more memory (0: all there is)", "0");
  std::string error;
  double depthScale = 0.04;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  double budget = 0.0;
  CommandLine::NoDataOption noData;
  if (!cl.GetDouble("--depth-scale", 0.0, 100.0, depthScale, error) ||
    !cl.GetDouble("--memory-budget", 0.0, 1e6, budget, error) ||
    !cl.GetNoData("--no-data", noData, error))
  {
    return cl.UsageError(error);
  }
  const std::string type = cl.Get("--type");
  const std::string border = cl.Get("--border");
  if (cl.Positional().size() != 1 || !cl.Has("--out") ||
    (type != "relaxed" && type != "conservative") || (border != "clamp" && border != "wrap"))
  {
    std::cerr << "mesolight cone: usage: mesolight cone DEPTH_IMAGE --out FILE.exr "
                 "[--type relaxed|conservative] [--border clamp|wrap]\n";
    return 2;
  }
  const std::string in = cl.Positional()[0];
  const std::string out = cl.Get("--out");
  const std::string problem = CheckOutputFile(out, { in });
  if (!problem.empty())
  {
    return cl.UsageError("--out: " + problem);
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(in.c_str());
  vtkNew<vtkConeMapFilter> cones;
  cones->SetInputConnection(reader->GetOutputPort());
  cones->SetDepthScale(depthScale);
  cones->SetInvertInput(cl.Has("--height"));
  cones->SetNormalizeRange(cl.Has("--normalize"));
  cones->SetUseNoDataValue(noData.Use);
  cones->SetNoDataValue(noData.Value);
  cones->SetUseInputNoDataValue(noData.UseFileValue);
  cones->SetMemoryBudget(static_cast<vtkTypeInt64>(budget * 1073741824.0));
  cones->SetBorderMode(border == "wrap" ? 1 : 0);
  cones->SetConeType(
    type == "conservative" ? vtkConeMapFilter::CONSERVATIVE : vtkConeMapFilter::RELAXED);
  cones->SetPacking(cl.Has("--8bit") ? vtkConeMapFilter::RATIO_8BIT : vtkConeMapFilter::FLOAT);
  const auto start = std::chrono::steady_clock::now();
  cones->Update();
  const double seconds = SecondsSince(start);
  if (cones->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "mesolight cone: could not make a cone map of " << in << "\n";
    return 1;
  }
  {
    // Integer formats (PNG, TIFF...) store [0, 1]: float-packed cone ratios above 1 are clamped
    // there (narrower cones: still valid, but slower stepping). Say so, and what keeps them.
    vtkDataArray* packed = cones->GetOutput()->GetPointData()->GetScalars();
    if (!cl.Has("--8bit") && !HasExtension(out, ".exr") && !HasExtension(out, ".hdr") && packed)
    {
      vtkIdType clamped = 0;
      double largest = 0.0;
      for (vtkIdType i = 0; i < packed->GetNumberOfTuples(); ++i)
      {
        const double ratio = packed->GetComponent(i, 2);
        clamped += ratio > 1.0 ? 1 : 0;
        largest = std::max(largest, ratio);
      }
      if (clamped > 0)
      {
        std::cerr << "mesolight cone: warning: " << clamped << " of " << packed->GetNumberOfTuples()
                  << " cone ratios exceed 1 (up to " << largest << ") and are clamped to 1 in '"
                  << out << "'; write .exr to keep them, or use --8bit\n";
      }
    }
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(cones->GetOutputPort());
  writer->SetFileName(out.c_str());
  if (!writer->Write())
  {
    std::cerr << "mesolight cone: could not write " << out << "\n";
    return 1;
  }
  ReportFileNoDataValue(in, !noData.Use && noData.UseFileValue);
  int dims[3];
  cones->GetOutput()->GetDimensions(dims);
  std::cout << "wrote " << out << " (" << dims[0] << "x" << dims[1] << " " << type << " cone map, "
            << seconds << " s)" << std::endl;
  return 0;
}

int RunProbeCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight probe",
    "mesolight probe PROBE_IMAGE --out FILE.exr [options]\n\nConverts a light probe "
    "picture (angular map or mirror ball) into a lat-long environment\n(+Z up, v = 0 "
    "at the top row; docs/environment-maps.md).\n");
  cl.AddValue("--out", "FILE.exr", "lat-long environment to write");
  cl.AddValue("--type", "TYPE", "angular (Debevec light probe) or mirror-ball", "angular");
  cl.AddValue("--width", "W", "output width (height W/2); 0 = twice the probe size", "0");
  cl.AddValue("--forward", "X,Y,Z", "direction the probe camera looked in", "1,0,0");
  cl.AddValue("--up", "X,Y,Z", "up direction of the probe picture", "0,0,1");
  cl.AddValue(
    "--merge", "PROBE_B", "second view of the same probe (the relief thesis' two-view merge)");
  cl.AddValue("--merge-forward", "X,Y,Z", "direction the second view looked in", "0,1,0");
  cl.AddValue("--mask", "IMAGE", "lat-long mask C: result = A C + B (1 - C)");
  cl.AddValue("--memory-budget", "GIB", "refuse maps needing more memory (0: all there is)", "0");
  std::string error;
  int width = 0;
  double forward[3], up[3], forwardB[3];
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  double budget = 0.0;
  if (!cl.GetInt("--width", 0, 32768, width, error) ||
    !cl.GetDouble("--memory-budget", 0.0, 1e6, budget, error))
  {
    return cl.UsageError(error);
  }
  const std::string type = cl.Get("--type");
  if (cl.Positional().size() != 1 || !cl.Has("--out") ||
    (type != "angular" && type != "mirror-ball") || !cl.GetDoubleVector("--forward", 3, forward) ||
    !cl.GetDoubleVector("--up", 3, up) || !cl.GetDoubleVector("--merge-forward", 3, forwardB) ||
    (cl.Has("--merge") != cl.Has("--mask")))
  {
    std::cerr << "mesolight probe: usage: mesolight probe PROBE_IMAGE --out FILE.exr "
                 "[--type angular|mirror-ball] [--forward x,y,z] [--up x,y,z] "
                 "[--merge PROBE_B --mask MASK]\n";
    return 2;
  }
  const std::string out = cl.Get("--out");
  const std::string problem =
    CheckOutputFile(out, { cl.Positional()[0], cl.Get("--merge"), cl.Get("--mask") });
  if (!problem.empty())
  {
    return cl.UsageError("--out: " + problem);
  }
  auto convert = [&](const std::string& file, const double f[3]) -> vtkSmartPointer<vtkImageData>
  {
    vtkNew<vtkOIIOImageReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkLightProbeToLatLong> toLatLong;
    toLatLong->SetInputConnection(reader->GetOutputPort());
    toLatLong->SetProbeType(type == "mirror-ball" ? vtkLightProbeToLatLong::MIRROR_BALL
                                                  : vtkLightProbeToLatLong::ANGULAR_MAP);
    toLatLong->SetOutputWidth(width);
    toLatLong->SetMemoryBudget(static_cast<vtkTypeInt64>(budget * 1073741824.0));
    toLatLong->SetForward(const_cast<double*>(f));
    toLatLong->SetUp(up);
    toLatLong->Update();
    if (toLatLong->GetOutput()->GetNumberOfPoints() == 0)
    {
      return nullptr;
    }
    auto result = vtkSmartPointer<vtkImageData>::New();
    result->DeepCopy(toLatLong->GetOutput());
    return result;
  };
  vtkSmartPointer<vtkImageData> map = convert(cl.Positional()[0], forward);
  if (!map)
  {
    std::cerr << "mesolight probe: could not convert " << cl.Positional()[0] << "\n";
    return 1;
  }
  if (cl.Has("--merge"))
  {
    vtkSmartPointer<vtkImageData> second = convert(cl.Get("--merge"), forwardB);
    vtkNew<vtkOIIOImageReader> maskReader;
    maskReader->SetFileName(cl.Get("--mask").c_str());
    maskReader->Update();
    int dims[3], maskDims[3];
    map->GetDimensions(dims);
    maskReader->GetOutput()->GetDimensions(maskDims);
    if (!second || maskDims[0] != dims[0] || maskDims[1] != dims[1])
    {
      std::cerr << "mesolight probe: the second view and the mask must convert to / be " << dims[0]
                << "x" << dims[1] << "\n";
      return 1;
    }
    vtkDataArray* maskValues = maskReader->GetOutput()->GetPointData()->GetScalars();
    // Integer masks mean [0, type max] -> [0, 1] (8- and 16-bit PNG/TIFF); float ones are as is.
    const double maskScale = mesolight::UnitScale(maskValues);
    std::vector<float> mask(static_cast<size_t>(dims[0]) * dims[1]);
    for (size_t p = 0; p < mask.size(); ++p)
    {
      mask[p] =
        static_cast<float>(maskValues->GetComponent(static_cast<vtkIdType>(p), 0) * maskScale);
    }
    const RgbImage merged = MergeWithMask(ToRgb(map), ToRgb(second), mask);
    std::copy(merged.Rgb.begin(), merged.Rgb.end(),
      vtkFloatArray::SafeDownCast(map->GetPointData()->GetScalars())->GetPointer(0));
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(map);
  writer->SetFileName(out.c_str());
  if (!writer->Write())
  {
    std::cerr << "mesolight probe: could not write " << out << "\n";
    return 1;
  }
  int dims[3];
  map->GetDimensions(dims);
  std::cout << "wrote " << out << " (" << dims[0] << "x" << dims[1] << " lat-long)" << std::endl;
  return 0;
}

} // namespace mesolight
