// `chute mesh parachute --gores N --diameter D --line-length L --element-size h --out FILE.msh
//  [--vent-diameter d] [--line-elements n] [--slider SIDE] [--payload-mass m] [--payload-box
//  a,b,c] [--riser-length l] [--start flat|folded|inflated] [--case FILE.toml]
//  [--units ft|si] [--speed V] [--altitude H] [--held] [--cloth-permeability cfm] [--pressure p]
//  [--ramp-time s] [--dt s] [--t-end s] [--config PARAMS.toml]`:
// a flat circular canopy with lines, slider and payload meshed with gmsh (docs/meshing.md).
// `chute mesh cluster --canopies 2|3 [the geometry and case options of mesh parachute]
//  [--spacing s] [--riser-length l] [--riser-elements n] [--payload-mass m]`: a cluster of
// parachutes on risers to one payload (ClusterGenerator.hpp).
// `chute mesh geo SCRIPT.geo --out FILE.msh [--timeout s] [--max-memory MiB]`: runs a gmsh script
// (which can run commands) and writes its mesh (GeoScript.hpp); the only way chute runs a .geo.
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <toml.hpp>
#include <vector>

#include "ClusterCaseWriter.hpp"
#include "ClusterGenerator.hpp"
#include "GeoScript.hpp"
#include "GmshSession.hpp"
#include "MeshError.hpp"
#include "MshReader.hpp"
#include "ParachuteCaseWriter.hpp"
#include "ParachuteGenerator.hpp"
#include "app/cli/Command.hpp"
#include "case/CaseSpec.hpp"
#include "case/RunLimits.hpp"
#include "case/TomlDepth.hpp"
#include "io/InputFile.hpp"

namespace chute::cli {

namespace {

// A case is written only if `chute run` would start it (docs/meshing.md): the reader and the
// limits judged before a run (an explicit run's steps at its stable step: a payload of 1e-6 on
// a box's corners gave a stable step of 5e-10 s, 4e9 steps). If not, the reason, with the option
// the limiting node belongs to, is thrown (KeptOutputs then removes the mesh and the case just
// written and puts back what they replaced).
void refuseCaseRunWouldRefuse(const std::string& caseFile) {
  int node = -1;
  CaseSpec spec;
  try {
    spec = readCase(caseFile);
    checkRunCanStart(spec, &node);
  } catch (const std::exception& e) {
    std::string why = e.what();
    const auto colon = why.find(": ");  // "case.toml:NN: key: reason": the file is ours, not theirs
    if (colon != std::string::npos && why.rfind(caseFile, 0) == 0) why = why.substr(colon + 2);
    // The option behind the node that sets the step: the payload's nodes are in its groups.
    std::string option;
    if (node >= 0)
      for (const auto& [set, nodes] : spec.model.nodeSets)
        if (set.find("payload") != std::string::npos &&
            std::find(nodes.begin(), nodes.end(), node) != nodes.end())
          option = "--payload-mass: ";
    throw std::invalid_argument(option + "the case would not run (nothing written): " + why);
  }
}

// Options from a TOML parameter file (key = option name without "--"), for the options the
// command line did not give. Returns an error message ("file:line: key: reason") or "".
std::string applyParameterFile(CLI::App& cmd, const std::string& file) {
  toml::value root;
  try {
    const std::string text = io::readInputFile(file, 1u << 20);
    if (const auto deep = tomlNestingProblem(text))
      return file + ":" + std::to_string(deep->line) + ": nested deeper than " +
             std::to_string(kMaxTomlDepth) + " levels";
    std::istringstream in(text);
    root = toml::parse(in, file);
  } catch (const toml::exception& e) {
    const std::string what = e.what();
    return file + ":" + std::to_string(e.location().line()) +
           ": malformed TOML: " + what.substr(0, what.find('\n'));
  } catch (const std::exception& e) {
    return e.what();
  }
  if (!root.is_table()) return file + ": not a TOML table";
  for (const auto& [key, value] : root.as_table()) {
    CLI::Option* opt = nullptr;
    try {
      opt = cmd.get_option("--" + key);
    } catch (const CLI::OptionNotFound&) {
    }
    const std::string where = file + ":" + std::to_string(value.location().line()) + ": " + key;
    if (!opt || key == "config") return where + ": not an option of chute mesh parachute";
    if (opt->count() > 0) continue;  // the command line wins
    // A number given as a TOML string ("8") is refused as the case reader refuses it: a parameter
    // file's types are TOML's, not the command line's text.
    const std::string type = opt->get_type_name();
    const bool numeric = type == "INT" || type == "UINT" || type == "FLOAT" || type == "NUMBER";
    if (numeric && (value.is_string() || (value.is_array() && !value.as_array().empty() &&
                                          value.as_array()[0].is_string())))
      return where + ": a number, not a string (write it without quotes)";
    std::vector<std::string> results;
    if (value.is_array()) {
      for (const auto& v : value.as_array())
        results.push_back(v.is_string() ? v.as_string().str : toml::format(v));
    } else {
      results.push_back(value.is_string() ? value.as_string().str : toml::format(value));
    }
    try {
      for (const auto& r : results) opt->add_result(r);
      opt->run_callback();
    } catch (const CLI::Error& e) {
      return where + ": " + e.what();
    }
  }
  return "";
}

// Two names of one file (the same path, or links to one existing file).
bool sameFile(const std::string& x, const std::string& y) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::weakly_canonical(x, ec) == fs::weakly_canonical(y, ec) && !ec) return true;
  return fs::exists(x, ec) && fs::exists(y, ec) && fs::equivalent(x, y, ec);
}

