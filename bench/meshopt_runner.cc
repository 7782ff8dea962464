#include "meshopt_runner.h"

#include <meshoptimizer.h>
#include <zstd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace qmc::bench {
namespace {

std::string check_input(const qmc::Mesh& mesh, const MeshoptOptions& options, int runs) {
  if (runs < 1) return "runs must be at least 1";
  if (options.position_bits < 1 || options.position_bits > 30) return "position_bits must be 1..30";
  if (mesh.positions.size() != 3 * mesh.vertex_count()) return "positions is not 3 floats per vertex";
  for (float x : mesh.positions) {
    if (!std::isfinite(x)) return "non-finite coordinate";
  }
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_sizes[f] < 3) return "face " + std::to_string(f) + " has fewer than 3 corners";
  }
  for (uint32_t v : mesh.corners) {
    if (v >= mesh.vertex_count()) return "corner index " + std::to_string(v) + " out of range";
  }
  return {};
}

// Fan from the first corner: triangle t of an n-gon is (v0, v[t+1], v[t+2]).
std::vector<uint32_t> fan_triangles(const qmc::Mesh& mesh) {
  std::vector<uint32_t> indices;
  size_t first = 0;
  for (uint32_t n : mesh.face_sizes) {
    const uint32_t* v = &mesh.corners[first];
    for (uint32_t t = 0; t + 2 < n; ++t) indices.insert(indices.end(), {v[0], v[t + 1], v[t + 2]});
    first += n;
  }
  return indices;
}

// Draco's grid (AttributeQuantizationTransform): the largest side of the box
// is the range (1 if the box is a point), 2^bits - 1 steps over it, rounding
// half up in float.
struct Grid {
  float origin[3] = {0, 0, 0};
  float range = 1;
  float inverse_step = 1;
};

Grid draco_grid(const qmc::Mesh& mesh, int bits) {
  Grid grid;
  float high[3];
  for (int a = 0; a < 3; ++a) grid.origin[a] = high[a] = mesh.positions.empty() ? 0.f : mesh.positions[a];
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    grid.origin[i % 3] = std::min(grid.origin[i % 3], mesh.positions[i]);
    high[i % 3] = std::max(high[i % 3], mesh.positions[i]);
  }
  grid.range = std::max({high[0] - grid.origin[0], high[1] - grid.origin[1], high[2] - grid.origin[2]});
  if (grid.range == 0.f) grid.range = 1.f;
  grid.inverse_step = float((uint64_t{1} << bits) - 1) / grid.range;
  return grid;
}

// Vertex records of `vertex_size` bytes: uint16 x 4 or uint32 x 3.
size_t vertex_size_for(int bits) { return bits <= 16 ? 4 * sizeof(uint16_t) : 3 * sizeof(uint32_t); }

std::vector<uint8_t> quantized_vertices(const qmc::Mesh& mesh, int bits) {
  const Grid grid = draco_grid(mesh, bits);
  const size_t size = vertex_size_for(bits);
  std::vector<uint8_t> records(mesh.vertex_count() * size, 0);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      const float offset = mesh.positions[3 * v + a] - grid.origin[a];
      const auto q = static_cast<uint32_t>(std::floor(offset * grid.inverse_step + 0.5f));
      uint8_t* at = &records[v * size];
      if (bits <= 16) {
        const auto q16 = static_cast<uint16_t>(q);
        std::memcpy(at + a * sizeof q16, &q16, sizeof q16);
      } else {
        std::memcpy(at + a * sizeof q, &q, sizeof q);
      }
    }
  }
  return records;
}

std::vector<uint8_t> zstd_compress(const std::vector<uint8_t>& data, int level) {
  std::vector<uint8_t> out(ZSTD_compressBound(data.size()));
  const size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), level);
  out.resize(ZSTD_isError(n) ? 0 : n);
  return out;
}

bool zstd_decompress(const std::vector<uint8_t>& frame, std::vector<uint8_t>* out) {
  const unsigned long long size = ZSTD_getFrameContentSize(frame.data(), frame.size());
  if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN) return false;
  out->resize(size);
  const size_t n = ZSTD_decompress(out->data(), out->size(), frame.data(), frame.size());
  return !ZSTD_isError(n) && n == size;
}

// What is stored, and the buffers it must decode back to.
struct Encoded {
  std::vector<uint32_t> indices;  // after the two optimizations
  std::vector<uint8_t> vertices;  // after the fetch optimization
  std::vector<uint8_t> index_frame, vertex_frame;
};

