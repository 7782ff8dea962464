// Connectivity method 2 (spec/qmc-format.md 5.4.1): the component list, the
// face symbols (5.4.3, 5.4.4), Spirale Reversi for polygons (5.4.5), then the
// records that close holes, glue seams and copies back (5.4.7) and the loose
// faces (5.4.8). Every count is checked against the bits that must follow
// before anything is reserved for it.
#include "decoder/polygon_connectivity_decoder.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "common/bit_reader.h"
#include "common/byte_io.h"
#include "common/huffman.h"
#include "common/polygon_symbols.h"
#include "common/union_find.h"
#include "common/quad_codings.h"
#include "decoder/coded_faces.h"
#include "decoder/connectivity_errors.h"
#include "decoder/output_budget.h"
#include "decoder/polygon_spirale_reversi.h"

namespace qmc {

Status check_face_degree(uint64_t d, const char* face) {
  if (d <= UINT32_MAX) return Status::Ok();
  return limit_error(std::string(face) + " of degree " + std::to_string(d) + ", above 2^32 - 1");
}

Status check_other_face(uint64_t d, bool fits, OtherFaceCorners* corners) {
  if (Status s = check_face_degree(d, "a face"); !s.ok()) return s;
  if (!fits) return limit_error("a face of degree " + std::to_string(d) + " cannot fit");
  return corners->take(d);
}

namespace {

// Faces reserved per byte of codings 7 and 8's symbol stream before decoding it.
constexpr uint64_t kReservedFacesPerSymbolByte = 32;

// bitlen(max_value), at least 1 (5.4.7, 5.4.8): every label costs a bit,
// so the counts read before them bound what they can allocate.
int label_width(uint64_t max_value) {
  int w = 1;
  while (max_value >> w) ++w;
  return w;
}

// One ue field: truncated past the end, bad_chunk_payload for a 32nd zero.
Status read_ue(BitReader* in, uint32_t* value) {
  *value = in->read_exp_golomb();
  if (in->overrun()) return truncated();
  if (in->invalid()) return payload_error("Exp-Golomb code with 32 leading zeros");
  return Status::Ok();
}

struct Components {
  std::vector<uint32_t> faces, first_degree;  // n_c, d_c
  uint64_t coded = 0;                          // K
};

// `symbol_bytes`: codings 7 and 8's range-coded stream length B, or -1 when the
// symbols are bits of this stream (codings 0 .. 5).
Status read_components(BitReader* in, int64_t symbol_bytes, Components* c) {
  uint32_t count = 0;
  if (Status s = read_ue(in, &count); !s.ok()) return s;
  // Each component costs at least two bits below (two ue fields).
  if (uint64_t(count) * 2 > in->bits_remaining())
    return limit_error(std::to_string(count) + " components cannot fit in the stream");
  c->faces.resize(count);
  c->first_degree.resize(count);
  for (uint32_t& n : c->faces) {
    if (Status s = read_ue(in, &n); !s.ok()) return s;
    if (n > UINT32_MAX - 2) return payload_error("component face count above 2^32 - 1");
    n += 2;
    c->coded += n - 1;
  }
  for (uint32_t& d : c->first_degree) {
    if (Status s = read_ue(in, &d); !s.ok()) return s;
    if (d > UINT32_MAX - 3) return payload_error("first face degree above 2^32 - 1");
    d += 3;
  }
  if (symbol_bytes < 0 ? c->coded > in->bits_remaining() : !range_stream_justifies(c->coded, uint64_t(symbol_bytes)))
    return limit_error(std::to_string(c->coded) + " face symbols cannot fit in the stream");
  return Status::Ok();
}

// Symbol 18's degree and bits (5.4.3).
Status read_other_shape(BitReader* in, FaceShapes* shapes, OtherFaceCorners* corners, std::vector<uint8_t>* scratch) {
  uint32_t extra = 0;
  if (Status s = read_ue(in, &extra); !s.ok()) return s;
  const uint64_t d = uint64_t(extra) + 5;
  if (Status s = check_other_face(d, d - 2 <= in->bits_remaining(), corners); !s.ok()) return s;
  const uint32_t m = uint32_t(d - 2);
  scratch->resize(2 * size_t(m) + 1);
  uint8_t* status = scratch->data();
  uint8_t* gaps = status + m;
  uint32_t gap_count = 0, free_in_gap = 0;
  for (uint32_t i = 0; i < m; ++i) {
    status[i] = uint8_t(in->read_bit());
    if (status[i]) {
      gaps[gap_count++] = free_in_gap == 0 ? 2 : 0;  // 2: kind still to read
      free_in_gap = 0;
    } else {
      ++free_in_gap;
    }
  }
  gaps[gap_count++] = free_in_gap == 0 ? 2 : 0;
  for (uint32_t g = 0; g < gap_count; ++g)
    if (gaps[g] == 2) gaps[g] = uint8_t(in->read_bit());
  if (in->overrun()) return truncated();
  shapes->add(uint32_t(d), status, gaps, gap_count);
  return Status::Ok();
}

Status read_mixed_symbols(BitReader* in, uint64_t count, FaceShapes* shapes, OtherFaceCorners* corners) {
  HuffmanDecoder table[2];
  bool present[2] = {false, false};
  for (int c = 0; c < 2; ++c) {
    present[c] = in->read_bit();
    if (in->overrun()) return truncated();
    if (present[c])
      if (Status s = read_table(in, kPolygonSymbolCount, &table[c]); !s.ok()) return s;
  }
  std::vector<uint8_t> scratch;
  int context = 1;
  for (uint64_t i = 0; i < count; ++i) {
    if (!present[context]) return symbol_error("a face symbol in a context without a Huffman table");
    const int symbol = table[context].decode(in);
    if (in->overrun()) return truncated();
    if (symbol < 0) return symbol_error("invalid face symbol code word");
    if (symbol == kPolygonOtherSymbol) {
      if (Status s = read_other_shape(in, shapes, corners, &scratch); !s.ok()) return s;
    } else {
      uint8_t status[2], gaps[3];
      uint32_t gap_count = 0;
      const uint32_t d = symbol_shape(symbol, status, gaps, &gap_count);
      shapes->add(d, status, gaps, gap_count);
    }
    context = face_class(*shapes, shapes->size() - 1);
  }
  return Status::Ok();
}

Status read_symbols(BitReader* in, int coding, uint64_t count, FaceShapes* shapes, OtherFaceCorners* corners) {
  // count <= the stream's bits (read_components), so this is bounded by the input.
  shapes->reserve(size_t(count));
  if (coding == kPolygonMixedHuffman) return read_mixed_symbols(in, count, shapes, corners);
  if (count == 0) return symbol_error("quad codings need at least one face symbol");
  std::vector<uint8_t> types;
  if (Status s = read_quad_stream(QuadCoding(coding), uint32_t(count), in, &types); !s.ok()) return s;
  for (uint8_t t : types) {
    uint8_t status[2], gaps[3];
    uint32_t gap_count = 0;
    const uint32_t d = symbol_shape(t - 1, status, gaps, &gap_count);
    shapes->add(d, status, gaps, gap_count);
  }
  return Status::Ok();
}

struct Records {
  std::vector<uint8_t> is_virtual;  // per surface face
  std::vector<uint32_t> seam_a, seam_b, seam_r;
  std::vector<uint32_t> ident_p, ident_q;
  uint32_t virtual_count = 0;
};

Status read_virtual_faces(BitReader* in, const std::vector<uint32_t>& degree, Records* r) {
  uint32_t count = 0;
  if (Status s = read_ue(in, &count); !s.ok()) return s;
  if (count > degree.size()) return symbol_error("more virtual faces than surface faces");
  // Each v_i takes at least one bit (5.4.7, section 8).
  if (count > in->bits_remaining()) return limit_error("virtual faces cannot fit in the stream");
  r->is_virtual.assign(degree.size(), 0);
  r->virtual_count = count;
  uint64_t index = 0;
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t step = 0;
    if (Status s = read_ue(in, &step); !s.ok()) return s;
    index += (i == 0 ? 0 : 1) + uint64_t(step);
    if (index >= degree.size()) return symbol_error("virtual face index past the last surface face");
    r->is_virtual[index] = 1;
  }
  return Status::Ok();
}

Status read_seams(BitReader* in, const std::vector<uint32_t>& degree, Records* r) {
  uint32_t count = 0;
  if (Status s = read_ue(in, &count); !s.ok()) return s;
  if (uint64_t(count) * 2 > r->virtual_count) return symbol_error("more seams than pairs of virtual faces");
  std::vector<uint8_t> used(degree.size(), 0);
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t a = 0, gap = 0, rot = 0;
    for (uint32_t* v : {&a, &gap, &rot})
      if (Status s = read_ue(in, v); !s.ok()) return s;
    const uint64_t b = uint64_t(a) + 1 + gap;
    if (a >= degree.size() || b >= degree.size() || !r->is_virtual[a] || !r->is_virtual[b])
      return symbol_error("a seam names a face that is not virtual");
    if (used[a] || used[b]) return symbol_error("a virtual face is in two seams");
    if (degree[a] != degree[b]) return symbol_error("a seam joins faces of different degrees");
    if (rot >= degree[a]) return symbol_error("a seam's rotation is not below its degree");
    used[a] = used[b] = 1;
    r->seam_a.push_back(a);
    r->seam_b.push_back(uint32_t(b));
    r->seam_r.push_back(rot);
  }
  return Status::Ok();
}

