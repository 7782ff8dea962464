// Sections 14.2 - 14.4 (and 15.4's values): the integers of a predicted
// grid decoded item by item, each predicted from the decoded ones and its
// residuals range decoded. Shared by POSN (methods 1 - 14) and aTTR; the
// per-vertex work of the position decoder, in a file of its own so that a
// build can compile it for speed and the chunk's header and method 0 for size,
// as the WebAssembly build does (web/CMakeLists.txt).
#include <memory>
#include <string>

#include "common/geometry_order.h"
#include "common/mirror_prediction.h"
#include "common/position_coding.h"
#include "common/range_coder.h"
#include "common/surface_lattice.h"
#include "common/vertex_prediction.h"
#include "decoder/position_decoder.h"

namespace qmc {
namespace {

// 14.15 (POSN method 14) for the vertex being decoded, the i-th visited:
// the steps of its residuals per axis predicted at p, in out (1 on the
// fine axis, k on the others), or all 1 without a lattice or where its
// normal estimate is 0.
struct Lattice {
  const PredictionVisit* visit = nullptr;  // null: no lattice
  int k = 1;
  uint32_t vertex = 0, i = 0;
  const uint32_t* q = nullptr;
  const int* steps(const VertexPrediction& p, int* out) const {
    static constexpr int kGridSteps[3] = {1, 1, 1};
    const int fine = visit ? lattice_fine_axis(*visit, vertex, i, q, p.value) : -1;
    if (fine < 0) return kGridSteps;
    for (int a = 0; a < 3; ++a) out[a] = a == fine ? 1 : k;
    return out;
  }
};

Status truncated_inside(const PredictedGridNames& names, uint32_t v) {
  return Status(ErrorCode::kTruncated, names.chunk + ": the range-coded stream ends inside " + names.item + " " +
                                           std::to_string(v) + " (section 14.4)");
}

Status outside_grid(const PredictedGridNames& names, uint32_t v, int a, int64_t value, uint32_t top) {
  return Status(ErrorCode::kBadSymbol, names.chunk + ": " + names.item + " " + std::to_string(v) + " " + names.axis +
                                           " " + std::to_string(a) + " decodes to " + std::to_string(value) +
                                           ", outside 0.." + std::to_string(top) + " (section 14.4)");
}

// Section 14.4's three residuals of one vertex (or attribute value, 15.4)
// predicted by p, axis a's in steps of divisor[a] (14.15's lattice; 1
// otherwise); the stream's end is checked after each, before the value it
// gave is.
Status decode_residuals(RangeDecoder* rc, PositionResidualModel* model, const PredictedGridNames& names, uint32_t v,
                        const uint32_t* top, const VertexPrediction* p, uint32_t* q, uint32_t* activity,
                        const int* divisor) {
  uint32_t magnitude[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    const SignedResidual r = code_position_residual(rc, model, *p, magnitude, a, SignedResidual{}, divisor[a]);
    if (rc->overrun()) return truncated_inside(names, v);
    const int64_t step = divisor[a] * int64_t(r.magnitude);  // below 2^35
    const int64_t value = p->value[a] + (r.negative ? -step : step);
    if (value < 0 || value > int64_t(top[a])) return outside_grid(names, v, a, value, top[a]);
    q[a] = uint32_t(value);
    magnitude[a] = uint32_t(step);  // |r| <= top_a < 2^30 once in range
  }
  *activity = magnitude[0] + magnitude[1] + magnitude[2];
  return Status::Ok();
}

// Section 14.4 for one vertex (or attribute value) whose candidates and
// fallback are in p: the mask, then the residuals. selected_all: p is
// selected with every candidate already (14.10's reference), which the mask
// of all candidates leaves as it is.
Status decode_vertex(RangeDecoder* rc, PositionResidualModel* model, const PredictedGridNames& names, uint32_t v,
                     const uint32_t* top, VertexPrediction* p, uint32_t* q, uint32_t* activity, const Lattice& lattice,
                     bool selected_all = false) {
  const unsigned all = (1u << p->candidates) - 1;
  const unsigned mask = code_candidate_mask(rc, model, p->candidates, 0, mask_context(*model, *p));
  if (!(selected_all && mask == all)) select_candidates(p, mask, top);
  if (rc->overrun()) return truncated_inside(names, v);
  int steps[3];
  return decode_residuals(rc, model, names, v, top, p, q, activity, lattice.steps(*p, steps));
}

// Section 14.10 (POSN methods 9 and 10) for vertex `vertex`, the i-th visited: if it
// has a mirror candidate, the decision whether it is used, and if it is,
// the residuals against it (*used then true; no mask is decoded).
Status decode_mirrored(RangeDecoder* rc, PositionResidualModel* model, const PredictedGridNames& names,
                       const MirrorSource& mirrors, uint32_t vertex, uint32_t i, const uint32_t* top,
                       VertexPrediction* p, uint32_t* q, uint32_t* activity, const Lattice& lattice, bool* used) {
  *used = false;
  select_candidates(p, (1u << p->candidates) - 1, top);  // the reference: every candidate
  int64_t candidate[3];
  if (!mirrors.find(vertex, q, *p, candidate)) return Status::Ok();
  const int use = rc->code(0, &model->mirror[mirror_context(candidate, p->value)]);
  if (rc->overrun()) return truncated_inside(names, i);
  if (!use) return Status::Ok();
  *used = true;
  p->kind = PredictionKind::kMirror;
  std::copy(candidate, candidate + 3, p->value);
  int steps[3];
  return decode_residuals(rc, model, names, i, top, p, &q[3 * size_t(vertex)], activity, lattice.steps(*p, steps));
}

}  // namespace

// Section 14: each vertex in label order or 14.6's geometry order,
// predicted from the decoded ones (14.3), its decisions range coded (14.4).
// Messages name the i-th vertex visited.
Status decode_predicted_grid(const uint8_t* stream, size_t size, const Mesh& faces, uint32_t count,
                             const uint32_t top[3], const PredictedGridNames& names, std::vector<uint32_t>* quantized,
                             ClassStart start, PredictionOrder order, const PositionGuide* guide, bool quad_twist,
                             bool mask_contexts, bool triangle_twist, const MirrorPlane* mirror,
                             const AttributeTwins* twins, int shear, bool extrapolate, bool axis_classes,
                             int lattice_factor) {
  if (!range_stream_justifies(count, size))  // section 14.1, before anything is reserved
    return Status(ErrorCode::kLimitExceeded, names.chunk + ": " + std::to_string(count) + " " + names.items +
                                                 " for " + std::to_string(size) +
                                                 " stream bytes, above 512 (L + 8) (section 14.1)");
  quantized->resize(size_t(count) * 3);
  VertexCorners corners;
  corners.build(count, faces.face_sizes, faces.corners);
  PredictionVisit visit(corners, order);
  visit.guide_by(guide);
  visit.twist_quads(quad_twist);
  visit.twist_triangles(triangle_twist);
  visit.shear(shear);
  visit.extrapolate_edges(extrapolate);
  TriangleTwistWeight twist_weight;
  std::vector<uint32_t> activity(count);
  std::vector<PositionResidualModel> model(1, PositionResidualModel(top, start, mask_contexts, axis_classes));
  Lattice lattice;
  if (lattice_factor > 1) {
    model[0].start_lattice_classes(start);
    lattice.visit = &visit;
    lattice.k = lattice_factor;
    lattice.q = quantized->data();
  }
  RangeDecoder rc(stream, size);
  if (rc.bad_start())
    return Status(ErrorCode::kBadChunkPayload,
                  names.chunk + ": the range coder's first four bytes are 0xFFFFFFFF (section 13.5.2)");
  std::unique_ptr<MirrorSource> mirrors;
  if (mirror) mirrors = std::make_unique<MirrorCandidates>(corners, *mirror, top);
  if (twins) mirrors = std::make_unique<ValueTwins>(corners, *twins, top);
  VertexPrediction p;
  // On large meshes a vertex's mirror bookkeeping (14.10) waits until the
  // next vertex is predicted, which reads none of it: its look-ups,
  // prefetched as soon as the vertex is known, then find their slots in
  // the cache. The last vertex's is never read. (kPrefetches, a constant,
  // lets a build without prefetch, WebAssembly's, leave this path out.)
  const bool deferred = kPrefetches && mirrors && mirrors->prefetches();
  uint32_t pending = GridPointTable::kNone;
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t v = visit.item(i);
    visit.predict(i, quantized->data(), activity.data(), top, &p);
    if (pending != GridPointTable::kNone) mirrors->decoded(pending, quantized->data());
    twist_weight.apply(&p);
    lattice.vertex = v;
    lattice.i = i;
    bool mirrored = false;
    if (mirrors)
      if (Status s = decode_mirrored(&rc, &model[0], names, *mirrors, v, i, top, &p, quantized->data(),
                                     &activity[v], lattice, &mirrored);
          !s.ok())
        return s;
    if (!mirrored) {
      if (Status s = decode_vertex(&rc, &model[0], names, i, top, &p, &(*quantized)[3 * size_t(v)], &activity[v],
                                   lattice, mirrors != nullptr);
          !s.ok())
        return s;
      twist_weight.learn(p, &(*quantized)[3 * size_t(v)]);
    }
    if (deferred) {
      mirrors->prefetch(v, quantized->data());
      pending = v;
    } else if (mirrors) {
      mirrors->decoded(v, quantized->data());
    }
  }
  if (rc.unread() != 0)
    return Status(ErrorCode::kBadChunkPayload, names.chunk + ": " + std::to_string(rc.unread()) +
                                                   " bytes after the range-coded data (section 13.5.2)");
  return Status::Ok();
}

}  // namespace qmc
