// qmc tools: output files replaced in one step. See atomic_file.h.
#include "atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace qmc::tools {
namespace {

Status cannot_write(const std::string& path, int error) {
  return Status(ErrorCode::kIo, "cannot write " + path + ": " + std::strerror(error != 0 ? error : EIO));
}

// Fills the stream, flushes it (to the disk too with `sync`) and closes it:
// the errno of the first step that failed, or 0.
int fill_and_close(std::FILE* file, const std::function<bool(std::FILE*)>& fill, bool sync) {
  errno = 0;
  int error = 0;
  if (!fill(file)) error = errno != 0 ? errno : EIO;
  if (error == 0 && std::fflush(file) != 0) error = errno;
  if (error == 0 && sync && fsync(fileno(file)) != 0) error = errno;
  if (std::fclose(file) != 0 && error == 0) error = errno;
  return error;
}

// A symlink is followed, so that the file it points to is the one replaced
// and the link stays.
std::string destination_of(const std::string& path) {
  struct stat link;
  if (lstat(path.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) return path;
  char* resolved = realpath(path.c_str(), nullptr);
  if (resolved == nullptr) return path;
  std::string target = resolved;
  std::free(resolved);
  return target;
}

// A new file beside `target`, created like any new file (0666 less the
// umask; mkstemp would give 0600), under a name no other writer uses.
int create_temporary(const std::string& target, std::string* name) {
  static std::atomic<unsigned> serial{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    *name = target + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(serial++);
    const int fd = open(name->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

Status write_file_atomically(const std::string& path, const std::function<bool(std::FILE*)>& fill) {
  const std::string target = destination_of(path);
  struct stat existing;
  const bool replacing = stat(target.c_str(), &existing) == 0;
  if (replacing && !S_ISREG(existing.st_mode)) {
    std::FILE* file = std::fopen(target.c_str(), "wb");
    if (file == nullptr) return cannot_write(path, errno);
    const int error = fill_and_close(file, fill, false);
    return error != 0 ? cannot_write(path, error) : Status::Ok();
  }
  // Same directory, so that the rename stays on one file system.
  std::string temporary;
  const int fd = create_temporary(target, &temporary);
  if (fd < 0) return cannot_write(path, errno);
  // A replaced file keeps its permissions.
  int error = 0;
  std::FILE* file = !replacing || fchmod(fd, existing.st_mode & 07777) == 0 ? fdopen(fd, "wb") : nullptr;
  if (file == nullptr) {
    error = errno;
    close(fd);
  } else {
    error = fill_and_close(file, fill, true);
  }
  if (error == 0 && std::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
  if (error != 0) {
    std::remove(temporary.c_str());
    return cannot_write(path, error);
  }
  return Status::Ok();
}

Status write_file_atomically(const std::string& path, const void* data, size_t size) {
  return write_file_atomically(path, [&](std::FILE* file) { return std::fwrite(data, 1, size, file) == size; });
}

}  // namespace qmc::tools
