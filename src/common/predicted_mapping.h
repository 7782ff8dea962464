// The per-corner mapping of an attribute predicted from the faces around
// each vertex (spec/qmc-format.md section 15.11, mapping 3). A seam is a
// curve of edges: most vertices have one value for all their corners, and a
// seam vertex's corner usually has the value of the face next to it across an
// edge. So a vertex first says whether its corners share one new value (one
// decision a vertex instead of 15.3's one or two a corner), and a later
// corner of a seam vertex whether it has the value of the nearest earlier
// face of the vertex across an edge; then, as values given per face (flat
// shading) repeat it, whether it has the value of the face's previous
// corner, before 15.3's decisions. One template
// runs on both sides, so encoder and decoder cannot drift apart.
#pragma once

#include <cstdint>
#include <vector>

#include "common/attribute_mapping.h"
#include "common/octahedral_normal.h"

namespace qmc {

// 15.11: at most this many earlier corners of a vertex are examined for the
// reference, so that a vertex of very high valence costs a bounded search.
inline constexpr uint32_t kReferenceCornersExamined = 8;
// 15.11: the 15.3 branch searches at most this many values of S_v for the
// encoder's "own" choice (the decoder reads any index the stream gives).
inline constexpr uint32_t kSearchedOwnValues = 64;

// 15.11: what a vertex's corners are known to refer to so far.
enum VertexValueState : uint8_t { kVertexUnmet = 0, kVertexSingle = 1, kVertexSeveral = 2 };

// 15.11's probabilities, all starting at 1024: SINGLE[state(w-)][state(w+)],
// SAME[min(n, 2) - 1][e], FACE[first corner of v ? 0 : 1], and 15.3's NEW and OWN.
struct PredictedMappingModel {
  AttributeMappingModel fallback;
  uint16_t face[2] = {1024, 1024};
  uint16_t single[3][3] = {{1024, 1024, 1024}, {1024, 1024, 1024}, {1024, 1024, 1024}};
  uint16_t same[2][4] = {{1024, 1024, 1024, 1024}, {1024, 1024, 1024, 1024}};
};

// 15.3's choice for a value the encoder knows: new, one of S_v, or any met.
inline MappingChoice fallback_choice(const VertexValueLists& lists, uint32_t v, uint32_t value, uint32_t met) {
  if (value == met) return {MappingChoice::kNew, 0};
  const uint32_t n = lists.length(v) < kSearchedOwnValues ? lists.length(v) : kSearchedOwnValues;
  for (uint32_t j = 0; j < n; ++j)
    if (lists.at(v, j) == value) return {MappingChoice::kOwn, j};
  return {MappingChoice::kMet, value};
}

// 15.11 (informative): the encoder calls a vertex single when all its corners
// refer to one value that is new at its first corner (m numbered by first
// reference, so that value is the first not met before).
inline std::vector<uint8_t> single_value_vertices(const std::vector<uint32_t>& corners, const std::vector<uint32_t>& m,
                                                  size_t vertex_count) {
  constexpr uint32_t kNoValue = UINT32_MAX;
  std::vector<uint8_t> single(vertex_count, 1);
  std::vector<uint32_t> first(vertex_count, kNoValue);
  uint32_t met = 0;
  for (size_t k = 0; k < m.size(); ++k) {
    const uint32_t v = corners[k];
    if (first[v] == kNoValue) {
      first[v] = m[k];
      if (m[k] != met) single[v] = 0;
    } else if (first[v] != m[k]) {
      single[v] = 0;
    }
    if (m[k] == met) ++met;
  }
  return single;
}

// The state of one mapping-3 stream over K corners (15.11).
class PredictedMapping {
 public:
  // corners: the vertex label of every corner (all < vertex_count), in faces of face_sizes.
  void reset(uint32_t vertex_count, const std::vector<uint32_t>& face_sizes, const std::vector<uint32_t>& corners) {
    corners_ = &corners;
    cycle_.build(face_sizes, corners.size());
    lists_.reset(vertex_count, corners);
    earlier_.reset(vertex_count, corners);
    state_.assign(vertex_count, kVertexUnmet);
    values_.assign(corners.size(), 0);
  }

  // Corner k's value m_k: decoded (truth null), or coded from truth[k] with
  // single[v] saying whether the encoder calls vertex v single. *met is U.
  template <class Coder>
  uint32_t code(Coder* coder, PredictedMappingModel* model, size_t k, uint64_t value_count, uint32_t* met,
                const uint32_t* truth, const std::vector<uint8_t>* single, MappingFault* fault) {
    const uint32_t v = (*corners_)[k];
    uint32_t value = 0;
    if (state_[v] == kVertexSingle) {
      value = lists_.at(v, 0);
    } else if (state_[v] == kVertexUnmet) {
      value = code_first(coder, model, k, v, value_count, met, truth, single, fault);
    } else {
      value = code_later(coder, model, k, v, value_count, met, truth, fault);
    }
    values_[k] = value;
    earlier_.append(v, uint32_t(k));
    return value;
  }

