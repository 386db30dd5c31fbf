#include "render/ProbePlot.hpp"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRect.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkVector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "render/ImageOutput.hpp"
#include "render/ProbeCsv.hpp"
#include "render/Quantities.hpp"
#include "render/RunUnits.hpp"
#include "render/VirtualDisplay.hpp"

namespace chute::render {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::array<unsigned char, 3>, 8> kPalette = {{{31, 119, 180},
                                                                   {214, 39, 40},
                                                                   {44, 160, 44},
                                                                   {255, 127, 14},
                                                                   {148, 103, 189},
                                                                   {140, 86, 75},
                                                                   {227, 119, 194},
                                                                   {23, 190, 207}}};

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

struct Series {
  std::string label;
  vtkSmartPointer<vtkTable> table;
  int colour = 0;
  bool reference = false;
};

// A panel: the columns of one quantity, and its axis title.
struct Panel {
  Quantity quantity = Quantity::Unknown;
  std::string unit, title;
  std::vector<std::string> columns;
  std::vector<Series> series;
};

// The probe columns named in an error line: the first kListed, then how many there are (a file
// of 200,000 columns gave a line of 1.7 MB).
std::string columnList(const std::vector<std::string>& header) {
  constexpr size_t kListed = 40;
  std::string known;
  for (size_t i = 1; i < header.size() && i <= kListed; ++i)
    known += (i > 1 ? ", " : "") + header[i].substr(0, 200);
  if (header.size() > kListed + 1)
    known += ", ... (" + std::to_string(header.size() - 1) + " columns in all)";
  return known;
}

}  // namespace

