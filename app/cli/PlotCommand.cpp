// `chute plot RUN_DIR... --columns a,b [--reference CSV] [--title T] [--size WxH] [--out PNG]`:
// probe time histories of one or several runs, overlaid.
#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "app/cli/Command.hpp"
#include "render/ProbePlot.hpp"

namespace chute::cli {

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
  cmd->add_option("--size", a->size, "image size WxH")->default_val("1200x700");
  cmd->add_option("--out", a->o.out, "PNG file")->default_val("plot.png");
  return {cmd, [a] {
            if (std::sscanf(a->size.c_str(), "%dx%d", &a->o.width, &a->o.height) != 2 ||
                a->o.width < 16 || a->o.height < 16) {
              fmt::print(stderr, "chute: --size: expected WxH, got '{}'\n", a->size);
              return kExitBadInput;
            }
            try {
              render::plotProbes(a->o);
            } catch (const std::runtime_error& e) {
              fmt::print(stderr, "chute: plot: {}\n", e.what());
              return kExitBadInput;
            }
            fmt::print("{}\n", a->o.out);
            return 0;
          }};
}

}  // namespace chute::cli
