// The C API of include/qmc/qmc.h over qmc::StreamDecoder. Every entry point
// catches what C++ could throw (QMC_TRY), so only error codes cross it.
#include "qmc/qmc.h"

#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "decoder/no_throw.h"
#include "qmc/decoder.h"

namespace {

using qmc::ErrorCode;

// qmc_error is qmc::ErrorCode, value for value (spec section 9).
static_assert(QMC_BAD_SIGNATURE == int(ErrorCode::kBadSignature));
static_assert(QMC_UNSUPPORTED_VERSION == int(ErrorCode::kUnsupportedVersion));
static_assert(QMC_TRUNCATED == int(ErrorCode::kTruncated));
static_assert(QMC_BAD_CRC == int(ErrorCode::kBadCrc));
static_assert(QMC_BAD_CHUNK_LENGTH == int(ErrorCode::kBadChunkLength));
static_assert(QMC_BAD_CHUNK_TYPE == int(ErrorCode::kBadChunkType));
static_assert(QMC_UNKNOWN_CRITICAL_CHUNK == int(ErrorCode::kUnknownCriticalChunk));
static_assert(QMC_CHUNK_ORDER == int(ErrorCode::kChunkOrder));
static_assert(QMC_TRAILING_DATA == int(ErrorCode::kTrailingData));
static_assert(QMC_BAD_CHUNK_PAYLOAD == int(ErrorCode::kBadChunkPayload));
static_assert(QMC_UNSUPPORTED_FEATURE == int(ErrorCode::kUnsupportedFeature));
static_assert(QMC_BAD_HUFFMAN_TABLE == int(ErrorCode::kBadHuffmanTable));
static_assert(QMC_BAD_SYMBOL == int(ErrorCode::kBadSymbol));
static_assert(QMC_LIMIT_EXCEEDED == int(ErrorCode::kLimitExceeded));
static_assert(QMC_INVALID_ARGUMENT == int(ErrorCode::kInvalidArgument));

qmc::DecoderLimits to_decoder_limits(const qmc_limits& l) {
  qmc::DecoderLimits d;
  d.max_chunk_length = l.max_chunk_length;
  d.max_levels = l.max_levels;
  d.max_vertices = l.max_vertices;
  d.max_faces = l.max_faces;
  d.max_pixels = l.max_pixels;
  d.max_output_bytes = l.max_output_bytes;
  return d;
}

void copy_message(const std::string& text, char* message, size_t message_size) {
  if (!message || message_size == 0) return;
  const size_t n = text.size() < message_size - 1 ? text.size() : message_size - 1;
  std::memcpy(message, text.data(), n);
  message[n] = '\0';
}

// malloc'd copy of a vector, so that the caller frees it with qmc_free.
template <typename T>
bool copy_array(const std::vector<T>& from, T** to) {
  *to = static_cast<T*>(std::malloc(from.empty() ? 1 : from.size() * sizeof(T)));
  if (!*to) return false;
  if (!from.empty()) std::memcpy(*to, from.data(), from.size() * sizeof(T));
  return true;
}

// Each polygon as a fan from its first corner: 3 (n - 2) indices for n corners.
std::vector<uint32_t> fan_triangles(const qmc::Mesh& mesh) {
  size_t count = 0;
  for (uint32_t n : mesh.face_sizes) count += n - 2;
  std::vector<uint32_t> triangles;
  triangles.reserve(3 * count);
  size_t first = 0;
  for (uint32_t n : mesh.face_sizes) {
    for (uint32_t k = 1; k + 1 < n; ++k) {
      triangles.push_back(mesh.corners[first]);
      triangles.push_back(mesh.corners[first + k]);
      triangles.push_back(mesh.corners[first + k + 1]);
    }
    first += n;
  }
  return triangles;
}

int fill_mesh(const qmc::Mesh& mesh, qmc_mesh* out) {
  const std::vector<uint32_t> triangles = fan_triangles(mesh);
  out->vertex_count = uint32_t(mesh.vertex_count());
  out->face_count = uint32_t(mesh.face_count());
  out->corner_count = uint32_t(mesh.corners.size());
  out->triangle_count = uint32_t(triangles.size() / 3);
  if (!copy_array(mesh.positions, &out->positions) || !copy_array(mesh.face_sizes, &out->face_sizes) ||
      !copy_array(mesh.corners, &out->corners) || !copy_array(triangles, &out->triangles)) {
    qmc_mesh_free(out);
    return QMC_LIMIT_EXCEEDED;
  }
  return QMC_OK;
}

}  // namespace

