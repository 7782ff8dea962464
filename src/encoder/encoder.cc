// The encoder entry point: validates the input, relabels vertices, and
// writes the chunks in the order spec/qmc-format.md section 4 requires.
#include "qmc/encoder.h"

#include <cmath>
#include <string>

#include "bitio/byte_io.h"
#include "encoder/chunk_writer.h"
#include "encoder/indexed_connectivity_encoder.h"
#include "encoder/position_encoder.h"
#include "encoder/vertex_order.h"

namespace qmc {
namespace {

Status invalid(const std::string& message) { return Status(ErrorCode::kInvalidArgument, message); }

Status validate(const Mesh& mesh, const EncodeOptions& options) {
  if (options.position_bits < kMinPositionBits || options.position_bits > kMaxPositionBits)
    return invalid("position bits must be in " + std::to_string(kMinPositionBits) + ".." +
                   std::to_string(kMaxPositionBits) + ", got " + std::to_string(options.position_bits));
  if (mesh.positions.size() % 3 != 0) return invalid("positions are not a multiple of 3 floats");
  if (mesh.vertex_count() > UINT32_MAX || mesh.face_count() > UINT32_MAX)
    return invalid("more than 2^32 - 1 vertices or faces");
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      return invalid("vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
  uint64_t total = 0;
  for (size_t f = 0; f < mesh.face_sizes.size(); ++f) {
    if (mesh.face_sizes[f] < 3)
      return invalid("face " + std::to_string(f) + " has " + std::to_string(mesh.face_sizes[f]) +
                     " corners; a face needs at least 3");
    total += mesh.face_sizes[f];
  }
  if (total != mesh.corners.size())
    return invalid("face sizes add up to " + std::to_string(total) + " corners but " +
                   std::to_string(mesh.corners.size()) + " are given");
  for (size_t k = 0; k < mesh.corners.size(); ++k)
    if (mesh.corners[k] >= mesh.vertex_count())
      return invalid("corner " + std::to_string(k) + " names vertex " + std::to_string(mesh.corners[k]) +
                     " of " + std::to_string(mesh.vertex_count()));
  for (const std::string& text : options.texts)
    if (text.size() > kMaxChunkLength) return invalid("text too long for one chunk");
  return Status::Ok();
}

void add_chunk(std::vector<uint8_t>* out, EncodeStats* stats, uint32_t type, const std::vector<uint8_t>& payload) {
  write_chunk(out, type, payload);
  if (stats) stats->chunks.push_back({type, 12 + uint64_t(payload.size())});
}

}  // namespace

Status encode(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out, EncodeStats* stats) {
  if (Status s = validate(mesh, options); !s.ok()) return s;
  const VertexOrder order = first_reference_order(mesh);
  const Mesh file_mesh = relabel(mesh, order);

  out->clear();
  if (stats) *stats = EncodeStats{};
  write_signature(out);
  add_chunk(out, stats, kChunkHeader, {kFormatMajor, kFormatMinor});
  for (const std::string& text : options.texts)
    add_chunk(out, stats, kChunkText, std::vector<uint8_t>(text.begin(), text.end()));
  add_chunk(out, stats, kChunkConnectivity, encode_indexed_connectivity(file_mesh));
  add_chunk(out, stats, kChunkPositions,
            encode_positions(quantize_positions(file_mesh.positions, options.position_bits)));
  add_chunk(out, stats, kChunkEnd, {});
  if (stats) {
    stats->method = ConnectivityMethod::kIndexed;
    stats->total_bytes = out->size();
    stats->file_vertex = order.file_vertex;
  }
  return Status::Ok();
}

}  // namespace qmc
