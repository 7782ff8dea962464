// Section 14.10 of spec/qmc-format.md: the mirror candidate.
#include "common/mirror_prediction.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include "common/exact_arith.h"  // bit_length64
#include "common/prefetch.h"
#include "common/splitmix64_mix.h"

namespace qmc {
namespace {

// 14.10: the neighbours of v whose image vertices are searched, and of
// each image vertex the corners examined. Two neighbours are next to v's
// twin from two sides; more add candidates near the reference that are not
// the twin (all of them: face's positions 2 % larger at 12 bits, spot's 3 %).
constexpr int kMirrorNeighbours = 2, kMirrorCorners = 16;

// A key no file can know: any key gives the same vertices, and one a file
// cannot aim at keeps the probes short.
uint64_t table_key(const void* table) {
  return splitmix64_mix(uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()) ^
                        uint64_t(reinterpret_cast<uintptr_t>(table)));
}

size_t table_size(uint32_t capacity_for) {
  size_t size = 16;
  while (size < 2 * size_t(capacity_for)) size *= 2;
  return size;
}

// A point's hash under a table's key: 64 bits, of which a table of 2^k
// slots takes the low k for the slot.
uint64_t point_hash(uint64_t key, const uint32_t q[3]) {
  return splitmix64_mix(splitmix64_mix(key ^ q[0]) ^ (uint64_t(q[1]) << 32 | q[2]));
}

bool same_point(const uint32_t* a, const uint32_t* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

}  // namespace

GridPointTable::GridPointTable(uint32_t capacity_for) {
  const size_t size = table_size(capacity_for);
  entries_.reset(new Entry[size]);
  for (size_t i = 0; i < size; ++i) entries_[i].vertex = kNone;
  mask_ = size - 1;
  key_ = table_key(entries_.get());
}

size_t GridPointTable::slot(const uint32_t q[3]) const { return size_t(point_hash(key_, q)) & mask_; }

uint32_t GridPointTable::find(const uint32_t q[3]) const {
  for (size_t i = slot(q);; i = (i + 1) & mask_) {
    const Entry& e = entries_[i];
    if (e.vertex == kNone) return kNone;
    if (same_point(e.q, q)) return e.vertex;
  }
}

uint32_t GridPointTable::insert(const uint32_t q[3], uint32_t v) {
  for (size_t i = slot(q);; i = (i + 1) & mask_) {
    Entry& e = entries_[i];
    if (e.vertex == kNone) {
      e = Entry{{q[0], q[1], q[2]}, v};
      return kNone;
    }
    if (same_point(e.q, q)) return e.vertex;
  }
}


VertexPointTable::VertexPointTable(uint32_t capacity_for) {
  const size_t size = table_size(capacity_for);
  entries_.reset(new Entry[size]);
  for (size_t i = 0; i < size; ++i) entries_[i] = Entry{kNone, 0};
  mask_ = size - 1;
  key_ = table_key(entries_.get());
}

uint32_t VertexPointTable::find(const uint32_t* points, const uint32_t q[3]) const {
  const uint64_t h = point_hash(key_, q);
  const uint32_t tag = uint32_t(h >> 32);
  for (size_t i = size_t(h) & mask_;; i = (i + 1) & mask_) {
    const Entry e = entries_[i];
    if (e.vertex == kNone) return kNone;
    if (e.tag == tag && same_point(&points[3 * size_t(e.vertex)], q)) return e.vertex;
  }
}

uint32_t VertexPointTable::find_next_to(const uint32_t* points, const uint32_t q[3], int axis) const {
  uint32_t vertex = kNone;
  for (const int step : {-1, 1}) {
    uint32_t point[3] = {q[0], q[1], q[2]};  // below 0 wraps above 2^31: no vertex is there
    point[axis] = uint32_t(int64_t(point[axis]) + step);
    if ((vertex = find(points, point)) != kNone) break;
  }
  return vertex;
}

void VertexPointTable::prefetch(const uint32_t q[3]) const {
  prefetch_for_read(&entries_[size_t(point_hash(key_, q)) & mask_]);
}

uint32_t VertexPointTable::insert(const uint32_t* points, uint32_t v) {
  const uint32_t* q = &points[3 * size_t(v)];
  const uint64_t h = point_hash(key_, q);
  const uint32_t tag = uint32_t(h >> 32);
  for (size_t i = size_t(h) & mask_;; i = (i + 1) & mask_) {
    Entry& e = entries_[i];
    if (e.vertex == kNone) {
      e = Entry{v, tag};
      return kNone;
    }
    if (e.tag == tag && same_point(&points[3 * size_t(e.vertex)], q)) return e.vertex;
  }
}

MirrorCandidates::MirrorCandidates(const VertexCorners& mesh, MirrorPlane plane, const uint32_t top[3])
    : mesh_(mesh),
      plane_(plane),
      first_at_(mesh.vertex_count()),
      first_(mesh.vertex_count(), GridPointTable::kNone),
      image_vertex_(mesh.vertex_count(), GridPointTable::kNone),
      image_point_(3 * size_t(mesh.vertex_count()), kNotDecoded) {
  std::copy(top, top + 3, top_);
}

bool MirrorCandidates::image(const uint32_t* point, uint32_t out[3]) const {
  for (int a = 0; a < 3; ++a) out[a] = point[a];
  const int64_t m = int64_t(plane_.sum) - int64_t(point[plane_.axis]);
  if (m < 0 || m > int64_t(top_[plane_.axis])) return false;
  out[plane_.axis] = uint32_t(m);
  return true;
}

bool MirrorCandidates::find(uint32_t v, const uint32_t* /*q*/, const VertexPrediction& p, int64_t out[3]) const {
  constexpr int64_t kNoneYet = std::numeric_limits<int64_t>::max();
  int64_t best = kNoneYet;
  const int64_t reference[3] = {p.value[0], p.value[1], p.value[2]};
  uint32_t searched[kMirrorNeighbours];
  int neighbours = 0;
  const VertexCorners::Sides* sides = mesh_.sides(v);
  for (const uint32_t* corner = mesh_.begin(v); corner != mesh_.end(v); ++corner, ++sides) {
    for (const uint32_t u : {sides->previous, sides->next}) {
      if (!is_decoded(u) || std::find(searched, searched + neighbours, u) != searched + neighbours) continue;
      const uint32_t u_image = image_vertex_[first_[u]];
      if (u_image == GridPointTable::kNone) continue;
      if (neighbours == kMirrorNeighbours) return best != kNoneYet;
      searched[neighbours++] = u;
      const VertexCorners::Sides* around = mesh_.sides(u_image);
      const int corners = int(std::min<ptrdiff_t>(mesh_.end(u_image) - mesh_.begin(u_image), kMirrorCorners));
      for (int k = 0; k < corners; ++k)
        for (const uint32_t w : {around[k].previous, around[k].next}) {
          const uint32_t* img = &image_point_[3 * size_t(w)];
          if (img[0] == kNotDecoded) continue;
          const int64_t distance = std::abs(int64_t(img[0]) - reference[0]) +
                                   std::abs(int64_t(img[1]) - reference[1]) +
                                   std::abs(int64_t(img[2]) - reference[2]);
          if (distance >= best) continue;  // only a smaller distance replaces the first
          best = distance;
          for (int a = 0; a < 3; ++a) out[a] = img[a];
          if (best == 0) return true;  // nothing later can be smaller
        }
    }
  }
  return best != kNoneYet;
}

// The slots decoded(v) looks up: v's point, its image, and with near
// images the two points beside the image. Callers ask only where the table
// outgrows the caches (prefetches()): below that, hashing each point twice
// costs more than it saves (face, beetle and camelhead decoded 0 - 5 %
// slower with it).
void MirrorCandidates::prefetch(uint32_t v, const uint32_t* q) const {
  const uint32_t* point = &q[3 * size_t(v)];
  first_at_.prefetch(point);
  uint32_t m[3];
  if (!image(point, m)) return;
  first_at_.prefetch(m);
  if (!plane_.near_images) return;
  for (const int step : {-1, 1}) {
    uint32_t beside[3] = {m[0], m[1], m[2]};
    beside[plane_.axis] = uint32_t(int64_t(beside[plane_.axis]) + step);
    first_at_.prefetch(beside);
  }
}

void MirrorCandidates::decoded(uint32_t v, const uint32_t* q) {
  const uint32_t* point = &q[3 * size_t(v)];
  // 14.10's img of v, clamped: what a search meeting v as a w compares.
  uint32_t* img = &image_point_[3 * size_t(v)];
  std::copy(point, point + 3, img);
  const int axis = plane_.axis;
  img[axis] = uint32_t(std::clamp<int64_t>(int64_t(plane_.sum) - int64_t(point[axis]), 0, top_[axis]));
  const uint32_t first = first_at_.insert(q, v);
  if (first != GridPointTable::kNone) {  // a duplicate: its images are the first vertex's
    first_[v] = first;
    return;
  }
  first_[v] = v;
  uint32_t m[3];
  if (!image(point, m)) return;
  // v itself when v lies on the plane; in method 10 (14.11) else the first
  // vertex decoded a step beside the image along the axis.
  uint32_t twin = first_at_.find(q, m);
  if (twin == GridPointTable::kNone && plane_.near_images) {
    twin = first_at_.find_next_to(q, m, plane_.axis);
    pairs_beside_ += twin != GridPointTable::kNone;
  }
  if (twin == GridPointTable::kNone) return;
  image_vertex_[v] = twin;
  // v is the first vertex at twin's image point: twin's image vertex.
  if (image_vertex_[twin] == GridPointTable::kNone) image_vertex_[twin] = v;
}

int mirror_context(const int64_t candidate[3], const int64_t reference[3]) {
  uint64_t distance = 0;
  for (int a = 0; a < 3; ++a) distance += uint64_t(std::abs(candidate[a] - reference[a]));
  return distance == 0 ? 0 : std::min(bit_length64(distance), kMirrorContexts - 1);
}

}  // namespace qmc
