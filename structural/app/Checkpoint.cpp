#include "app/Checkpoint.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace chute {

namespace {
constexpr int kFormat = 1;

// FNV-1a over raw bytes.
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
  nlohmann::json j;
  j["format"] = kFormat;
  j["case"] = c.caseName;
  j["model_hash"] = c.modelHash;
  j["t"] = c.state.t;
  j["x"] = toVector(c.state.x);
  j["v"] = toVector(c.state.v);
  j["a"] = toVector(c.state.a);
  j["dt"] = c.dt;
  j["event_step"] = c.eventStep;
  j["successes_since_cut"] = c.successesSinceCut;
  j["linear_solver_lu"] = c.linearSolverLU;
  j["probe_clock"] = c.probeClockIndex;
  j["vtu_clock"] = c.vtuClockIndex;
  j["vtu_last"] = c.vtuLast;
  j["active"] = c.active;
  j["handovers"] = c.handovers;
  j["splits"] = c.splits;
  j["steps"] = c.steps;
  j["rejected_steps"] = c.rejectedSteps;
  j["event_retries"] = c.eventRetries;
  j["newton_iterations"] = c.newtonIterations;
  j["max_newton_in_step"] = c.maxNewtonInStep;
  j["energy"] = {c.energyInitial, c.energyMaxDrift, c.kineticMax};
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(j);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<long>(bytes.size()));
    out.flush();
    if (!out) throw std::runtime_error("cannot write checkpoint " + tmp);
  }
  std::filesystem::rename(tmp, path);  // atomic: the old checkpoint stays until this one is whole
}

Checkpoint readCheckpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open checkpoint");
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                        std::istreambuf_iterator<char>()};
  Checkpoint c;
  try {
    const auto j = nlohmann::json::from_cbor(bytes);
    if (j.at("format").get<int>() != kFormat)
      throw std::runtime_error("unsupported checkpoint format");
    c.caseName = j.at("case").get<std::string>();
    c.modelHash = j.at("model_hash").get<std::uint64_t>();
    c.state.t = j.at("t").get<double>();
    c.state.x = fromVector(j.at("x").get<std::vector<double>>());
    c.state.v = fromVector(j.at("v").get<std::vector<double>>());
    c.state.a = fromVector(j.at("a").get<std::vector<double>>());
    c.dt = j.at("dt").get<double>();
    c.eventStep = j.at("event_step").get<double>();
    c.successesSinceCut = j.at("successes_since_cut").get<int>();
    c.linearSolverLU = j.at("linear_solver_lu").get<bool>();
    c.probeClockIndex = j.at("probe_clock").get<long>();
    c.vtuClockIndex = j.at("vtu_clock").get<long>();
    c.vtuLast = j.at("vtu_last").get<double>();
    c.active = j.at("active").get<std::vector<std::vector<int>>>();
    c.handovers = j.at("handovers").get<std::vector<long>>();
    if (j.contains("splits")) c.splits = j.at("splits").get<std::vector<std::vector<double>>>();
    c.steps = j.at("steps").get<long>();
    c.rejectedSteps = j.at("rejected_steps").get<long>();
    c.eventRetries = j.at("event_retries").get<long>();
    c.newtonIterations = j.at("newton_iterations").get<long>();
    c.maxNewtonInStep = j.at("max_newton_in_step").get<int>();
    const auto e = j.at("energy").get<std::vector<double>>();
    if (e.size() != 3) throw std::runtime_error("bad energy record");
    c.energyInitial = e[0], c.energyMaxDrift = e[1], c.kineticMax = e[2];
  } catch (const std::exception& ex) {
    throw std::runtime_error(path + ": not a chute checkpoint (" + ex.what() + ")");
  }
  if (c.state.x.size() != c.state.v.size() || c.state.x.size() != c.state.a.size())
    throw std::runtime_error(path + ": inconsistent state sizes");
  return c;
}

}  // namespace chute
