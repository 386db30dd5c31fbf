// `chute plot RUN_DIR... --columns a,b [--reference CSV] [--title T] [--size WxH] [--out PNG]`:
// probe time histories of one or several runs, overlaid.
#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "app/cli/Command.hpp"
#include "app/cli/ImageSize.hpp"
#include "app/cli/RenderPlugin.hpp"
#include "io/InputFile.hpp"
#include "render/ImageOutput.hpp"
#include "render/ProbeCsv.hpp"
#include "render/ProbePlot.hpp"

namespace chute::cli {

namespace {

// Why the inputs and output of a plot cannot be used, checked before any is read; "" if they can.
std::string problemOf(const render::PlotOptions& o) {
  namespace fs = std::filesystem;
  for (const auto& dir : o.runDirs) {
    const std::string csv = (fs::path(dir) / "probes.csv").string();
    if (const auto p = io::inputFileProblem(csv, render::kMaxCsvBytes)) return csv + ": " + *p;
  }
  if (!o.reference.empty())
    if (const auto p = io::inputFileProblem(o.reference, render::kMaxCsvBytes))
      return "--reference: " + o.reference + ": " + *p;
  if (fs::path(o.out).extension() != ".png" && !fs::is_directory(o.out))
    return "--out: " + o.out + ": name a .png file";
  if (const std::string bad = render::imageFileProblem(o.out); !bad.empty()) return "--out: " + bad;
  return "";
}

}  // namespace

Command addPlotCommand(CLI::App& app) {
  struct Args {
    render::PlotOptions o;
    std::string size = "1200x700";
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("plot", "plot probe columns of one or several runs to a PNG");
  cmd->add_option("run_dirs", a->o.runDirs, "run output directories (hold probes.csv)")->required();
  cmd->add_option("--columns", a->o.columns, "probe columns, e.g. bead.x,bead.z")
      ->delimiter(',')
      ->required();
  cmd->add_option("--reference", a->o.reference, "CSV with t and reference columns");
  cmd->add_option("--title", a->o.title, "chart title");
  cmd->add_option("--size", a->size,
                  "image size WxH (each side 16 to 8192, at most 33,554,432 pixels)")
      ->default_val("1200x700");
  cmd->add_option("--out", a->o.out, "PNG file")->default_val("plot.png")->check(notEmptyPath());
  return {cmd, [a] {
            if (const auto bad = parseImageSize(a->size, a->o.width, a->o.height)) {
              fmt::print(stderr, "chute: plot: --size: {}\n", *bad);
              return kExitBadInput;
            }
            if (const std::string bad = problemOf(a->o); !bad.empty()) {
              fmt::print(stderr, "chute: plot: {}\n", bad);
              return kExitBadInput;
            }
            try {
              render::plotProbes(a->o);
            } catch (const render::ImageWriteError& e) {
              fmt::print(stderr, "chute: plot: {}\n", e.what());
              return kExitRunFailed;
            } catch (const std::runtime_error& e) {
              fmt::print(stderr, "chute: plot: {}\n", e.what());
              return kExitBadInput;
            }
            std::error_code ec;
            if (std::filesystem::file_size(a->o.out, ec) == 0 || ec) {
              fmt::print(stderr, "chute: plot: {}: the image could not be written\n", a->o.out);
              return kExitRunFailed;
            }
            fmt::print("{}\n", a->o.out);
            return 0;
          }};
}

}  // namespace chute::cli
