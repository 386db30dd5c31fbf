#pragma once
// The columns of a probes.csv (or a reference CSV) that a plot asks for, read in one pass with
// bounded memory: the file is streamed (a 900 MiB probes.csv ran `chute plot` out of 4 GiB when it
// was held whole), only the asked columns are kept, and each is kept as the envelope of its
// curve -- the first, least, largest and last point of each run of rows -- over at most about
// 2 x `buckets` runs: what a plot `buckets` pixels wide can show, exactly; a file of no more than
// 2 x `buckets` rows keeps every row. Every value of every row is still checked (a file with a
// non-number anywhere is refused naming its line).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace chute::render {

// One column over time, as kept (t ascending as in the file).
struct ProbeSeries {
  std::string name;
  std::vector<double> t, y;
};

struct ProbeColumns {
  std::vector<std::string> header;  // every column of the file, the first being the time
  std::vector<ProbeSeries> series;  // the asked columns the file has, in the order asked
  std::uint64_t rows = 0;
};

// Keeps the envelope of a curve given point by point (see above).
class EnvelopeDecimator {
 public:
  explicit EnvelopeDecimator(std::size_t buckets) : max_(buckets < 1 ? 1 : buckets) {}
  void add(double t, double y);
  // The kept points in the order they came.
  void points(std::vector<double>& t, std::vector<double>& y) const;
  std::uint64_t rowsPerBucket() const { return perBucket_; }

 private:
  struct Point {
    double t = 0.0, y = 0.0;
    std::uint64_t i = 0;
  };
  struct Bucket {
    Point first, last, lo, hi;
    bool loSet = false, hiSet = false;
  };
  static Bucket merged(const Bucket& a, const Bucket& b);
  std::vector<Bucket> done_;
  Bucket open_;
  std::uint64_t perBucket_ = 1, inOpen_ = 0, count_ = 0;
  std::size_t max_;
};

// Largest probes.csv or reference CSV a plot reads (docs/limits.md), and longest line.
inline constexpr std::uintmax_t kMaxCsvBytes = 1ull << 30;
inline constexpr std::size_t kMaxCsvLine = 16u << 20;

// Reads the columns `wanted` of the CSV at `path` (first column: the time). Throws
// std::runtime_error "path:line: reason" for anything that is not a header and rows of numbers.
ProbeColumns readProbeColumns(const std::string& path, const std::vector<std::string>& wanted,
                              std::size_t buckets);

}  // namespace chute::render
