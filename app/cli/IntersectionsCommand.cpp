// `chute intersections RUN_DIR|SERIES.pvd|FRAME.vtu [--times t1,t2] [--expect-none] [--csv FILE]`:
// counts, per frame, the pairs of non-adjacent triangles that meet and the line segments that
// meet a triangle (mesh/IntersectionCheck.hpp), independently of any contact model.
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "VtuSeries.hpp"
#include "app/cli/Command.hpp"
#include "app/cli/RenderPlugin.hpp"
#include "render/IntersectionFrameFile.hpp"

namespace chute::cli {

namespace {

namespace fs = std::filesystem;

// The frames named by `path`: a .vtu alone (time NaN), a .pvd series, or a run directory that
// holds exactly one .pvd. Throws std::runtime_error naming the path.
std::vector<PvdEntry> framesOf(const std::string& path, fs::path& dir) {
  if (fs::is_regular_file(path) && fs::path(path).extension() == ".vtu") {
    dir = fs::path(path).parent_path();
    return {{std::nan(""), fs::path(path).filename().string()}};
  }
  fs::path pvd = path;
  if (fs::is_directory(path)) {
    std::vector<fs::path> found;
    for (const auto& e : fs::directory_iterator(path))
      if (e.path().extension() == ".pvd") found.push_back(e.path());
    if (found.empty())
      throw std::runtime_error(path +
                               ": no .pvd series (ask for one with [output.vtu] in the case)");
    if (found.size() > 1) throw std::runtime_error(path + ": more than one .pvd series");
    pvd = found[0];
  } else if (!fs::is_regular_file(path) || pvd.extension() != ".pvd") {
    throw std::runtime_error(path + ": expected a run directory, a .pvd series or a .vtu frame");
  }
  dir = pvd.parent_path();
  auto frames = readPvd(pvd.string());
  if (frames.empty()) throw std::runtime_error(pvd.string() + ": the series is empty");
  return frames;
}

}  // namespace

Command addIntersectionsCommand(CLI::App& app) {
  struct Args {
    std::string path, csv;
    std::vector<double> times;
    bool expectNone = false, quiet = false;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand(
      "intersections",
      "count intersecting pairs of non-adjacent triangles and of line segments and triangles in "
      "a run's frames (exact tests, independent of contact)");
  cmd->add_option("path", a->path, "run directory, .pvd series or .vtu frame")->required();
  cmd->add_option("--times", a->times, "times to check (nearest frames; default: every frame)")
      ->delimiter(',');
  cmd->add_flag("--expect-none", a->expectNone,
                "exit with status 6 if any checked frame has an intersection");
  cmd->add_option("--csv", a->csv, "also write the counts to this CSV file");
  cmd->add_flag("--quiet", a->quiet, "print only the last frame's summary line");
  return {
      cmd, [a] {
        fs::path dir;
        std::vector<PvdEntry> frames;
        try {
          frames = framesOf(a->path, dir);
        } catch (const std::runtime_error& e) {
          fmt::print(stderr, "chute: intersections: {}\n", e.what());
          return kExitBadInput;
        }
        std::vector<size_t> chosen;
        if (a->times.empty()) {
          for (size_t i = 0; i < frames.size(); ++i) chosen.push_back(i);
        } else {
          for (double t : a->times) {
            size_t best = 0;
            for (size_t i = 1; i < frames.size(); ++i)
              if (std::abs(frames[i].t - t) < std::abs(frames[best].t - t)) best = i;
            chosen.push_back(best);
          }
        }
        std::string rows = "t,triangle_pairs,segment_triangle,triangles,segments,file\n";
        if (!a->quiet)
          fmt::print("{:>10}  {:>14}  {:>16}  {:>9}  {:>8}  {}\n", "t", "triangle_pairs",
                     "segment_triangle", "triangles", "segments", "file");
        long any = 0;
        mesh::IntersectionCounts last;
        double lastT = 0.0;
        for (size_t i : chosen) {
          const std::string file = (dir / frames[i].file).string();
          mesh::IntersectionMesh m;
          try {
            m = render::readIntersectionMesh(file);
          } catch (const std::exception& e) {
            fmt::print(stderr, "chute: intersections: {}\n", e.what());
            return kExitBadInput;
          }
          last = mesh::countIntersections(m);
          lastT = frames[i].t;
          any += last.total();
          if (!a->quiet)
            fmt::print("{:>10.4f}  {:>14}  {:>16}  {:>9}  {:>8}  {}\n", frames[i].t,
                       last.trianglePairs, last.segmentTriangle, m.triangles.size(),
                       m.segments.size(), frames[i].file);
          rows += fmt::format("{},{},{},{},{},{}\n", frames[i].t, last.trianglePairs,
                              last.segmentTriangle, m.triangles.size(), m.segments.size(),
                              frames[i].file);
          std::fflush(stdout);
        }
        fmt::print(
            "last frame checked (t = {:g}): {} intersecting triangle pairs, {} segment-triangle "
            "pairs{}\n",
            lastT, last.trianglePairs, last.segmentTriangle,
            last.degenerateTriangles > 0
                ? fmt::format(" ({} degenerate triangles skipped)", last.degenerateTriangles)
                : "");
        if (!a->csv.empty()) {
          std::ofstream out(a->csv);
          out << rows;
          if (!out) {
            fmt::print(stderr, "chute: intersections: --csv: cannot write '{}'\n", a->csv);
            return kExitOutputFailed;
          }
        }
        if (a->expectNone && any > 0) {
          fmt::print(stderr, "chute: intersections: {} intersecting pairs over {} frames\n", any,
                     chosen.size());
          return kExitIntersections;
        }
        return 0;
      }};
}

}  // namespace chute::cli
