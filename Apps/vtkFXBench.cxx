#include "vtkFXBench.h"

#include "vtkFXScenes.h"

#include "vtkAxis.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlot.h"
#include "vtkPixelBufferObject.h"
#include "vtkPlotPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkTable.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace vtkFXBench
{
double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? -1.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

double PairedRatio(const std::vector<double>& a, const std::vector<double>& b)
{
  std::vector<double> ratios;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    if (b[i] > 0.0)
    {
      ratios.push_back(a[i] / b[i]);
    }
  }
  return Median(ratios);
}

bool OpenReport(const Options& o, const std::string& name, std::ofstream& csv, std::string& path,
  const std::string& extraColumns)
{
  path = o.Out + "/" + name + ".csv";
  csv.open(path.c_str());
  if (!csv)
  {
    std::cerr << "vtkfx-bench: cannot write " << path << "\n";
    return false;
  }
  csv << "scene,method,setting,ms,rmse,psnr" << (extraColumns.empty() ? "" : ",") << extraColumns
      << "\n";
  return true;
}

double RMSE(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    const double d = (static_cast<double>(a[i]) - b[i]) / 255.0;
    sum += d * d;
  }
  return a.empty() ? 0.0 : std::sqrt(sum / a.size());
}

std::vector<float> Download(vtkRenderWindow* window, vtkTextureObject* texture, int components)
{
  std::vector<float> values;
  if (!texture)
  {
    return values;
  }
  window->MakeCurrent();
  vtkPixelBufferObject* pbo = texture->Download();
  if (!pbo)
  {
    return values;
  }
  const size_t n = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() * components;
  values.resize(n);
  const void* data = pbo->MapPackedBuffer();
  if (pbo->GetType() == VTK_FLOAT)
  {
    std::copy_n(static_cast<const float*>(data), n, values.begin());
  }
  else
  {
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::transform(bytes, bytes + n, values.begin(), [](unsigned char b) { return b / 255.0f; });
  }
  pbo->UnmapPackedBuffer();
  pbo->Delete();
  return values;
}

double TimedRender(vtkRenderWindow* window, vtkTimerLog* timer)
{
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  return 1000.0 * timer->GetElapsedTime();
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(const Options& o)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(o.Width, o.Height);
  return window;
}

vtkSmartPointer<vtkRenderer> Stage(
  vtkRenderWindow* window, const std::string& input, std::string& error, double dataBounds[6])
{
  // The old scene's mappers and passes delete their GL names as they go,
  // in whichever context is current: this window's, not the one the last
  // frame of another window left current (whose buffers they would delete).
  window->MakeCurrent();
  window->GetRenderers()->RemoveAllItems();
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  window->AddRenderer(renderer);
  return vtkFXScenes::Populate(renderer, input, vtkFXScenes::Options(), error, dataBounds)
    ? renderer
    : nullptr;
}

std::string FileTag(const std::string& input)
{
  std::string tag = input.substr(input.find_last_of("/:") + 1);
  return tag.substr(0, tag.find('.'));
}

void WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}

void WriteRGBStrip(const std::vector<const std::vector<unsigned char>*>& images, int width,
  int height, const std::string& path)
{
  vtkNew<vtkImageData> strip;
  strip->SetDimensions(width * static_cast<int>(images.size()), height, 1);
  strip->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(strip->GetScalarPointer());
  for (size_t k = 0; k < images.size(); ++k)
  {
    for (int y = 0; y < height; ++y)
    {
      const size_t row = static_cast<size_t>(y) * width * 3;
      std::copy(images[k]->begin() + row, images[k]->begin() + row + 3 * width,
        out + (static_cast<size_t>(y) * images.size() + k) * width * 3);
    }
  }
  WritePNG(strip, path);
}

