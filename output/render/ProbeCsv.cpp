#include "render/ProbeCsv.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "io/InputFile.hpp"

namespace chute::render {

void EnvelopeDecimator::add(double t, double y) {
  const Point p{t, y, count_++};
  if (inOpen_ == 0) open_ = Bucket{p, p, p, p, false, false};
  open_.last = p;
  if (!std::isnan(y)) {
    if (!open_.loSet || y < open_.lo.y) open_.lo = p, open_.loSet = true;
    if (!open_.hiSet || y > open_.hi.y) open_.hi = p, open_.hiSet = true;
  }
  if (++inOpen_ < perBucket_) return;
  done_.push_back(open_);
  inOpen_ = 0;
  if (done_.size() < 2 * max_) return;
  // Twice the buckets allowed: each pair becomes one, twice as long.
  for (std::size_t k = 0; k < done_.size() / 2; ++k)
    done_[k] = merged(done_[2 * k], done_[2 * k + 1]);
  done_.resize(done_.size() / 2);
  perBucket_ *= 2;
}

EnvelopeDecimator::Bucket EnvelopeDecimator::merged(const Bucket& a, const Bucket& b) {
  Bucket m = a;
  m.last = b.last;
  if (b.loSet && (!m.loSet || b.lo.y < m.lo.y)) m.lo = b.lo, m.loSet = true;
  if (b.hiSet && (!m.hiSet || b.hi.y > m.hi.y)) m.hi = b.hi, m.hiSet = true;
  return m;
}

void EnvelopeDecimator::points(std::vector<double>& t, std::vector<double>& y) const {
  t.clear(), y.clear();
  std::uint64_t lastIndex = ~std::uint64_t{0};
  auto emit = [&](const Point& p) {
    if (p.i == lastIndex) return;
    t.push_back(p.t), y.push_back(p.y), lastIndex = p.i;
  };
  auto bucket = [&](const Bucket& b) {
    emit(b.first);
    Point inner[2];
    int n = 0;
    if (b.loSet && b.lo.i != b.first.i && b.lo.i != b.last.i) inner[n++] = b.lo;
    if (b.hiSet && b.hi.i != b.first.i && b.hi.i != b.last.i && (n == 0 || b.hi.i != b.lo.i))
      inner[n++] = b.hi;
    if (n == 2 && inner[1].i < inner[0].i) std::swap(inner[0], inner[1]);
    for (int k = 0; k < n; ++k) emit(inner[k]);
    emit(b.last);
  };
  for (const auto& b : done_) bucket(b);
  if (inOpen_ > 0) bucket(open_);
}

namespace {

// A cell as a number: chute writes the shortest round-trip form ("0.25", "1e-05", "nan");
// spaces around it and a leading '+' are allowed. Subnormal values are numbers (chute writes
// them); an overflow (1e999) is not.
bool parseNumber(std::string_view cell, double& v) {
  while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
  while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t' || cell.back() == '\r'))
    cell.remove_suffix(1);
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  if (cell.empty()) return false;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (end != cell.data() + cell.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    v = std::strtod(std::string(cell).c_str(), nullptr);
    return std::abs(v) <= 1.0;  // an underflow, not an overflow
  }
  return ec == std::errc();
}

std::string clipped(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32) c = '?';
  if (s.size() > 40) out.append("...");
  return out;
}

}  // namespace

ProbeColumns readProbeColumns(const std::string& path, const std::vector<std::string>& wanted,
                              std::size_t buckets) {
  ProbeColumns out;
  const int fd = io::openInputFile(path, kMaxCsvBytes);
  std::vector<int> columnOf;  // for each asked column found: its index in a row
  std::vector<EnvelopeDecimator> kept;
  std::string pending;
  std::vector<char> buffer(1u << 20);
  long lineNo = 0;
  bool header = true;
  std::vector<double> row;
  auto fail = [&](long line, const std::string& why) {
    ::close(fd);
    throw std::runtime_error(path + ":" + std::to_string(line) + ": " + why);
  };
  auto handle = [&](std::string_view line) {
    ++lineNo;
    if (header) {
      header = false;
      std::size_t start = 0;
      while (true) {
        const std::size_t comma = line.find(',', start);
        std::string name(
            line.substr(start, comma == std::string_view::npos ? line.npos : comma - start));
        while (!name.empty() && (name.back() == '\r' || name.back() == ' ')) name.pop_back();
        out.header.push_back(name);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
      }
      for (const auto& w : wanted)
        for (std::size_t k = 1; k < out.header.size(); ++k)
          if (out.header[k] == w) {
            columnOf.push_back(static_cast<int>(k));
            out.series.push_back({w, {}, {}});
            kept.emplace_back(buckets);
            break;
          }
      return;
    }
    if (line.empty() || line == "\r") return;
    row.clear();
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      const std::string_view cell =
          line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
      if (row.size() == out.header.size()) fail(lineNo, "more values than columns");
      double v = 0.0;
      if (!parseNumber(cell, v)) {
        std::string why = "'";
        why.append(clipped(cell)).append("' is not a number");
        fail(lineNo, why);
      }
      row.push_back(v);
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (row.size() != out.header.size())
      fail(lineNo, std::to_string(row.size()) + " values, " + std::to_string(out.header.size()) +
                       " columns");
    ++out.rows;
    for (std::size_t k = 0; k < columnOf.size(); ++k) kept[k].add(row[0], row[columnOf[k]]);
  };
  while (true) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(lineNo + 1, std::string("cannot read: ") + std::strerror(errno));
    if (n == 0) break;
    std::string_view chunk(buffer.data(), static_cast<std::size_t>(n));
    while (!chunk.empty()) {
      const std::size_t nl = chunk.find('\n');
      if (nl == std::string_view::npos) {
        pending.append(chunk);
        if (pending.size() > kMaxCsvLine)
          fail(lineNo + 1, "a line longer than " + std::to_string(kMaxCsvLine) + " bytes");
        break;
      }
      if (pending.empty()) {
        handle(chunk.substr(0, nl));
      } else {
        pending.append(chunk.substr(0, nl));
        handle(pending);
        pending.clear();
      }
      chunk.remove_prefix(nl + 1);
    }
  }
  if (!pending.empty()) handle(pending);
  ::close(fd);
  if (header) throw std::runtime_error(path + ":1: empty file");
  for (std::size_t k = 0; k < kept.size(); ++k) kept[k].points(out.series[k].t, out.series[k].y);
  return out;
}

}  // namespace chute::render
