#pragma once
// A validating view of one TOML table: typed accessors that remember every key they were asked
// for, range checks, and finish(), which rejects keys nobody asked for with a did-you-mean.
// Every error names file, line and the key's dotted path.
#include <Eigen/Core>
#include <set>
#include <string>
#include <toml.hpp>
#include <vector>

#include "case/CaseError.hpp"

namespace chute {

class TomlTable {
 public:
  TomlTable(const toml::value& table, std::string path, std::string file);

  bool has(const std::string& key) const;
  const std::string& path() const { return path_; }
  const toml::value& raw() const { return *table_; }

  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  double positive(const std::string& key);
  double positive(const std::string& key, double fallback);
  double nonNegative(const std::string& key, double fallback);
  long integer(const std::string& key, long fallback, long min, long max);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed);
  Eigen::Vector3d vec3(const std::string& key);
  Eigen::Vector3d vec3(const std::string& key, const Eigen::Vector3d& fallback);
  std::vector<std::string> strings(const std::string& key);
  std::vector<std::string> strings(const std::string& key,
                                   const std::vector<std::string>& fallback);
  std::vector<long> integers(const std::string& key);

  TomlTable table(const std::string& key);
  std::vector<TomlTable> tables(const std::string& key);  // array of tables; empty if absent
  // Every key of this table (for tables whose keys are names, such as [nodes]).
  std::vector<std::string> keys() const;

  // Fails for the first of `keys` present: keys of the schema that this table's choices leave
  // unused ("not used <why>", e.g. why = "by static runs"), so they are not reported as unknown.
  void notUsed(const std::vector<std::string>& keys, const std::string& why) const;
  // Throws for the first key present that was never asked for (with a did-you-mean).
  void finish() const;
  // The same, counting `known` as asked (checks a table's keys before reading it).
  void finish(const std::vector<std::string>& known) const;

  // Key recorder, for the test that keeps docs/case-files.md in step with the readers: while a
  // sink is set, every key any table is asked for (has, a typed read, notUsed, finish(known)) is
  // added to it by its schema path: array elements as "[]", names as "<name>" (tables read
  // through keys(), such as [materials] and [nodes]), e.g. "loads.pressure[].set",
  // "materials.<name>.E". Null (the default) records nothing. Not thread-safe: tests only.
  static void recordKeysInto(std::set<std::string>* sink) { recorder_ = sink; }

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  [[noreturn]] void failAt(const toml::value& v, const std::string& key,
                           const std::string& message) const;
  // "file:line: path.key" ("--set k=v: path.key" for a value given on the command line).
  std::string where(const std::string& key) const;

 private:
  const toml::value& at(const std::string& key) const;
  std::string dotted(const std::string& key) const;
  // Marks `key` as asked (and records its schema path when a recorder is set).
  void ask(const std::string& key) const;
  std::string schemaOf(const std::string& key) const;
  const toml::value* table_;
  std::string path_, file_;
  std::string schema_;              // path_ with indices as "[]" and names as "<name>"
  mutable bool namedKeys_ = false;  // keys() was asked: this table's keys are names
  mutable std::set<std::string> asked_;
  inline static std::set<std::string>* recorder_ = nullptr;
};

// Levenshtein distance, for did-you-mean suggestions.
int editDistance(const std::string& a, const std::string& b);

}  // namespace chute
