#pragma once
// `chute plot`: time histories of probe columns from one or several runs, overlaid, to a PNG
// (VTK's chart module, off-screen), with a legend, the case's units, and an optional reference
// curve read from a CSV file whose first column is t.
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

struct CsvTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;   // columns[0] is t
  int column(const std::string& name) const;  // -1 if absent
};
// Reads a numeric CSV with a header row; throws std::runtime_error naming the file and line.
CsvTable readCsv(const std::string& path);

void plotProbes(const PlotOptions& options);

}  // namespace chute::render
