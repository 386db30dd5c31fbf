#include "render/ProbePlot.hpp"

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
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "io/InputFile.hpp"
#include "render/VirtualDisplay.hpp"

namespace chute::render {

namespace fs = std::filesystem;

int CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  CsvTable t;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ":1: empty file");
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');) {
    while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
    t.names.push_back(cell);
  }
  t.columns.resize(t.names.size());
  int lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line == "\r") continue;
    std::stringstream row(line);
    size_t k = 0;
    for (std::string cell; std::getline(row, cell, ','); ++k) {
      if (k >= t.names.size())
        throw std::runtime_error(path + ":" + std::to_string(lineNo) +
                                 ": more values than columns");
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(cell.c_str(), &end);
      // ERANGE with a small result is an underflow: chute writes subnormal numbers (%.17g).
      if (end == cell.c_str() || (errno == ERANGE && std::abs(v) > 1.0))
        throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": '" + cell +
                                 "' is not a number");
      t.columns[k].push_back(v);
    }
    if (k != t.names.size())
      throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " + std::to_string(k) +
                               " values, " + std::to_string(t.names.size()) + " columns");
  }
  return t;
}

namespace {
constexpr std::array<std::array<unsigned char, 3>, 8> kPalette = {{{31, 119, 180},
                                                                   {214, 39, 40},
                                                                   {44, 160, 44},
                                                                   {255, 127, 14},
                                                                   {148, 103, 189},
                                                                   {140, 86, 75},
                                                                   {227, 119, 194},
                                                                   {23, 190, 207}}};

// The units line of the run's summary.json, if it has one (a run stopped early may have none).
// Read through io::readInputFile like probes.csv: a FIFO or /dev/zero named summary.json would
// otherwise block or never end.
std::string unitsOf(const std::string& runDir) {
  const std::string path = (fs::path(runDir) / "summary.json").string();
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec)) || ec) return {};
  const std::string text = io::readInputFile(path, std::uintmax_t{1} << 20);
  try {
    const auto j = nlohmann::json::parse(text);
    return j.value("units", std::string());
  } catch (const std::exception&) {
    return {};
  }
}

vtkSmartPointer<vtkTable> seriesTable(const std::vector<double>& t, const std::vector<double>& y,
                                      const std::string& name) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> tx, vy;
  tx->SetName("t");
  vy->SetName(name.c_str());
  for (size_t i = 0; i < t.size(); ++i) tx->InsertNextValue(t[i]), vy->InsertNextValue(y[i]);
  table->AddColumn(tx);
  table->AddColumn(vy);
  return table;
}
}  // namespace

void plotProbes(const PlotOptions& o) {
  if (o.runDirs.empty()) throw std::runtime_error("no run directory given");
  if (o.columns.empty()) throw std::runtime_error("no column given (--columns bead.x,bead.z)");
  struct Series {
    std::string label;
    vtkSmartPointer<vtkTable> table;
    bool reference = false;
  };
  std::vector<Series> series;
  std::string units;
  for (const auto& dir : o.runDirs) {
    const CsvTable csv = readCsv((fs::path(dir) / "probes.csv").string());
    if (units.empty()) units = unitsOf(dir);
    const std::string run = fs::path(dir).filename().string();
    for (const auto& c : o.columns) {
      const int k = csv.column(c);
      if (k < 0) {
        std::string known;
        for (size_t i = 1; i < csv.names.size(); ++i) known += (i > 1 ? ", " : "") + csv.names[i];
        throw std::runtime_error(dir + "/probes.csv: no column '" + c + "' (columns: " + known +
                                 ")");
      }
      const std::string label = o.runDirs.size() > 1 ? run + ": " + c : c;
      series.push_back({label, seriesTable(csv.columns[0], csv.columns[k], label), false});
    }
  }
  if (!o.reference.empty()) {
    const CsvTable ref = readCsv(o.reference);
    bool any = false;
    for (const auto& c : o.columns) {
      const int k = ref.column(c);
      if (k < 0) continue;
      any = true;
      const std::string label = "reference: " + c;
      series.push_back({label, seriesTable(ref.columns[0], ref.columns[k], label), true});
    }
    if (!any) throw std::runtime_error(o.reference + ": none of the requested columns");
  }

  VirtualDisplay display;
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(o.width, o.height);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  std::string title = o.title;
  if (!units.empty()) title += (title.empty() ? "" : "   ") + std::string("units: ") + units;
  chart->SetTitle(title);
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("t");
  std::string yTitle;
  for (const auto& c : o.columns) yTitle += (yTitle.empty() ? "" : ", ") + c;
  chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  size_t colour = 0;
  for (const auto& s : series) {
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(s.table, 0, 1);
    line->SetLabel(s.label);
    const auto& rgb = kPalette[s.reference ? 7 : colour++ % 7];
    line->SetColor(rgb[0], rgb[1], rgb[2], 255);
    line->SetWidth(s.reference ? 1.5f : 2.5f);
    if (s.reference) line->GetPen()->SetLineType(vtkPen::DASH_LINE);
  }
  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->ReadFrontBufferOff();
  grab->Update();
  if (const auto parent = fs::path(o.out).parent_path(); !parent.empty())
    fs::create_directories(parent);
  vtkNew<vtkPNGWriter> png;
  png->SetFileName(o.out.c_str());
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  if (!fs::exists(o.out)) throw std::runtime_error("cannot write " + o.out);
}

}  // namespace chute::render
