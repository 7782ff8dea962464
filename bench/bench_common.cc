#include "bench_common.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <unistd.h>

#include "mesh_io.h"
#include "qmc/decoder.h"

namespace qmc::bench {

void fail(const char* program, const std::string& message) {
  std::fprintf(stderr, "%s: %s\n", program, message.c_str());
  std::exit(3);
}

void progress(const std::string& what) {
  if (!isatty(STDERR_FILENO)) return;
  std::fprintf(stderr, "\r%-70s", what.substr(0, 70).c_str());
  if (what.empty()) std::fputs("\r", stderr);
}

std::string format(const char* fmt, ...) {
  char buf[1024];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

size_t end_of_connectivity(const EncodeStats& stats) {
  size_t offset = sizeof kSignature;
  for (const ChunkStats& c : stats.chunks) {
    offset += c.bytes;
    if (c.type == kChunkConnectivity) return offset;
  }
  return 0;
}

bool decode_connectivity_only(const std::vector<uint8_t>& file, size_t conn_end, size_t faces) {
  StreamDecoder decoder(DecoderLimits::unlimited());  // our own files: spec 8.1's limits are for embedders
  if (!decoder.feed(file.data(), conn_end).ok()) return false;
  return decoder.has_connectivity() && decoder.file().mesh.face_count() == faces;
}

std::string display_name(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos || slash == 0) return path;
  const size_t parent = path.find_last_of('/', slash - 1);
  return parent == std::string::npos ? path : path.substr(parent + 1);
}

Status read_geometry(const std::string& path, Mesh* mesh, std::vector<std::string>* notes) {
  Status status = tools::read_mesh(path, mesh, notes);
  mesh->attributes.clear();
  mesh->face_labels.clear();
  return status;
}

size_t drop_unused_vertices(Mesh* mesh) {
  constexpr uint32_t kUnused = UINT32_MAX;
  std::vector<uint32_t> new_index(mesh->vertex_count(), kUnused);
  for (uint32_t v : mesh->corners) new_index[v] = 0;
  uint32_t kept = 0;
  for (size_t v = 0; v < new_index.size(); ++v) {
    if (new_index[v] == kUnused) continue;
    new_index[v] = kept;
    for (int a = 0; a < 3; ++a) mesh->positions[3 * size_t(kept) + a] = mesh->positions[3 * v + a];
    ++kept;
  }
  const size_t dropped = new_index.size() - kept;
  mesh->positions.resize(3 * size_t(kept));
  for (uint32_t& v : mesh->corners) v = new_index[v];
  return dropped;
}

}  // namespace qmc::bench
