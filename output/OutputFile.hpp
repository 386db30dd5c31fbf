#pragma once
// The files a run writes (probes.csv, .vtu frames, the .pvd, checkpoint.cbor, summary.json), made
// so that a write never reaches another file and a failed write is one OutputError:
//  - created, never opened through what is at the path: the entry there (a planted symbolic
//    link, a file of an earlier run) is removed and the file created with
//    O_CREAT | O_EXCL | O_NOFOLLOW, so a link planted in the output directory is replaced, its
//    target untouched;
//  - every write checked whole (a short write is retried, a failure throws OutputError naming
//    the file and the reason: a full disk, a removed directory, a file size limit).
#include <sys/types.h>

#include <string>
#include <string_view>

namespace chute {

// The reason of errno `err` as a message ("no space left on device (disk full)", "the directory
// was removed during the run").
std::string writeFailure(int err);

// Creates `path` for writing (O_WRONLY, mode 0644) after removing whatever entry is there;
// returns its descriptor. Throws OutputError when it cannot (a directory at the path, the
// directory gone, no space).
int createOutputFile(const std::string& path);

// Writes all of `bytes` at `offset` of fd (pwrite, retried on EINTR and short writes). Throws
// OutputError naming `path`.
void writeAllAt(int fd, std::string_view bytes, off_t offset, const std::string& path);

// Replaces `path` with `bytes` at once: written whole to `path.tmp` (created as above), synced to
// disk when `sync`, then renamed over `path` (the old file stays until the new one is whole).
// Throws OutputError (the temporary file removed) when any of it fails.
void replaceFile(const std::string& path, std::string_view bytes, bool sync);

// Whether the file open on fd is still in the directory tree (it was not removed, nor its
// directory): false once unlinked.
bool stillLinked(int fd);

}  // namespace chute
