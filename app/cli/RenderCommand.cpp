// `chute render RUN_DIR [--times t1,t2 | --all] [--view side|below|iso] [--color FIELD]
//  [--compare OTHER_RUN_DIR] [--size WxH] [--out DIR]`: PNG snapshots, off-screen.
#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "app/cli/Command.hpp"
#include "app/cli/ImageSize.hpp"
#include "app/cli/RenderPlugin.hpp"
#include "render/ImageOutput.hpp"
#include "render/SnapshotRenderer.hpp"

namespace chute::cli {

Command addRenderCommand(CLI::App& app) {
  struct Args {
    render::SnapshotOptions o;
    std::string size = "1280x720";
    bool quiet = false;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("render", "render PNG snapshots of a run's VTU series");
  cmd->add_option("run_dir", a->o.runDir, "output directory of a run (holds <case>.pvd)")
      ->required();
  cmd->add_option("--times", a->o.times, "times to show (nearest frames; default: the last)")
      ->delimiter(',');
  cmd->add_flag("--all", a->o.allFrames, "every frame of the series");
  cmd->add_option("--view", a->o.view, "side, below or iso")->default_val("iso");
  cmd->add_option("--color", a->o.color,
                  "stress (membranes by max principal stress, lines by axial force) or one point "
                  "or cell field for everything (vectors by magnitude)")
      ->default_val("stress");
  cmd->add_flag("--cell-values", a->o.cellValues,
                "membrane fields element by element (default: averaged at the nodes for display)");
  cmd->add_option("--compare", a->o.compareDir, "a second run shown side by side");
  cmd->add_option("--size", a->size, "image size WxH")->default_val("1280x720");
  cmd->add_option("--out", a->o.outDir, "directory for the PNG files (default RUN_DIR/snapshots)")
      ->check(notEmptyPath());
  cmd->add_flag("--quiet", a->quiet, "do not list the files written");
  return {cmd, [a] {
            if (const auto bad = parseImageSize(a->size, a->o.width, a->o.height)) {
              fmt::print(stderr, "chute: render: --size: {}\n", *bad);
              return kExitBadInput;
            }
            if (a->o.outDir.empty()) a->o.outDir = a->o.runDir + "/snapshots";
            try {
              for (const auto& f : render::renderSnapshots(a->o))
                if (!a->quiet) fmt::print("{}\n", f);
            } catch (const render::ImageWriteError& e) {
              fmt::print(stderr, "chute: render: {}\n", e.what());
              return kExitRunFailed;
            } catch (const std::runtime_error& e) {
              fmt::print(stderr, "chute: render: {}\n", e.what());
              return kExitBadInput;
            }
            return 0;
          }};
}

}  // namespace chute::cli
