#include "draco_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <utility>

#include "draco/compression/config/compression_shared.h"
#include "draco/compression/decode.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"
#include "draco/mesh/mesh.h"
#include "draco/metadata/geometry_metadata.h"
#include "cold_heap.h"

namespace qmc::bench {
namespace {

// The name Draco's OBJ loader gives the polygon attribute; the OBJ writer
// looks the attribute up by it, so using the same name keeps our buffers
// readable by Draco's own tools as polygon meshes.
constexpr const char* kAddedEdgesName = "added_edges";

// ---------------------------------------------------------------------------
// Input checks

std::string check_options(const DracoOptions& options, int runs) {
  if (runs < 1) return "runs must be at least 1";
  if (options.position_bits < 0 || options.position_bits > 30) {
    return "position_bits must be 0 (no quantization) or 1..30";
  }
  if (options.compression_level < 0 || options.compression_level > 10) {
    return "compression_level must be 0..10";
  }
  return {};
}

std::string check_mesh(const qmc::Mesh& mesh) {
  if (mesh.positions.size() % 3 != 0) return "positions is not a multiple of 3 floats";
  for (float x : mesh.positions) {
    if (!std::isfinite(x)) return "non-finite coordinate";
  }
  if (mesh.face_count() == 0) return "no faces: Draco's mesh encoder needs at least one";
  size_t corner_total = 0;
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_sizes[f] < 3) return "face " + std::to_string(f) + " has fewer than 3 corners";
    corner_total += mesh.face_sizes[f];
  }
  if (corner_total != mesh.corners.size()) return "face_sizes do not add up to corners.size()";
  for (uint32_t v : mesh.corners) {
    if (v >= mesh.vertex_count()) return "corner index " + std::to_string(v) + " out of range";
  }
  return {};
}

// ---------------------------------------------------------------------------
// qmc::Mesh -> draco::Mesh

struct DracoInput {
  std::unique_ptr<draco::Mesh> mesh;
  int position_id = -1;
  int edges_id = -1;                  // the polygon attribute, if any
  std::vector<uint32_t> source_face;  // qmc face of each draco triangle
};

// Mirrors the OBJ loader, which adds the attribute only when some face really
// is a polygon; an all-triangle mesh is encoded exactly as without the option.
bool wants_polygon_attribute(const qmc::Mesh& mesh, const DracoOptions& options) {
  if (!options.preserve_polygons) return false;
  return std::any_of(mesh.face_sizes.begin(), mesh.face_sizes.end(),
                     [](uint32_t n) { return n > 3; });
}

size_t fan_triangle_count(const qmc::Mesh& mesh) {
  size_t count = 0;
  for (uint32_t n : mesh.face_sizes) count += n - 2;
  return count;
}

// One value per qmc vertex, deliberately not merged by value as the OBJ
// loader does: coincident vertices are distinct vertices of the input. (Where
// merging would create a non-manifold vertex, Draco splits it again, which is
// why suzanne's coincident seam vertices give the same bytes either way.)
int add_positions(const qmc::Mesh& mesh, bool at_origin, draco::Mesh* out) {
  draco::GeometryAttribute ga;
  ga.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false,
          sizeof(float) * 3, 0);
  const auto count = static_cast<uint32_t>(mesh.vertex_count());
  const int id = out->AddAttribute(ga, false, count);
  draco::PointAttribute* att = out->attribute(id);
  const float origin[3] = {0.f, 0.f, 0.f};
  for (uint32_t v = 0; v < count; ++v) {
    att->SetAttributeValue(draco::AttributeValueIndex(v), at_origin ? origin : &mesh.positions[3 * size_t{v}]);
  }
  return id;
}

