#pragma once
// What a term remembers from one step to the next, as an exact record: the numbers it wrote, in
// the order it wrote them (doubles bit for bit). A term's save() writes its committed history,
// load() reads it back and checks every value it reads (a checkpoint file may be forged).
// Checkpoints, coupling windows and step rejection all go through this one record
// (StructuralSystem::saveState), so a term with history that save/load misses cannot pass
// tests/structural/solver/test_history.cpp.
#include <Eigen/Core>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace chute {

class HistoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class History {
 public:
  void put(double v) { reals_.push_back(v); }
  void put(std::int64_t v) { ints_.push_back(v); }
  void put(int v) { ints_.push_back(v); }
  void put(bool v) { ints_.push_back(v ? 1 : 0); }
  void put(const std::vector<double>& v);
  void put(const std::vector<int>& v);
  void put(const Eigen::VectorXd& v);

  const std::vector<double>& reals() const { return reals_; }
  const std::vector<std::int64_t>& ints() const { return ints_; }
  static History fromRecords(std::vector<double> reals, std::vector<std::int64_t> ints);
  bool empty() const { return reals_.empty() && ints_.empty(); }
  bool operator==(const History& o) const;

 private:
  std::vector<double> reals_;
  std::vector<std::int64_t> ints_;
};

// Reads a History in the order it was written; every read is checked (HistoryError names the
// owner and what was wrong).
class HistoryReader {
 public:
  HistoryReader(const History& h, std::string owner) : h_(&h), owner_(std::move(owner)) {}
  double real();
  double finiteReal();
  std::int64_t integer(std::int64_t min, std::int64_t max);
  int index(int size) { return static_cast<int>(integer(0, size - 1)); }
  bool flag() { return integer(0, 1) != 0; }
  std::vector<double> reals(size_t expectedSize);
  std::vector<int> ints(size_t expectedSize, int min, int max);
  Eigen::VectorXd vector(long expectedSize);  // expectedSize < 0: empty or any size
  // Every value was read (a record longer than the term expects is another term's).
  void finish() const;
  [[noreturn]] void fail(const std::string& what) const;

 private:
  const History* h_;
  std::string owner_;
  size_t r_ = 0, i_ = 0;
};

}  // namespace chute