Status read_identifications(BitReader* in, uint32_t labels, Records* r) {
  uint32_t count = 0;
  if (Status s = read_ue(in, &count); !s.ok()) return s;
  if (count > in->bits_remaining()) return limit_error("vertex identifications cannot fit in the stream");
  const int w = label_width(labels == 0 ? 0 : labels - 1);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t p = in->read_bits(w), q = in->read_bits(w);
    if (in->overrun()) return truncated();
    if (p >= labels || q >= labels || p == q) return symbol_error("invalid vertex identification");
    r->ident_p.push_back(p);
    r->ident_q.push_back(q);
  }
  return Status::Ok();
}

Status read_loose_faces(BitReader* in, uint32_t vertex_count, Mesh* loose) {
  uint32_t count = 0;
  if (Status s = read_ue(in, &count); !s.ok()) return s;
  if (uint64_t(count) * 3 > in->bits_remaining()) return limit_error("loose faces cannot fit in the stream");
  const int w = label_width(vertex_count == 0 ? 0 : vertex_count - 1);
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t extra = 0;
    if (Status s = read_ue(in, &extra); !s.ok()) return s;
    const uint64_t d = uint64_t(extra) + 3;
    if (Status s = check_face_degree(d, "a loose face"); !s.ok()) return s;
    if (d * uint64_t(w) > in->bits_remaining()) return limit_error("a loose face cannot fit in the stream");
    loose->face_sizes.push_back(uint32_t(d));
    for (uint64_t k = 0; k < d; ++k) {
      const uint32_t label = in->read_bits(w);
      if (in->overrun()) return truncated();
      if (label >= vertex_count) return symbol_error("loose face names vertex " + std::to_string(label));
      loose->corners.push_back(label);
    }
  }
  return Status::Ok();
}

