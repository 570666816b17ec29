// SPDX-License-Identifier: BSD-3-Clause
#include "HallucinateCommand.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "OutputFile.h"
#include "ProgressLine.h"
#include "Timing.h"

#include "DepthHallucination.h"
#include "HallucinationReference.h"
#include "ProceduralHeightFields.h"
#include "vtkDepthHallucinationFilter.h"
#include "vtkMessageCollector.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"
#include "vtkUnitScale.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace mesolight
{
namespace
{
vtkSmartPointer<vtkImageData> ToImage(const float* values, int w, int h, int components)
{
  vtkNew<vtkFloatArray> array;
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  std::copy(values, values + static_cast<std::size_t>(w) * h * components, array->GetPointer(0));
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->GetPointData()->SetScalars(array);
  return image;
}

// --layers: "feature" (-2, the default), "average" (0), "auto" (-1) or a count 1..12.
bool GetHallucinationLayers(const CommandLine& cl, int& layers, std::string& error)
{
  const std::string value = cl.Get("--layers");
  if (value == "feature" || value.empty())
  {
    layers = HallucinationFeatureLayers;
    return true;
  }
  if (value == "average")
  {
    layers = 0;
    return true;
  }
  if (value == "auto")
  {
    layers = -1;
    return true;
  }
  return cl.GetInt("--layers", 1, 12, layers, error);
}

// --model: "ratio" (the default) or "shading" (the previous model).
bool GetHallucinationModel(const CommandLine& cl, HallucinationModel& model, std::string& error)
{
  const std::string value = cl.Get("--model");
  if (value == "ratio" || value.empty())
  {
    model = HallucinationModel::Ratio;
    return true;
  }
  if (value == "shading")
  {
    model = HallucinationModel::Shading;
    return true;
  }
  error = "--model must be ratio or shading, not " + value;
  return false;
}

// An RGB (or grey) image file as RgbImage; false if unreadable.
bool ReadRgb(const std::string& file, RgbImage& out)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || image->GetNumberOfPoints() == 0)
  {
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  out = RgbImage(dims[0], dims[1]);
  const int components = values->GetNumberOfComponents();
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Rgb[3 * static_cast<std::size_t>(p) + static_cast<std::size_t>(c)] =
        static_cast<float>(values->GetComponent(p, std::min(c, components - 1)));
    }
  }
  return true;
}

// Depth and albedo are float: a .png or .tif keeps 16 bits of them (8 bits gave 256 depth
// levels without a word); .exr keeps them as they are.
bool WriteImage(vtkImageData* image, const std::string& file)
{
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(file.c_str());
  writer->SetBitDepth(16);
  return writer->Write() != 0 && writer->GetErrorCode() == 0;
}
} // namespace