// Why `path` cannot be written as an output file ("" if it can): it must end in `extension`
// (when given), not be a directory, and its directory must exist, so that a mistyped path is
// refused before minutes of meshing rather than by the last write.
std::string outputPathProblem(const std::string& path, const std::string& extension) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!extension.empty() && fs::path(path).extension() != extension)
    return "'" + path + "': name a " + extension + " file";
  if (fs::is_directory(path, ec)) return "'" + path + "' is a directory";
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    return "'" + path + "': no directory " + parent.string();
  // Something there already is replaced only if it is a file (through links): writing into a
  // FIFO would wait for a reader for ever, and a link to nothing may lead to another output.
  if (fs::exists(fs::symlink_status(path, ec))) {
    const fs::file_status target = fs::status(path, ec);
    if (!fs::exists(target)) return "'" + path + "' is a link to nothing";
    if (!fs::is_regular_file(target)) return "'" + path + "' exists and is not a regular file";
  }
  return "";
}

// The files a generator writes over, kept aside until it has succeeded (exit-codes.md: a refused
// command leaves the files it names as they were): each existing one (the file a link leads to,
// the link left in place) renamed to a hidden name beside it, and put back, over whatever was
// written there, unless succeeded() is called.
class KeptOutputs {
 public:
  explicit KeptOutputs(const std::vector<std::string>& paths) {
    namespace fs = std::filesystem;
    for (const auto& path : paths) {
      if (path.empty()) continue;
      std::error_code ec;
      Kept k;
      k.existed = fs::exists(path, ec);
      k.target = k.existed ? fs::canonical(path, ec) : fs::path(path);
      if (ec) {
        restore();
        throw std::invalid_argument("'" + path + "': " + ec.message());
      }
      if (k.existed) {
        k.aside = k.target.parent_path() / ("." + k.target.filename().string() + ".chute-kept-" +
                                            std::to_string(::getpid()));
        fs::rename(k.target, k.aside, ec);
        if (ec) {
          restore();  // the ones already kept aside (no destructor runs for this one)
          throw std::invalid_argument("'" + path + "' cannot be replaced: " + ec.message());
        }
      }
      kept_.push_back(k);
    }
  }
  KeptOutputs(const KeptOutputs&) = delete;
  KeptOutputs& operator=(const KeptOutputs&) = delete;
  void succeeded() {
    std::error_code ec;
    for (const auto& k : kept_)
      if (k.existed) std::filesystem::remove(k.aside, ec);
    kept_.clear();
  }
  ~KeptOutputs() { restore(); }

