// Polygon traversal, spec/qmc-format.md 5.4.2. As for quads (5.3.3), the
// region not yet encoded is tracked with two flags: faces processed, and
// vertices touched by a processed face (anchors); loops are never stored.
#include "encoder/polygon_traversal_encoder.h"

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

class PolygonTraversalEncoder {
 public:
  PolygonTraversalEncoder(const PolygonSurfaceModel& s, PolygonTraversal* out)
      : s_(s), out_(out), processed_(s.face_count(), 0), touched_(s.vertex_count(), 0) {
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
  uint32_t start_component(uint32_t f);
  void encode_face(uint32_t gate, std::vector<uint32_t>* stack, uint32_t* next_gate);

  const PolygonSurfaceModel& s_;
  PolygonTraversal* out_;
  std::vector<uint8_t> processed_, touched_;
  std::vector<uint8_t> status_, gaps_;
  std::vector<uint32_t> gap_start_;  // half-edge leaving each gap's first anchor
};

// The initial loop c1 -> c0 -> c(d-1) .. c2, gate c1 -> c0, labelled from c1.
uint32_t PolygonTraversalEncoder::start_component(uint32_t f) {
  const uint32_t b = s_.face_begin[f], d = s_.degree(f);
  give_label(s_.corners[b + 1]);
  give_label(s_.corners[b]);
  for (uint32_t i = d - 1; i >= 2; --i) give_label(s_.corners[b + i]);
  take(f, 0);
  return s_.twin[b];
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
  std::vector<uint32_t> stack;
  for (uint32_t f0 = 0; f0 < s_.face_count(); ++f0) {
    if (processed_[f0]) continue;
    // First face: the component's first virtual face, else f0. Find the
    // component by flooding (cheap: each face is flooded once).
    std::vector<uint32_t> faces{f0};
    component[f0] = f0;
    uint32_t first = f0;
    for (size_t i = 0; i < faces.size(); ++i) {
      if (s_.source[faces[i]] == kVirtualFace && (s_.source[first] != kVirtualFace || faces[i] < first))
        first = faces[i];
      for (uint32_t h = s_.face_begin[faces[i]]; h < s_.face_begin[faces[i] + 1]; ++h) {
        const uint32_t g = s_.face_of[s_.twin[h]];
        if (component[g] == kNone) {
          component[g] = f0;
          faces.push_back(g);
        }
      }
    }
    const size_t before = out_->shapes.size();
    out_->first_degree.push_back(s_.degree(first));
    uint32_t gate = start_component(first);
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

std::string traverse_polygon_surface(const PolygonSurfaceModel& surface, PolygonTraversal* out) {
  *out = PolygonTraversal{};
  PolygonTraversalEncoder encoder(surface, out);
  return encoder.run();
}

}  // namespace qmc
