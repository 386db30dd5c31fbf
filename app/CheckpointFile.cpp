#include "app/CheckpointFile.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "OutputFile.hpp"
#include "app/CborNesting.hpp"

namespace chute {

namespace {
constexpr int kFormat = 4;  // 4: membrane states with stress resultants, canopy-flow and contact
                            // histories; 3: every case key; 2: the solver's
// A checkpoint holds a few vectors of the model's size: anything far larger is not one.
constexpr std::uintmax_t kMaxBytes = std::uintmax_t{4} << 30;
// The deepest a checkpoint nests is 4 (payload, terms, a term's record, its lists); anything far
// deeper is refused before the recursive CBOR reader sees it (app/CborNesting.hpp).
constexpr int kMaxNesting = 16;

// FNV-1a over raw bytes: a fingerprint of the model, and the payload's checksum (it detects
// damage and edits, not a forger who recomputes it; the values are range-checked as well).
struct Fnv {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void add(const T& v) {
    add(&v, sizeof v);
  }
};

std::vector<double> toVector(const Eigen::VectorXd& v) {
  return {v.data(), v.data() + v.size()};
}
Eigen::VectorXd fromVector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<long>(v.size()));
}

nlohmann::json payloadOf(const Checkpoint& c) {
  const auto& s = c.stepping.snapshot.state;
  nlohmann::json j;
  j["case"] = c.caseName;
  j["model_hash"] = c.modelHash;
  j["settings"] = c.settings;
  j["t"] = s.t;
  j["x"] = toVector(s.x);
  j["v"] = toVector(s.v);
  j["a"] = toVector(s.a);
  j["dt"] = s.control.dt;
  j["event_step"] = s.control.eventStep;
  j["successes_since_cut"] = s.control.successesSinceCut;
  j["terms"] = nlohmann::json::array();
  const auto& snap = c.stepping.snapshot;
  for (size_t k = 0; k < snap.histories.size(); ++k)
    j["terms"].push_back({{"name", snap.termNames[k]},
                          {"reals", snap.histories[k].reals()},
                          {"ints", snap.histories[k].ints()}});
  j["linear_solver_lu"] = c.stepping.linearSolverLU;
  const auto& n = c.stepping.counters;
  j["counters"] = {n.steps, n.rejectedSteps, n.eventRetries, n.newtonIterations,
                   static_cast<long>(n.maxNewtonInStep)};
  const auto& o = c.output;
  j["output"] = {{"probe_rows", o.probeRows},
                 {"vtu_frames", o.vtuFrames},
                 {"probe_clock", o.probeClockIndex},
                 {"vtu_clock", o.vtuClockIndex},
                 {"vtu_last", o.vtuLast},
                 {"energy", {o.energyInitial, o.energyMaxDrift, o.kineticMax}}};
  return j;
}

// A number that must be finite (energies, times) or a count in [min, max].
double finite(const nlohmann::json& j, const char* key) {
  const double v = j.at(key).get<double>();
  if (!std::isfinite(v)) throw std::runtime_error(std::string(key) + " is not finite");
  return v;
}
long count(const nlohmann::json& v, const char* key, long min, long max) {
  if (!v.is_number_integer()) throw std::runtime_error(std::string(key) + " is not an integer");
  const long n = v.get<long>();
  if (n < min || n > max) throw std::runtime_error(std::string(key) + " out of range");
  return n;
}

