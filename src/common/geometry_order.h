// The geometry order of POSN method 4 and aTTR coding 4
// (spec/qmc-format.md sections 14.6, 15.9): the order in which the vertices
// are predicted, computed from the faces alone. The next vertex is one that
// two faces or more close on (all their other corners placed), else one
// that a face closes on, the smallest label first, so that most vertices
// are predicted from several parallelograms instead of the one the
// connectivity traversal left them.
#pragma once

#include <cstdint>
#include <vector>

#include "common/vertex_prediction.h"

namespace qmc {

// The order in which section 14's predictions visit the items: the labels'
// (POSN methods 1 and 3, aTTR coding 0) or 14.6's geometry order (POSN
// method 4, aTTR coding 4, 15.9).
enum class PredictionOrder : uint8_t { kLabels, kGeometry };

// order[i] = g_i, the label placed i-th, over the faces `mesh` was built from.
void geometry_order(const VertexCorners& mesh, std::vector<uint32_t>* order);

// The same from the faces alone; corners must be below vertex_count.
std::vector<uint32_t> geometry_order(uint32_t vertex_count, const std::vector<uint32_t>& face_sizes,
                                     const std::vector<uint32_t>& corners);

// Section 14's visit of the items: item i is label i (label order) or g_i
// (14.6, with its ranks), predicted from the items visited before it.
class PredictionVisit {
 public:
  PredictionVisit(const VertexCorners& mesh, PredictionOrder order) : mesh_(mesh) {
    if (order == PredictionOrder::kLabels) return;
    geometry_order(mesh, &order_);
    rank_.resize(order_.size());
    for (uint32_t i = 0; i < uint32_t(order_.size()); ++i) rank_[order_[i]] = i;
  }
  uint32_t item(uint32_t i) const { return order_.empty() ? i : order_[i]; }
  // Whether vertex u is visited before the i-th item, i.e. decoded before it.
  bool visited_before(uint32_t u, uint32_t i) const { return order_.empty() ? u < i : rank_[u] < i; }
  const VertexCorners& mesh() const { return mesh_; }
  // 15.12: texture coordinates guided by the positions (null: 14.3 alone),
  // the orientation starting at +1.
  void guide_by(const PositionGuide* guide) {
    if (!guide) return;
    guide_ = *guide;
    guide_.orientation = 1;
    guided_ = true;
  }
  // POSN method 5 (14.7): quads' runs carry their neighbours' twist; geometry order only.
  void twist_quads(bool on = true) { twist_ = on && !order_.empty(); }
  // POSN method 8 (14.9): triangle candidates carry their twists; geometry order only.
  void twist_triangles(bool on = true) { triangle_twist_ = on && !order_.empty(); }
  bool twists_triangles() const { return triangle_twist_; }
  // POSN method 11 (14.12): parallelogram candidates sheared by k / 16 (0: not); geometry order only.
  void shear(int k) { shear_ = order_.empty() ? 0 : k; }
  int shear() const { return shear_; }
  // POSN method 12 (14.13): a vertex without candidates extrapolates an edge; geometry order only.
  void extrapolate_edges(bool on = true) { extrapolate_ = on && !order_.empty(); }
  // 14.3 for item(i), in order i = 0, 1, ... (the guide's orientation carries on).
  void predict(uint32_t i, const uint32_t* q, const uint32_t* activity, const uint32_t top[3],
               VertexPrediction* out) const {
    PositionGuide* guide = guided_ ? &guide_ : nullptr;
    if (order_.empty()) return predict_vertex(mesh_, i, q, activity, top, out, guide);
    predict_vertex_in_order(mesh_, order_.data(), rank_.data(), i, q, activity, top, out, guide, twist_,
                            triangle_twist_, shear_, extrapolate_);
  }

 private:
  const VertexCorners& mesh_;
  mutable PositionGuide guide_;  // 15.12's orientation changes as the values are predicted
  bool guided_ = false;
  bool twist_ = false;
  bool triangle_twist_ = false;
  int shear_ = 0;
  bool extrapolate_ = false;
  std::vector<uint32_t> order_, rank_;  // empty in label order
};

}  // namespace qmc
