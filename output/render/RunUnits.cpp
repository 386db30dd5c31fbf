#include "render/RunUnits.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/InputFile.hpp"

namespace chute::render {

UnitSystem runUnits(const std::string& runDir) {
  namespace fs = std::filesystem;
  const std::string path = (fs::path(runDir) / "summary.json").string();
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec)) || ec) return parseUnits("");
  const std::string text = io::readInputFile(path, std::uintmax_t{1} << 20);
  try {
    const auto j = nlohmann::json::parse(text);
    return parseUnits(j.value("units", std::string()));
  } catch (const std::exception&) {
    return parseUnits("");
  }
}

}  // namespace chute::render