uint32_t find(std::vector<uint32_t>& parent, uint32_t v) { return union_find_root(parent, v); }
void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) { union_find_join(parent, a, b); }

// Section 5.4.7: surface labels to final labels; returns N'.
uint32_t final_labels(const PolygonSurface& s, const Records& r, std::vector<uint32_t>* final) {
  std::vector<uint32_t> parent(s.labels);
  for (uint32_t v = 0; v < s.labels; ++v) parent[v] = v;
  std::vector<uint32_t> begin(s.face_degree.size() + 1, 0);
  for (size_t f = 0; f < s.face_degree.size(); ++f) begin[f + 1] = begin[f] + s.face_degree[f];
  for (size_t i = 0; i < r.seam_a.size(); ++i) {
    const uint32_t a = r.seam_a[i], b = r.seam_b[i], d = s.face_degree[a];
    for (uint32_t k = 0; k < d; ++k)
      unite(parent, s.corners[begin[a] + k], s.corners[begin[b] + (r.seam_r[i] + d - k) % d]);
  }
  for (size_t i = 0; i < r.ident_p.size(); ++i) unite(parent, r.ident_p[i], r.ident_q[i]);
  // Union by smaller label: each class's root is its smallest label.
  final->assign(s.labels, 0);
  uint32_t classes = 0;
  for (uint32_t v = 0; v < s.labels; ++v) {
    const uint32_t root = find(parent, v);
    (*final)[v] = root == v ? classes++ : (*final)[root];
  }
  return classes;
}

}  // namespace

