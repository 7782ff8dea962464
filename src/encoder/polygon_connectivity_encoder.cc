// Method 2 payload (spec/qmc-format.md 5.4.1): components, face symbols under
// the cheapest coding (5.4.4), then the records of 5.4.7 and 5.4.8, which the
// encoder derives from the surface so that the decoder's final labels are
// exactly the input's vertices.
#include "encoder/polygon_connectivity_encoder.h"

#include <algorithm>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/huffman.h"
#include "common/polygon_symbols.h"
#include "common/union_find.h"
#include "common/quad_codings.h"
#include "common/polygon_symbol_coding.h"
#include "common/range_coder.h"
#include "decoder/polygon_spirale_reversi.h"
#include "encoder/polygon_surface.h"
#include "encoder/polygon_traversal_encoder.h"
#include "encoder/vertex_order.h"
#include "qmc/format.h"

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

int label_width(uint64_t max_value) {
  int w = 1;
  while (max_value >> w) ++w;
  return w;
}

uint32_t find(std::vector<uint32_t>& parent, uint32_t v) { return union_find_root(parent, v); }
void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) { union_find_join(parent, a, b); }

void write_other_shape(const FaceShapes& shapes, size_t f, BitWriter* out) {
  out->write_exp_golomb(shapes.degree[f] - 5);
  const uint32_t m = shapes.degree[f] - 2;
  const uint8_t* status = &shapes.status[shapes.status_begin[f]];
  for (uint32_t i = 0; i < m; ++i) out->write_bit(status[i]);
  // Kinds of the gaps without free vertices.
  uint32_t g = 0, free_in_gap = 0;
  const uint8_t* gaps = &shapes.gap_is_edge[shapes.gap_begin[f]];
  for (uint32_t i = 0; i <= m; ++i) {
    if (i == m || status[i]) {
      if (free_in_gap == 0) out->write_bit(gaps[g]);
      ++g;
      free_in_gap = 0;
    } else {
      ++free_in_gap;
    }
  }
}

// `symbols[f]`: face_symbol(shapes, f), computed once per face for every
// coding tried (5.4.4).
void write_mixed_symbols(const FaceShapes& shapes, const std::vector<int>& symbols, BitWriter* out) {
  std::vector<uint64_t> counts[2] = {std::vector<uint64_t>(kPolygonSymbolCount, 0),
                                     std::vector<uint64_t>(kPolygonSymbolCount, 0)};
  int context = 1;
  for (size_t f = 0; f < shapes.size(); ++f) {
    ++counts[context][symbols[f]];
    context = face_class(shapes, f);
  }
  std::vector<uint8_t> lengths[2];
  for (int c = 0; c < 2; ++c) {
    const bool present = std::any_of(counts[c].begin(), counts[c].end(), [](uint64_t n) { return n > 0; });
    out->write_bit(present);
    if (!present) continue;
    lengths[c] = huffman_code_lengths(counts[c]);
    write_code_lengths(out, lengths[c]);
  }
  const HuffmanEncoder coder[2] = {HuffmanEncoder(lengths[0].empty() ? std::vector<uint8_t>(1, 1) : lengths[0]),
                                   HuffmanEncoder(lengths[1].empty() ? std::vector<uint8_t>(1, 1) : lengths[1])};
  context = 1;
  for (size_t f = 0; f < shapes.size(); ++f) {
    coder[context].write(out, uint32_t(symbols[f]));
    if (symbols[f] == kPolygonOtherSymbol) write_other_shape(shapes, f, out);
    context = face_class(shapes, f);
  }
}

bool all_quads(const FaceShapes& shapes) {
  for (uint32_t d : shapes.degree)
    if (d != 4) return false;
  return !shapes.degree.empty();
}

std::vector<uint8_t> quad_types(const std::vector<int>& symbols) {
  std::vector<uint8_t> types(symbols.size());
  for (size_t f = 0; f < symbols.size(); ++f) types[f] = uint8_t(symbols[f] + 1);
  return types;
}

uint8_t symbol_groups(const FaceShapes& shapes) {
  uint8_t groups = 0;
  for (uint32_t d : shapes.degree) groups |= d == 3 ? kGroupTriangles : d == 4 ? kGroupQuads : kGroupOther;
  return groups;
}

