#pragma once
// `chute plot`: time histories of probe columns from one or several runs, overlaid, to a PNG
// (VTK's chart module, off-screen), with an optional reference curve read from a CSV file whose
// first column is t. One quantity per panel: the columns are grouped by what they measure
// (render/Quantities.hpp), each group in a panel of its own, its axis titled with the quantity
// and the unit of the case's `units` ("skirt radius (ft)"); the panels share the time axis
// ("t (s)"). Each panel's legend stands outside its axes, on the right, where it covers no data.
// The probes are streamed (render/ProbeCsv.hpp): memory does not grow with the file.
#include <string>
#include <vector>

namespace chute::render {

struct PlotOptions {
  std::vector<std::string> runDirs;  // each holds probes.csv (and summary.json for the units)
  std::vector<std::string> columns;  // probe columns, e.g. bead.x
  std::string reference;             // optional CSV: t, then columns named like the probes'
  std::string title;
  std::string out = "plot.png";
  int width = 1200, height = 700;
};

// Throws std::runtime_error naming the file (and line) or the option at fault.
void plotProbes(const PlotOptions& options);

}  // namespace chute::render