namespace
{
// An offscreen chart on white, titled, with a legend.
void SetUpChart(vtkContextView* view, vtkChartXY* chart, int width, int height,
  const std::string& title, const std::string& xTitle, const std::string& yTitle)
{
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(width, height);
  view->GetRenderer()->SetBackground(1, 1, 1);
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  chart->SetShowLegend(true);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
}

// Renders the chart and writes it as a PNG.
void SaveChart(vtkContextView* view, int width, int height, const std::string& path)
{
  view->GetRenderWindow()->Render();
  vtkNew<vtkImageData> image;
  std::vector<unsigned char> pixels = vtkFXScenes::Capture(view->GetRenderWindow());
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(pixels.begin(), pixels.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  vtkFXBench::WritePNG(image, path);
}
}

void WriteLinePlot(const std::vector<PlotLine>& lines, const std::string& title,
  const std::string& xTitle, const std::string& yTitle, const std::string& path)
{
  const int width = 900, height = 600;
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;
  SetUpChart(view, chart, width, height, title, xTitle, yTitle);
  for (const auto& line : lines)
  {
    vtkNew<vtkTable> table;
    vtkNew<vtkFloatArray> x, y;
    x->SetName("x");
    y->SetName(line.Name.c_str());
    for (size_t i = 0; i < line.X.size() && i < line.Y.size(); ++i)
    {
      x->InsertNextValue(static_cast<float>(line.X[i]));
      y->InsertNextValue(static_cast<float>(line.Y[i]));
    }
    table->AddColumn(x);
    table->AddColumn(y);
    vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(line.R, line.G, line.B, 255);
    plot->SetWidth(2.0);
  }
  SaveChart(view, width, height, path);
}

void WritePointsPlot(const std::vector<PlotFamily>& families, const std::vector<PlotPoint>& points,
  const std::string& title, const std::string& xTitle, const std::string& yTitle,
  const std::string& path)
{
  const int width = 900, height = 600;
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;
  SetUpChart(view, chart, width, height, title, xTitle, yTitle);
  for (size_t f = 0; f < families.size(); ++f)
  {
    const PlotFamily& family = families[f];
    vtkNew<vtkTable> table;
    vtkNew<vtkFloatArray> x, y;
    x->SetName("x");
    y->SetName(family.Name.c_str());
    for (const auto& p : points)
    {
      if (p.Family == static_cast<int>(f))
      {
        x->InsertNextValue(static_cast<float>(p.X));
        y->InsertNextValue(static_cast<float>(p.Y));
      }
    }
    table->AddColumn(x);
    table->AddColumn(y);
    vtkPlot* plot = chart->AddPlot(vtkChart::POINTS);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(family.R, family.G, family.B, 255);
    vtkPlotPoints::SafeDownCast(plot)->SetMarkerStyle(family.Marker);
    vtkPlotPoints::SafeDownCast(plot)->SetMarkerSize(8);
  }
  view->GetRenderWindow()->Render();
  // Labels: each point's setting beside it, placed from the axes' ranges
  // and screen positions of the rendered chart.
  vtkAxis* xAxis = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* yAxis = chart->GetAxis(vtkAxis::LEFT);
  const float* x0 = xAxis->GetPoint1();
  const float* x1 = xAxis->GetPoint2();
  const float* y0 = yAxis->GetPoint1();
  const float* y1 = yAxis->GetPoint2();
  for (const auto& p : points)
  {
    const PlotFamily& family = families[p.Family];
    const double fx =
      (p.X - xAxis->GetMinimum()) / std::max(1e-9, xAxis->GetMaximum() - xAxis->GetMinimum());
    const double fy =
      (p.Y - yAxis->GetMinimum()) / std::max(1e-9, yAxis->GetMaximum() - yAxis->GetMinimum());
    vtkNew<vtkTextActor> label;
    label->SetInput(p.Label.c_str());
    label->GetTextProperty()->SetFontSize(11);
    label->GetTextProperty()->SetColor(family.R / 255.0, family.G / 255.0, family.B / 255.0);
    // Right of the point, or left of it near the right border.
    const bool left = fx > 0.8;
    label->GetTextProperty()->SetJustification(left ? VTK_TEXT_RIGHT : VTK_TEXT_LEFT);
    label->SetDisplayPosition(static_cast<int>(x0[0] + fx * (x1[0] - x0[0])) + (left ? -6 : 6),
      static_cast<int>(y0[1] + fy * (y1[1] - y0[1])) - 4);
    view->GetRenderer()->AddActor2D(label);
  }
  SaveChart(view, width, height, path);
}
}