// Codings 7 and 8 (5.4.10): the encoder runs the decoder's Spirale Reversi
// over its own symbols, so each one is coded in exactly the gate context the
// decoder will see when it decodes it.
class EncodedFaces : public FaceSymbolSource {
 public:
  EncodedFaces(const FaceShapes& shapes, const std::vector<int>& symbols, bool quad_neighbours)
      : shapes_(shapes), symbols_(symbols) {
    model_.groups = symbol_groups(shapes);
    model_.quad_neighbours = quad_neighbours;
  }
  Status face(const GateContext& gate, size_t f, const FaceShapes** shapes, size_t* index) override {
    const int symbol = symbols_[f];
    code_face_symbol(&range_, &model_, gate, symbol);
    if (symbol == kPolygonOtherSymbol) {
      uint32_t extra = shapes_.degree[f] - 5;
      code_other_degree(&range_, &extra);
      const uint32_t m = shapes_.degree[f] - 2, gaps = shapes_.gap_count(f);
      std::vector<uint8_t> status(&shapes_.status[shapes_.status_begin[f]], &shapes_.status[shapes_.status_begin[f]] + m);
      std::vector<uint8_t> kinds(&shapes_.gap_is_edge[shapes_.gap_begin[f]],
                                 &shapes_.gap_is_edge[shapes_.gap_begin[f]] + gaps);
      code_other_shape(&range_, &model_, m, status.data(), kinds.data());
    }
    *shapes = &shapes_;
    *index = f;
    return Status::Ok();
  }
  uint8_t groups() const { return model_.groups; }
  std::vector<uint8_t> finish() { return range_.finish(); }

 private:
  const FaceShapes& shapes_;
  const std::vector<int>& symbols_;
  PolygonSymbolModel model_ = kFreshPolygonSymbolModel;
  RangeEncoder range_;
};

// The groups byte, the length and the range-coded symbols of coding 7 (or
// 8, with quad_neighbours); empty if the traversal's own symbols did not
// replay (then the coding is not offered, and self_check still guards
// whichever coding is written).
std::vector<uint8_t> context_coded_symbols(const PolygonTraversal& t, const std::vector<int>& symbols,
                                           bool quad_neighbours) {
  EncodedFaces faces(t.shapes, symbols, quad_neighbours);
  if (!polygon_spirale_contexts(t.component_faces, t.first_degree, &faces).ok()) return {};
  const std::vector<uint8_t> stream = faces.finish();
  std::vector<uint8_t> out;
  put_u8(&out, faces.groups());
  put_varint(&out, stream.size());
  out.insert(out.end(), stream.begin(), stream.end());
  return out;
}

void write_symbols(const FaceShapes& shapes, const std::vector<int>& symbols, int coding, BitWriter* out) {
  if (coding == kPolygonMixedHuffman) write_mixed_symbols(shapes, symbols, out);
  else write_quad_stream(QuadCoding(coding), quad_types(symbols), out);
}

// Everything the decoder needs after the symbols, and the file mesh.
struct Records {
  std::vector<uint32_t> virtual_index;                  // surface face indices
  std::vector<std::array<uint32_t, 3>> seams;            // a, b, r
  std::vector<std::pair<uint32_t, uint32_t>> idents;     // surface labels
};

// Output corners (surface labels) of surface face index i.
// Into `out`, reused from face to face.
void output_face(const PolygonSurfaceModel& s, const PolygonTraversal& t, uint32_t i, std::vector<uint32_t>* out) {
  const uint32_t f = t.order[i], d = s.degree(f), b = s.face_begin[f];
  out->resize(d);
  for (uint32_t k = 0; k < d; ++k) (*out)[k] = t.label[s.corners[b + (t.rotation[i] + k) % d]];
}

void derive_records(const PolygonSurfaceModel& s, const PolygonTraversal& t, Records* r,
                    std::vector<uint32_t>* parent) {
  std::vector<uint32_t> index_of(s.face_count());
  for (uint32_t i = 0; i < t.order.size(); ++i) {
    index_of[t.order[i]] = i;
    if (s.source[t.order[i]] == kVirtualFace) r->virtual_index.push_back(i);
  }
  parent->resize(t.labels);
  for (uint32_t v = 0; v < t.labels; ++v) (*parent)[v] = v;
  std::vector<uint32_t> fa, fb;
  for (const auto& seam : s.seams) {
    uint32_t ia = index_of[seam.a], ib = index_of[seam.b];
    const uint32_t d = s.degree(seam.a);
    // Stored corners: a[i] ~ b[(shift - i) mod d]; output starts at the
    // rotations, so r = shift - rot_a - rot_b (mod d), symmetric in a, b.
    const uint32_t rot = uint32_t((uint64_t(seam.shift) + 2 * uint64_t(d) - t.rotation[ia] - t.rotation[ib]) % d);
    if (ia > ib) std::swap(ia, ib);
    r->seams.push_back({ia, ib, rot});
    output_face(s, t, ia, &fa);
    output_face(s, t, ib, &fb);
    for (uint32_t k = 0; k < d; ++k) unite(*parent, fa[k], fb[(rot + d - k) % d]);
  }
  // Copies not joined by seams: one identification each, with the input
  // vertex's first surface label.
  std::vector<uint32_t> first(s.original.empty() ? 0 : *std::max_element(s.original.begin(), s.original.end()) + 1,
                              kNone);
  for (uint32_t v = 0; v < s.vertex_count(); ++v) {
    const uint32_t l = t.label[v];
    if (l == kNone) continue;
    uint32_t& f = first[s.original[v]];
    if (f == kNone) {
      f = l;
    } else if (find(*parent, l) != find(*parent, f)) {
      r->idents.push_back({l, f});
      unite(*parent, l, f);
    }
  }
  std::sort(r->virtual_index.begin(), r->virtual_index.end());
}

}  // namespace

