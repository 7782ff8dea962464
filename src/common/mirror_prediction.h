// Sections 14.10 and 14.11 of spec/qmc-format.md (POSN methods 9, 10): the mirror
// candidate. A mesh modelled with a mirror (most characters, animals,
// vehicles and heads are) has a vertex v' for nearly every vertex v with
// q[v'] = M(q[v]), M a reflection across a plane of the grid. When v' was
// decoded before v, M(q[v']) predicts v exactly. The decoder finds v'
// through v's decoded neighbours u: u's mirror image is a decoded vertex u'
// (the first decoded at M(q[u])), and v' is a neighbour of u', the one whose
// image is nearest to v's usual prediction. Nothing but the plane is
// transmitted.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "common/prefetch.h"
#include "common/vertex_prediction.h"

namespace qmc {

// 14.10: M(q) = q with q[axis] replaced by sum - q[axis].
struct MirrorPlane {
  int axis = 0;       // 0, 1 or 2
  uint32_t sum = 0;   // 0 .. 2 top[axis]
  bool near_images = false;  // 14.11 (POSN method 10): image vertices also a step from the image
};

// The first vertex inserted at each grid point (any three integers the
// caller makes up: the encoder's plane search keeps columns and blocks in
// one): an open-addressing table whose hash is keyed per table, so that no
// file can make its probes long (the vertices it returns do not depend on
// the key).
class GridPointTable {
 public:
  explicit GridPointTable(uint32_t capacity_for);
  // The first vertex inserted at q, or kNone.
  uint32_t find(const uint32_t q[3]) const;
  // Inserts v at q unless a vertex is there already; returns that vertex,
  // or kNone when v was inserted.
  uint32_t insert(const uint32_t q[3], uint32_t v);
  static constexpr uint32_t kNone = 0xFFFFFFFFu;

 private:
  struct Entry {
    uint32_t q[3];
    uint32_t vertex;
  };
  size_t slot(const uint32_t q[3]) const;
  std::unique_ptr<Entry[]> entries_;
  size_t mask_ = 0;
  uint64_t key_ = 0;
};

// The same for points that live in the caller's array of three integers a
// vertex (points[3 v ..]): a slot holds the vertex and 32 more bits of the
// point's hash, 8 bytes instead of 16, and the point itself is compared
// only where those bits match. Half the table for the processor's caches:
// 14.10's search looks up each decoded vertex's point and image.
class VertexPointTable {
 public:
  explicit VertexPointTable(uint32_t capacity_for);
  // The first vertex inserted at q, or kNone.
  uint32_t find(const uint32_t* points, const uint32_t q[3]) const;
  // 14.11: the first vertex at q a step down the axis, else a step up:
  // where a mirror image falls when the quantized halves round apart (the
  // plane between grid points). POSN method 10's image vertices and aTTR
  // coding 9's twins (15.14) look there when none is at the image itself.
  uint32_t find_next_to(const uint32_t* points, const uint32_t q[3], int axis) const;
  // Inserts v (at points[3 v ..]) unless a vertex is at its point already;
  // returns that vertex, or kNone when v was inserted.
  uint32_t insert(const uint32_t* points, uint32_t v);
  // Asks the processor for the slot where a look-up of q starts, so that one
  // made a little later finds it in the cache.
  void prefetch(const uint32_t q[3]) const;
  // Whether the table is larger than a processor's caches keep (2 MB: from
  // about 130,000 vertices on), where prefetch() pays.
  bool outgrows_caches() const { return (mask_ + 1) * sizeof(Entry) > (size_t(2) << 20); }
  static constexpr uint32_t kNone = GridPointTable::kNone;

 private:
  struct Entry {
    uint32_t vertex, tag;
  };
  std::unique_ptr<Entry[]> entries_;
  size_t mask_ = 0;
  uint64_t key_ = 0;
};

// Where a vertex (or value) may take one candidate besides 14.3's, decided
// by 14.10's "the mirror candidate is used": POSN method 9's (14.10,
// MirrorCandidates) or aTTR coding 9's (15.14, ValueTwins).
class MirrorSource {
 public:
  virtual ~MirrorSource() = default;
  // The candidate of item v (its prediction p selected with every
  // candidate, so that p.value is the reference), clamped to the grid, in
  // out; false if v has none. q: 3 integers per item, those of the items
  // decoded() so far meaningful.
  virtual bool find(uint32_t v, const uint32_t* q, const VertexPrediction& p, int64_t out[3]) const = 0;
  // After v's integers q[3 v ..] are known.
  virtual void decoded(uint32_t v, const uint32_t* q) = 0;
  // Whether prefetch() does anything (where the look-ups outgrow the caches).
  virtual bool prefetches() const { return false; }
  // Before decoded(v, q): fetches into the cache what decoded() will read,
  // so that a caller can do other work (the next prediction) while the
  // memory answers. Changes nothing that find() or decoded() give.
  virtual void prefetch(uint32_t /*v*/, const uint32_t* /*q*/) const {}
};

// 14.10's search, shared by the encoder and the decoder; with the plane's
// near_images, POSN method 10's (14.11).
class MirrorCandidates final : public MirrorSource {
 public:
  MirrorCandidates(const VertexCorners& mesh, MirrorPlane plane, const uint32_t top[3]);
  bool find(uint32_t v, const uint32_t* q, const VertexPrediction& p, int64_t out[3]) const override;
  void decoded(uint32_t v, const uint32_t* q) override;
  bool prefetches() const override { return kPrefetches && first_at_.outgrows_caches(); }
  void prefetch(uint32_t v, const uint32_t* q) const override;
  // Method 10: how many vertices have paired with a partner beside their image (14.11).
  uint32_t pairs_beside() const { return pairs_beside_; }

 private:
  bool is_decoded(uint32_t u) const { return first_[u] != GridPointTable::kNone; }
  // M(point) into out; false if it leaves the grid.
  bool image(const uint32_t* point, uint32_t out[3]) const;
  const VertexCorners& mesh_;
  MirrorPlane plane_;
  uint32_t top_[3];
  VertexPointTable first_at_;
  // Per vertex: the first vertex decoded at its point (itself, or one it
  // duplicates; kNone while it is not decoded), and for such a first vertex
  // its image vertex once one is decoded (kNone before). Kept as vertices are decoded, so that a
  // search looks up no grid point: each image vertex is found once.
  std::vector<uint32_t> first_, image_vertex_;
  // Per vertex, once decoded: M(q) with the axis clamped to the grid (14.10's
  // img), kept so that a search reads it instead of working it out again for
  // each of the up to 64 w; kNotDecoded (above any grid integer) before.
  std::vector<uint32_t> image_point_;
  static constexpr uint32_t kNotDecoded = 0xFFFFFFFFu;
  uint32_t pairs_beside_ = 0;
};

inline constexpr int kMirrorContexts = 12;

// 14.10: the context of the decision "the mirror candidate is used", from
// the L1 distance between it and the reference, s = min(bitlen(D), 11).
int mirror_context(const int64_t candidate[3], const int64_t reference[3]);

}  // namespace qmc