namespace {

struct PolygonHeader {
  uint8_t coding = 0, groups = 0;
  const uint8_t* symbols = nullptr;  // codings 7 and 8: the range-coded stream
  int64_t symbol_bytes = -1;
};

Status read_polygon_header(ByteReader* bytes, PolygonHeader* h) {
  uint8_t flags = 0;
  if (!bytes->get_u8(&flags) || !bytes->get_u8(&h->coding)) return payload_error("polygon header cut short");
  if (flags != 0) return payload_error("reserved polygon flags set");
  if (h->coding >= kPolygonCodingCount || h->coding == kPolygonUnassignedCoding)
    return Status(ErrorCode::kUnsupportedFeature, "CONN: polygon coding " + std::to_string(h->coding));
  if (!is_context_coding(h->coding)) return Status::Ok();
  uint64_t length = 0;
  if (!bytes->get_u8(&h->groups)) return payload_error("polygon header cut short");
  if (h->groups > (kGroupTriangles | kGroupQuads | kGroupOther)) return payload_error("unknown symbol groups");
  if (!bytes->get_varint(&length)) return payload_error("face symbol stream length missing or malformed");
  // Compared before any narrowing: size_t is 32 bits in WebAssembly.
  if (length > bytes->remaining()) return truncated();
  h->symbols = bytes->cursor();
  bytes->skip(size_t(length));
  h->symbol_bytes = int64_t(length);
  return Status::Ok();
}

// The records of 5.4.7 and 5.4.8, which follow the symbols.
Status read_records(BitReader* in, const std::vector<uint32_t>& degree, uint64_t labels, uint32_t vertex_count,
                    Records* records, Mesh* loose) {
  if (labels > UINT32_MAX) return limit_error("more than 2^32 - 1 surface vertices");
  if (Status s = read_virtual_faces(in, degree, records); !s.ok()) return s;
  if (Status s = read_seams(in, degree, records); !s.ok()) return s;
  if (Status s = read_identifications(in, uint32_t(labels), records); !s.ok()) return s;
  if (Status s = read_loose_faces(in, vertex_count, loose); !s.ok()) return s;
  if (!in->at_clean_end()) return payload_error("bits left over after the polygon stream");
  return Status::Ok();
}

// Codings 0 .. 5: symbols, records, then Spirale Reversi (5.4.1's order).
Status decode_stored(BitReader* in, const PolygonHeader& h, uint32_t vertex_count, PolygonSurface* surface,
                     Records* records, Mesh* loose, Components* components_out, OtherFaceCorners* corners) {
  Components& components = *components_out;
  if (Status s = read_components(in, -1, &components); !s.ok()) return s;
  FaceShapes shapes;
  if (Status s = read_symbols(in, h.coding, components.coded, &shapes, corners); !s.ok()) return s;
  // Degrees of the surface faces and N (5.4.7), known before decoding.
  std::vector<uint32_t> degree;
  degree.reserve(components.faces.size() + size_t(components.coded));
  uint64_t labels = 0;
  for (size_t c = 0, f = 0; c < components.faces.size(); ++c) {
    degree.push_back(components.first_degree[c]);
    labels += components.first_degree[c];
    for (uint32_t i = 1; i < components.faces[c]; ++i, ++f) {
      degree.push_back(shapes.degree[f]);
      for (uint32_t k = 0; k < shapes.degree[f] - 2; ++k)
        labels += shapes.status[shapes.status_begin[f] + k] ? 0 : 1;
    }
  }
  if (Status s = read_records(in, degree, labels, vertex_count, records, loose); !s.ok()) return s;
  return polygon_spirale_reversi(components.faces, components.first_degree, shapes, surface);
}

// Codings 7 and 8: components, Spirale Reversi decoding each symbol as it goes,
// then the records (5.4.10).
Status decode_context_coded(BitReader* in, const PolygonHeader& h, uint32_t vertex_count, uint32_t face_count,
                            PolygonSurface* surface, Records* records, Mesh* loose, Components* components_out,
                            OtherFaceCorners* corners) {
  Components& components = *components_out;
  if (Status s = read_components(in, h.symbol_bytes, &components); !s.ok()) return s;
  // The surface's C + K faces are face_count - L real ones and H virtual
  // ones, each virtual face costing at least a bit of what follows (5.4.7):
  // a bound that the caller's max_faces also holds, whatever B allows.
  const uint64_t surface_faces = components.faces.size() + components.coded;
  if (surface_faces > uint64_t(face_count) + in->bits_remaining())
    return limit_error(std::to_string(surface_faces) + " surface faces for face_count " + std::to_string(face_count) +
                       " and " + std::to_string(in->bits_remaining()) + " bits of records");
  if (h.groups == 0 && components.coded > 0) return symbol_error("face symbols but no symbol group");
  CodedFaces faces(h.symbols, size_t(h.symbol_bytes), h.groups, h.coding == kPolygonQuadContextCoded, corners);
  if (Status s = faces.start(); !s.ok()) return s;
  // 512 (B + 8) faces may be far more than the decisions in the stream
  // actually build before it ends (5.4.10), so only what a well-compressed
  // mesh takes is reserved (bunny: 13 faces a byte); the rest grows.
  const uint64_t expected = std::min<uint64_t>(surface_faces, kReservedFacesPerSymbolByte * (uint64_t(h.symbol_bytes) + 8));
  if (Status s = polygon_spirale_reversi(components.faces, components.first_degree, &faces, size_t(expected), surface);
      !s.ok())
    return s;
  return read_records(in, surface->face_degree, surface->labels, vertex_count, records, loose);
}

}  // namespace

