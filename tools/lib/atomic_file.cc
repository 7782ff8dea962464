// qmc tools: output files replaced in one step. See atomic_file.h.
#include "atomic_file.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

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

// A replaced file keeps its permissions; a new one gets the usual 0666
// less the umask (mkstemp alone would leave 0600).
mode_t mode_for(const std::string& path) {
  struct stat existing;
  if (stat(path.c_str(), &existing) == 0) return existing.st_mode & 07777;
  const mode_t mask = umask(0);
  umask(mask);
  return 0666 & ~mask;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

Status write_file_atomically(const std::string& path, const std::function<bool(std::FILE*)>& fill) {
  const std::string target = destination_of(path);
  struct stat existing;
  if (stat(target.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode)) {
    std::FILE* file = std::fopen(target.c_str(), "wb");
    if (file == nullptr) return cannot_write(path, errno);
    const int error = fill_and_close(file, fill, false);
    return error != 0 ? cannot_write(path, error) : Status::Ok();
  }
  // Same directory, so that the rename stays on one file system.
  std::string temporary = target + ".tmp-XXXXXX";
  const int fd = mkstemp(temporary.data());
  if (fd < 0) return cannot_write(path, errno);
  int error = 0;
  std::FILE* file = fchmod(fd, mode_for(target)) == 0 ? fdopen(fd, "wb") : nullptr;
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
