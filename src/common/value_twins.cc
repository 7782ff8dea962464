// Section 15.14 of spec/qmc-format.md: the twin candidate of an attribute
// value (aTTR coding 9).
#include "common/value_twins.h"

#include <algorithm>

namespace qmc {
namespace {

// 15.14: the corners of a value, and of a twin vertex, examined.
constexpr int kTwinCorners = 16;
constexpr uint32_t kNone = GridPointTable::kNone;

// 15.14's sign of component j: +1 where the step from a to b equals the
// step from a' to b' better than its opposite does, -1 where the opposite
// equals it better (a texture mirrored along that component), `carried`
// where the two tell nothing apart (a step of 0: an edge along the other
// component, as the seam on the mirror plane often is).
int twin_sign(int64_t step, int64_t twin_step, int carried) {
  const int64_t same = step - twin_step, flipped = step + twin_step;
  const int64_t same_error = same < 0 ? -same : same, flipped_error = flipped < 0 ? -flipped : flipped;
  return same_error < flipped_error ? 1 : flipped_error < same_error ? -1 : carried;
}

}  // namespace

ValueTwins::ValueTwins(const VertexCorners& values, const AttributeTwins& twins, const uint32_t top[3])
    : values_(values), twin_(twins.vertex_count, kNone), decoded_(values.vertex_count(), 0) {
  std::copy(top, top + 3, top_);
  vertices_.build(twins.vertex_count, twins.faces->face_sizes, twins.faces->corners);
  VertexPointTable first_at(twins.vertex_count);
  for (uint32_t x = 0; x < twins.vertex_count; ++x) first_at.insert(twins.positions, x);
  const int axis = twins.plane.axis;
  for (uint32_t x = 0; x < twins.vertex_count; ++x) {
    uint32_t image[3];
    std::copy(&twins.positions[3 * size_t(x)], &twins.positions[3 * size_t(x)] + 3, image);
    if (image[axis] > twins.plane.sum) continue;  // the image's coordinate would be below 0
    image[axis] = twins.plane.sum - image[axis];
    twin_[x] = first_at.find(twins.positions, image);  // 15.14: 14.11's points beside the image too
    if (twin_[x] == kNone) twin_[x] = first_at.find_next_to(twins.positions, image, axis);
  }
}

uint32_t ValueTwins::mirrored_corner(uint32_t k) const {
  const uint32_t twin = twin_[vertices_.vertex(k)];
  const uint32_t twin_a = twin_[vertices_.along(k, 1)], twin_b = twin_[vertices_.along(k, -1)];
  if (twin == kNone || twin_a == kNone || twin_b == kNone) return kNone;
  const int corners = int(std::min<ptrdiff_t>(vertices_.end(twin) - vertices_.begin(twin), kTwinCorners));
  const VertexCorners::Sides* sides = vertices_.sides(twin);
  for (int i = 0; i < corners; ++i)
    if (sides[i].previous == twin_a && sides[i].next == twin_b) return vertices_.begin(twin)[i];
  return kNone;
}

bool ValueTwins::find(uint32_t v, const uint32_t* q, const VertexPrediction&, int64_t out[3]) const {
  const int corners = int(std::min<ptrdiff_t>(values_.end(v) - values_.begin(v), kTwinCorners));
  for (int i = 0; i < corners; ++i) {
    const uint32_t k = values_.begin(v)[i];
    const uint32_t t = mirrored_corner(k);
    if (t == kNone) continue;
    // The value at k and its neighbours a and b, the twin's at t and its
    // neighbours a' (twin of a's vertex) and b'.
    const uint32_t a = values_.along(k, 1), b = values_.along(k, -1);
    const uint32_t twin = values_.vertex(t), twin_a = values_.along(t, -1), twin_b = values_.along(t, 1);
    if (!is_decoded(twin) || !is_decoded(a) || !is_decoded(twin_a)) continue;
    const bool steps = is_decoded(b) && is_decoded(twin_b);  // else the flips carried
    for (int j = 0; j < 3; ++j) {
      const int64_t qa = q[3 * size_t(a) + j], ta = q[3 * size_t(twin_a) + j];
      if (steps)
        sign_[j] = twin_sign(int64_t(q[3 * size_t(b) + j]) - qa, int64_t(q[3 * size_t(twin_b) + j]) - ta, sign_[j]);
      out[j] = std::clamp<int64_t>(qa + sign_[j] * (int64_t(q[3 * size_t(twin) + j]) - ta), 0, top_[j]);
    }
    return true;
  }
  return false;
}

}  // namespace qmc
