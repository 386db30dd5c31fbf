#pragma once
// probes.csv as a run writes it (docs/output.md): a header, then one row per output time, each
// row written whole in one write. Rows go to disk as they come and are not kept: a run of any
// length holds none of them in memory. A failed write (a full disk, a file size limit) cuts the
// file back to its last whole row and says which; a file removed under the run (its directory
// deleted) is noticed within a second and reported the same way.
#include <sys/types.h>

#include <chrono>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace chute {

class CsvWriter {
 public:
  // A new file (whatever was at the path is replaced, never written through: OutputFile.hpp).
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);
  // Continues the file of a restarted run: its first keepRows rows (those written up to the
  // checkpoint) are kept, each passed to `kept` as it is read (nothing else holds them), and
  // whatever follows them is dropped. Throws std::runtime_error before changing the file if it has
  // fewer rows, other columns or rows that are not numbers (not the output of this run).
  using RowVisitor = std::function<void(double t, const std::vector<double>& values)>;
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, long keepRows,
            const RowVisitor& kept);
  ~CsvWriter();
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  // Appends a row. Throws OutputError when it cannot be written whole; the file then ends with
  // the previous row.
  void row(double t, const std::vector<double>& values);

  // Where the file stands: whole rows, their bytes, the time of the last one (NaN: none).
  struct Mark {
    long rows = 0;
    off_t bytes = 0;
    double lastTime = std::numeric_limits<double>::quiet_NaN();
  };
  Mark mark() const { return mark_; }
  // Cuts the file back to an earlier mark (the rows after it are dropped).
  void cutBackTo(const Mark& m);
  const std::string& path() const { return path_; }

 private:
  void checkStillThere();
  std::string path_;
  int fd_ = -1;
  Mark mark_;
  std::chrono::steady_clock::time_point lastCheck_{};
};

}  // namespace chute
