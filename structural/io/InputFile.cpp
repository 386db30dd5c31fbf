#include "io/InputFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace chute::io {

namespace {

std::optional<std::string> problemOf(const struct stat& st, std::uintmax_t maxBytes) {
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode)) return "is not a regular file (FIFO, device or socket): refused";
  if (static_cast<std::uintmax_t>(st.st_size) > maxBytes)
    return "is " + std::to_string(st.st_size) + " bytes, more than the limit of " +
           std::to_string(maxBytes);
  return std::nullopt;
}

std::string errnoText(int e) {
  return e == ENOENT ? "no such file" : std::strerror(e);
}

}  // namespace

std::optional<std::string> inputFileProblem(const std::string& path, std::uintmax_t maxBytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return errnoText(errno);
  return problemOf(st, maxBytes);
}

int openInputFile(const std::string& path, std::uintmax_t maxBytes) {
  // O_NONBLOCK: opening a FIFO with no writer must not wait for one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(path + ": cannot open: " + errnoText(errno));
  struct stat st {};
  std::optional<std::string> problem;
  if (::fstat(fd, &st) != 0) problem = errnoText(errno);
  if (!problem) problem = problemOf(st, maxBytes);
  if (problem) {
    ::close(fd);
    throw std::runtime_error(path + ": cannot open: " + *problem);
  }
  return fd;
}

std::string readInputFile(const std::string& path, std::uintmax_t maxBytes) {
  const int fd = openInputFile(path, maxBytes);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int e = errno;
    ::close(fd);
    throw std::runtime_error(path + ": cannot open: " + errnoText(e));
  }
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int e = errno;
      ::close(fd);
      throw std::runtime_error(path + ": cannot read: " + std::strerror(e));
    }
    if (n == 0) break;  // the file shrank while being read: what is there is read
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  bytes.resize(got);
  return bytes;
}

}  // namespace chute::io
