#pragma once
// Input files as a hostile user may give them: a FIFO never ends, /dev/zero never ends and a
// directory is no file. Every input chute reads whole (meshes, case files, probes and reference
// CSVs) is opened here: regular files only, sizes bounded before anything is read.
#include <cstdint>
#include <optional>
#include <string>

namespace chute::io {

// Why `path` cannot be read as an input file ("no such file", "is a directory", "is not a
// regular file (FIFO, device or socket)", "is larger than N bytes"), or nullopt when it can.
std::optional<std::string> inputFileProblem(const std::string& path, std::uintmax_t maxBytes);

// The whole of a regular file of at most maxBytes. The file is opened without blocking and
// checked on the open descriptor (a path swapped for a FIFO after the check is still refused);
// at most the size seen at open is read. Throws std::runtime_error("path: cannot open: reason").
std::string readInputFile(const std::string& path, std::uintmax_t maxBytes);

// The same checks, for a file read piece by piece: an open descriptor of the regular file (the
// caller closes it). Throws std::runtime_error("path: cannot open: reason").
int openInputFile(const std::string& path, std::uintmax_t maxBytes);

}  // namespace chute::io