struct qmc_decoder {
  explicit qmc_decoder(const qmc::DecoderLimits& limits) : stream(limits) {}
  qmc::StreamDecoder stream;
  qmc::Status status;  // the first rejection, or of the API's own checks
};

namespace {

int fail(qmc_decoder* d, ErrorCode code, const char* message) {
  if (d->status.ok()) d->status = qmc::Status(code, message);
  return int(d->status.code());
}

int record(qmc_decoder* d, const qmc::Status& s) {
  if (d->status.ok() && !s.ok()) d->status = s;
  return int(d->status.code());
}

}  // namespace

extern "C" {

const char* qmc_error_name(int error) {
  if (error < 0 || error > QMC_INVALID_ARGUMENT) return "unknown";
  return qmc::error_code_name(ErrorCode(error));
}

void qmc_limits_default(qmc_limits* limits) {
  if (!limits) return;
  const qmc::DecoderLimits d;
  limits->max_chunk_length = d.max_chunk_length;
  limits->max_levels = d.max_levels;
  limits->max_vertices = d.max_vertices;
  limits->max_faces = d.max_faces;
  limits->max_pixels = d.max_pixels;
  limits->max_output_bytes = d.max_output_bytes;
}

int qmc_peek(const uint8_t* data, size_t size, qmc_summary* out, char* message, size_t message_size) {
  if (!out || (!data && size > 0)) {
    copy_message("qmc_peek: NULL data or summary", message, message_size);
    return QMC_INVALID_ARGUMENT;
  }
  std::memset(out, 0, sizeof(*out));
  QMC_TRY {
    qmc::FileSummary s;
    const qmc::Status status = qmc::peek(data, size, &s);
    copy_message(status.ok() ? std::string() : status.message(), message, message_size);
    out->version_major = s.version_major;
    out->version_minor = s.version_minor;
    out->has_connectivity = s.has_connectivity;
    out->method = uint32_t(s.method);
    out->vertex_count = s.vertex_count;
    out->face_count = s.face_count;
    out->level_count = s.loop_level_count;
    out->finest_face_count = s.finest_face_count;
    out->has_geometry_image = s.has_geometry_image;
    out->gim_width = s.gim_width;
    out->gim_height = s.gim_height;
    out->gim_plane_count = s.gim_plane_count;
    out->min_output_bytes = s.min_output_bytes;
    return int(status.code());
  }
  QMC_CATCH_ALL(copy_message("qmc_peek: out of memory", message, message_size); return QMC_LIMIT_EXCEEDED)
}

void qmc_mesh_free(qmc_mesh* mesh) {
  if (!mesh) return;
  std::free(mesh->positions);
  std::free(mesh->face_sizes);
  std::free(mesh->corners);
  std::free(mesh->triangles);
  std::memset(mesh, 0, sizeof(*mesh));
}

void qmc_free(void* array) { std::free(array); }

qmc_decoder* qmc_decoder_create(const qmc_limits* limits) {
  qmc_limits l;
  qmc_limits_default(&l);
  if (limits) l = *limits;
  QMC_TRY { return new (std::nothrow) qmc_decoder(to_decoder_limits(l)); }
  QMC_CATCH_ALL(return nullptr)
}

void qmc_decoder_destroy(qmc_decoder* decoder) { delete decoder; }

int qmc_decoder_feed(qmc_decoder* decoder, const uint8_t* data, size_t size) {
  if (!decoder) return QMC_INVALID_ARGUMENT;
  if (!data && size > 0) return fail(decoder, ErrorCode::kInvalidArgument, "qmc_decoder_feed: NULL data");
  if (!decoder->status.ok()) return int(decoder->status.code());
  QMC_TRY { return record(decoder, decoder->stream.feed(data, size)); }
  QMC_CATCH_ALL(return fail(decoder, ErrorCode::kLimitExceeded, "qmc_decoder_feed: out of memory"))
}

int qmc_decoder_finish(qmc_decoder* decoder) {
  if (!decoder) return QMC_INVALID_ARGUMENT;
  if (!decoder->status.ok()) return int(decoder->status.code());
  QMC_TRY { return record(decoder, decoder->stream.finish()); }
  QMC_CATCH_ALL(return fail(decoder, ErrorCode::kLimitExceeded, "qmc_decoder_finish: out of memory"))
}

int qmc_decoder_decode(qmc_decoder* decoder, const uint8_t* data, size_t size) {
  const int fed = qmc_decoder_feed(decoder, data, size);
  return fed == QMC_OK ? qmc_decoder_finish(decoder) : fed;
}

int qmc_decoder_error(const qmc_decoder* decoder) {
  return decoder ? int(decoder->status.code()) : QMC_INVALID_ARGUMENT;
}

const char* qmc_decoder_message(const qmc_decoder* decoder) {
  return decoder ? decoder->status.message().c_str() : "qmc_decoder_message: NULL decoder";
}

int qmc_decoder_complete(const qmc_decoder* decoder) {
  return decoder && decoder->status.ok() && decoder->stream.complete();
}

int qmc_decoder_has_mesh(const qmc_decoder* decoder) {
  return decoder && decoder->status.ok() && decoder->stream.has_positions();
}

int qmc_decoder_level_count(const qmc_decoder* decoder) { return decoder ? decoder->stream.level_count() : 0; }

int qmc_decoder_complete_level(const qmc_decoder* decoder) {
  return decoder ? decoder->stream.complete_level() : -1;
}

int qmc_decoder_mesh(const qmc_decoder* decoder, int level, qmc_mesh* out) {
  if (!decoder || !out) return QMC_INVALID_ARGUMENT;
  std::memset(out, 0, sizeof(*out));
  // Spec 9: a rejected file yields no mesh; 3.5: a streamed one shows what arrived.
  if (!decoder->status.ok()) return int(decoder->status.code());
  if (level != QMC_FINEST && (level < 0 || level > decoder->stream.complete_level())) return QMC_INVALID_ARGUMENT;
  QMC_TRY {
    const qmc::DecodedFile& file = decoder->stream.file();
    if (level == QMC_FINEST) return fill_mesh(file.mesh, out);
    return fill_mesh(qmc::level_mesh(file.levels[size_t(level)]), out);
  }
  QMC_CATCH_ALL(qmc_mesh_free(out); return QMC_LIMIT_EXCEEDED)
}

int qmc_decoder_attribute_count(const qmc_decoder* decoder) {
  if (!decoder || !decoder->status.ok()) return 0;
  const qmc::DecodedFile& file = decoder->stream.file();
  const qmc::GeometryImageData& gim = file.gim;
  // The 13.9 mesh exists once plane 2 is in; planes arrive in order (13.1).
  if (!gim.present || gim.vertex_pixels.size() != file.mesh.vertex_count()) return 0;
  int count = 0;
  while (size_t(3 + count) < gim.planes.size() && !gim.planes[size_t(3 + count)].samples.empty()) ++count;
  return count;
}

int qmc_decoder_attribute(const qmc_decoder* decoder, int index, qmc_attribute* out) {
  if (!decoder || !out) return QMC_INVALID_ARGUMENT;
  std::memset(out, 0, sizeof(*out));
  if (!decoder->status.ok()) return int(decoder->status.code());
  if (index < 0 || index >= qmc_decoder_attribute_count(decoder)) return QMC_INVALID_ARGUMENT;
  const qmc::GeometryImageData& gim = decoder->stream.file().gim;
  const int plane = 3 + index;
  const size_t count = gim.vertex_pixels.size();
  out->values = static_cast<float*>(std::malloc(count ? count * sizeof(float) : 1));
  if (!out->values) return QMC_LIMIT_EXCEEDED;
  for (size_t v = 0; v < count; ++v) out->values[v] = float(gim.value(plane, gim.vertex_pixels[v]));
  out->kind = gim.planes[size_t(plane)].kind;
  out->count = uint32_t(count);
  return QMC_OK;
}

int qmc_decoder_corner_attribute_count(const qmc_decoder* decoder) {
  if (!decoder || !decoder->status.ok()) return 0;
  return int(decoder->stream.file().mesh.attributes.size());
}

void qmc_corner_attribute_free(qmc_corner_attribute* attribute) {
  if (!attribute) return;
  std::free(attribute->values);
  std::free(attribute->corner_values);
  std::memset(attribute, 0, sizeof(*attribute));
}

int qmc_decoder_corner_attribute(const qmc_decoder* decoder, int index, qmc_corner_attribute* out) {
  if (!decoder || !out) return QMC_INVALID_ARGUMENT;
  std::memset(out, 0, sizeof(*out));
  if (!decoder->status.ok()) return int(decoder->status.code());
  if (index < 0 || index >= qmc_decoder_corner_attribute_count(decoder)) return QMC_INVALID_ARGUMENT;
  const qmc::MeshAttribute& a = decoder->stream.file().mesh.attributes[size_t(index)];
  out->values = static_cast<float*>(std::malloc(a.values.empty() ? 1 : a.values.size() * sizeof(float)));
  out->corner_values =
      static_cast<uint32_t*>(std::malloc(a.corner_values.empty() ? 1 : a.corner_values.size() * sizeof(uint32_t)));
  if (!out->values || !out->corner_values) {
    qmc_corner_attribute_free(out);
    return QMC_LIMIT_EXCEEDED;
  }
  if (!a.values.empty()) std::memcpy(out->values, a.values.data(), a.values.size() * sizeof(float));
  if (!a.corner_values.empty())
    std::memcpy(out->corner_values, a.corner_values.data(), a.corner_values.size() * sizeof(uint32_t));
  std::memcpy(out->name, a.name.data(), a.name.size() < 255 ? a.name.size() : 255);
  out->kind = uint32_t(a.kind);
  out->components = a.components;
  out->value_count = uint32_t(a.value_count());
  out->corner_count = uint32_t(a.corner_values.size());
  return QMC_OK;
}

int qmc_decoder_face_labels_count(const qmc_decoder* decoder) {
  if (!decoder || !decoder->status.ok()) return 0;
  return int(decoder->stream.file().mesh.face_labels.size());
}

int qmc_decoder_face_labels(const qmc_decoder* decoder, int index, qmc_face_labels* out) {
  if (!decoder || !out) return QMC_INVALID_ARGUMENT;
  std::memset(out, 0, sizeof(*out));
  if (!decoder->status.ok()) return int(decoder->status.code());
  if (index < 0 || index >= qmc_decoder_face_labels_count(decoder)) return QMC_INVALID_ARGUMENT;
  const qmc::FaceLabels& l = decoder->stream.file().mesh.face_labels[size_t(index)];
  out->face_values =
      static_cast<uint32_t*>(std::malloc(l.face_values.empty() ? 1 : l.face_values.size() * sizeof(uint32_t)));
  if (!out->face_values) return QMC_LIMIT_EXCEEDED;
  if (!l.face_values.empty())
    std::memcpy(out->face_values, l.face_values.data(), l.face_values.size() * sizeof(uint32_t));
  std::memcpy(out->name, l.name.data(), l.name.size() < 255 ? l.name.size() : 255);
  out->value_count = uint32_t(l.values.size());
  out->reference_count = uint32_t(l.references.size());
  out->face_count = uint32_t(l.face_values.size());
  return QMC_OK;
}

const char* qmc_decoder_face_label_string(const qmc_decoder* decoder, int index, int reference, uint32_t value,
                                          uint32_t* length) {
  if (!decoder || !decoder->status.ok() || index < 0 || index >= qmc_decoder_face_labels_count(decoder)) return nullptr;
  const qmc::FaceLabels& l = decoder->stream.file().mesh.face_labels[size_t(index)];
  const std::vector<std::string>& table = reference ? l.references : l.values;
  if (value >= table.size()) return nullptr;
  if (length) *length = uint32_t(table[value].size());
  return table[value].c_str();
}

int qmc_decoder_canonical_output(const qmc_decoder* decoder, uint8_t** bytes, size_t* size) {
  if (!decoder || !bytes || !size) return QMC_INVALID_ARGUMENT;
  *bytes = nullptr;
  *size = 0;
  if (!decoder->status.ok()) return int(decoder->status.code());
  QMC_TRY {
    const std::vector<uint8_t> output = qmc::canonical_output(decoder->stream.file());
    if (!copy_array(output, bytes)) return QMC_LIMIT_EXCEEDED;
    *size = output.size();
    return QMC_OK;
  }
  QMC_CATCH_ALL(return QMC_LIMIT_EXCEEDED)
}

}  // extern "C"
