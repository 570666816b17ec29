// SPDX-License-Identifier: BSD-3-Clause
// Scatter plots with VTK charts (vtkContextView + vtkChartXY), rendered offscreen to PNG.
#ifndef mesolight_ChartPlot_h
#define mesolight_ChartPlot_h

#include <cstddef>
#include <string>
#include <vector>

namespace mesolight
{

struct ChartSeries
{
  std::string Name;
  std::vector<double> X;
  std::vector<double> Y;
};

struct ScatterChart
{
  std::string Title;
  std::string XLabel;
  std::string YLabel;
  bool LogY = false;
  double YFloor = 1e-3;            // with LogY, smaller values (and zero) are drawn at this value
  std::vector<ChartSeries> Points; // one marker style and colour each, in the legend
  ChartSeries Line;                // drawn as a line (e.g. a Pareto front) when not empty
  int Width = 1100;
  int Height = 750;
};

/** Renders the chart offscreen and writes it as PNG; false with a message on failure. */
bool WriteScatterChartPng(
  const ScatterChart& chart, const std::string& fileName, std::string& error);

/**
 * Indices of the Pareto-optimal points when both x and y are minimized (no other point is at
 * least as good in both and better in one), sorted by increasing x.
 */
std::vector<size_t> ParetoFront(const std::vector<double>& x, const std::vector<double>& y);

} // namespace mesolight

#endif