 private:
  void restore() {
    std::error_code ec;
    for (const auto& k : kept_) {
      std::filesystem::remove(k.target, ec);
      if (k.existed) std::filesystem::rename(k.aside, k.target, ec);
    }
    kept_.clear();
  }
  struct Kept {
    std::filesystem::path target, aside;
    bool existed = false;
  };
  std::vector<Kept> kept_;
};

}  // namespace

std::function<int()> addMeshGeoCommand(CLI::App& mesh) {
  struct Args {
    std::string script, out;
    mesh::GeoScriptLimits limits;
  };
  auto a = std::make_shared<Args>();
  auto* g = mesh.add_subcommand(
      "geo",
      "run a gmsh script (.geo) and write its mesh. A gmsh script is a program: it can run "
      "shell commands (System) -- run only scripts you trust");
  g->add_option("script", a->script, "gmsh script (.geo)")->required();
  g->add_option("--out", a->out, "mesh to write (.msh, format 4.1)")
      ->required()
      ->check(notEmptyPath());
  g->add_option("--timeout", a->limits.seconds, "seconds the script may run")
      ->default_val(a->limits.seconds)
      ->check(CLI::Range(0.1, 86400.0));
  g->add_option("--max-memory", a->limits.memoryMiB, "MiB of address space gmsh may add")
      ->default_val(a->limits.memoryMiB)
      ->check(CLI::Range(64.0, 1048576.0));
  return [a] {
    if (sameFile(a->script, a->out)) {
      fmt::print(stderr, "chute: mesh geo: --out: '{}' is the script\n", a->out);
      return kExitBadInput;
    }
    if (const std::string bad = outputPathProblem(a->out, ""); !bad.empty()) {
      fmt::print(stderr, "chute: mesh geo: --out: {}\n", bad);
      return kExitBadInput;
    }
    fmt::print("{}: running the gmsh script (gmsh scripts can run commands)\n", a->script);
    std::fflush(stdout);
    mesh::GmshMesh m;
    try {
      KeptOutputs kept({a->out});
      m = mesh::meshGeoScript(a->script, a->out, a->limits);
      kept.succeeded();
    } catch (const mesh::MeshError& e) {
      fmt::print(stderr, "chute: mesh geo: {}\n", e.what());
      return kExitBadInput;
    } catch (const std::invalid_argument& e) {  // --out cannot be replaced (KeptOutputs)
      fmt::print(stderr, "chute: mesh geo: --out: {}\n", e.what());
      return kExitBadInput;
    }
    fmt::print("{}: {} nodes, {} physical groups\n", a->out, m.nodeTags.size(), m.groups.size());
    return 0;
  };
}

