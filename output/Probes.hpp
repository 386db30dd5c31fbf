#pragma once
// Probe quantities of a run (docs/output.md: probes.csv, one column per "<probe>.<quantity>")
// and the CSV file they go to, flushed row by row so a run stopped half-way leaves valid rows.
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "OutputError.hpp"
#include "case/CaseSpec.hpp"
#include "solver/EquilibriumPoint.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

// The energy balance's figures a row writes (solver/EnergyMonitor.hpp; NaN without one).
struct ProbeBalance {
  double work = std::numeric_limits<double>::quiet_NaN();
  double balance = std::numeric_limits<double>::quiet_NaN();
};

class ProbeSet {
 public:
  ProbeSet(const Model& model, std::vector<ProbeSpec> probes);
  std::vector<std::string> columns() const;
  // The motion (positions, velocities, sliders) at s, the forces and strains at eq, where the
  // step's equations hold (solver/EquilibriumPoint.hpp); energy: the system's energy at eq (the
  // run needs it anyway for its drift: evaluated once).
  // balance: the energy balance's work and balance (solver/EnergyMonitor.hpp; NaN without one).
  std::vector<double> evaluate(const StructuralSystem& sys, const StructuralState& s,
                               const EquilibriumPoint& eq, const EnergyBreakdown& energy,
                               const ProbeBalance& balance = {}) const;
  const std::vector<ProbeSpec>& probes() const { return probes_; }
  // Offset of probe p's first column in an evaluate() row.
  int columnOffset(int p) const { return offset_[p]; }

 private:
  const Model* model_;
  std::vector<ProbeSpec> probes_;
  std::vector<int> offset_;
};

class CsvWriter {
 public:
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);
  // Continues the file of a restarted run: its first keepRows rows (those written up to the
  // checkpoint) are kept and returned through times and rows, whatever follows them is dropped.
  // Throws if the file has fewer rows or other columns (not the output of this run).
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, size_t keepRows,
            std::vector<double>& times, std::vector<std::vector<double>>& rows);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  void row(double t, const std::vector<double>& values);

 private:
  std::string path_;
  std::FILE* f_ = nullptr;
};

}  // namespace chute
