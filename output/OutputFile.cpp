#include "OutputFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "OutputError.hpp"

namespace chute {

std::string writeFailure(int err) {
  switch (err) {
    case ENOSPC:
      return "no space left on device (disk full)";
    case EDQUOT:
      return "disk quota exceeded (disk full)";
    case EFBIG:
      return "file too large (a file size limit: disk full)";
    case ENOENT:
      return "no such directory (the output directory was removed during the run)";
    default:
      return std::strerror(err);
  }
}

int createOutputFile(const std::string& path) {
  // unlink removes a symbolic link itself, never its target.
  if (::unlink(path.c_str()) != 0 && errno != ENOENT) {
    const int err = errno;
    throw OutputError(
        path + ": cannot replace what is there: " +
        (err == EISDIR || err == EPERM ? std::string("a directory") : writeFailure(err)));
  }
  for (;;) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0) return fd;
    if (errno == EINTR) continue;
    throw OutputError(path + ": cannot create: " + writeFailure(errno));
  }
}

void writeAllAt(int fd, std::string_view bytes, off_t offset, const std::string& path) {
  const char* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::pwrite(fd, p, left, offset);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw OutputError(path + ": cannot write: " + writeFailure(errno));
    }
    if (n == 0) throw OutputError(path + ": cannot write: " + writeFailure(ENOSPC));
    p += n, left -= static_cast<size_t>(n), offset += n;
  }
}

void replaceFile(const std::string& path, std::string_view bytes, bool sync) {
  const std::string tmp = path + ".tmp";
  const int fd = createOutputFile(tmp);
  try {
    writeAllAt(fd, bytes, 0, tmp);
    if (sync && ::fsync(fd) != 0) throw OutputError(tmp + ": cannot write: " + writeFailure(errno));
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw OutputError(tmp + ": cannot write: " + writeFailure(err));
  }
  // rename replaces the entry at path (a link there is replaced, not followed).
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw OutputError(path + ": cannot replace: " + writeFailure(err));
  }
}

bool stillLinked(int fd) {
  struct stat st {};
  return ::fstat(fd, &st) == 0 && st.st_nlink > 0;
}

}  // namespace chute