namespace {

// The options of one parachute's geometry and start (shared by `mesh parachute` and `mesh
// cluster`).
void addGeometryOptions(CLI::App* p, mesh::ParachuteSpec& s) {
  p->add_option("--gores", s.gores, "number of gores (and suspension lines)");
  p->add_option("--diameter", s.diameter, "nominal (flat) diameter of the canopy");
  p->add_option("--vent-diameter", s.ventDiameter, "vent diameter (0: none)")->default_val(0.0);
  p->add_option("--line-length", s.lineLength, "suspension line length, skirt to confluence");
  p->add_option("--line-elements", s.lineElements, "elements per line")->default_val(8);
  p->add_option("--element-size", s.elementSize, "canopy mesh size");
  p->add_option("--mesh-algorithm", s.meshAlgorithm,
                "gmsh Mesh.Algorithm: 6 Frontal-Delaunay, 5 Delaunay, 1 MeshAdapt")
      ->default_val(6);
  p->add_option("--max-elements", s.maxElements,
                "limit on the estimated number of elements (docs/limits.md)")
      ->default_val(s.maxElements);
  p->add_option("--slider", s.sliderSide, "slider: side of the square (grommets at the corners)");
  p->add_option("--slider-divisions", s.sliderDivisions, "quads along a slider edge")
      ->default_val(1);
  p->add_option("--start", s.start, "start configuration: flat, folded, inflated or packed")
      ->default_val("flat");
  p->add_option("--inflated-ratio", s.inflatedRatio,
                "inflated: projected diameter / D of the spherical-cap start")
      ->default_val(0.7);
  p->add_option("--bundle-radius", s.bundleRadius, "folded: packed canopy radius (default D/40)");
  p->add_option("--slider-drop", s.sliderDrop,
                "slider below the skirt at the start (default L/20)");
  p->add_option("--line-slack", s.lineSlack, "start slack of the longest line (fraction)")
      ->default_val(0.005);
  p->add_option("--pack-length", s.packLength, "packed: length of the bag (default D/12)");
  p->add_option("--pack-diameter", s.packDiameter, "packed: diameter of the bag (default D/25)");
  p->add_option("--pack-gap", s.packGap,
                "packed: least gap between layers of cloth (default 1 mm in the --units)");
}

struct Outputs {
  mesh::ParachuteCaseOptions caseOptions;
  std::string out, caseFile, config;
  bool quiet = false;
};

// The flight a generated parachute's case starts (docs/flight.md).
void addFlightOptions(CLI::App* p, Outputs& o) {
  p->add_option("--speed", o.caseOptions.speed,
                "case: the system's speed at line stretch, downward (held: the wind's), in the "
                "--units (default 20 m/s = 65.6 ft/s)");
  p->add_option("--altitude", o.caseOptions.altitude,
                "case: altitude of the standard atmosphere, in the --units (default 0)");
  p->add_flag(
      "--held", o.caseOptions.held,
      "case: the payload held in a steady wind of --speed (the wind tunnel, infinite mass)");
  p->add_option("--cloth-permeability", o.caseOptions.clothPermeability,
                "case: the cloth's air permeability, ft^3/ft^2/min at 0.5 in of water "
                "(default 100: MIL-C-7020 type I; 0: impermeable)")
      ->default_val(100.0);
}

void addOutputOptions(CLI::App* p, Outputs& o) {
  p->add_option("--config", o.config,
                "parameter file (TOML): option = value, names without '--'; the command line wins");
  p->add_option("--out", o.out, "output mesh (.msh, format 4.1)")->check(notEmptyPath());
  p->add_option("--case", o.caseFile, "also write a case file that runs the mesh")
      ->check(notEmptyPath());
  p->add_option("--units", o.caseOptions.units,
                "case: ft (ft, slug, s, lbf) or si (m, kg, s, N); the mesh's lengths are in them")
      ->default_val("ft")
      ->check(CLI::IsMember({"ft", "si"}));
  p->add_option("--pressure", o.caseOptions.pressure,
                "case: a constant canopy pressure in the frame of the falling payload instead of "
                "the airflow's loads (legacy; mesh cluster: its default 0.1 psf or 4.79 Pa)");
  p->add_option("--ramp-time", o.caseOptions.rampTime, "case: --pressure's ramp time")
      ->default_val(0.1);
  p->add_option("--t-end", o.caseOptions.tEnd, "case: end time")->default_val(2.0);
  p->add_option("--dt", o.caseOptions.dt, "case: time step")->default_val(2e-3);
  p->add_option("--probe-interval", o.caseOptions.probeInterval,
                "case: time between probes.csv rows")
      ->default_val(o.caseOptions.probeInterval);
  p->add_option("--vtu-interval", o.caseOptions.vtuInterval,
                "case: time between VTU frames (0: no series)")
      ->default_val(o.caseOptions.vtuInterval);
  p->add_flag("--quiet", o.quiet, "print nothing");
}

// The checks before meshing common to both verbs: the parameter file, the output names, the
// default gap of a packed start. Returns an exit status, or -1 to go on.
int prepare(CLI::App* p, Outputs& o, mesh::ParachuteSpec& spec, const std::string& verb) {
  if (!o.config.empty()) {
    if (const std::string e = applyParameterFile(*p, o.config); !e.empty()) {
      fmt::print(stderr, "chute: mesh {}: {}\n", verb, e);
      return kExitBadInput;
    }
  }
  if (o.out.empty()) {
    fmt::print(stderr, "chute: mesh {}: --out: give the .msh file to write\n", verb);
    return kExitBadInput;
  }
  if (const std::string bad = outputPathProblem(o.out, ".msh"); !bad.empty()) {
    fmt::print(stderr, "chute: mesh {}: --out: {}\n", verb, bad);
    return kExitBadInput;
  }
  if (!o.caseFile.empty())
    if (const std::string bad = outputPathProblem(o.caseFile, ""); !bad.empty()) {
      fmt::print(stderr, "chute: mesh {}: --case: {}\n", verb, bad);
      return kExitBadInput;
    }
  if (!o.caseFile.empty() && sameFile(o.caseFile, o.out)) {
    fmt::print(stderr, "chute: mesh {}: --case: '{}' is the --out mesh file\n", verb, o.caseFile);
    return kExitBadInput;
  }
  if (!o.config.empty() &&
      (sameFile(o.config, o.out) || (!o.caseFile.empty() && sameFile(o.config, o.caseFile)))) {
    fmt::print(stderr, "chute: mesh {}: --config: '{}' is an output file\n", verb, o.config);
    return kExitBadInput;
  }
  if (p->count("--pressure") && !std::isfinite(o.caseOptions.pressure)) {
    fmt::print(stderr, "chute: mesh {}: --pressure: must be finite\n", verb);
    return kExitBadInput;
  }
  // 1 mm: of the order of a contact thickness for cloth (docs/meshing.md, "Packed start").
  if (!p->count("--pack-gap")) spec.packGap = o.caseOptions.units == "si" ? 1e-3 : 1e-3 / 0.3048;
  return -1;
}

void printSingle(const mesh::GeneratedParachute& g, const std::string& what) {
  fmt::print(
      "  {}canopy area {:.6g} (flat pattern {:.6g}, {:+.3f} %), line length error {:.2e}, start "
      "stretch <= {:.6f}\n",
      what, g.canopyArea, g.flatArea, 100 * (g.canopyArea / g.flatArea - 1), g.maxLineLengthError,
      g.maxStartStretch);
}

std::function<int()> addMeshClusterCommand(CLI::App& mesh) {
  struct Args {
    mesh::ClusterSpec spec;
    Outputs o;
  };
  auto a = std::make_shared<Args>();
  auto* c = mesh.add_subcommand(
      "cluster", "two or three parachutes on risers to one payload (docs/meshing.md)");
  addGeometryOptions(c, a->spec.parachute);
  c->add_option("--canopies", a->spec.canopies, "2 or 3 canopies")->default_val(3);
  c->add_option("--spacing", a->spec.spacing,
                "canopy centres apart at the skirts (default 0.7 D: inflated canopies touch)");
  c->add_option("--riser-length", a->spec.riserLength,
                "payload to each confluence (default a third of the line length)");
  c->add_option("--riser-elements", a->spec.riserElements, "elements per riser")->default_val(4);
  c->add_option("--payload-mass", a->spec.payloadMass, "payload mass at the risers' meeting");
  addOutputOptions(c, a->o);
  return [a, c] {
    if (const int status = prepare(c, a->o, a->spec.parachute, "cluster"); status >= 0)
      return status;
    mesh::GeneratedCluster g;
    try {
      if (!a->o.caseFile.empty()) mesh::checkParachuteCaseOptions(a->o.caseOptions);
      KeptOutputs kept({a->o.out, a->o.caseFile});
      g = mesh::generateCluster(a->spec, a->o.out);
      if (!a->o.caseFile.empty()) {
        mesh::writeClusterCase(a->spec, g, a->o.caseFile, a->o.out, a->o.caseOptions);
        refuseCaseRunWouldRefuse(a->o.caseFile);
      }
      kept.succeeded();
    } catch (const std::invalid_argument& e) {
      fmt::print(stderr, "chute: mesh cluster: {}\n", e.what());
      return kExitBadInput;
    } catch (const std::runtime_error& e) {
      fmt::print(stderr, "chute: mesh cluster: {}\n", e.what());
      return kExitRunFailed;
    }
    if (!a->o.quiet) {
      fmt::print(
          "{}: {} canopies, {} nodes, {} groups; centres {:.4g} apart, axes tilted {:.2f} "
          "deg, risers {:.4g}\n",
          a->o.out, a->spec.canopies, g.mesh.nodeTags.size(), g.mesh.groups.size(), g.spacing,
          g.tilt * 180 / std::numbers::pi, g.riserLength);
      printSingle(g.single, "each: " + std::to_string(g.single.triangles) + " triangles, ");
      if (!a->o.caseFile.empty()) fmt::print("  case: {}\n", a->o.caseFile);
    }
    return 0;
  };
}

}  // namespace

