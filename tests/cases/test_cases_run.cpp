// Every case in cases/ runs a few steps, so that no case rots.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/RunCase.hpp"
#include "case/CaseSpec.hpp"

using namespace chute;

TEST(ShippedCases, EveryCaseRunsAFewSteps) {
  int count = 0;
  for (const auto& e : std::filesystem::directory_iterator(CHUTE_SOURCE_DIR "/cases")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    CaseSpec spec = readCase(e.path().string());
    if (spec.solver.type == AnalysisType::Dynamic)
      spec = readCase(e.path().string(), {"solver.t_end=" + std::to_string(5 * spec.solver.dt)});
    const auto r = runCase(spec, RunOptions{});
    std::printf("%-40s %s, %ld steps, %.2f Newton iterations/step\n", e.path().filename().c_str(),
                std::string(runStatusName(r.status)).c_str(), r.steps, r.newtonPerStep());
    EXPECT_EQ(r.status, RunStatus::Completed);
    ++count;
  }
  EXPECT_GE(count, 3);
}