void plotProbes(const PlotOptions& o) {
  if (o.runDirs.empty()) throw std::runtime_error("no run directory given");
  if (o.columns.empty()) throw std::runtime_error("no column given (--columns bead.x,bead.z)");
  if (const auto bad = imageSizeProblem(o.width, o.height))
    throw std::runtime_error("--size: " + *bad);
  // Each column's envelope over about one point per pixel of the plot's width.
  const auto buckets = static_cast<std::size_t>(o.width);

  std::vector<ProbeColumns> runs;
  UnitSystem units;
  for (const auto& dir : o.runDirs) {
    const std::string csv = (fs::path(dir) / "probes.csv").string();
    runs.push_back(readProbeColumns(csv, o.columns, buckets));
    const auto& header = runs.back().header;
    // Every panel is drawn against the time: a file whose first column is not `t` is not a run's
    // probes.csv (its first column was taken as the time whatever it held).
    if (!header.empty() && header[0] != "t")
      throw std::runtime_error(csv + ": its first column is '" + header[0].substr(0, 200) +
                               "', not the time 't' (not a probes.csv chute wrote)");
    for (const auto& c : o.columns) {
      if (!header.empty() && c == header[0])
        throw std::runtime_error("--columns: '" + c +
                                 "' is the time, the axis every panel is drawn against; name "
                                 "probe columns (" +
                                 columnList(header) + ")");
      if (std::none_of(runs.back().series.begin(), runs.back().series.end(),
                       [&](const ProbeSeries& s) { return s.name == c; }))
        throw std::runtime_error(csv + ": no column '" + c + "' (columns: " + columnList(header) +
                                 ")");
    }
    const UnitSystem u = runUnits(dir);
    if (runs.size() == 1)
      units = u;
    else if (u.note != units.note)
      throw std::runtime_error(dir + ": its units ('" + u.note + "') are not those of " +
                               o.runDirs[0] + " ('" + units.note + "'): one axis, two units");
  }
  ProbeColumns reference;
  if (!o.reference.empty()) {
    reference = readProbeColumns(o.reference, o.columns, buckets);
    if (reference.series.empty())
      throw std::runtime_error(o.reference + ": none of the requested columns");
  }

  // Panels: one per quantity (and unit), in the order the columns were asked; a column of
  // unknown quantity has a panel of its own (its unit is not known to match any other's).
  std::vector<Panel> panels;
  std::map<std::string, std::string> titleOf;
  for (const auto& c : o.columns) {
    const ColumnInfo info = probeColumn(c, runs[0].header);
    const std::string unit = unitOf(info.quantity, units);
    auto it = std::find_if(panels.begin(), panels.end(), [&](const Panel& p) {
      return info.quantity != Quantity::Unknown && p.quantity == info.quantity && p.unit == unit;
    });
    if (it == panels.end()) {
      panels.push_back({info.quantity, unit, info.title, {}, {}});
      it = panels.end() - 1;
    } else if (it->title != info.title) {
      it->title = quantityName(info.quantity);  // several measurements of one kind
    }
    if (std::find(it->columns.begin(), it->columns.end(), c) == it->columns.end())
      it->columns.push_back(c);
  }
  int colours = 0;
  for (auto& p : panels) {
    for (const auto& c : p.columns) {
      int first = -1;
      for (size_t r = 0; r < runs.size(); ++r) {
        for (const auto& s : runs[r].series) {
          if (s.name != c) continue;
          const std::string label =
              runs.size() > 1 ? fs::path(o.runDirs[r]).filename().string() + ": " + c : c;
          if (first < 0) first = colours;
          p.series.push_back({label, seriesTable(s.t, s.y, label), colours++, false});
        }
      }
      for (const auto& s : reference.series)
        if (s.name == c)
          p.series.push_back(
              {"reference: " + c, seriesTable(s.t, s.y, "reference: " + c), first, true});
    }
  }

  // Layout in pixels: a title, the panels stacked over the shared time axis, each legend to the
  // right of its axes, outside them.
  const int font = std::max(12, o.height / 48);
  size_t longest = 0;
  for (const auto& p : panels)
    for (const auto& s : p.series) longest = std::max(longest, s.label.size());
  const double legendWidth =
      std::min(0.4 * o.width, 0.62 * font * static_cast<double>(longest) + 3.5 * font);
  const double left = 6.5 * font, right = legendWidth + 1.5 * font, bottom = 3.4 * font;
  const double top = o.title.empty() ? 1.2 * font : 3.0 * font, gap = 2.2 * font;
  const auto n = static_cast<double>(panels.size());
  const double plotHeight = (o.height - top - bottom - (n - 1) * gap) / n;
  const double plotWidth = o.width - left - right;
  if (plotHeight < 3 * font || plotWidth < 6 * font)
    throw std::runtime_error("--size: " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                             " has no room for " + std::to_string(panels.size()) +
                             " panels (one per quantity): ask for a larger image or fewer "
                             "quantities");
  double t0 = std::numeric_limits<double>::infinity(), t1 = -t0;
  for (const auto& p : panels)
    for (const auto& s : p.series) {
      auto* t = vtkDoubleArray::SafeDownCast(s.table->GetColumn(0));
      for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
        if (std::isfinite(t->GetValue(i)))
          t0 = std::min(t0, t->GetValue(i)), t1 = std::max(t1, t->GetValue(i));
    }
  if (!(t1 > t0)) t0 = std::isfinite(t0) ? t0 - 0.5 : 0.0, t1 = t0 + 1.0;

  if (const std::string bad = imageFileProblem(o.out); !bad.empty()) throw std::runtime_error(bad);
  VirtualDisplay display;
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetMultiSamples(multiSamplesFor(o.width, o.height));
  view->GetRenderWindow()->SetSize(o.width, o.height);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  std::vector<std::pair<vtkChartLegend*, float>> legends;  // and the top of their axes
  for (size_t k = 0; k < panels.size(); ++k) {
    const Panel& p = panels[k];
    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);
    chart->SetLayoutStrategy(vtkChart::AXES_TO_RECT);
    const double y0 = bottom + (n - 1 - static_cast<double>(k)) * (plotHeight + gap);
    chart->SetSize(vtkRectf(static_cast<float>(left), static_cast<float>(y0),
                            static_cast<float>(plotWidth), static_cast<float>(plotHeight)));
    if (k == 0 && !o.title.empty()) {
      chart->SetTitle(o.title);
      chart->GetTitleProperties()->SetFontSize(font + 2);
      chart->GetTitleProperties()->SetBold(true);
    }
    vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
    x->SetTitle(k + 1 == panels.size() ? withUnit("t", Quantity::Time, units) : "");
    x->SetBehavior(vtkAxis::FIXED);
    x->SetRange(t0, t1);
    vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
    y->SetTitle(withUnit(p.title, p.quantity, units));
    for (vtkAxis* a : {x, y}) {
      a->GetTitleProperties()->SetFontSize(font);
      a->GetLabelProperties()->SetFontSize(font - 2);
    }
    // The legend outside the axes, right of them, its top at theirs: it covers no data. Its
    // anchor is its lower left corner; its height is known once drawn (below).
    chart->SetShowLegend(true);
    vtkChartLegend* legend = chart->GetLegend();
    legend->SetHorizontalAlignment(vtkChartLegend::CUSTOM);
    legend->SetVerticalAlignment(vtkChartLegend::CUSTOM);
    legend->SetLabelSize(font - 1);
    legend->SetPadding(8);  // the default 5 let the longest label touch the box
    legend->SetPoint(vtkVector2f(static_cast<float>(left + plotWidth + 0.8 * font),
                                 static_cast<float>(y0 + plotHeight)));
    legends.push_back({legend, static_cast<float>(y0 + plotHeight)});
    for (const auto& s : p.series) {
      vtkPlot* line = chart->AddPlot(vtkChart::LINE);
      line->SetInputData(s.table, 0, 1);
      // Two no-break spaces: VTK sizes the legend box to end at the longest label's last pixel.
      line->SetLabel(s.label + "\u00a0\u00a0");
      const auto& rgb = kPalette[static_cast<size_t>(std::max(0, s.colour)) % kPalette.size()];
      line->SetColor(rgb[0], rgb[1], rgb[2], 255);
      line->SetWidth(s.reference ? 1.5f : 2.5f);
      if (s.reference) line->GetPen()->SetLineType(vtkPen::DASH_LINE);
    }
  }
  view->GetRenderWindow()->Render();
  for (const auto& [legend, topY] : legends) {
    const vtkRectf box = legend->GetBoundingRect(view->GetContext());
    legend->SetPoint(vtkVector2f(legend->GetPointVector().GetX(), topY - box.GetHeight()));
  }
  view->GetRenderWindow()->Render();
  writeWindowPng(view->GetRenderWindow(), o.out);
}

}  // namespace chute::render