// A per-corner uint8 with two values: 1 when the edge opposite the corner
// was added by triangulation, 0 when it is an edge of the original polygon.
// Named through attribute metadata, as the OBJ loader does.
int add_added_edges(draco::Mesh* out) {
  draco::GeometryAttribute ga;
  ga.Init(draco::GeometryAttribute::GENERIC, nullptr, 1, draco::DT_UINT8, false, 1, 0);
  const int id = out->AddAttribute(ga, false, 2);
  for (uint8_t value : {uint8_t{0}, uint8_t{1}}) {
    out->attribute(id)->SetAttributeValue(draco::AttributeValueIndex(value), &value);
  }
  auto metadata = std::make_unique<draco::AttributeMetadata>();
  metadata->AddEntryString("name", kAddedEdgesName);
  out->AddAttributeMetadata(id, std::move(metadata));
  return id;
}

// Fan from the first corner: triangle t of an n-gon is (v0, v[t+1], v[t+2]).
// Every triangle but the last has an added edge (v[t+2], v0), which lies
// opposite its corner 1 -- the same marking the OBJ loader uses.
void add_fan_triangles(const qmc::Mesh& mesh, DracoInput* in) {
  draco::PointAttribute* pos = in->mesh->attribute(in->position_id);
  draco::PointAttribute* edges = in->edges_id >= 0 ? in->mesh->attribute(in->edges_id) : nullptr;
  uint32_t point = 0;
  size_t first = 0;
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t n = mesh.face_sizes[f];
    const uint32_t* v = &mesh.corners[first];
    for (uint32_t t = 0; t + 2 < n; ++t) {
      const uint32_t corner_vertex[3] = {v[0], v[t + 1], v[t + 2]};
      draco::Mesh::Face face;
      for (size_t c = 0; c < 3; ++c, ++point) {
        face[c] = draco::PointIndex(point);
        pos->SetPointMapEntry(face[c], draco::AttributeValueIndex(corner_vertex[c]));
        const bool added = c == 1 && t + 3 < n;
        if (edges) edges->SetPointMapEntry(face[c], draco::AttributeValueIndex(added ? 1 : 0));
      }
      in->mesh->AddFace(face);
      in->source_face.push_back(static_cast<uint32_t>(f));
    }
    first += n;
  }
}

DracoInput build_draco_mesh(const qmc::Mesh& mesh, const DracoOptions& options) {
  DracoInput in;
  in.mesh = std::make_unique<draco::Mesh>();
  // Explicit point maps are sized by the point count, so it must be known
  // before the attributes are added: one point per triangle corner.
  in.mesh->set_num_points(static_cast<uint32_t>(3 * fan_triangle_count(mesh)));
  in.position_id = add_positions(mesh, options.positions_at_origin, in.mesh.get());
  if (wants_polygon_attribute(mesh, options)) in.edges_id = add_added_edges(in.mesh.get());
  add_fan_triangles(mesh, &in);
  // Corners that share vertex and flag become one point, as in the OBJ loader.
  in.mesh->DeduplicatePointIds();
  return in;
}

// ---------------------------------------------------------------------------
// Loss accounting: Draco's edgebreaker skips triangles whose position
// indices repeat, so predict that from the input and let the caller compare
// with what came back.

bool is_degenerate(const draco::Mesh& mesh, const draco::PointAttribute& pos,
                   draco::FaceIndex f) {
  const draco::Mesh::Face& face = mesh.face(f);
  const auto a = pos.mapped_index(face[0]), b = pos.mapped_index(face[1]),
             c = pos.mapped_index(face[2]);
  return a == b || b == c || c == a;
}

void account_losses(const qmc::Mesh& mesh, const DracoInput& in, DracoResult* result) {
  const draco::PointAttribute& pos = *in.mesh->attribute(in.position_id);
  std::vector<uint32_t> kept(mesh.face_count(), 0), lost(mesh.face_count(), 0);
  std::vector<bool> used(mesh.vertex_count(), false);
  for (draco::FaceIndex f(0); f < in.mesh->num_faces(); ++f) {
    const uint32_t source = in.source_face[f.value()];
    if (is_degenerate(*in.mesh, pos, f)) {
      ++lost[source];
      continue;
    }
    ++kept[source];
    for (size_t c = 0; c < 3; ++c) used[pos.mapped_index(in.mesh->face(f)[c]).value()] = true;
  }
  result->input_triangles = in.mesh->num_faces();
  result->degenerate_triangles = std::accumulate(lost.begin(), lost.end(), size_t{0});
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    if (kept[f] == 0) ++result->dropped_faces;
    else if (lost[f] > 0) ++result->damaged_faces;
  }
  result->unreferenced_vertices = static_cast<size_t>(std::count(used.begin(), used.end(), false));
}

