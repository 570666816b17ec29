// SPDX-License-Identifier: BSD-3-Clause
#include "ChartPlot.h"

#include <vtkAutoInit.h>
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <numeric>

// The OpenGL context device of vtkContextView and the interactor style its view sets up.
// mesolight_application is a static library, so the executables' autoinit does not reach the
// chart code: register them here.
VTK_MODULE_INIT(vtkRenderingContextOpenGL2);
VTK_MODULE_INIT(vtkInteractionStyle);

namespace mesolight
{
namespace
{
// Colours that stay apart for up to 16 series, then repeat with another marker.
const unsigned char Palette[][3] = { { 31, 119, 180 }, { 255, 127, 14 }, { 44, 160, 44 },
  { 214, 39, 40 }, { 148, 103, 189 }, { 140, 86, 75 }, { 227, 119, 194 }, { 127, 127, 127 },
  { 188, 189, 34 }, { 23, 190, 207 }, { 0, 0, 128 }, { 128, 0, 0 }, { 0, 128, 128 },
  { 255, 200, 0 }, { 90, 200, 120 }, { 0, 0, 0 } };
const int Markers[] = { vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
  vtkPlotPoints::CROSS, vtkPlotPoints::PLUS };

vtkSmartPointer<vtkTable> MakeTable(const ChartSeries& series, const ScatterChart& chart)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> x, y;
  x->SetName(chart.XLabel.empty() ? "x" : chart.XLabel.c_str());
  y->SetName(series.Name.empty() ? "y" : series.Name.c_str());
  const size_t n = std::min(series.X.size(), series.Y.size());
  for (size_t i = 0; i < n; ++i)
  {
    x->InsertNextValue(series.X[i]);
    y->InsertNextValue(chart.LogY ? std::max(series.Y[i], chart.YFloor) : series.Y[i]);
  }
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}
} // namespace

//------------------------------------------------------------------------------
bool WriteScatterChartPng(
  const ScatterChart& chart, const std::string& fileName, std::string& error)
{
  vtkNew<vtkContextView> view;
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkRenderWindow* window = view->GetRenderWindow();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(chart.Width, chart.Height);

  vtkNew<vtkChartXY> xy;
  view->GetScene()->AddItem(xy);
  xy->SetTitle(chart.Title);
  xy->GetTitleProperties()->SetFontSize(16);
  xy->GetAxis(vtkAxis::BOTTOM)->SetTitle(chart.XLabel);
  xy->GetAxis(vtkAxis::LEFT)->SetTitle(chart.YLabel);
  xy->GetAxis(vtkAxis::LEFT)->SetLogScale(chart.LogY);
  xy->SetShowLegend(true);
  xy->GetLegend()->SetInline(false);
  xy->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  xy->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);

  std::vector<vtkSmartPointer<vtkTable>> tables; // kept alive until the render
  if (chart.Line.X.size() >= 2) // a line of one point draws nothing (and VTK warns)
  {
    tables.push_back(MakeTable(chart.Line, chart));
    vtkPlot* line = xy->AddPlot(vtkChart::LINE);
    line->SetInputData(tables.back(), 0, 1);
    line->SetColor(0, 0, 0, 160);
    line->SetWidth(1.5);
    line->GetPen()->SetLineType(vtkPen::DASH_LINE);
    line->SetLabel(chart.Line.Name);
  }
  for (size_t s = 0; s < chart.Points.size(); ++s)
  {
    const ChartSeries& series = chart.Points[s];
    if (series.X.empty())
    {
      continue;
    }
    tables.push_back(MakeTable(series, chart));
    auto* points = vtkPlotPoints::SafeDownCast(xy->AddPlot(vtkChart::POINTS));
    if (!points)
    {
      error = "chart: could not add a point plot";
      return false;
    }
    points->SetInputData(tables.back(), 0, 1);
    const unsigned char* c = Palette[s % 16];
    points->SetColor(c[0], c[1], c[2], 255);
    points->SetMarkerStyle(Markers[(s / 16 + s) % 5]);
    points->SetMarkerSize(9.0);
    points->SetLabel(series.Name);
  }

  // Fixed ranges with a margin, so no marker sits on the frame.
  double xMin = 0.0, xMax = 0.0, yMin = 0.0, yMax = 0.0;
  bool first = true;
  for (const ChartSeries& series : chart.Points)
  {
    for (size_t i = 0; i < std::min(series.X.size(), series.Y.size()); ++i)
    {
      const double y = chart.LogY ? std::max(series.Y[i], chart.YFloor) : series.Y[i];
      xMin = first ? series.X[i] : std::min(xMin, series.X[i]);
      xMax = first ? series.X[i] : std::max(xMax, series.X[i]);
      yMin = first ? y : std::min(yMin, y);
      yMax = first ? y : std::max(yMax, y);
      first = false;
    }
  }
  if (!first)
  {
    const double dx = std::max(xMax - xMin, 1e-3 * std::max(1.0, std::abs(xMax)));
    xy->GetAxis(vtkAxis::BOTTOM)->SetBehavior(vtkAxis::FIXED);
    xy->GetAxis(vtkAxis::BOTTOM)->SetRange(std::max(0.0, xMin - 0.06 * dx), xMax + 0.06 * dx);
    vtkAxis* left = xy->GetAxis(vtkAxis::LEFT);
    left->SetBehavior(vtkAxis::FIXED);
    if (chart.LogY)
    {
      left->SetUnscaledRange(yMin / 1.8, yMax * 1.8);
    }
    else
    {
      const double dy = std::max(yMax - yMin, 1e-6);
      left->SetRange(yMin - 0.06 * dy, yMax + 0.06 * dy);
    }
  }

  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(fileName.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error = "chart: could not write " + fileName;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<size_t> ParetoFront(const std::vector<double>& x, const std::vector<double>& y)
{
  const size_t n = std::min(x.size(), y.size());
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(),
    [&](size_t a, size_t b) { return x[a] < x[b] || (x[a] == x[b] && y[a] < y[b]); });
  std::vector<size_t> front;
  double best = 0.0;
  for (size_t i : order)
  {
    if (front.empty() || y[i] < best)
    {
      front.push_back(i);
      best = y[i];
    }
  }
  return front;
}

} // namespace mesolight
