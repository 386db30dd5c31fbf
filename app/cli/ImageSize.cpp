#include "app/cli/ImageSize.hpp"

#include <regex>

namespace chute::cli {

std::optional<std::string> parseImageSize(const std::string& text, int& width, int& height) {
  static const std::regex kSize(R"(([0-9]{1,6})x([0-9]{1,6}))");
  std::smatch m;
  if (!std::regex_match(text, m, kSize)) return "expected WxH in pixels, got '" + text + "'";
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 16 || h < 16 || w > kMaxImageSide || h > kMaxImageSide)
    return "each side must be 16 to " + std::to_string(kMaxImageSide) + " pixels, got '" + text +
           "'";
  width = w;
  height = h;
  return std::nullopt;
}

}  // namespace chute::cli