// ---------------------------------------------------------------------------
// Encoding and decoding, timed

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Set up like the draco_encoder tool, which goes through ExpertEncoder so it
// can send the polygon flags without prediction: the tool's authors found the
// default prediction makes that attribute larger (and it does, by ~60 bytes on
// fandisk's 764 quads).
draco::Status configure(const DracoInput& in, const DracoOptions& options,
                        draco::ExpertEncoder* encoder) {
  if (options.position_bits > 0) {
    encoder->SetAttributeQuantization(in.position_id, options.position_bits);
  }
  const int speed = 10 - options.compression_level;  // the draco_encoder -cl mapping
  encoder->SetSpeedOptions(speed, speed);
  encoder->SetEncodingMethod(draco::MESH_EDGEBREAKER_ENCODING);
  if (in.edges_id < 0) return draco::OkStatus();
  return encoder->SetAttributePredictionScheme(in.edges_id, draco::PREDICTION_NONE);
}

bool encode_runs(const DracoInput& in, const DracoOptions& options, int runs,
                 std::vector<char>* bytes, DracoResult* result) {
  for (int r = 0; r < runs; ++r) {
    draco::ExpertEncoder encoder(*in.mesh);
    draco::Status status = configure(in, options, &encoder);
    draco::EncoderBuffer buffer;
    const auto start = std::chrono::steady_clock::now();
    if (status.ok()) status = encoder.EncodeToBuffer(&buffer);  // EncodeMeshToBuffer inside
    result->encode_seconds.push_back(seconds_since(start));
    if (!status.ok()) {
      result->error = "Draco encode: " + status.error_msg_string();
      return false;
    }
    bytes->assign(buffer.data(), buffer.data() + buffer.size());
  }
  result->bytes = bytes->size();
  return true;
}

// One DecodeMeshFromBuffer, timed.
draco::StatusOr<std::unique_ptr<draco::Mesh>> timed_decode(const std::vector<char>& bytes, double* seconds) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  const auto start = std::chrono::steady_clock::now();
  auto status_or = decoder.DecodeMeshFromBuffer(&buffer);
  *seconds = seconds_since(start);
  return status_or;
}

std::unique_ptr<draco::Mesh> decode_runs(const std::vector<char>& bytes, int runs, bool cold_heap,
                                         DracoResult* result) {
  std::unique_ptr<draco::Mesh> decoded;
  for (int r = 0; r < runs; ++r) {
    double seconds = 0;
    auto status_or = timed_decode(bytes, &seconds);
    result->decode_seconds.push_back(seconds);
    if (!status_or.ok() || !status_or.value()) {
      result->error = "Draco decode: " + status_or.status().error_msg_string();
      return nullptr;
    }
    decoded = std::move(status_or).value();
  }
  if (cold_heap) {
    decoded.reset();
    hand_heap_back();
    auto status_or = timed_decode(bytes, &result->cold_decode_seconds);
    if (!status_or.ok() || !status_or.value()) {
      result->error = "Draco decode: " + status_or.status().error_msg_string();
      return nullptr;
    }
    decoded = std::move(status_or).value();
  }
  return decoded;
}

// ---------------------------------------------------------------------------
// draco::Mesh -> qmc::Mesh

// Decoded triangles as position-value indices plus the polygon flag of each
// corner (all 0 when there is no polygon attribute).
struct Triangles {
  std::vector<uint32_t> vertex;  // 3 per triangle
  std::vector<uint8_t> added;    // 3 per triangle: edge opposite the corner was added
  size_t count() const { return vertex.size() / 3; }
};

