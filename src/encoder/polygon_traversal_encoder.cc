// Polygon traversal, spec/qmc-format.md 5.4.2. As for quads (5.3.3), the
// region not yet encoded is tracked with two flags: faces processed, and
// vertices touched by a processed face (anchors); loops are never stored.
#include "encoder/polygon_traversal_encoder.h"

#include <algorithm>

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

// The faces of the component of f0, in the order a flood from f0 reaches
// them; marks them in `component`.
void flood_component(const PolygonSurfaceModel& s, uint32_t f0, std::vector<uint32_t>* component,
                     std::vector<uint32_t>* faces) {
  faces->assign(1, f0);
  (*component)[f0] = f0;
  for (size_t i = 0; i < faces->size(); ++i) {
    const uint32_t f = (*faces)[i];
    for (uint32_t h = s.face_begin[f]; h < s.face_begin[f + 1]; ++h) {
      const uint32_t g = s.face_of[s.twin[h]];
      if ((*component)[g] == kNone) {
        (*component)[g] = f0;
        faces->push_back(g);
      }
    }
  }
}

// The first face of a component (its faces as flood_component lists them)
// under `start`, and the corner that is its c0 (TraversalStart).
std::array<uint32_t, 2> first_face(const PolygonSurfaceModel& s, const std::vector<uint32_t>& faces,
                                   TraversalStart start, std::vector<uint32_t>* scratch) {
  scratch->clear();
  for (uint32_t f : faces)
    if (s.source[f] == kVirtualFace) scratch->push_back(f);
  std::sort(scratch->begin(), scratch->end());
  const std::vector<uint32_t>& from = scratch->empty() ? faces : *scratch;
  const uint64_t fraction = uint32_t(start.trial * 0x9E3779B9u);  // frac(t / phi) in units of 2^-32
  const uint32_t f = from[size_t((fraction * from.size()) >> 32)];
  return {f, start.trial % s.degree(f)};
}

class PolygonTraversalEncoder {
 public:
  PolygonTraversalEncoder(const PolygonSurfaceModel& s, PolygonTraversal* out, TraversalStart start)
      : s_(s), out_(out), start_(start), processed_(s.face_count(), 0), touched_(s.vertex_count(), 0) {
    out_->label.assign(s.vertex_count(), kNone);
    out_->rotation.assign(s.face_count(), 0);
    // Every face but each component's first is coded once: at most this.
    out_->order.reserve(s.face_count());
    out_->shapes.reserve(s.face_count());
  }

  std::string run();

 private:
  void give_label(uint32_t v) {
    if (out_->label[v] == kNone) out_->label[v] = out_->labels++;
  }
  void take(uint32_t f, uint32_t start_corner) {
    processed_[f] = 1;
    out_->rotation[out_->order.size()] = start_corner;
    out_->order.push_back(f);
    for (uint32_t h = s_.face_begin[f]; h < s_.face_begin[f + 1]; ++h) touched_[s_.corners[h]] = 1;
  }
  uint32_t start_component(uint32_t f, uint32_t r);
  void encode_face(uint32_t gate, std::vector<uint32_t>* stack, uint32_t* next_gate);

  const PolygonSurfaceModel& s_;
  PolygonTraversal* out_;
  TraversalStart start_;
  std::vector<uint8_t> processed_, touched_;
  std::vector<uint32_t> candidates_;  // first_face's scratch
  std::vector<uint8_t> status_, gaps_;
  std::vector<uint32_t> gap_start_;  // half-edge leaving each gap's first anchor
};

// The initial loop c1 -> c0 -> c(d-1) .. c2, gate c1 -> c0, labelled from
// c1; c0 is the face's corner r.
uint32_t PolygonTraversalEncoder::start_component(uint32_t f, uint32_t r) {
  const uint32_t b = s_.face_begin[f], d = s_.degree(f);
  const auto c = [&](uint32_t i) { return s_.corners[b + (r + i) % d]; };
  give_label(c(1));
  give_label(c(0));
  for (uint32_t i = d - 1; i >= 2; --i) give_label(c(i));
  take(f, r);
  return s_.twin[b + r];
}

