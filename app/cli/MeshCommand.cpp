// `chute mesh parachute --gores N --diameter D --line-length L --element-size h --out FILE.msh
//  [--vent-diameter d] [--line-elements n] [--slider SIDE] [--payload-mass m] [--payload-box
//  a,b,c] [--riser-length l] [--start flat|folded|inflated] [--case FILE.toml]
//  [--units ft|si] [--pressure p] [--ramp-time s] [--dt s] [--t-end s] [--config PARAMS.toml]`:
// a flat circular canopy with lines, slider and payload meshed with gmsh (docs/meshing.md).
// `chute mesh geo SCRIPT.geo --out FILE.msh [--timeout s] [--max-memory MiB]`: runs a gmsh script
// (which can run commands) and writes its mesh (GeoScript.hpp); the only way chute runs a .geo.
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <toml.hpp>
#include <vector>

#include "GeoScript.hpp"
#include "GmshSession.hpp"
#include "MeshError.hpp"
#include "MshReader.hpp"
#include "ParachuteCaseWriter.hpp"
#include "ParachuteGenerator.hpp"
#include "app/cli/Command.hpp"
#include "case/CaseSpec.hpp"
#include "case/TomlDepth.hpp"
#include "io/InputFile.hpp"

namespace chute::cli {

namespace {

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
  return "";
}

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
  g->add_option("--out", a->out, "mesh to write (.msh, format 4.1)")->required();
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
    fmt::print("{}: running the gmsh script (gmsh scripts can run commands)\n", a->script);
    std::fflush(stdout);
    mesh::GmshMesh m;
    try {
      m = mesh::meshGeoScript(a->script, a->out, a->limits);
    } catch (const mesh::MeshError& e) {
      fmt::print(stderr, "chute: mesh geo: {}\n", e.what());
      return kExitBadInput;
    }
    fmt::print("{}: {} nodes, {} physical groups\n", a->out, m.nodeTags.size(), m.groups.size());
    return 0;
  };
}

