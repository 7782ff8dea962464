#include "cli_common.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "mesh_io.h"

namespace qmc::cli {

Status read_file(const std::string& path, std::vector<uint8_t>* bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(ErrorCode::kIo, "cannot open " + path + ": " + std::strerror(errno));
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return Status(ErrorCode::kIo, "error reading " + path);
  return Status::Ok();
}

Status write_file(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return Status(ErrorCode::kIo, "cannot create " + path + ": " + std::strerror(errno));
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  out.close();
  if (!out) return Status(ErrorCode::kIo, "error writing " + path);
  return Status::Ok();
}

Status load_mesh(const std::string& path, Mesh* mesh) {
  std::vector<std::string> warnings;
  Status s = tools::read_mesh(path, mesh, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "note: %s: %s\n", path.c_str(), w.c_str());
  return s;
}

int fail(const char* command, const Status& status) {
  std::fprintf(stderr, "qmc %s: %s\n", command, status.to_string().c_str());
  return kExitError;
}

int usage_error(const char* command, const std::string& message) {
  std::fprintf(stderr, "qmc %s: %s (see 'qmc %s --help')\n", command, message.c_str(), command);
  return kExitUsage;
}

bool take_option(int argc, char** argv, int* i, const std::string& name, std::string* value) {
  const std::string arg = argv[*i];
  if (arg.rfind(name + "=", 0) == 0) {
    *value = arg.substr(name.size() + 1);
    return true;
  }
  if (arg == name && *i + 1 < argc) {
    *value = argv[++*i];
    return true;
  }
  return false;
}

bool parse_int(const std::string& text, long min, long max, long* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < min || v > max) return false;
  *out = v;
  return true;
}

double max_quantization_step(const QuantizationInfo& q) {
  if (q.bits <= 0) return 0;
  double step = 0;
  for (int a = 0; a < 3; ++a) {
    const double s = (double(q.max[a]) - double(q.min[a])) / double((uint64_t(1) << q.bits) - 1);
    if (s > step) step = s;
  }
  return step;
}

std::string human_bytes(uint64_t bytes) {
  char buf[64];
  if (bytes < 10 * 1024)
    std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
  else if (bytes < 10 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f KiB", double(bytes) / 1024);
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / (1024 * 1024));
  return buf;
}

}  // namespace qmc::cli
