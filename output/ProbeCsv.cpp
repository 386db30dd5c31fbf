#include "ProbeCsv.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <stdexcept>

#include "OutputError.hpp"
#include "OutputFile.hpp"

namespace chute {

namespace {

std::string headerOf(const std::vector<std::string>& columns) {
  std::string header = "t";
  for (const auto& c : columns) header += "," + c;
  return header + "\n";
}

// Lines of a file read through a fixed buffer, each at most maxLine bytes (a file of one endless
// line is refused, not read into memory).
class LineReader {
 public:
  LineReader(int fd, size_t maxLine) : fd_(fd), maxLine_(maxLine) {}
  // The next line without its '\n'; false at the end of the file. Throws when a line is too long.
  bool next(std::string& line) {
    line.clear();
    for (;;) {
      if (at_ == end_) {
        const ssize_t n = ::read(fd_, buf_, sizeof buf_);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw std::runtime_error(std::string("cannot read: ") + std::strerror(errno));
        if (n == 0) return !line.empty();
        at_ = 0, end_ = static_cast<size_t>(n);
      }
      const char* nl = static_cast<const char*>(std::memchr(buf_ + at_, '\n', end_ - at_));
      const size_t take = nl ? static_cast<size_t>(nl - (buf_ + at_)) : end_ - at_;
      if (line.size() + take > maxLine_) throw std::runtime_error("a line longer than any row");
      line.append(buf_ + at_, take);
      at_ += take;
      if (nl) {
        ++at_;
        return true;
      }
    }
  }

 private:
  int fd_;
  size_t maxLine_;
  char buf_[1 << 16];
  size_t at_ = 0, end_ = 0;
};

}  // namespace

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path) {
  fd_ = createOutputFile(path);
  const std::string header = headerOf(columns);
  try {
    writeAllAt(fd_, header, 0, path_);
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
  mark_.bytes = static_cast<off_t>(header.size());
  lastCheck_ = std::chrono::steady_clock::now();
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns,
                     long keepRows, const RowVisitor& kept)
    : path_(path) {
  const std::string header = headerOf(columns);
  // The old file, opened without following a link and only if it is a regular file.
  const int in = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  struct stat st {};
  if (in < 0 || ::fstat(in, &st) != 0 || !S_ISREG(st.st_mode)) {
    if (in >= 0) ::close(in);
    if (keepRows > 0)
      throw std::runtime_error(path + ": not a regular file with the rows of this run");
  }
  const std::string tmp = path + ".tmp";
  int out = -1;
  try {
    out = createOutputFile(tmp);
    writeAllAt(out, header, 0, tmp);
    off_t bytes = static_cast<off_t>(header.size());
    long rows = 0;
    double last = std::numeric_limits<double>::quiet_NaN();
    if (in >= 0) {
      // Each row: the time and one number per column, at most ~32 characters each.
      LineReader lines(in, 64 * (columns.size() + 1) + 256);
      std::string line;
      try {
        if (lines.next(line) && line + "\n" != header)
          throw std::runtime_error("its columns are not this case's probes");
        std::vector<double> values;
        while (rows < keepRows && lines.next(line)) {
          values.clear();
          const char* p = line.c_str();
          for (;;) {
            char* end = nullptr;
            values.push_back(std::strtod(p, &end));
            if (end == p || (*end != ',' && *end != '\0'))
              throw std::runtime_error("row " + std::to_string(rows + 1) +
                                       " is not a row of numbers");
            if (*end == '\0') break;
            p = end + 1;
          }
          if (values.size() != columns.size() + 1)
            throw std::runtime_error("row " + std::to_string(rows + 1) +
                                     " has the wrong number of columns");
          const std::string whole = line + "\n";
          writeAllAt(out, whole, bytes, tmp);
          bytes += static_cast<off_t>(whole.size());
          ++rows;
          last = values[0];
          if (kept) kept(values[0], std::vector<double>(values.begin() + 1, values.end()));
        }
      } catch (const OutputError&) {
        throw;
      } catch (const std::exception& e) {
        throw std::runtime_error(path + ": " + e.what() + " (not this run's output)");
      }
      ::close(in);
    }
    if (rows < keepRows)
      throw std::runtime_error(path + ": " + std::to_string(rows) +
                               " rows where the checkpoint was taken after " +
                               std::to_string(keepRows) + " (not this run's output)");
    if (::rename(tmp.c_str(), path.c_str()) != 0)
      throw OutputError(path + ": cannot replace: " + writeFailure(errno));
    fd_ = out;
    mark_ = {rows, bytes, last};
  } catch (const OutputError& e) {
    if (out >= 0) ::close(out);
    ::unlink(tmp.c_str());
    throw OutputError(std::string(e.what()) + "; " + path + " left as it was");
  } catch (...) {
    if (out >= 0) ::close(out);
    ::unlink(tmp.c_str());
    throw;
  }
  lastCheck_ = std::chrono::steady_clock::now();
}

CsvWriter::~CsvWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void CsvWriter::checkStillThere() {
  // An unlinked file takes writes without an error: its removal (the directory deleted under the
  // run) is looked for once a second.
  const auto now = std::chrono::steady_clock::now();
  if (now - lastCheck_ < std::chrono::seconds(1)) return;
  lastCheck_ = now;
  if (!stillLinked(fd_))
    throw OutputError(path_ + ": removed during the run (the output directory was deleted?)");
}

void CsvWriter::row(double t, const std::vector<double>& values) {
  checkStillThere();
  // Shortest text that reads back to the same double: the last row's time is the run's
  // final_time exactly (an event step ends at an arbitrary instant), and a restart cuts the
  // file at the checkpoint's time without ambiguity.
  std::string line = fmt::format("{}", t);
  for (double v : values) fmt::format_to(std::back_inserter(line), ",{}", v);
  line += '\n';
  try {
    writeAllAt(fd_, line, mark_.bytes, path_);
  } catch (const OutputError& e) {
    // Part of the row may have reached the file: cut it off, so the file ends with a whole row.
    const bool cut = ::ftruncate(fd_, mark_.bytes) == 0;
    throw OutputError(fmt::format("{}; the row at t = {} was not written{}", e.what(), t,
                                  cut ? "" : " (and could not be cut off the file)"));
  }
  mark_.bytes += static_cast<off_t>(line.size());
  ++mark_.rows;
  mark_.lastTime = t;
}

void CsvWriter::cutBackTo(const Mark& m) {
  if (m.rows >= mark_.rows) return;
  if (::ftruncate(fd_, m.bytes) != 0)
    throw OutputError(path_ + ": cannot cut back to row " + std::to_string(m.rows) + ": " +
                      writeFailure(errno));
  mark_ = m;
}

}  // namespace chute