void PolygonTraversalEncoder::encode_face(uint32_t gate, std::vector<uint32_t>* stack, uint32_t* next_gate) {
  const uint32_t f = s_.face_of[gate], d = s_.degree(f), m = d - 2;
  status_.resize(m);  // every entry set below
  gaps_.clear();
  gap_start_.clear();
  // Walk w1 .. wm from g1; a gap starts at g1 and after each anchor.
  uint32_t h = s_.next(gate);  // g1 -> w1
  gap_start_.push_back(h);
  uint32_t free_in_gap = 0;
  for (uint32_t i = 0; i < m; ++i) {
    const uint32_t leaving = s_.next(h);  // w_i -> w_(i+1)
    const uint32_t w = s_.corners[leaving];
    status_[i] = touched_[w];
    if (touched_[w]) {
      gaps_.push_back(free_in_gap == 0 && processed_[s_.face_of[s_.twin[h]]] ? 1 : 0);
      gap_start_.push_back(leaving);
      free_in_gap = 0;
    } else {
      ++free_in_gap;
    }
    h = leaving;
  }
  gaps_.push_back(free_in_gap == 0 && processed_[s_.face_of[s_.twin[h]]] ? 1 : 0);
  out_->shapes.add(d, status_.data(), gaps_.data(), uint32_t(gaps_.size()));
  take(f, gate - s_.face_begin[f]);
  // Free vertices get labels in cycle order.
  for (uint32_t i = 0, e = s_.next(gate); i < m; ++i, e = s_.next(e))
    if (!status_[i]) give_label(s_.corners[s_.next(e)]);
  // New loops: one per detour, gate = the twin of the gap's first edge;
  // pushed from g0's side, the one nearest g1 is next.
  *next_gate = kNone;
  for (uint32_t g = uint32_t(gaps_.size()); g-- > 0;) {
    if (gaps_[g]) continue;
    if (*next_gate != kNone) stack->push_back(*next_gate);
    *next_gate = s_.twin[gap_start_[g]];
  }
}

std::string PolygonTraversalEncoder::run() {
  std::vector<uint32_t> component(s_.face_count(), kNone);
  std::vector<uint32_t> stack, faces;
  for (uint32_t f0 = 0; f0 < s_.face_count(); ++f0) {
    if (processed_[f0]) continue;
    // Each face is flooded once.
    flood_component(s_, f0, &component, &faces);
    const auto [first, c0] = first_face(s_, faces, start_, &candidates_);
    const size_t before = out_->shapes.size();
    out_->first_degree.push_back(s_.degree(first));
    uint32_t gate = start_component(first, c0);
    while (gate != kNone) {
      uint32_t next = kNone;
      encode_face(gate, &stack, &next);
      if (next == kNone && !stack.empty()) {
        next = stack.back();
        stack.pop_back();
      }
      gate = next;
    }
    const size_t coded = out_->shapes.size() - before;
    if (coded + 1 != faces.size()) return "internal: the traversal did not reach every face of a component";
    out_->component_faces.push_back(uint32_t(faces.size()));
  }
  for (uint32_t v = 0; v < s_.vertex_count(); ++v)
    if (out_->label[v] == kNone && touched_[v]) return "internal: a surface vertex got no label";
  return {};
}

}  // namespace

std::string traverse_polygon_surface(const PolygonSurfaceModel& surface, PolygonTraversal* out,
                                     TraversalStart start) {
  *out = PolygonTraversal{};
  PolygonTraversalEncoder encoder(surface, out, start);
  return encoder.run();
}

std::vector<std::array<uint32_t, 2>> first_labels(const PolygonSurfaceModel& surface, uint32_t starts) {
  std::vector<std::array<uint32_t, 2>> labels;
  if (surface.face_count() == 0) return labels;
  std::vector<uint32_t> component(surface.face_count(), kNone), faces, scratch;
  flood_component(surface, 0, &component, &faces);
  for (uint32_t t = 0; t < starts; ++t) {
    const auto [f, r] = first_face(surface, faces, {t}, &scratch);
    const uint32_t b = surface.face_begin[f], d = surface.degree(f);
    labels.push_back({surface.corners[b + (r + 1) % d], surface.corners[b + r]});
  }
  return labels;
}

}  // namespace qmc