 private:
  // v's first corner: SINGLE, then for a seam vertex 15.3's decisions.
  template <class Coder>
  uint32_t code_first(Coder* coder, PredictedMappingModel* model, size_t k, uint32_t v, uint64_t value_count,
                      uint32_t* met, const uint32_t* truth, const std::vector<uint8_t>* single, MappingFault* fault) {
    const uint32_t before = state_[(*corners_)[cycle_.previous[k]]], after = state_[(*corners_)[cycle_.next[k]]];
    int is_single = 0;
    if (*met < value_count) is_single = coder->code(truth && (*single)[v], &model->single[before][after]);
    if (is_single) {
      state_[v] = kVertexSingle;
      const uint32_t value = (*met)++;
      lists_.append(v, value);
      return value;
    }
    state_[v] = kVertexSeveral;
    return fallback(coder, model, k, v, 0, value_count, met, truth, fault);
  }

  // A later corner of a seam vertex: SAME[min(n, 2) - 1][e], then 15.3's decisions.
  template <class Coder>
  uint32_t code_later(Coder* coder, PredictedMappingModel* model, size_t k, uint32_t v, uint64_t value_count,
                      uint32_t* met, const uint32_t* truth, MappingFault* fault) {
    uint32_t reference = 0;
    const int e = find_reference(k, v, &reference);
    const int n = lists_.length(v) >= 2 ? 2 : 1;
    if (coder->code(truth && truth[k] == reference, &model->same[n - 1][e])) return reference;
    return fallback(coder, model, k, v, 1, value_count, met, truth, fault);
  }

  // 15.11's face rule, then 15.3's decisions: first the value of the face's
  // previous corner, which values given per face (flat-shaded normals)
  // repeat; not that of a single vertex, which a seam never does.
  template <class Coder>
  uint32_t fallback(Coder* coder, PredictedMappingModel* model, size_t k, uint32_t v, int later, uint64_t value_count,
                    uint32_t* met, const uint32_t* truth, MappingFault* fault) {
    if (!first_in_face(k) && state_[(*corners_)[k - 1]] == kVertexSeveral &&
        coder->code(truth && truth[k] == values_[k - 1], &model->face[later])) {
      lists_.append(v, values_[k - 1]);
      return values_[k - 1];
    }
    const MappingChoice choice = fallback_choice(lists_, v, truth ? truth[k] : 0, *met);
    return code_corner_value(coder, &model->fallback, &lists_, v, value_count, met, choice, fault);
  }

  // 15.11's reference of corner k (vertex v, seam state): the value of the
  // latest of v's last 8 earlier corners whose face has w- or w+ next to v;
  // returns e (0 found, 1 and 2 found with the edge to w- known continuous or
  // cut at w-, 3 none: the last value of S_v).
  int find_reference(size_t k, uint32_t v, uint32_t* reference) const {
    const uint32_t w_before = (*corners_)[cycle_.previous[k]], w_after = (*corners_)[cycle_.next[k]];
    const uint32_t count = earlier_.length(v);
    const uint32_t examined = count < kReferenceCornersExamined ? count : kReferenceCornersExamined;
    for (uint32_t t = 0; t < examined; ++t) {
      const uint32_t g = earlier_.at(v, count - 1 - t);
      const uint32_t next = cycle_.next[g], previous = cycle_.previous[g];
      const uint32_t a = (*corners_)[next], b = (*corners_)[previous];
      if (a != w_before && b != w_before && a != w_after && b != w_after) continue;
      *reference = values_[g];
      if (first_in_face(k) || (a != w_before && b != w_before)) return 0;
      const uint32_t at_w = a == w_before ? next : previous;
      if (at_w >= k) return 0;  // not decoded yet (v twice in one face)
      return values_[at_w] == values_[k - 1] ? 1 : 2;
    }
    *reference = lists_.at(v, lists_.length(v) - 1);
    return 3;
  }

  // Whether corner k opens its face (i = 0): only there is the corner before
  // it in the face not k - 1.
  bool first_in_face(size_t k) const { return k == 0 || cycle_.previous[k] != k - 1; }

  const std::vector<uint32_t>* corners_ = nullptr;
  CornerCycle cycle_;
  VertexValueLists lists_;    // S_v of 15.3
  VertexValueLists earlier_;  // C_v: v's corners so far, in order
  std::vector<uint8_t> state_;
  std::vector<uint32_t> values_;  // m_k of the corners so far
};

}  // namespace qmc