bool encode_once(const qmc::Mesh& mesh, const MeshoptOptions& options, Encoded* out) {
  const size_t vertex_size = vertex_size_for(options.position_bits);
  const std::vector<uint32_t> fan = fan_triangles(mesh);
  const std::vector<uint8_t> quantized = quantized_vertices(mesh, options.position_bits);
  out->indices.resize(fan.size());
  meshopt_optimizeVertexCache(out->indices.data(), fan.data(), fan.size(), mesh.vertex_count());
  out->vertices.resize(quantized.size());
  const size_t kept = meshopt_optimizeVertexFetch(out->vertices.data(), out->indices.data(), fan.size(),
                                                  quantized.data(), mesh.vertex_count(), vertex_size);
  out->vertices.resize(kept * vertex_size);

  std::vector<uint8_t> index_codes(meshopt_encodeIndexBufferBound(fan.size(), kept));
  index_codes.resize(meshopt_encodeIndexBuffer(index_codes.data(), index_codes.size(), out->indices.data(),
                                               out->indices.size()));
  std::vector<uint8_t> vertex_codes(meshopt_encodeVertexBufferBound(kept, vertex_size));
  vertex_codes.resize(meshopt_encodeVertexBuffer(vertex_codes.data(), vertex_codes.size(), out->vertices.data(),
                                                 kept, vertex_size));
  out->index_frame = zstd_compress(index_codes, options.zstd_level);
  out->vertex_frame = zstd_compress(vertex_codes, options.zstd_level);
  return !out->index_frame.empty() && !out->vertex_frame.empty();
}

// Decodes into `indices` and `vertices`; false on any decoder error.
bool decode_once(const Encoded& in, size_t vertex_size, std::vector<uint32_t>* indices,
                 std::vector<uint8_t>* vertices) {
  std::vector<uint8_t> index_codes, vertex_codes;
  if (!zstd_decompress(in.index_frame, &index_codes) || !zstd_decompress(in.vertex_frame, &vertex_codes)) {
    return false;
  }
  indices->resize(in.indices.size());
  vertices->resize(in.vertices.size());
  return meshopt_decodeIndexBuffer(indices->data(), indices->size(), sizeof(uint32_t), index_codes.data(),
                                   index_codes.size()) == 0 &&
         meshopt_decodeVertexBuffer(vertices->data(), vertices->size() / vertex_size, vertex_size,
                                    vertex_codes.data(), vertex_codes.size()) == 0;
}

// The index codec keeps the order of triangles and their orientation but
// may rotate a triangle's corners, so equality is up to that rotation.
bool same_triangles(const std::vector<uint32_t>& decoded, const std::vector<uint32_t>& encoded) {
  if (decoded.size() != encoded.size()) return false;
  for (size_t t = 0; t < encoded.size(); t += 3) {
    const uint32_t* d = &decoded[t];
    const uint32_t* e = &encoded[t];
    bool rotation = false;
    for (size_t r = 0; r < 3 && !rotation; ++r) {
      rotation = d[0] == e[r] && d[1] == e[(r + 1) % 3] && d[2] == e[(r + 2) % 3];
    }
    if (!rotation) return false;
  }
  return true;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double draco_grid_step(const qmc::Mesh& mesh, int bits) {
  return double(draco_grid(mesh, bits).range) / double((uint64_t{1} << bits) - 1);
}

MeshoptResult run_meshopt(const qmc::Mesh& mesh, const MeshoptOptions& options, int runs) {
  MeshoptResult result;
  result.error = check_input(mesh, options, runs);
  if (!result.error.empty()) return result;
  // Version 1, the one glTF's EXT_meshopt_compression requires, set explicitly.
  meshopt_encodeIndexVersion(1);

  Encoded encoded;
  const size_t vertex_size = vertex_size_for(options.position_bits);
  std::vector<uint32_t> indices;
  std::vector<uint8_t> vertices;
  for (int r = 0; r < runs; ++r) {
    auto start = std::chrono::steady_clock::now();
    const bool encoded_ok = encode_once(mesh, options, &encoded);
    result.encode_seconds.push_back(seconds_since(start));
    if (!encoded_ok) {
      result.error = "meshopt/zstd encode failed";
      return result;
    }
    start = std::chrono::steady_clock::now();
    const bool decoded_ok = decode_once(encoded, vertex_size, &indices, &vertices);
    result.decode_seconds.push_back(seconds_since(start));
    if (!decoded_ok) {
      result.error = "meshopt/zstd decode reported an error";
      return result;
    }
    if (vertices != encoded.vertices) {
      result.error = "meshopt/zstd decode did not give back the vertex buffer";
      return result;
    }
    if (!same_triangles(indices, encoded.indices)) {
      result.error = "meshopt/zstd decode did not give back the index buffer";
      return result;
    }
  }
  result.index_bytes = encoded.index_frame.size();
  result.vertex_bytes = encoded.vertex_frame.size();
  result.bytes = MeshoptResult::kHeaderBytes + result.index_bytes + result.vertex_bytes;
  result.triangles = encoded.indices.size() / 3;
  result.vertices = encoded.vertices.size() / vertex_size;
  result.ok = true;
  return result;
}

}  // namespace qmc::bench