Checkpoint checkpointOf(const nlohmann::json& j) {
  Checkpoint c;
  c.caseName = j.at("case").get<std::string>();
  c.modelHash = j.at("model_hash").get<std::uint64_t>();
  c.settings = j.at("settings").get<std::map<std::string, std::string>>();
  auto& s = c.stepping.snapshot.state;
  s.t = finite(j, "t");
  if (s.t < 0.0) throw std::runtime_error("t is negative (a run starts at t = 0)");
  s.x = fromVector(j.at("x").get<std::vector<double>>());
  s.v = fromVector(j.at("v").get<std::vector<double>>());
  s.a = fromVector(j.at("a").get<std::vector<double>>());
  s.control.dt = finite(j, "dt");
  s.control.eventStep = finite(j, "event_step");
  if (s.control.eventStep < 0.0) throw std::runtime_error("event_step is negative");
  s.control.successesSinceCut =
      static_cast<int>(count(j.at("successes_since_cut"), "successes_since_cut", 0, 1 << 20));
  for (const auto& t : j.at("terms")) {
    c.stepping.snapshot.termNames.push_back(t.at("name").get<std::string>());
    c.stepping.snapshot.histories.push_back(History::fromRecords(
        t.at("reals").get<std::vector<double>>(), t.at("ints").get<std::vector<std::int64_t>>()));
  }
  c.stepping.linearSolverLU = j.at("linear_solver_lu").get<bool>();
  const auto& n = j.at("counters");
  if (!n.is_array() || n.size() != 5) throw std::runtime_error("counters: 5 integers expected");
  // Counters a run can reach (a run is held to 1e9 steps, docs/limits.md; Newton to 1000
  // iterations a step), far from where the counting on would overflow: a forged 2^63 - 1 was
  // read and wrapped to a negative count (or, under a sanitizer, stopped the run).
  constexpr long kMaxSteps = 1'000'000'000'000L, kMaxIterations = 1'000'000'000'000'000L;
  c.stepping.counters.steps = count(n[0], "steps", 0, kMaxSteps);
  c.stepping.counters.rejectedSteps = count(n[1], "rejected_steps", 0, kMaxSteps);
  c.stepping.counters.eventRetries = count(n[2], "event_retries", 0, kMaxSteps);
  c.stepping.counters.newtonIterations = count(n[3], "newton_iterations", 0, kMaxIterations);
  c.stepping.counters.maxNewtonInStep =
      static_cast<int>(count(n[4], "max_newton_in_step", 0, 1 << 20));
  const auto& o = j.at("output");
  c.output.probeRows = count(o.at("probe_rows"), "probe_rows", 0, kMaxSteps);
  c.output.vtuFrames = count(o.at("vtu_frames"), "vtu_frames", 0, 1 << 30);
  c.output.probeClockIndex = count(o.at("probe_clock"), "probe_clock", 0, kMaxSteps);
  c.output.vtuClockIndex = count(o.at("vtu_clock"), "vtu_clock", 0, kMaxSteps);
  c.output.vtuLast = o.at("vtu_last").get<double>();  // -inf before the first frame
  if (std::isnan(c.output.vtuLast)) throw std::runtime_error("vtu_last is not a number");
  const auto e = o.at("energy").get<std::vector<double>>();
  if (e.size() != 3 || !std::isfinite(e[0]) || !std::isfinite(e[1]) || !std::isfinite(e[2]))
    throw std::runtime_error("energy: 3 finite numbers expected");
  c.output.energyInitial = e[0], c.output.energyMaxDrift = e[1], c.output.kineticMax = e[2];
  if (!(s.control.dt > 0.0) || s.control.eventStep < 0.0)
    throw std::runtime_error("step control out of range");
  if (s.x.size() != s.v.size() || s.x.size() != s.a.size())
    throw std::runtime_error("inconsistent state sizes");
  return c;
}
}  // namespace

std::uint64_t modelHash(const Model& m) {
  Fnv f;
  for (const auto& x : m.X) f.add(x.data(), 3 * sizeof(double));
  for (const auto& c : m.constraint) f.add(c.fixed);
  for (const auto& c : m.cables) f.add(c.a), f.add(c.b), f.add(c.L);
  for (const auto& g : m.groups) {
    f.add(g.chain.data(), g.chain.size() * sizeof(int));
    f.add(g.sliders.data(), g.sliders.size() * sizeof(int));
  }
  for (const auto& e : m.membranes) f.add(e.nodes);
  return f.h;
}

void writeCheckpoint(const std::string& path, const Checkpoint& c) {
  const std::vector<std::uint8_t> payload = nlohmann::json::to_cbor(payloadOf(c));
  Fnv sum;
  sum.add(payload.data(), payload.size());
  nlohmann::json j;
  j["format"] = kFormat;
  j["payload"] = nlohmann::json::binary(payload);
  j["checksum"] = sum.h;
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(j);
  // Synced before the rename: the old checkpoint stays until this one is whole on disk.
  replaceFile(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
              true);
}

Checkpoint readCheckpoint(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::is_regular_file(status))
    throw std::runtime_error(path + ": not a checkpoint file (missing or not a regular file)");
  if (std::filesystem::file_size(path, ec) > kMaxBytes || ec)
    throw std::runtime_error(path + ": too large to be a checkpoint");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open checkpoint");
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                        std::istreambuf_iterator<char>()};
  try {
    if (auto why = cborNestingProblem(bytes, kMaxNesting); !why.empty())
      throw std::runtime_error(why);
    const auto outer = nlohmann::json::from_cbor(bytes);
    if (!outer.is_object() || !outer.contains("format"))
      throw std::runtime_error("no format field");
    if (outer.at("format") != kFormat)
      throw std::runtime_error("format " + outer.at("format").dump() + ", this build reads " +
                               std::to_string(kFormat));
    const auto& payload = outer.at("payload").get_binary();
    Fnv sum;
    sum.add(payload.data(), payload.size());
    if (outer.at("checksum").get<std::uint64_t>() != sum.h)
      throw std::runtime_error("checksum mismatch: the file is damaged or was edited");
    if (auto why = cborNestingProblem(payload, kMaxNesting); !why.empty())
      throw std::runtime_error("payload: " + why);
    return checkpointOf(nlohmann::json::from_cbor(payload));
  } catch (const std::exception& ex) {
    throw std::runtime_error(path + ": not a valid chute checkpoint (" + ex.what() + ")");
  }
}

}  // namespace chute