//------------------------------------------------------------------------------
int RunHallucinateCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight hallucinate",
    "mesolight hallucinate DIFFUSE FLASH [--calibration CARD] --albedo A.exr --depth D.exr\n\n"
    "Depth hallucination (Glencross et al. 2008): from a photograph under diffuse light\n"
    "(overcast sky or shade) and one of the same view with a flash at the camera, the albedo\n"
    "(I_f - I_d) / I_c and a depth map (0 = highest, 1 = deepest) from the diffuse shading.\n"
    "Photographs must be linear light and aligned pixel for pixel: RAW (through OpenImageIO),\n"
    "16-bit linear TIFF/PNG or EXR. docs/hallucination.md says what the depth is worth.\n");
  cl.AddValue("--calibration", "CARD", "flash photograph of a white card (else a uniform flash)");
  cl.AddValue("--albedo", "FILE", "albedo to write (float RGB; .exr keeps it linear)");
  cl.AddValue("--depth", "FILE", "depth map to write (float; 0 = highest, 1 = deepest)");
  cl.AddValue("--depth-scale", "K", "the user's depth scale: multiplies the model's depth", "1");
  cl.AddValue("--layers", "N",
    "scale layers; sigma 1, 2, 4, ... texels (feature: from the ratio's feature size, the "
    "average on fine features, one wide count on broad ones; average: every count the "
    "photograph holds, averaged; auto: one count from the photographs' octave energies)",
    "feature");
  cl.AddValue("--model", "NAME",
    "ratio: layers of the diffuse/flash ratio, each count weighted by its agreement with it; "
    "shading: the previous model, layers of the shading, equal weights",
    "ratio");
  cl.AddValue("--residual-weight", "W",
    "sigma of the residual layer (the widest layer against the open sky) in widest sigmas; 0: "
    "none",
    "8");
  cl.AddValue("--hill-weight", "W", "weight of the hill law (orientation to the sky)", "1");
  cl.AddValue("--valley-weight", "W", "weight of the valley law (visible aperture)", "1");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  if (cl.Positional().size() != 2 || (!cl.Has("--albedo") && !cl.Has("--depth")))
  {
    return cl.UsageError("usage: mesolight hallucinate DIFFUSE FLASH [--calibration CARD] "
                         "--albedo A.exr --depth D.exr");
  }
  std::string error;
  double depthScale = 1.0, hill = 1.0, valley = 1.0, residual = 8.0;
  int layers = HallucinationFeatureLayers;
  HallucinationModel model = HallucinationModel::Ratio;
  if (!cl.GetDouble("--depth-scale", 1e-6, 1e6, depthScale, error) ||
    !GetHallucinationLayers(cl, layers, error) || !GetHallucinationModel(cl, model, error) ||
    !cl.GetDouble("--hill-weight", 0.0, 100.0, hill, error) ||
    !cl.GetDouble("--valley-weight", 0.0, 100.0, valley, error) ||
    !cl.GetDouble("--residual-weight", 0.0, 100.0, residual, error))
  {
    return cl.UsageError(error);
  }
  if (!(hill > 0.0) && !(valley > 0.0))
  {
    return cl.UsageError(
      "--hill-weight and --valley-weight are both 0: the depth would be flat (give either > 0)");
  }
  const std::string diffuseFile = cl.Positional()[0], flashFile = cl.Positional()[1];
  const std::string calibrationFile = cl.Get("--calibration");
  const std::string problem =
    CheckOutputOptions(cl, { "--albedo", "--depth" }, { diffuseFile, flashFile, calibrationFile });
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }

  // Read each photograph, one line per failure.
  const auto read = [](const std::string& file, const char* role)
  {
    vtkNew<MessageCollector> errors; // errors only: warnings go to the console
    auto reader = vtkSmartPointer<vtkOIIOImageReader>::New();
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkSmartPointer<vtkImageData> image = reader->GetOutput();
    if (reader->GetErrorCode() != 0 || image->GetNumberOfPoints() == 0)
    {
      std::cerr << "mesolight hallucinate: cannot read the " << role << " photograph " << file
                << (errors->Errors.empty() ? "" : ": " + errors->ErrorText()) << "\n";
      return vtkSmartPointer<vtkImageData>();
    }
    if (image->GetPointData()->GetScalars()->GetDataType() == VTK_UNSIGNED_CHAR)
    {
      std::cerr << "mesolight hallucinate: warning: " << file
                << " is 8-bit, usually sRGB-encoded; it is read as linear light\n";
    }
    return image;
  };
  vtkSmartPointer<vtkImageData> diffuse = read(diffuseFile, "diffuse");
  vtkSmartPointer<vtkImageData> flash = diffuse ? read(flashFile, "flash") : nullptr;
  vtkSmartPointer<vtkImageData> calibration =
    (flash && !calibrationFile.empty()) ? read(calibrationFile, "calibration") : nullptr;
  if (!diffuse || !flash || (!calibrationFile.empty() && !calibration))
  {
    return 1;
  }

  vtkNew<vtkDepthHallucinationFilter> filter;
  vtkNew<MessageCollector> errors; // errors only: warnings go to the console
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->SetInputData(0, diffuse);
  filter->SetInputData(1, flash);
  if (calibration)
  {
    filter->SetInputData(2, calibration);
  }
  filter->SetDepthScale(depthScale);
  filter->SetNumberOfLayers(layers);
  filter->SetUseRatio(model == HallucinationModel::Ratio ? 1 : 0);
  filter->SetHillWeight(hill);
  filter->SetValleyWeight(valley);
  filter->SetResidualWeight(residual);
  {
    int size[3];
    diffuse->GetDimensions(size);
    const int longest = std::max(size[0], size[1]);
    // The coarsest layer's sigma (2^(layers - 1) texels) beyond the photograph's longer side
    // compares every pixel with the mean of the whole photograph, as the layer before did.
    if (layers > 0 && std::min(size[0], size[1]) >= HallucinationMinimumSide &&
      (1 << (layers - 1)) > longest)
    {
      int most = 1;
      while ((1 << most) <= longest && most < 12)
      {
        ++most;
      }
      return cl.UsageError("--layers " + std::to_string(layers) + " on a " +
        std::to_string(size[0]) + "x" + std::to_string(size[1]) + " photograph: the coarsest " +
        "layer's sigma, " + std::to_string(1 << (layers - 1)) +
        " texels, exceeds the photograph; use --layers " + std::to_string(most) + " or fewer");
    }
    // A per-pixel part (checks, albedo, shading) and a part per multiply-add of the blurs
    // (HallucinationWork), measured on a loaded 2-core machine, so rather an upper estimate
    // (docs/measurements/hallucination/hallucination-cost.csv: 2048^2 in 1.8 s with 1 layer,
    // 10 s with 5).
    constexpr double SecondsPerPixel = 3.5e-7, SecondsPerWork = 5e-9;
    // The automatic choice is estimated at its most (sigma up to half the longer side), plus
    // its own measure (about one layer's work).
    int estimatedLayers = layers;
    if (layers <= 0)
    {
      estimatedLayers = 2;
      while (estimatedLayers < 12 && (1 << estimatedLayers) <= longest / 2)
      {
        ++estimatedLayers;
      }
    }
    const double estimate = SecondsPerPixel * size[0] * size[1] +
      SecondsPerWork * HallucinationWork(size[0], size[1], estimatedLayers);
    if (estimate > 2.0)
    {
      std::cerr << "hallucinating " << size[0] << "x" << size[1] << ", "
                << (layers > 0        ? std::to_string(layers) + " layers"
                       : layers == 0  ? "the scale average"
                       : layers == -1 ? "automatic layers"
                                      : "layers from the feature size")
                << ": at most about " << std::setprecision(2) << estimate << " s\n";
    }
  }
  // Progress on stderr, the tool's way (ProgressLine.h).
  ProgressCallback printed = PrintedProgress("hallucinating");
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* clientData, void*)
    {
      (*static_cast<ProgressCallback*>(clientData))(
        static_cast<vtkAlgorithm*>(caller)->GetProgress());
    });
  progress->SetClientData(&printed);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double seconds = SecondsSince(start);
  EndProgressLine();
  if (!errors->Errors.empty() || filter->GetDepthOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "mesolight hallucinate: "
              << (errors->Errors.empty() ? std::string("the filter failed") : errors->ErrorText())
              << "\n";
    return 1;
  }
  int dims[3];
  filter->GetDepthOutput()->GetDimensions(dims);
  if (cl.Has("--albedo") && !WriteImage(filter->GetAlbedoOutput(), cl.Get("--albedo")))
  {
    std::cerr << "mesolight hallucinate: could not write " << cl.Get("--albedo") << "\n";
    return 1;
  }
  if (cl.Has("--depth") && !WriteImage(filter->GetDepthOutput(), cl.Get("--depth")))
  {
    std::cerr << "mesolight hallucinate: could not write " << cl.Get("--depth") << "\n";
    return 1;
  }
  std::cout << "hallucinated " << dims[0] << "x" << dims[1] << " in " << std::setprecision(3)
            << seconds << " s" << (calibration ? "" : " (uniform flash: no --calibration)") << "\n";
  if (filter->GetLayersAveraged())
  {
    std::cout << "layers: the average of 1 to " << filter->GetLayersUsed() << " (widest sigma "
              << (1 << (filter->GetLayersUsed() - 1)) << " texels)";
    if (layers == HallucinationFeatureLayers)
    {
      std::cout << ", fine features (autocorrelation length " << std::setprecision(3)
                << filter->GetCorrelationLengthTexels() << " texels)";
    }
    std::cout << "\n";
  }
  else if (layers == HallucinationFeatureLayers)
  {
    std::cout << "layers: " << filter->GetLayersUsed() << " (widest sigma "
              << (1 << (filter->GetLayersUsed() - 1))
              << " texels), broad features (autocorrelation length " << std::setprecision(3)
              << filter->GetCorrelationLengthTexels() << " texels)\n";
  }
  else if (layers < 0)
  {
    std::cout << "layers: " << filter->GetLayersUsed() << " (widest sigma "
              << (1 << (filter->GetLayersUsed() - 1)) << " texels), chosen from the feature size "
              << std::setprecision(3) << filter->GetFeatureSizeTexels() << " texels\n";
  }
  else
  {
    std::cout << "layers: " << layers << " (widest sigma " << (1 << (layers - 1)) << " texels)\n";
  }
  if (!(filter->GetDepthRangeTexels() > 0.0))
  {
    std::cerr << "mesolight hallucinate: warning: the depth is flat (the diffuse photograph's "
                 "shading is uniform once the albedo is divided out)\n";
  }
  if (cl.Has("--albedo"))
  {
    std::cout << "wrote " << cl.Get("--albedo") << " (albedo)\n";
  }
  if (cl.Has("--depth"))
  {
    std::cout << "wrote " << cl.Get("--depth")
              << " (depth; the model's depth 1 = " << filter->GetDepthRangeTexels()
              << " texels, i.e. --depth-scale " << filter->GetDepthRangeTexels() / dims[0]
              << " for bake/render)\n";
  }
  return 0;
}

