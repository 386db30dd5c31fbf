#pragma once
// The images `chute render` and `chute plot` draw: their size limits, derived from a memory
// budget, and how a finished image reaches its file.
//
// Memory: an off-screen VTK render window costs about 37 bytes a pixel while it draws (colour and
// depth buffers, the image read back, the PNG), 61 with 4x multisampling (measured on the C-9
// series: 1,397 MB at 8192 x 4096 without, 655 MB at 4096 x 2048 with). An image has at most
// kMaxImagePixels pixels (about 1.4 GB at most), and is multisampled (smooth edges) up to
// kMultisamplePixels (about 0.65 GB); a 4K image is. docs/limits.md.
#include <optional>
#include <stdexcept>
#include <string>

class vtkRenderWindow;

namespace chute::render {

inline constexpr int kMinImageSide = 16;
inline constexpr int kMaxImageSide = 8192;
inline constexpr long kMaxImagePixels = 1L << 25;     // 33,554,432: 8192 x 4096, 5792 x 5792
inline constexpr long kMultisamplePixels = 1L << 23;  // 8,388,608: 4096 x 2048, 3840 x 2160

// Why an image of w x h pixels is not drawn ("each side must be 16 to 8192 pixels", "... more
// than 33554432 pixels"), or nullopt.
std::optional<std::string> imageSizeProblem(int width, int height);

// The multisampling of a window of w x h pixels: 4 up to kMultisamplePixels, then none.
int multiSamplesFor(int width, int height);

// Why `path` cannot receive an image, checked before anything is drawn ("" if it can): an
// existing path must be a regular file (a FIFO would block the write, a symbolic link would
// write through to its target), its directory must exist.
std::string imageFileProblem(const std::string& path);

// An image drawn but not written (a full disk, a file that became a FIFO): the run of the verb
// failed after it started (exit status 3), unlike bad input.
class ImageWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads the window's image back and writes it to `path` as PNG: encoded in memory, written to a
// new file in the same directory and renamed over `path` (a symbolic link there is replaced, not
// written through; a FIFO never opened; a reader or a concurrent writer of the same path never
// sees a part-written file). Throws ImageWriteError naming the file.
void writeWindowPng(vtkRenderWindow* window, const std::string& path);

}  // namespace chute::render
