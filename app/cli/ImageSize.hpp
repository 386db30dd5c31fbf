#pragma once
// `--size WxH` of `chute plot` and `chute render`: each side 16 to 8192 pixels and at most
// 2^25 pixels in all (render/ImageOutput.hpp, docs/limits.md: memory while drawing).
#include <optional>
#include <string>

namespace chute::cli {

// The reason `text` is not a size ("expected WxH, ...", "each side ...", "... pixels"), or
// nullopt with width and height set.
std::optional<std::string> parseImageSize(const std::string& text, int& width, int& height);

}  // namespace chute::cli
