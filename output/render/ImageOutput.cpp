#include "render/ImageOutput.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace chute::render {

std::optional<std::string> imageSizeProblem(int width, int height) {
  if (width < kMinImageSide || height < kMinImageSide || width > kMaxImageSide ||
      height > kMaxImageSide)
    return "each side must be " + std::to_string(kMinImageSide) + " to " +
           std::to_string(kMaxImageSide) + " pixels, got " + std::to_string(width) + "x" +
           std::to_string(height);
  if (long(width) * long(height) > kMaxImagePixels)
    return std::to_string(width) + "x" + std::to_string(height) + " is " +
           std::to_string(long(width) * long(height)) + " pixels, more than the " +
           std::to_string(kMaxImagePixels) + " an image may have (about 1.4 GB while drawn; " +
           "e.g. 8192x4096 or 5792x5792)";
  return std::nullopt;
}

int multiSamplesFor(int width, int height) {
  return long(width) * long(height) <= kMultisamplePixels ? 4 : 0;
}

std::string imageFileProblem(const std::string& path) {
  namespace fs = std::filesystem;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode)) return path + ": is a symbolic link: refused (name the file itself)";
    if (S_ISDIR(st.st_mode)) return path + ": is a directory; name a .png file";
    if (!S_ISREG(st.st_mode))
      return path + ": is not a regular file (FIFO, device or socket): refused";
  }
  std::error_code ec;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    return path + ": no directory " + parent.string();
  return "";
}

void writeWindowPng(vtkRenderWindow* window, const std::string& path) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> png;
  png->WriteToMemoryOn();
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (!bytes || bytes->GetNumberOfValues() == 0)
    throw ImageWriteError("cannot write " + path + ": the image could not be encoded");
  if (const std::string bad = imageFileProblem(path); !bad.empty()) throw ImageWriteError(bad);
  // Written whole to a new file beside `path`, then renamed over it: a reader, or another chute
  // writing the same path at the same time, sees the old image or the new one, never a file
  // truncated to 0 bytes (two `chute plot` runs with one --out, each checking its image after
  // the write, saw the other's truncation: "the image could not be written"). mkstemp creates
  // the file (O_EXCL: never a link or FIFO planted there); rename replaces a name, never
  // writing through a link to its target.
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(path).parent_path();
  std::string tmp =
      (parent.empty() ? fs::path(".chute-png-XXXXXX") : parent / ".chute-png-XXXXXX").string();
  const int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
  if (fd < 0) throw ImageWriteError("cannot write " + path + ": " + std::strerror(errno));
  auto fail = [&](int e) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw ImageWriteError("cannot write " + path + ": " + std::strerror(e));
  };
  // mkstemp's file is 0600: give the image the mode a plain create would (0644 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd, 0644 & ~mask) != 0) fail(errno);
  const auto* data = bytes->GetPointer(0);
  std::size_t left = static_cast<std::size_t>(bytes->GetNumberOfValues()), done = 0;
  while (left > 0) {
    const ssize_t n = ::write(fd, data + done, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : EIO);
    done += static_cast<std::size_t>(n);
    left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) {
    const int e = errno;
    ::unlink(tmp.c_str());
    throw ImageWriteError("cannot write " + path + ": " + std::strerror(e));
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int e = errno;
    ::unlink(tmp.c_str());
    throw ImageWriteError("cannot write " + path + ": " + std::strerror(e));
  }
}

}  // namespace chute::render