//------------------------------------------------------------------------------
int RunHallucinationBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench hallucinate",
    "mesolight bench hallucinate [--maps LIST] [--samples N] [--csv FILE] [--photos DIR]\n\n"
    "Photographs known height fields with the path tracer (uniform overcast sky; flash at the\n"
    "camera; a white card), runs depth hallucination on them and compares with the truth:\n"
    "correlation and mean absolute error (texels) after the best scale and offset, against\n"
    "inverted brightness and plain dark-is-deep; the albedo's mean relative error.\n");
  std::string defaultMaps = "Bricks,Stone,HemisphereTorus";
#ifdef MESOLIGHT_HALLUCINATION_DATA
  const std::string real = MESOLIGHT_HALLUCINATION_DATA "/jacksboro-fault-depth-128.png";
  if (std::filesystem::exists(real))
  {
    defaultMaps += "," + real + ":4.9";
  }
#endif
  cl.AddValue("--maps", "LIST",
    "Bricks, Stone, HemisphereTorus, Panels, Holes or depth images (0 = top), each "
    "NAME[:RELIEF_TEXELS]",
    defaultMaps);
  cl.AddValue("--size", "N", "photograph size for the procedural maps", "128");
  cl.AddValue("--relief", "TEXELS", "depth of depth 1 in texels, unless given per map", "8");
  cl.AddValue("--samples", "N", "path samples per pixel", "32");
  cl.AddValue("--layers", "N",
    "scale layers of the model (feature: from the ratio's feature size; average: every count "
    "averaged; auto: one count from the octave energies)",
    "feature");
  cl.AddValue("--model", "NAME",
    "ratio: layers of the diffuse/flash ratio, each count weighted by its agreement with it; "
    "shading: the previous model, layers of the shading, equal weights",
    "ratio");
  cl.AddValue("--sweep", "LIST",
    "also run the model with each of these fixed layer counts (e.g. 1,2,3,4,5,6,7,8,9): the "
    "summary names the best");
  cl.AddFlag("--height", "depth images are height maps (white = high): depth = 1 - value");
  cl.AddValue("--plot", "FILE", "correlation per layer count and map as PNG (needs --sweep)");
  cl.AddValue("--csv", "FILE", "figures as CSV (and FILE's stem + -summary.csv)");
  cl.AddValue("--photos", "DIR", "also write each map's photographs and true depth (.exr) there");
  cl.AddValue("--from-photos", "DIR",
    "read each map's photographs and true depth from DIR (as\n--photos writes them) instead of "
    "rendering; no albedo error, no ideal-flash row");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  std::string error;
  int size = 128, samples = 32, layers = 0;
  double relief = 8.0;
  std::vector<int> sweep;
  HallucinationModel model = HallucinationModel::Ratio;
  if (!GetHallucinationModel(cl, model, error) || !cl.GetInt("--size", 8, 2048, size, error) ||
    !cl.GetInt("--samples", 1, 4096, samples, error) ||
    !GetHallucinationLayers(cl, layers, error) ||
    !cl.GetDouble("--relief", 0.01, 1000.0, relief, error) ||
    (cl.Has("--sweep") && !cl.GetIntList("--sweep", 1, 12, sweep, error)))
  {
    return cl.UsageError(error);
  }
  if (cl.Has("--plot") && sweep.empty())
  {
    return cl.UsageError("--plot draws the correlation per layer count: give --sweep");
  }
  const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, {});
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }
  const std::string photos = cl.Get("--photos");
  if (!photos.empty() && !std::filesystem::is_directory(photos))
  {
    return cl.UsageError("--photos: " + photos + " is not a directory");
  }

  std::ostringstream csv, summaryCsv;
  csv << "map,width,height,relief_texels,samples,method,layers,correlation,mae_texels,"
         "best_constant_mae_texels,depth_range_texels,albedo_relative_error,render_s,filter_s\n";
  summaryCsv << "map,width,height,default_layers,default_averaged,correlation_length_texels,"
                "default_correlation,ratio_average_correlation,"
                "previous_default_correlation,auto_layers,"
                "feature_size_texels,auto_correlation,old_default_correlation,best_fixed_layers,"
                "best_fixed_correlation,inverted_brightness_correlation,flash_ratio_correlation\n";
  struct Summary
  {
    std::string Map;
    int Layers = 0, AutoLayers = 0;
    bool Averaged = false;
    float Feature = 0.0f, CorrelationLength = 0.0f;
    double Default = 0.0, Average = 0.0, Previous = 0.0, Auto = 0.0, Best = -2.0, Five = 0.0,
           Brightness = 0.0, Ratio = 0.0;
    int BestLayers = 0;
    std::vector<double> Sweep;
    std::vector<int> SweepLayers;
  };
  std::vector<Summary> summaries;
  std::cout << std::left << std::setw(27) << "map" << std::setw(22) << "method" << std::right
            << std::setw(12) << "correlation" << std::setw(12) << "MAE texels" << std::setw(12)
            << "flat MAE"
            << "\n";
  for (const std::string& entry : cl.GetStringList("--maps"))
  {
    std::string name = entry;
    double texels = relief;
    const std::size_t colon = entry.rfind(':');
    if (colon != std::string::npos && colon + 1 < entry.size() &&
      entry.find_first_not_of("0123456789.", colon + 1) == std::string::npos)
    {
      name = entry.substr(0, colon);
      texels = std::stod(entry.substr(colon + 1));
    }
    int w = size, h = size;
    std::vector<float> depth;
    std::string label = name;
    if (name == "Panels" || name == "Holes")
    {
      HallucinationTestSurface surface = MakeHallucinationTestSurface(name == "Panels");
      w = h = surface.Side;
      depth = std::move(surface.Depth);
      if (colon == std::string::npos || name == entry)
      {
        texels = surface.ReliefTexels;
      }
    }
    else if (name == "Bricks" || name == "Stone" || name == "HemisphereTorus")
    {
      HeightFieldParameters parameters;
      parameters.Pattern = name == "Bricks" ? ReliefPattern::Bricks
        : name == "Stone"                   ? ReliefPattern::Stone
                                            : ReliefPattern::HemisphereTorus;
      depth.resize(static_cast<std::size_t>(w) * h);
      GenerateHeightField(parameters, w, h, depth.data(), nullptr);
    }
    else
    {
      vtkNew<vtkOIIOImageReader> reader;
      reader->SetFileName(name.c_str());
      reader->Update();
      vtkImageData* image = reader->GetOutput();
      if (reader->GetErrorCode() != 0 || image->GetNumberOfPoints() == 0)
      {
        std::cerr << "mesolight bench hallucinate: cannot read the depth map " << name << "\n";
        return 1;
      }
      int dims[3];
      image->GetDimensions(dims);
      w = dims[0];
      h = dims[1];
      vtkDataArray* values = image->GetPointData()->GetScalars();
      const double scale = mesolight::UnitScale(values);
      const bool height = cl.Has("--height");
      for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
      {
        const double v = scale * values->GetComponent(p, 0);
        depth.push_back(static_cast<float>(height ? 1.0 - v : v));
      }
      label = std::filesystem::path(name).stem().string();
    }
    HallucinationPhotoSettings photo;
    photo.ReliefDepthTexels = static_cast<float>(texels);
    photo.Samples = samples;
    auto start = std::chrono::steady_clock::now();
    const std::string fromPhotos = cl.Get("--from-photos");
    HallucinationPhotographs shots;
    if (fromPhotos.empty())
    {
      shots = RenderHallucinationPhotographs(depth, w, h, {}, photo);
    }
    else
    {
      // Photographs rendered before (--photos), the same renderer and settings: the table can be
      // redone without rendering again. The true albedo is not stored.
      const std::filesystem::path dir(fromPhotos);
      RgbImage trueDepth;
      if (!ReadRgb((dir / (label + "-diffuse.exr")).string(), shots.Diffuse) ||
        !ReadRgb((dir / (label + "-flash.exr")).string(), shots.Flash) ||
        !ReadRgb((dir / (label + "-calibration.exr")).string(), shots.Calibration) ||
        !ReadRgb((dir / (label + "-true-depth.exr")).string(), trueDepth) || trueDepth.Width != w ||
        trueDepth.Height != h)
      {
        std::cerr << "mesolight bench hallucinate: no photographs of " << label << " in "
                  << fromPhotos << " (or of another size)\n";
        return 1;
      }
      for (std::size_t p = 0; p < depth.size(); ++p)
      {
        depth[p] = trueDepth.Rgb[3 * p];
      }
      shots.TrueAlbedo = shots.Calibration; // not stored: no albedo error, no ideal-flash row
    }
    const double renderSeconds = SecondsSince(start);
    HallucinationSettings settings;
    settings.Layers = layers;
    settings.Model = model;
    start = std::chrono::steady_clock::now();
    HallucinationResult result, uncalibrated, ideal;
    double filterSeconds = 0.0;
    try
    {
      result = HallucinateDepth(shots.Diffuse, shots.Flash, &shots.Calibration, settings);
      filterSeconds = SecondsSince(start);
      // The same photographs without the card: a uniform flash assumed.
      uncalibrated = HallucinateDepth(shots.Diffuse, shots.Flash, nullptr, settings);
      // An ideal flash that measures the albedo alone (no cosine to the flash, no
      // interreflection): what the model makes of the true shading.
      RgbImage idealFlash = shots.Diffuse;
      for (std::size_t k = 0; k < idealFlash.Rgb.size(); ++k)
      {
        idealFlash.Rgb[k] += shots.TrueAlbedo.Rgb[k];
      }
      ideal = fromPhotos.empty() ? HallucinateDepth(shots.Diffuse, idealFlash, nullptr, settings)
                                 : result;
    }
    catch (const HallucinationError& e)
    {
      std::cerr << "mesolight bench hallucinate: " << label << ": " << e.what() << "\n";
      return 1;
    }
    std::vector<float> truth(depth);
    for (float& d : truth)
    {
      d *= static_cast<float>(texels);
    }
    double albedoError = 0.0;
    std::vector<float> brightness(depth.size()), darkIsDeep(depth.size()), ratio(depth.size());
    for (std::size_t p = 0; p < depth.size(); ++p)
    {
      const float t = Luminance(&shots.TrueAlbedo.Rgb[3 * p]);
      albedoError += std::abs(Luminance(&result.Albedo.Rgb[3 * p]) - t) / t;
      brightness[p] = -Luminance(&shots.Diffuse.Rgb[3 * p]);
      darkIsDeep[p] = -result.Shading[p];
      // The diffuse/flash ratio: the albedo divides out, dark is deep, no scales.
      const float flashLuminance = Luminance(&shots.Flash.Rgb[3 * p]);
      ratio[p] =
        flashLuminance > 0.0f ? -Luminance(&shots.Diffuse.Rgb[3 * p]) / flashLuminance : 0.0f;
    }
    albedoError = fromPhotos.empty() ? albedoError / static_cast<double>(depth.size())
                                     : std::numeric_limits<double>::quiet_NaN();
    struct Method
    {
      std::string Name;
      std::vector<float> Estimate;
      int Layers = 0;
    };
    std::vector<Method> methods = { { "model", result.Depth, result.Layers },
      { "model-without-card", uncalibrated.Depth, uncalibrated.Layers },
      { "model-true-albedo", ideal.Depth, ideal.Layers }, { "inverted-brightness", brightness, 0 },
      { "flash-ratio", ratio, 0 }, { "dark-is-deep-shading", darkIsDeep, 0 } };
    // The model at fixed layer counts, on the same photographs (the shading does not depend on
    // the layers): what the best fixed choice would have given on this map.
    Summary summary;
    summary.Map = label;
    summary.Layers = result.Layers;
    summary.Averaged = result.Averaged;
    summary.CorrelationLength = result.CorrelationLengthTexels;
    {
      // The ratio's scale average at every feature size (the default before the layers followed
      // the feature size: --layers average).
      HallucinationSettings average = settings;
      average.Layers = 0;
      average.Model = HallucinationModel::Ratio;
      methods.push_back({ "model-ratio-average", DepthFromShading(result.Ratio, w, h, average),
        HallucinationAverageLayers(w, h) });
      // The previous default (the shading's scale average, equal weights), the automatic layer
      // count, and the model as it was before the residual layer (five layers, none): the same
      // photographs, the same shading.
      HallucinationSettings previous = settings;
      previous.Layers = 0;
      previous.Model = HallucinationModel::Shading;
      methods.push_back({ "model-shading-average", DepthFromShading(result.Shading, w, h, previous),
        result.Layers });
      HallucinationSettings automatic = settings;
      automatic.Layers = 0;
      const HallucinationScale chosen = ChooseHallucinationLayers(result.Shading, w, h);
      summary.AutoLayers = chosen.Layers;
      summary.Feature = chosen.FeatureSizeTexels;
      automatic.Layers = chosen.Layers;
      methods.push_back(
        { "model-auto", DepthFromShading(result.Shading, w, h, automatic), chosen.Layers });
      HallucinationSettings old = settings;
      old.Layers = 5;
      old.ResidualWeight = 0.0f;
      methods.push_back(
        { "model-5-layers-no-residual", DepthFromShading(result.Shading, w, h, old), 5 });
    }
    const int longest = std::max(w, h);
    // The sweep reads what the model reads (the ratio, or the shading under --model shading).
    const std::vector<float>& layerInput =
      model == HallucinationModel::Ratio ? result.Ratio : result.Shading;
    for (int n : sweep)
    {
      if ((1 << (n - 1)) > longest)
      {
        continue;
      }
      HallucinationSettings fixed = settings;
      fixed.Layers = n;
      methods.push_back(
        { "model-layers-" + std::to_string(n), DepthFromShading(layerInput, w, h, fixed), n });
    }
    for (const auto& method : methods)
    {
      const DepthAgreement a = CompareDepth(method.Estimate, truth, w, h, 4);
      std::cout << std::left << std::setw(27) << label << std::setw(22) << method.Name << std::right
                << std::fixed << std::setprecision(3) << std::setw(12) << a.Correlation
                << std::setw(12) << a.MeanAbsoluteError << std::setw(12)
                << a.TruthMeanAbsoluteDeviation << "\n";
      csv << label << "," << w << "," << h << "," << texels << "," << samples << "," << method.Name
          << "," << method.Layers << "," << a.Correlation << "," << a.MeanAbsoluteError << ","
          << a.TruthMeanAbsoluteDeviation << "," << result.DepthRangeTexels << "," << albedoError
          << "," << renderSeconds << "," << filterSeconds << "\n";
      if (method.Name == "model")
      {
        summary.Default = a.Correlation;
      }
      else if (method.Name == "inverted-brightness")
      {
        summary.Brightness = a.Correlation;
      }
      else if (method.Name == "flash-ratio")
      {
        summary.Ratio = a.Correlation;
      }
      else if (method.Name == "model-ratio-average")
      {
        summary.Average = a.Correlation;
      }
      else if (method.Name == "model-shading-average")
      {
        summary.Previous = a.Correlation;
      }
      else if (method.Name == "model-auto")
      {
        summary.Auto = a.Correlation;
      }
      else if (method.Name == "model-5-layers-no-residual")
      {
        summary.Five = a.Correlation;
      }
      else if (method.Name.rfind("model-layers-", 0) == 0)
      {
        summary.Sweep.push_back(a.Correlation);
        summary.SweepLayers.push_back(method.Layers);
        if (a.Correlation > summary.Best)
        {
          summary.Best = a.Correlation;
          summary.BestLayers = method.Layers;
        }
      }
    }
    summaryCsv << label << "," << w << "," << h << "," << summary.Layers << ","
               << (summary.Averaged ? 1 : 0) << "," << summary.CorrelationLength << ","
               << summary.Default << "," << summary.Average << "," << summary.Previous << ","
               << summary.AutoLayers << "," << summary.Feature << "," << summary.Auto << ","
               << summary.Five << "," << summary.BestLayers << "," << summary.Best << ","
               << summary.Brightness << "," << summary.Ratio << "\n";
    summaries.push_back(summary);
    std::cout << std::left << std::setw(27) << label << "albedo mean relative error " << albedoError
              << "; model depth range " << result.DepthRangeTexels << " texels (true " << texels
              << "); render " << renderSeconds << " s, filter " << filterSeconds << " s\n";
    std::cout.unsetf(std::ios::fixed);
    if (!photos.empty())
    {
      const std::filesystem::path dir(photos);
      const bool written = WriteImage(ToImage(shots.Diffuse.Rgb.data(), w, h, 3),
                             (dir / (label + "-diffuse.exr")).string()) &&
        WriteImage(
          ToImage(shots.Flash.Rgb.data(), w, h, 3), (dir / (label + "-flash.exr")).string()) &&
        WriteImage(ToImage(shots.Calibration.Rgb.data(), w, h, 3),
          (dir / (label + "-calibration.exr")).string()) &&
        WriteImage(ToImage(depth.data(), w, h, 1), (dir / (label + "-true-depth.exr")).string());
      if (!written)
      {
        std::cerr << "mesolight bench hallucinate: could not write the photographs to " << photos
                  << "\n";
        return 1;
      }
    }
  }
  // The summary: the default against the best fixed layer count and both naive baselines.
  std::cout << "\n"
            << std::left << std::setw(24) << "map" << std::right << std::setw(9) << "default"
            << std::setw(7) << "(N)" << std::setw(8) << "length" << std::setw(9) << "average"
            << std::setw(10) << "previous" << std::setw(8) << "auto" << std::setw(5) << "(N)"
            << std::setw(9) << "feature" << std::setw(9) << "old" << std::setw(8) << "best"
            << std::setw(5) << "(N)" << std::setw(12) << "brightness" << std::setw(8) << "ratio"
            << "  default beats both\n";
  double meanDefault = 0.0, meanAverage = 0.0, meanPrevious = 0.0, meanAuto = 0.0, meanFive = 0.0,
         meanBest = 0.0;
  int beaten = 0, averageBeaten = 0, previousBeaten = 0, autoBeaten = 0, fiveBeaten = 0;
  const double count = static_cast<double>(std::max<std::size_t>(1, summaries.size()));
  for (const Summary& s : summaries)
  {
    const bool beats = s.Default > s.Brightness && s.Default > s.Ratio;
    beaten += beats ? 1 : 0;
    averageBeaten += (s.Average > s.Brightness && s.Average > s.Ratio) ? 1 : 0;
    previousBeaten += (s.Previous > s.Brightness && s.Previous > s.Ratio) ? 1 : 0;
    autoBeaten += (s.Auto > s.Brightness && s.Auto > s.Ratio) ? 1 : 0;
    fiveBeaten += (s.Five > s.Brightness && s.Five > s.Ratio) ? 1 : 0;
    meanDefault += s.Default / count;
    meanAverage += s.Average / count;
    meanPrevious += s.Previous / count;
    meanAuto += s.Auto / count;
    meanFive += s.Five / count;
    meanBest += (s.BestLayers ? s.Best : 0.0) / count;
    std::cout << std::left << std::setw(24) << s.Map << std::right << std::fixed
              << std::setprecision(3) << std::setw(9) << s.Default << std::setw(7)
              << (std::to_string(s.Layers) + (s.Averaged ? "a" : "")) << std::setprecision(2)
              << std::setw(8) << s.CorrelationLength << std::setprecision(3) << std::setw(9)
              << s.Average << std::setw(10) << s.Previous << std::setw(8) << s.Auto << std::setw(5)
              << s.AutoLayers << std::setprecision(1) << std::setw(9) << s.Feature
              << std::setprecision(3) << std::setw(9) << s.Five;
    // Without --sweep there is no best fixed count: "-", not "0.000 0".
    if (s.BestLayers)
    {
      std::cout << std::setw(8) << s.Best << std::setw(5) << s.BestLayers;
    }
    else
    {
      std::cout << std::setw(8) << "-" << std::setw(5) << "-";
    }
    std::cout << std::setw(12) << s.Brightness << std::setw(8) << s.Ratio << "  "
              << (beats ? "yes" : "NO") << "\n";
  }
  std::cout << std::setprecision(3) << "mean correlation: default " << meanDefault
            << " (beats both baselines on " << beaten << " of " << summaries.size()
            << " maps), ratio average at every feature size (--layers average) " << meanAverage
            << " (" << averageBeaten << "), shading average (--model shading) " << meanPrevious
            << " (" << previousBeaten << "), automatic layers " << meanAuto << " (" << autoBeaten
            << "), old default (5 layers, no residual) " << meanFive << " (" << fiveBeaten << ")";
  if (!sweep.empty())
  {
    std::cout << ", best fixed layer count per map " << meanBest;
  }
  std::cout << "\n";
  std::cout.unsetf(std::ios::fixed);
  if (cl.Has("--csv"))
  {
    const std::filesystem::path file(cl.Get("--csv"));
    const std::filesystem::path summaryFile =
      file.parent_path() / (file.stem().string() + "-summary.csv");
    std::ofstream out(file);
    out << csv.str();
    std::ofstream outSummary(summaryFile);
    outSummary << summaryCsv.str();
    if (!out || !outSummary)
    {
      std::cerr << "mesolight bench hallucinate: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    std::cout << "wrote " << file.string() << " and " << summaryFile.string() << "\n";
  }
  if (cl.Has("--plot"))
  {
    ScatterChart chart;
    chart.Title = "Depth hallucination: correlation with the true depth per fixed layer count "
                  "(one marker per map), and the default's choice";
    chart.XLabel = "layers (widest sigma 2^(N-1) texels)";
    chart.YLabel = "correlation with the true depth";
    for (const Summary& s : summaries)
    {
      ChartSeries series;
      series.Name = s.Map;
      series.X.assign(s.SweepLayers.begin(), s.SweepLayers.end());
      series.Y = s.Sweep;
      chart.Points.push_back(series);
    }
    ChartSeries chosen;
    chosen.Name = "default (automatic)";
    for (const Summary& s : summaries)
    {
      chosen.X.push_back(s.Layers);
      chosen.Y.push_back(s.Default);
    }
    chart.Points.push_back(chosen);
    std::string plotError;
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), plotError))
    {
      std::cerr << "mesolight bench hallucinate: " << plotError << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--plot") << "\n";
  }
  return 0;
}

} // namespace mesolight