Command addMeshCommand(CLI::App& app) {
  struct Args {
    mesh::ParachuteSpec spec;
    mesh::ParachuteCaseOptions caseOptions;
    std::vector<double> box;
    std::string out, caseFile, config;
    bool quiet = false;
  };
  auto a = std::make_shared<Args>();
  auto* mesh = app.add_subcommand("mesh", "build meshes with gmsh");
  mesh->require_subcommand(1);
  const auto geoRun = addMeshGeoCommand(*mesh);
  auto* p = mesh->add_subcommand("parachute", "flat circular canopy, lines, slider and payload");
  p->add_option("--config", a->config,
                "parameter file (TOML): option = value, names without '--'; the command line wins");
  auto& s = a->spec;
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
  p->add_option("--payload-mass", s.payloadMass,
                "payload mass (at the confluence, the riser's "
                "end or the box corners)");
  p->add_option("--payload-box", a->box, "payload box edge lengths a,b,c (braced trusses)")
      ->delimiter(',')
      ->expected(3);
  p->add_option("--riser-length", s.riserLength,
                "confluence to payload point (box: to each top corner)");
  p->add_option("--riser-elements", s.riserElements, "elements per riser")->default_val(1);
  p->add_option("--start", s.start, "start configuration: flat, folded or inflated")
      ->default_val("flat");
  p->add_option("--inflated-ratio", s.inflatedRatio,
                "inflated: projected diameter / D of the spherical-cap start")
      ->default_val(0.7);
  p->add_option("--bundle-radius", s.bundleRadius, "folded: packed canopy radius (default D/40)");
  p->add_option("--slider-drop", s.sliderDrop,
                "slider below the skirt at the start (default L/20)");
  p->add_option("--line-slack", s.lineSlack, "start slack of the longest line (fraction)")
      ->default_val(0.005);
  p->add_option("--out", a->out, "output mesh (.msh, format 4.1)");
  p->add_option("--case", a->caseFile, "also write a case file that runs the mesh");
  p->add_option("--units", a->caseOptions.units,
                "case: ft (ft, slug, s, lbf) or si (m, kg, s, N); the mesh's lengths are in them")
      ->default_val("ft")
      ->check(CLI::IsMember({"ft", "si"}));
  p->add_option("--pressure", a->caseOptions.pressure,
                "case: canopy pressure, the dynamic pressure of the descent (default 0.1 psf or "
                "4.79 Pa; 0: none)");
  p->add_option("--ramp-time", a->caseOptions.rampTime, "case: pressure ramp time")
      ->default_val(0.1);
  p->add_option("--t-end", a->caseOptions.tEnd, "case: end time")->default_val(2.0);
  p->add_option("--dt", a->caseOptions.dt, "case: time step")->default_val(2e-3);
  p->add_flag("--quiet", a->quiet, "print nothing");
  return {
      mesh, [a, p, geoRun] {
        if (!*p) return geoRun();
        if (!a->config.empty()) {
          if (const std::string e = applyParameterFile(*p, a->config); !e.empty()) {
            fmt::print(stderr, "chute: mesh parachute: {}\n", e);
            return kExitBadInput;
          }
        }
        if (a->out.empty()) {
          fmt::print(stderr, "chute: mesh parachute: --out: give the .msh file to write\n");
          return kExitBadInput;
        }
        if (const std::string bad = outputPathProblem(a->out, ".msh"); !bad.empty()) {
          fmt::print(stderr, "chute: mesh parachute: --out: {}\n", bad);
          return kExitBadInput;
        }
        if (!a->caseFile.empty())
          if (const std::string bad = outputPathProblem(a->caseFile, ""); !bad.empty()) {
            fmt::print(stderr, "chute: mesh parachute: --case: {}\n", bad);
            return kExitBadInput;
          }
        if (!a->caseFile.empty() && sameFile(a->caseFile, a->out)) {
          fmt::print(stderr, "chute: mesh parachute: --case: '{}' is the --out mesh file\n",
                     a->caseFile);
          return kExitBadInput;
        }
        if (!a->config.empty() && (sameFile(a->config, a->out) ||
                                   (!a->caseFile.empty() && sameFile(a->config, a->caseFile)))) {
          fmt::print(stderr, "chute: mesh parachute: --config: '{}' is an output file\n",
                     a->config);
          return kExitBadInput;
        }
        if (!a->box.empty()) a->spec.payloadBox = {a->box[0], a->box[1], a->box[2]};
        if (!a->caseFile.empty()) {
          // The case must be one `chute run` takes with its default limits (docs/limits.md).
          a->spec.caseLimits.maxNodes = mesh::MshLimits{}.maxNodes;
          a->spec.caseLimits.maxElements = mesh::MshLimits{}.maxElements;
          a->spec.caseLimits.maxEquations =
              static_cast<std::size_t>(CaseSpec{}.solver.maxEquations);
        }
        mesh::GeneratedParachute g;
        try {
          if (p->count("--pressure") && !std::isfinite(a->caseOptions.pressure))
            throw std::invalid_argument("--pressure: must be finite");
          if (!a->caseFile.empty()) mesh::checkParachuteCaseOptions(a->caseOptions);
          g = mesh::generateParachute(a->spec, a->out);
          if (!a->caseFile.empty()) {
            mesh::writeParachuteCase(a->spec, g, a->caseFile, a->out, a->caseOptions);
          }
        } catch (const std::invalid_argument& e) {
          fmt::print(stderr, "chute: mesh parachute: {}\n", e.what());
          return kExitBadInput;
        } catch (const std::runtime_error& e) {  // gmsh, folding, unwritable files
          fmt::print(stderr, "chute: mesh parachute: {}\n", e.what());
          return kExitRunFailed;
        }
        if (!a->quiet) {
          fmt::print("{}: {} nodes, {} canopy triangles, {} groups, meshed in {:.2f} s\n", a->out,
                     g.mesh.nodeTags.size(), g.triangles, g.mesh.groups.size(), g.meshSeconds);
          fmt::print(
              "  canopy area {:.6g} (flat pattern {:.6g}, {:+.3f} %), line length error "
              "{:.2e}, start stretch <= {:.6f}\n",
              g.canopyArea, g.flatArea, 100 * (g.canopyArea / g.flatArea - 1), g.maxLineLengthError,
              g.maxStartStretch);
          if (!a->caseFile.empty()) fmt::print("  case: {}\n", a->caseFile);
        }
        return 0;
      }};
}

}  // namespace chute::cli