const draco::PointAttribute* find_added_edges(const draco::Mesh& mesh) {
  const draco::GeometryMetadata* metadata = mesh.GetMetadata();
  if (!metadata) return nullptr;
  const draco::AttributeMetadata* entry =
      metadata->GetAttributeMetadataByStringEntry("name", kAddedEdgesName);
  if (!entry) return nullptr;
  const draco::PointAttribute* att = mesh.GetAttributeByUniqueId(entry->att_unique_id());
  if (!att || att->num_components() != 1 || att->data_type() != draco::DT_UINT8) return nullptr;
  return att;
}

Triangles read_triangles(const draco::Mesh& mesh, const draco::PointAttribute& pos,
                         const draco::PointAttribute* added) {
  Triangles tris;
  tris.vertex.reserve(3 * size_t{mesh.num_faces()});
  tris.added.reserve(3 * size_t{mesh.num_faces()});
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (size_t c = 0; c < 3; ++c) {
      const draco::PointIndex p = mesh.face(f)[c];
      uint8_t flag = 0;
      if (added) added->GetMappedValue(p, &flag);
      tris.vertex.push_back(pos.mapped_index(p).value());
      tris.added.push_back(flag);
    }
  }
  return tris;
}

bool copy_positions(const draco::PointAttribute& pos, qmc::Mesh* out) {
  out->positions.resize(3 * pos.size());
  for (uint32_t v = 0; v < pos.size(); ++v) {
    if (!pos.ConvertValue<float, 3>(draco::AttributeValueIndex(v), &out->positions[3 * size_t{v}])) {
      return false;
    }
  }
  return true;
}

void append_face(const uint32_t* vertices, uint32_t n, qmc::Mesh* out) {
  out->face_sizes.push_back(n);
  out->corners.insert(out->corners.end(), vertices, vertices + n);
}

// Triangles that belong to one original polygon, found by crossing added
// edges. Union-find keeps this linear however large the polygon.
class TriangleGroups {
 public:
  explicit TriangleGroups(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  uint32_t root(uint32_t t) {
    while (parent_[t] != t) t = parent_[t] = parent_[parent_[t]];
    return t;
  }
  void join(uint32_t a, uint32_t b) { parent_[root(a)] = root(b); }

 private:
  std::vector<uint32_t> parent_;
};

uint64_t edge_key(uint32_t from, uint32_t to) { return (uint64_t{from} << 32) | to; }

// Corner k = 3t + c of triangle t faces the directed edge from corner c+1 to c+2.
uint64_t opposite_edge(const Triangles& tris, size_t k) {
  const size_t t = k / 3, c = k % 3;
  return edge_key(tris.vertex[3 * t + (c + 1) % 3], tris.vertex[3 * t + (c + 2) % 3]);
}

uint64_t reversed(uint64_t key) { return (key << 32) | (key >> 32); }

// Marks every added edge, and its twin in the neighbouring triangle, as
// interior and joins the two triangles. Only one side of an added edge
// carries the flag, so the twin is found by its reversed directed edge. An
// added edge without twin (its other triangle was degenerate and dropped by
// Draco) stays a boundary edge, as in Draco's OBJ writer.
std::vector<bool> pair_added_edges(const Triangles& tris, TriangleGroups* groups) {
  const size_t corners = tris.vertex.size();
  std::vector<std::pair<uint64_t, uint32_t>> by_edge(corners);
  for (size_t k = 0; k < corners; ++k) by_edge[k] = {opposite_edge(tris, k), static_cast<uint32_t>(k)};
  std::sort(by_edge.begin(), by_edge.end());

  std::vector<bool> interior(corners, false);
  for (size_t k = 0; k < corners; ++k) {
    if (!tris.added[k] || interior[k]) continue;
    const uint64_t twin_key = reversed(opposite_edge(tris, k));
    auto it = std::lower_bound(by_edge.begin(), by_edge.end(), std::make_pair(twin_key, uint32_t{0}));
    for (; it != by_edge.end() && it->first == twin_key; ++it) {
      const uint32_t j = it->second;
      if (interior[j] || j / 3 == k / 3) continue;
      interior[k] = interior[j] = true;
      groups->join(static_cast<uint32_t>(k / 3), j / 3);
      break;
    }
  }
  return interior;
}

// Chains the boundary edges of one group into a single cycle. Fails (returns
// false) if they do not form exactly one closed loop.
bool chain_cycle(std::vector<std::pair<uint32_t, uint32_t>> edges, std::vector<uint32_t>* cycle) {
  const std::pair<uint32_t, uint32_t> first = edges.front();
  std::sort(edges.begin(), edges.end());
  std::vector<bool> used(edges.size(), false);
  const auto index_of = [&](auto it) { return static_cast<size_t>(it - edges.begin()); };
  used[index_of(std::lower_bound(edges.begin(), edges.end(), first))] = true;
  cycle->assign(1, first.first);
  uint32_t at = first.second;
  while (at != first.first) {
    auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(at, uint32_t{0}));
    while (it != edges.end() && it->first == at && used[index_of(it)]) ++it;
    if (it == edges.end() || it->first != at) return false;
    used[index_of(it)] = true;
    cycle->push_back(at);
    at = it->second;
  }
  return cycle->size() == edges.size();
}