Command addMeshCommand(CLI::App& app) {
  struct Args {
    mesh::ParachuteSpec spec;
    Outputs o;
    std::vector<double> box;
  };
  auto a = std::make_shared<Args>();
  auto* mesh = app.add_subcommand("mesh", "build meshes with gmsh");
  mesh->require_subcommand(1);
  const auto geoRun = addMeshGeoCommand(*mesh);
  const auto clusterRun = addMeshClusterCommand(*mesh);
  auto* p = mesh->add_subcommand("parachute", "flat circular canopy, lines, slider and payload");
  auto& s = a->spec;
  addGeometryOptions(p, s);
  p->add_option("--payload-mass", s.payloadMass,
                "payload mass (at the confluence, the riser's "
                "end or the box corners)");
  p->add_option("--payload-box", a->box, "payload box edge lengths a,b,c (braced trusses)")
      ->delimiter(',')
      ->expected(3);
  p->add_option("--riser-length", s.riserLength,
                "confluence to payload point (box: to each top corner)");
  p->add_option("--riser-elements", s.riserElements, "elements per riser")->default_val(1);
  addOutputOptions(p, a->o);
  addFlightOptions(p, a->o);
  return {mesh, [a, p, geoRun, clusterRun, mesh] {
            if (mesh->got_subcommand("geo")) return geoRun();
            if (mesh->got_subcommand("cluster")) return clusterRun();
            if (const int status = prepare(p, a->o, a->spec, "parachute"); status >= 0)
              return status;
            if (!a->box.empty()) a->spec.payloadBox = {a->box[0], a->box[1], a->box[2]};
            if (!a->o.caseFile.empty()) {
              // The case must be one `chute run` takes with its default limits (limits.md).
              a->spec.caseLimits.maxNodes = mesh::MshLimits{}.maxNodes;
              a->spec.caseLimits.maxElements = mesh::MshLimits{}.maxElements;
              a->spec.caseLimits.maxEquations =
                  static_cast<std::size_t>(CaseSpec{}.solver.maxEquations);
            }
            mesh::GeneratedParachute g;
            try {
              if (!a->o.caseFile.empty()) mesh::checkParachuteCaseOptions(a->o.caseOptions);
              KeptOutputs kept({a->o.out, a->o.caseFile});
              g = mesh::generateParachute(a->spec, a->o.out);
              if (!a->o.caseFile.empty()) {
                mesh::writeParachuteCase(a->spec, g, a->o.caseFile, a->o.out, a->o.caseOptions);
                refuseCaseRunWouldRefuse(a->o.caseFile);
              }
              kept.succeeded();
            } catch (const std::invalid_argument& e) {
              fmt::print(stderr, "chute: mesh parachute: {}\n", e.what());
              return kExitBadInput;
            } catch (const std::runtime_error& e) {  // gmsh, folding, unwritable files
              fmt::print(stderr, "chute: mesh parachute: {}\n", e.what());
              return kExitRunFailed;
            }
            if (!a->o.quiet) {
              fmt::print("{}: {} nodes, {} canopy triangles, {} groups, meshed in {:.2f} s\n",
                         a->o.out, g.mesh.nodeTags.size(), g.triangles, g.mesh.groups.size(),
                         g.meshSeconds);
              printSingle(g, "");
              if (!a->o.caseFile.empty()) fmt::print("  case: {}\n", a->o.caseFile);
            }
            return 0;
          }};
}

}  // namespace chute::cli
