// qmc tools: output files that are replaced in one step, never left half
// written (issue #12 item 7).
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>

#include "qmc/status.h"

namespace qmc::tools {

// True when both paths name one existing file: the same device and inode,
// however the paths are spelled (links, "./", symlinks).
bool same_file(const std::string& a, const std::string& b);

// Writes `path` through a temporary file in the same directory that `fill`
// writes to (returning false when a write fails); only once every byte is
// flushed to disk is the temporary renamed over `path`. On any failure the
// temporary is removed, `path` is left as it was, and the status says
// "cannot write PATH: <the system's reason>". A `path` that exists and is
// not a regular file (/dev/null, a pipe) is written in place.
qmc::Status write_file_atomically(const std::string& path, const std::function<bool(std::FILE*)>& fill);
qmc::Status write_file_atomically(const std::string& path, const void* data, size_t size);

}  // namespace qmc::tools
