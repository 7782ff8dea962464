// Section 14.6 of spec/qmc-format.md: the geometry order.
#include "common/geometry_order.h"

#include <cstddef>

namespace qmc {
namespace {

// The index of the lowest set bit of a non-zero word (C++17 has no
// countr_zero): the compiler's builtin, else de Bruijn multiplication.
int lowest_bit(uint64_t word) {
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(word);
#else
  static constexpr int kIndex[64] = {0,  1,  2,  53, 3,  7,  54, 27, 4,  38, 41, 8,  34, 55, 48, 28,
                                     62, 5,  39, 46, 44, 42, 22, 9,  24, 35, 59, 56, 49, 18, 29, 11,
                                     63, 52, 6,  26, 37, 40, 33, 47, 61, 45, 43, 21, 23, 58, 17, 10,
                                     51, 25, 36, 32, 60, 20, 57, 16, 50, 31, 19, 15, 30, 14, 13, 12};
  return kIndex[((word & (~word + 1)) * 0x022FDD63CC95386Dull) >> 58];
#endif
}

// A set of labels below a bound that gives its smallest member at once: a
// bit per label, and above it levels of one bit per non-zero 64-bit word,
// up to a single word.
class LabelSet {
 public:
  explicit LabelSet(uint32_t bound) {
    size_t n = bound;
    do {
      n = (n + 63) / 64;
      levels_.emplace_back(n, 0);
    } while (n > 1);
  }
  void insert(uint32_t label) {
    size_t i = label;
    for (auto& level : levels_) {
      uint64_t& word = level[i / 64];
      const bool was_empty = word == 0;
      word |= uint64_t(1) << (i % 64);
      if (!was_empty) return;
      i /= 64;
    }
  }
  void erase(uint32_t label) {
    size_t i = label;
    for (auto& level : levels_) {
      uint64_t& word = level[i / 64];
      word &= ~(uint64_t(1) << (i % 64));
      if (word != 0) return;
      i /= 64;
    }
  }
  bool empty() const { return levels_.back()[0] == 0; }
  // The smallest member; the set must not be empty.
  uint32_t smallest() const {
    size_t i = 0;
    for (size_t l = levels_.size(); l-- > 0;) i = i * 64 + size_t(lowest_bit(levels_[l][i]));
    return uint32_t(i);
  }

 private:
  std::vector<std::vector<uint64_t>> levels_;  // levels_[0] has a bit per label
};

// 14.6's construction: which vertices are placed, how many faces close on
// each unplaced one (up to 2, the rule's two classes), the sets of those
// closing 1 and 2, and the smallest unplaced label (which only grows).
class Placement {
 public:
  explicit Placement(const VertexCorners& mesh)
      : mesh_(mesh),
        unplaced_corners_(mesh.face_count()),
        closing_(mesh.vertex_count(), 0),
        closing_one_(mesh.vertex_count()),
        closing_two_(mesh.vertex_count()) {
    for (uint32_t f = 0; f < mesh.face_count(); ++f) unplaced_corners_[f] = mesh.face_end(f) - mesh.face_begin(f);
  }

  // 14.6: closing two faces or more, else one, else none; the smallest
  // label. Call only while a vertex is unplaced.
  uint32_t next() {
    if (!closing_two_.empty()) return closing_two_.smallest();
    if (!closing_one_.empty()) return closing_one_.smallest();
    while (closing_[smallest_unplaced_] == kPlaced) ++smallest_unplaced_;
    return smallest_unplaced_;
  }

  void place(uint32_t v) {
    if (closing_[v] == 1) closing_one_.erase(v);
    if (closing_[v] == 2) closing_two_.erase(v);
    closing_[v] = kPlaced;
    for (const uint32_t* k = mesh_.begin(v); k != mesh_.end(v); ++k) {
      const uint32_t f = mesh_.face(*k);
      if (--unplaced_corners_[f] == 1) close_face(f);
    }
  }

 private:
  static constexpr uint8_t kPlaced = 3;

  // Face f has one unplaced corner (or none, while a vertex at two of its
  // corners is being placed): it closes on that corner's vertex.
  void close_face(uint32_t f) {
    for (uint32_t c = mesh_.face_begin(f); c < mesh_.face_end(f); ++c) {
      const uint32_t w = mesh_.vertex(c);
      if (closing_[w] == kPlaced) continue;
      if (closing_[w] == 0) {
        closing_one_.insert(w);
        closing_[w] = 1;
      } else if (closing_[w] == 1) {
        closing_one_.erase(w);
        closing_two_.insert(w);
        closing_[w] = 2;
      }
      return;
    }
  }

  const VertexCorners& mesh_;
  std::vector<uint32_t> unplaced_corners_;  // per face
  std::vector<uint8_t> closing_;            // per vertex: min(closing(w), 2), or kPlaced
  LabelSet closing_one_, closing_two_;
  uint32_t smallest_unplaced_ = 0;
};

}  // namespace

void geometry_order(const VertexCorners& mesh, std::vector<uint32_t>* order) {
  order->clear();
  if (mesh.vertex_count() == 0) return;
  Placement placement(mesh);
  order->resize(mesh.vertex_count());
  for (uint32_t i = 0; i < mesh.vertex_count(); ++i) {
    (*order)[i] = placement.next();
    placement.place((*order)[i]);
  }
}

std::vector<uint32_t> geometry_order(uint32_t vertex_count, const std::vector<uint32_t>& face_sizes,
                                     const std::vector<uint32_t>& corners) {
  VertexCorners mesh;
  mesh.build(vertex_count, face_sizes, corners);
  std::vector<uint32_t> order;
  geometry_order(mesh, &order);
  return order;
}

}  // namespace qmc
