#pragma once
// `--size WxH` of `chute plot` and `chute render`: each side 16 to kMaxImageSide pixels
// (docs/limits.md); 20000x20000 is 1.6 GB of pixels before anything is drawn.
#include <optional>
#include <string>

namespace chute::cli {

constexpr int kMaxImageSide = 8192;

// The reason `text` is not a size ("expected WxH, ...", "... more than 8192"), or nullopt with
// width and height set.
std::optional<std::string> parseImageSize(const std::string& text, int& width, int& height);

}  // namespace chute::cli