// Emits each group of triangles as one polygon, in the order of each group's
// first triangle; a group that does not close into a single cycle is emitted
// as its triangles and counted.
void emit_polygons(const Triangles& tris, qmc::Mesh* out, size_t* unrecovered) {
  TriangleGroups groups(tris.count());
  const std::vector<bool> interior = pair_added_edges(tris, &groups);

  std::vector<std::vector<uint32_t>> members(tris.count());
  std::vector<uint32_t> order;
  for (uint32_t t = 0; t < tris.count(); ++t) {
    const uint32_t r = groups.root(t);
    if (members[r].empty()) order.push_back(r);
    members[r].push_back(t);
  }
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  std::vector<uint32_t> cycle;
  for (uint32_t r : order) {
    edges.clear();
    for (uint32_t t : members[r]) {
      for (size_t c = 0; c < 3; ++c) {
        if (interior[3 * t + c]) continue;
        const uint64_t key = opposite_edge(tris, 3 * t + c);
        edges.emplace_back(static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key));
      }
    }
    if (members[r].size() > 1 && !chain_cycle(edges, &cycle)) {
      ++*unrecovered;
      for (uint32_t t : members[r]) append_face(&tris.vertex[3 * t], 3, out);
    } else if (members[r].size() > 1) {
      append_face(cycle.data(), static_cast<uint32_t>(cycle.size()), out);
    } else {
      append_face(&tris.vertex[3 * r], 3, out);
    }
  }
}

bool convert_decoded(const draco::Mesh& decoded, DracoResult* result) {
  const draco::PointAttribute* pos = decoded.GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (!pos || !copy_positions(*pos, &result->decoded)) {
    result->error = "decoded Draco mesh has no usable position attribute";
    return false;
  }
  const draco::PointAttribute* added = find_added_edges(decoded);
  const Triangles tris = read_triangles(decoded, *pos, added);
  if (added) {
    emit_polygons(tris, &result->decoded, &result->unrecovered_polygons);
  } else {
    for (size_t t = 0; t < tris.count(); ++t) append_face(&tris.vertex[3 * t], 3, &result->decoded);
  }
  const size_t decoded_triangles = tris.count();
  result->dropped_triangles =
      result->input_triangles > decoded_triangles ? result->input_triangles - decoded_triangles : 0;
  return true;
}

}  // namespace

DracoResult run_draco(const qmc::Mesh& mesh, const DracoOptions& options, int runs) {
  DracoResult result;
  result.error = check_options(options, runs);
  if (result.error.empty()) result.error = check_mesh(mesh);
  if (!result.error.empty()) return result;

  const DracoInput input = build_draco_mesh(mesh, options);
  account_losses(mesh, input, &result);

  std::vector<char> bytes;
  if (!encode_runs(input, options, runs, &bytes, &result)) return result;
  const std::unique_ptr<draco::Mesh> decoded = decode_runs(bytes, runs, options.cold_heap_decode, &result);
  if (!decoded || !convert_decoded(*decoded, &result)) return result;
  result.ok = true;
  return result;
}

}  // namespace qmc::bench
