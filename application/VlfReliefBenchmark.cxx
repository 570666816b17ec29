// SPDX-License-Identifier: BSD-3-Clause
#include "VlfReliefBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "CornellRegions.h" // ReadLinearImage
#include "OutputFile.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <stdexcept>

namespace mesolight
{
namespace
{
double Luminance(const float* rgb)
{
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

struct Row
{
  std::string Name;
  std::string File;
  MaskedError Error;
  double Seconds = -1.0; // the render's time per frame, when given
};

// NAME=VALUE
bool SplitNamed(const std::string& spec, std::string& name, std::string& value)
{
  const std::size_t equals = spec.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == spec.size())
  {
    return false;
  }
  name = spec.substr(0, equals);
  value = spec.substr(equals + 1);
  return true;
}

std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size())
  {
    const std::size_t comma = text.find(',', start);
    const std::string item =
      text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty())
    {
      items.push_back(item);
    }
    if (comma == std::string::npos)
    {
      break;
    }
    start = comma + 1;
  }
  return items;
}
} // namespace

MaskedError MaskedRelativeError(const RgbImage& image, const RgbImage& reference,
  const RgbImage& mask, double coverage, double floor)
{
  if (image.Width != reference.Width || image.Height != reference.Height ||
    mask.Width != reference.Width || mask.Height != reference.Height)
  {
    throw std::invalid_argument("the image, the reference and the mask differ in size (" +
      std::to_string(image.Width) + "x" + std::to_string(image.Height) + ", " +
      std::to_string(reference.Width) + "x" + std::to_string(reference.Height) + ", " +
      std::to_string(mask.Width) + "x" + std::to_string(mask.Height) + ")");
  }
  MaskedError result;
  std::vector<double> errors;
  double sum = 0.0, sumReference = 0.0;
  for (int j = 0; j < reference.Height; ++j)
  {
    for (int i = 0; i < reference.Width; ++i)
    {
      if (mask.Pixel(i, j)[0] < coverage - 1e-6)
      {
        continue;
      }
      const double yRef = Luminance(reference.Pixel(i, j));
      const double y = Luminance(image.Pixel(i, j));
      if (!(yRef > floor) || !std::isfinite(y))
      {
        continue;
      }
      errors.push_back(std::abs(y - yRef) / yRef);
      sum += y;
      sumReference += yRef;
    }
  }
  result.Pixels = errors.size();
  if (errors.empty())
  {
    return result;
  }
  double total = 0.0;
  for (double e : errors)
  {
    total += e;
  }
  result.MeanRelativeError = total / static_cast<double>(errors.size());
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  result.MedianRelativeError = errors[errors.size() / 2];
  result.MeanRatio = sum / sumReference;
  return result;
}

int RunVlfReliefBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench vlf-relief",
    "mesolight bench vlf-relief --reference REF.exr --mask MASK.exr --image NAME=FILE.exr "
    "[...]\n\n"
    "The mean relative luminance error per pixel of relief renderings against the path-traced\n"
    "dense displaced mesh (`mesolight trace --relief ... --relief-mask MASK.exr`), over the "
    "pixels\n"
    "wholly on the relief. The first --image is the method under test (the relief lit by the\n"
    "light field); the others are the negative cases it must beat by --margin. Renders and\n"
    "timings come from scripts/bench-vlf-relief.sh.\n");
  cl.AddValue("--reference", "REF.exr", "the path-traced dense mesh (required)");
  cl.AddValue("--reference-2", "REF2.exr",
    "the same reference with other random paths: its error is the reference's own noise");
  cl.AddValue("--mask", "MASK.exr", "the relief's coverage per pixel (required)");
  cl.AddValue("--images", "NAME=FILE.exr,..", "the renderings, method under test first");
  cl.AddValue("--times", "NAME=SECONDS,..", "seconds per frame of some renderings (cost ratios)");
  cl.AddValue("--cost-pair", "A,B", "report the time ratio A / B (e.g. field,vtk-light)");
  cl.AddValue("--coverage", "X", "least share of a pixel on the relief to count it", "1");
  cl.AddValue("--goal", "X", "largest mean relative error of the first image", "0.08");
  cl.AddValue("--margin", "X", "the others' error must be at least X times the first's", "2");
  cl.AddValue("--label", "TEXT", "a name for the run in the CSV (scene, directions)", "cornell");
  cl.AddValue("--csv", "FILE", "append the rows as CSV (header written to a new file)");
  cl.AddValue("--plot", "FILE.png", "plot the errors");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  double coverage = 1.0, goal = 0.08, margin = 2.0;
  if (!cl.GetDouble("--coverage", 0.0, 1.0, coverage, error) ||
    !cl.GetDouble("--goal", 0.0, 100.0, goal, error) ||
    !cl.GetDouble("--margin", 0.0, 1000.0, margin, error))
  {
    return cl.UsageError(error);
  }
  if (!cl.Has("--reference") || !cl.Has("--mask") || !cl.Has("--images"))
  {
    return cl.UsageError("--reference, --mask and --images are required");
  }
  RgbImage reference, mask;
  if (!ReadLinearImage(cl.Get("--reference"), reference, error) ||
    !ReadLinearImage(cl.Get("--mask"), mask, error))
  {
    std::cerr << "mesolight bench vlf-relief: " << error << "\n";
    return 1;
  }
  std::vector<Row> rows;
  for (const std::string& spec : SplitList(cl.Get("--images")))
  {
    Row row;
    if (!SplitNamed(spec, row.Name, row.File))
    {
      return cl.UsageError("--images takes NAME=FILE.exr,.. not '" + spec + "'");
    }
    rows.push_back(row);
  }
  if (cl.Has("--reference-2"))
  {
    rows.push_back({ "reference-noise", cl.Get("--reference-2"), {}, -1.0 });
  }
  for (const std::string& spec : SplitList(cl.Get("--times")))
  {
    std::string name, value;
    if (!SplitNamed(spec, name, value))
    {
      return cl.UsageError("--times takes NAME=SECONDS,.. not '" + spec + "'");
    }
    for (Row& row : rows)
    {
      if (row.Name == name)
      {
        row.Seconds = std::atof(value.c_str());
      }
    }
  }
  try
  {
    for (Row& row : rows)
    {
      RgbImage image;
      if (!ReadLinearImage(row.File, image, error))
      {
        std::cerr << "mesolight bench vlf-relief: " << error << "\n";
        return 1;
      }
      row.Error = MaskedRelativeError(image, reference, mask, coverage);
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "mesolight bench vlf-relief: " << e.what() << "\n";
    return 1;
  }
  const std::string label = cl.Get("--label");
  std::cout << "relief pixels: " << (rows.empty() ? 0 : rows[0].Error.Pixels)
            << " (coverage >= " << coverage << ")\n";
  std::cout << std::left << std::setw(22) << "image" << std::right << std::setw(12) << "mean rel."
            << std::setw(12) << "median" << std::setw(12) << "mean ratio" << std::setw(12)
            << "s/frame"
            << "\n";
  for (const Row& row : rows)
  {
    std::cout << std::left << std::setw(22) << row.Name << std::right << std::fixed
              << std::setprecision(4) << std::setw(12) << row.Error.MeanRelativeError
              << std::setw(12) << row.Error.MedianRelativeError << std::setw(12)
              << row.Error.MeanRatio << std::setw(12);
    if (row.Seconds >= 0.0)
    {
      std::cout << row.Seconds;
    }
    else
    {
      std::cout << "-";
    }
    std::cout << "\n";
  }
  bool pass = !rows.empty() && rows[0].Error.Pixels > 0 && rows[0].Error.MeanRelativeError <= goal;
  for (std::size_t k = 1; k < rows.size(); ++k)
  {
    if (rows[k].Name == "reference-noise")
    {
      continue;
    }
    const double factor =
      rows[k].Error.MeanRelativeError / std::max(rows[0].Error.MeanRelativeError, 1e-12);
    std::cout << rows[k].Name << " / " << rows[0].Name << ": " << std::setprecision(2) << factor
              << "x the error (goal >= " << margin << "x)\n";
    pass = pass && factor >= margin;
  }
  if (cl.Has("--cost-pair"))
  {
    const std::vector<std::string> pair = SplitList(cl.Get("--cost-pair"));
    const Row* a = nullptr;
    const Row* b = nullptr;
    for (const Row& row : rows)
    {
      a = pair.size() == 2 && row.Name == pair[0] ? &row : a;
      b = pair.size() == 2 && row.Name == pair[1] ? &row : b;
    }
    if (a && b && a->Seconds > 0.0 && b->Seconds > 0.0)
    {
      std::cout << "cost: " << a->Name << " / " << b->Name << " = " << std::setprecision(2)
                << a->Seconds / b->Seconds << " (time per frame, same run)\n";
    }
    else
    {
      std::cout << "cost: no times for --cost-pair " << cl.Get("--cost-pair") << "\n";
    }
  }
  std::cout << (pass ? "PASS" : "FAIL") << ": " << rows[0].Name << " within " << goal
            << " mean relative error and every other image at least " << margin << "x worse\n";
  if (cl.Has("--csv"))
  {
    const std::string csv = cl.Get("--csv");
    const bool fresh = !std::ifstream(csv).good();
    std::ofstream out(csv, std::ios::app);
    if (fresh)
    {
      out << "label,image,pixels,mean_relative_error,median_relative_error,mean_ratio,"
             "seconds_per_frame\n";
    }
    for (const Row& row : rows)
    {
      out << label << "," << row.Name << "," << row.Error.Pixels << ","
          << row.Error.MeanRelativeError << "," << row.Error.MedianRelativeError << ","
          << row.Error.MeanRatio << "," << row.Seconds << "\n";
    }
    if (!out)
    {
      std::cerr << "mesolight bench vlf-relief: cannot write " << csv << "\n";
      return 1;
    }
    std::cout << "wrote " << csv << "\n";
  }
  if (cl.Has("--plot"))
  {
    ScatterChart chart;
    chart.Title = "relief vs the path-traced dense mesh (" + label + ")";
    chart.XLabel = "image (order given)";
    chart.YLabel = "mean relative error per relief pixel";
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
      chart.Points.push_back(
        { rows[k].Name, { static_cast<double>(k + 1) }, { rows[k].Error.MeanRelativeError } });
    }
    chart.Line.Name = "goal";
    chart.Line.X = { 0.5, rows.size() + 0.5 };
    chart.Line.Y = { goal, goal };
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), error))
    {
      std::cerr << "mesolight bench vlf-relief: " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--plot") << "\n";
  }
  return pass ? 0 : 1;
}

} // namespace mesolight
