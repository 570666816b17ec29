// SPDX-License-Identifier: BSD-3-Clause
#include "HallucinateCommand.h"

#include "CommandLine.h"
#include "OutputFile.h"
#include "Timing.h"

#include "DepthHallucination.h"
#include "HallucinationReference.h"
#include "ProceduralHeightFields.h"
#include "vtkDepthHallucinationFilter.h"
#include "vtkMessageCollector.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

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

bool WriteImage(vtkImageData* image, const std::string& file)
{
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(file.c_str());
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
  cl.AddValue("--layers", "N", "scale layers; sigma 1, 2, 4, ... texels", "5");
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
  double depthScale = 1.0, hill = 1.0, valley = 1.0;
  int layers = 5;
  if (!cl.GetDouble("--depth-scale", 1e-6, 1e6, depthScale, error) ||
    !cl.GetInt("--layers", 1, 12, layers, error) ||
    !cl.GetDouble("--hill-weight", 0.0, 100.0, hill, error) ||
    !cl.GetDouble("--valley-weight", 0.0, 100.0, valley, error))
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
  filter->SetHillWeight(hill);
  filter->SetValleyWeight(valley);
  {
    int size[3];
    diffuse->GetDimensions(size);
    const int longest = std::max(size[0], size[1]);
    // The coarsest layer's sigma (2^(layers - 1) texels) beyond the photograph's longer side
    // compares every pixel with the mean of the whole photograph, as the layer before did.
    if (std::min(size[0], size[1]) >= HallucinationMinimumSide && (1 << (layers - 1)) > longest)
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
    const double estimate = SecondsPerPixel * size[0] * size[1] +
      SecondsPerWork * HallucinationWork(size[0], size[1], layers);
    if (estimate > 2.0)
    {
      std::cerr << "hallucinating " << size[0] << "x" << size[1] << ", " << layers
                << " layers: about " << std::setprecision(2) << estimate << " s\n";
    }
  }
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* clientData, void*)
    {
      // Progress on stderr in steps of 10%.
      int& last = *static_cast<int*>(clientData);
      const int step = static_cast<int>(10.0 * static_cast<vtkAlgorithm*>(caller)->GetProgress());
      if (step > last)
      {
        last = step;
        std::cerr << "\rhallucinating " << step * 10 << "%" << (step >= 10 ? "\n" : "")
                  << std::flush;
      }
    });
  int lastStep = -1;
  progress->SetClientData(&lastStep);
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double seconds = SecondsSince(start);
  if (lastStep >= 0 && lastStep < 10)
  {
    std::cerr << "\n";
  }
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
    "Bricks, Stone, HemisphereTorus or depth images (0 = top),\neach NAME[:RELIEF_TEXELS]",
    defaultMaps);
  cl.AddValue("--size", "N", "photograph size for the procedural maps", "128");
  cl.AddValue("--relief", "TEXELS", "depth of depth 1 in texels, unless given per map", "8");
  cl.AddValue("--samples", "N", "path samples per pixel", "32");
  cl.AddValue("--layers", "N", "scale layers of the model", "5");
  cl.AddValue("--csv", "FILE", "figures as CSV");
  cl.AddValue("--photos", "DIR", "also write each map's photographs and true depth (.exr) there");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  std::string error;
  int size = 128, samples = 32, layers = 5;
  double relief = 8.0;
  if (!cl.GetInt("--size", 8, 2048, size, error) ||
    !cl.GetInt("--samples", 1, 4096, samples, error) ||
    !cl.GetInt("--layers", 1, 12, layers, error) ||
    !cl.GetDouble("--relief", 0.01, 1000.0, relief, error))
  {
    return cl.UsageError(error);
  }
  const std::string problem = CheckOutputOptions(cl, { "--csv" }, {});
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }
  const std::string photos = cl.Get("--photos");
  if (!photos.empty() && !std::filesystem::is_directory(photos))
  {
    return cl.UsageError("--photos: " + photos + " is not a directory");
  }

  std::ostringstream csv;
  csv << "map,width,height,relief_texels,samples,method,correlation,mae_texels,"
         "best_constant_mae_texels,depth_range_texels,albedo_relative_error,render_s,filter_s\n";
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
    if (name == "Bricks" || name == "Stone" || name == "HemisphereTorus")
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
      const double scale = values->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0
        : values->GetDataType() == VTK_UNSIGNED_SHORT                 ? 1.0 / 65535.0
                                                                      : 1.0;
      for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
      {
        depth.push_back(static_cast<float>(scale * values->GetComponent(p, 0)));
      }
      label = std::filesystem::path(name).stem().string();
    }
    HallucinationPhotoSettings photo;
    photo.ReliefDepthTexels = static_cast<float>(texels);
    photo.Samples = samples;
    auto start = std::chrono::steady_clock::now();
    const HallucinationPhotographs shots = RenderHallucinationPhotographs(depth, w, h, {}, photo);
    const double renderSeconds = SecondsSince(start);
    HallucinationSettings settings;
    settings.Layers = layers;
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
      ideal = HallucinateDepth(shots.Diffuse, idealFlash, nullptr, settings);
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
    std::vector<float> brightness(depth.size()), darkIsDeep(depth.size());
    for (std::size_t p = 0; p < depth.size(); ++p)
    {
      const float t = RgbLuminance(&shots.TrueAlbedo.Rgb[3 * p]);
      albedoError += std::abs(RgbLuminance(&result.Albedo.Rgb[3 * p]) - t) / t;
      brightness[p] = -RgbLuminance(&shots.Diffuse.Rgb[3 * p]);
      darkIsDeep[p] = -result.Shading[p];
    }
    albedoError /= static_cast<double>(depth.size());
    const struct
    {
      const char* Method;
      const std::vector<float>* Estimate;
    } methods[] = { { "model", &result.Depth }, { "model-without-card", &uncalibrated.Depth },
      { "model-true-albedo", &ideal.Depth }, { "inverted-brightness", &brightness },
      { "dark-is-deep-shading", &darkIsDeep } };
    for (const auto& method : methods)
    {
      const DepthAgreement a = CompareDepth(*method.Estimate, truth, w, h, 4);
      std::cout << std::left << std::setw(27) << label << std::setw(22) << method.Method
                << std::right << std::fixed << std::setprecision(3) << std::setw(12)
                << a.Correlation << std::setw(12) << a.MeanAbsoluteError << std::setw(12)
                << a.TruthMeanAbsoluteDeviation << "\n";
      csv << label << "," << w << "," << h << "," << texels << "," << samples << ","
          << method.Method << "," << a.Correlation << "," << a.MeanAbsoluteError << ","
          << a.TruthMeanAbsoluteDeviation << "," << result.DepthRangeTexels << "," << albedoError
          << "," << renderSeconds << "," << filterSeconds << "\n";
    }
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
  if (cl.Has("--csv"))
  {
    std::ofstream out(cl.Get("--csv"));
    out << csv.str();
    if (!out)
    {
      std::cerr << "mesolight bench hallucinate: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  return 0;
}

} // namespace mesolight