Status decode_polygon_connectivity(const uint8_t* data, size_t size, uint32_t vertex_count, uint32_t face_count,
                                   Mesh* mesh, PolygonConnectivityInfo* info, const OutputBudget* budget) {
  ByteReader bytes(data, size);
  PolygonHeader header;
  if (Status s = read_polygon_header(&bytes, &header); !s.ok()) return s;
  info->coding = header.coding;
  BitReader in(bytes.cursor(), bytes.remaining());
  PolygonSurface surface;
  Records records;
  Mesh loose;
  Components components;
  OtherFaceCorners corners(budget);
  const Status decoded = is_context_coding(header.coding)
                             ? decode_context_coded(&in, header, vertex_count, face_count, &surface, &records, &loose,
                                                    &components, &corners)
                             : decode_stored(&in, header, vertex_count, &surface, &records, &loose, &components,
                                             &corners);
  if (!decoded.ok()) return decoded;
  const std::vector<uint32_t>& degree = surface.face_degree;
  // Without seams or identifications every surface label is a class of its
  // own (5.4.7): the final labels are the surface's, and no table is built.
  const bool joined = !records.seam_a.empty() || !records.ident_p.empty();
  std::vector<uint32_t> final;
  const uint32_t classes = joined ? final_labels(surface, records, &final) : surface.labels;
  if (classes > vertex_count)
    return symbol_error("the surface has " + std::to_string(classes) + " vertices but vertex_count is " +
                        std::to_string(vertex_count));
  const uint64_t real = degree.size() - records.virtual_count;
  if (real + loose.face_count() != face_count)
    return symbol_error("face_count " + std::to_string(face_count) + " is not the " + std::to_string(real) +
                        " real surface faces plus " + std::to_string(loose.face_count()) + " loose faces");

  // The real faces with final labels, compacted within the surface's own
  // tables (a face never moves up), which then become the mesh's.
  if (joined || records.virtual_count > 0) {
    size_t faces_kept = 0, corners_kept = 0;
    for (size_t f = 0, begin = 0; f < degree.size(); begin += degree[f], ++f) {
      if (records.is_virtual[f]) continue;
      for (uint32_t k = 0; k < degree[f]; ++k) {
        const uint32_t v = surface.corners[begin + k];
        surface.corners[corners_kept++] = joined ? final[v] : v;
      }
      surface.face_degree[faces_kept++] = degree[f];
    }
    surface.face_degree.resize(faces_kept);
    surface.corners.resize(corners_kept);
  }
  mesh->face_sizes = std::move(surface.face_degree);
  mesh->corners = std::move(surface.corners);
  mesh->face_sizes.insert(mesh->face_sizes.end(), loose.face_sizes.begin(), loose.face_sizes.end());
  mesh->corners.insert(mesh->corners.end(), loose.corners.begin(), loose.corners.end());
  info->components = uint32_t(components.faces.size());
  info->virtual_faces = records.virtual_count;
  info->seams = uint32_t(records.seam_a.size());
  info->identifications = uint32_t(records.ident_p.size());
  info->loose_faces = uint32_t(loose.face_count());
  return Status::Ok();
}

}  // namespace qmc