std::string encode_polygon_connectivity(const Mesh& mesh, int forced, bool context_coding, bool quad_contexts,
                                        bool unused_along_curve, PolygonEncoding* out, TraversalStart start) {
  *out = PolygonEncoding{};
  PolygonSurfaceModel surface;
  if (std::string why = build_polygon_surface(mesh, &surface); !why.empty()) return why;
  PolygonTraversal traversal;
  if (std::string why = traverse_polygon_surface(surface, &traversal, start); !why.empty()) return why;
  Records records;
  std::vector<uint32_t> parent;
  derive_records(surface, traversal, &records, &parent);

  // Final labels: classes by smallest surface label, then the vertices of
  // loose faces only in input order, then those of no face along a curve.
  std::vector<uint32_t> final(traversal.labels);
  uint32_t classes = 0;
  for (uint32_t v = 0; v < traversal.labels; ++v) final[v] = find(parent, v) == v ? classes++ : final[find(parent, v)];
  std::vector<uint32_t> label_vertex(traversal.labels, kNone);
  for (uint32_t v = 0; v < surface.vertex_count(); ++v)
    if (traversal.label[v] != kNone) label_vertex[traversal.label[v]] = surface.original[v];
  std::vector<uint32_t> input_final(mesh.vertex_count(), kNone);
  out->file_vertex.assign(classes, kNone);
  for (uint32_t l = 0; l < traversal.labels; ++l) {
    out->file_vertex[final[l]] = label_vertex[l];
    input_final[label_vertex[l]] = final[l];
  }
  std::vector<uint8_t> used(mesh.vertex_count(), 0);
  for (uint32_t v : mesh.corners) used[v] = 1;
  std::vector<uint32_t> rest[2];  // used by loose faces only (input order); by no face (curve order)
  for (uint32_t v = 0; v < mesh.vertex_count(); ++v)
    if (input_final[v] == kNone) rest[used[v] ? 0 : 1].push_back(v);
  if (unused_along_curve) sort_along_curve(mesh, &rest[1]);
  for (const std::vector<uint32_t>& part : rest)
    for (uint32_t v : part) {
      input_final[v] = uint32_t(out->file_vertex.size());
      out->file_vertex.push_back(v);
    }

  // File mesh: real surface faces in surface order, then loose faces; in
  // all, the input's faces.
  out->file_mesh.face_sizes.reserve(mesh.face_count());
  out->file_mesh.corners.reserve(mesh.corners.size());
  out->face_source.reserve(mesh.face_count());
  std::vector<uint32_t> corners;
  for (uint32_t i = 0; i < traversal.order.size(); ++i) {
    const uint32_t f = traversal.order[i];
    if (surface.source[f] == kVirtualFace) continue;
    output_face(surface, traversal, i, &corners);
    out->file_mesh.face_sizes.push_back(uint32_t(corners.size()));
    for (uint32_t l : corners) out->file_mesh.corners.push_back(final[l]);
    out->face_source.push_back(surface.source[f]);
    if (corners.size() != 4) ++out->non_quad_faces;
  }
  std::vector<uint32_t> input_begin(mesh.face_count() + 1, 0);
  for (size_t f = 0; f < mesh.face_count(); ++f) input_begin[f + 1] = input_begin[f] + mesh.face_sizes[f];
  for (uint32_t f : surface.loose) {
    out->file_mesh.face_sizes.push_back(mesh.face_sizes[f]);
    for (uint32_t k = input_begin[f]; k < input_begin[f + 1]; ++k)
      out->file_mesh.corners.push_back(input_final[mesh.corners[k]]);
    out->face_source.push_back(f);
  }

  // Coding: the smallest (5.4.4).
  const FaceShapes& shapes = traversal.shapes;
  std::vector<int> symbols(shapes.size());
  for (size_t f = 0; f < shapes.size(); ++f) ++out->symbol_counts[symbols[f] = face_symbol(shapes, f)];
  const bool quads = all_quads(shapes);
  const std::vector<uint8_t> types = quads ? quad_types(symbols) : std::vector<uint8_t>{};
  int best = -1;
  const bool try_context = context_coding || forced == kPolygonContextCoded;
  const std::vector<uint8_t> coded_symbols = try_context ? context_coded_symbols(traversal, symbols, false) : std::vector<uint8_t>{};
  // Coding 8 differs from 7 only in its quads' contexts: tried where there
  // are quads (elsewhere it is coding 7's bytes under a number 1.17 decoders reject).
  const bool try_quad_contexts = forced == kPolygonQuadContextCoded ||
                                 (context_coding && quad_contexts && (symbol_groups(shapes) & kGroupQuads));
  const std::vector<uint8_t> quad_coded_symbols =
      try_quad_contexts ? context_coded_symbols(traversal, symbols, true) : std::vector<uint8_t>{};
  const auto coded_by = [&](int coding) -> const std::vector<uint8_t>& {
    return coding == kPolygonContextCoded ? coded_symbols : quad_coded_symbols;
  };
  for (int c = 0; c < kPolygonCodingCount; ++c) {
    if (c == kPolygonUnassignedCoding) {
      out->coding_bits[c] = -1;
    } else if (is_context_coding(c)) {
      out->coding_bits[c] = coded_by(c).empty() ? -1 : int64_t(8 * coded_by(c).size());
    } else if (c == kPolygonMixedHuffman) {
      BitWriter trial;
      write_mixed_symbols(shapes, symbols, &trial);
      out->coding_bits[c] = int64_t(trial.bit_count());
    } else {
      out->coding_bits[c] = quads ? quad_stream_bits(QuadCoding(c), types) : -1;
    }
    if (out->coding_bits[c] >= 0 && (best < 0 || out->coding_bits[c] < out->coding_bits[best])) best = c;
  }
  if (forced >= 0) {
    if (forced >= kPolygonCodingCount || out->coding_bits[forced] < 0)
      return "polygon coding " + std::to_string(forced) + " cannot code this mesh's faces";
    best = forced;
  }
  out->coding = uint8_t(best);

  BitWriter bits;
  bits.write_exp_golomb(uint32_t(traversal.component_faces.size()));
  for (uint32_t n : traversal.component_faces) bits.write_exp_golomb(n - 2);
  for (uint32_t d : traversal.first_degree) bits.write_exp_golomb(d - 3);
  if (!is_context_coding(best)) write_symbols(shapes, symbols, best, &bits);
  const uint64_t before_records = bits.bit_count();
  bits.write_exp_golomb(uint32_t(records.virtual_index.size()));
  for (size_t i = 0; i < records.virtual_index.size(); ++i)
    bits.write_exp_golomb(i == 0 ? records.virtual_index[0] : records.virtual_index[i] - records.virtual_index[i - 1] - 1);
  bits.write_exp_golomb(uint32_t(records.seams.size()));
  for (const auto& [a, b, r] : records.seams) {
    bits.write_exp_golomb(a);
    bits.write_exp_golomb(b - a - 1);
    bits.write_exp_golomb(r);
  }
  bits.write_exp_golomb(uint32_t(records.idents.size()));
  const int w = label_width(traversal.labels == 0 ? 0 : traversal.labels - 1);
  for (const auto& [p, q] : records.idents) {
    bits.write_bits(p, w);
    bits.write_bits(q, w);
  }
  bits.write_exp_golomb(uint32_t(surface.loose.size()));
  const int wl = label_width(mesh.vertex_count() == 0 ? 0 : mesh.vertex_count() - 1);
  for (uint32_t f : surface.loose) {
    bits.write_exp_golomb(mesh.face_sizes[f] - 3);
    for (uint32_t k = input_begin[f]; k < input_begin[f + 1]; ++k) bits.write_bits(input_final[mesh.corners[k]], wl);
  }
  out->record_bits = bits.bit_count() - before_records;

  put_u8(&out->payload, uint8_t(ConnectivityMethod::kPolygon));
  put_varint(&out->payload, mesh.vertex_count());
  put_varint(&out->payload, out->file_mesh.face_count());
  put_u8(&out->payload, 0);
  put_u8(&out->payload, out->coding);
  if (is_context_coding(best)) out->payload.insert(out->payload.end(), coded_by(best).begin(), coded_by(best).end());
  const std::vector<uint8_t> stream = bits.finish();
  out->payload.insert(out->payload.end(), stream.begin(), stream.end());
  out->components = uint32_t(traversal.component_faces.size());
  out->holes = surface.holes;
  out->handles = surface.handles;
  out->identifications = uint32_t(records.idents.size());
  out->loose_faces = uint32_t(surface.loose.size());
  return {};
}

}  // namespace qmc
