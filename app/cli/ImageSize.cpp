#include "app/cli/ImageSize.hpp"

#include <regex>

#include "render/ImageOutput.hpp"

namespace chute::cli {

std::optional<std::string> parseImageSize(const std::string& text, int& width, int& height) {
  static const std::regex kSize(R"(([0-9]{1,6})x([0-9]{1,6}))");
  std::smatch m;
  if (!std::regex_match(text, m, kSize)) return "expected WxH in pixels, got '" + text + "'";
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (const auto bad = render::imageSizeProblem(w, h)) return *bad;
  width = w;
  height = h;
  return std::nullopt;
}

}  // namespace chute::cli
