// Gate-stack traversal of seed 001 §3.2 (Program 1) over the opposite-edge
// table, classifying each quad as Q1..Q13 (spec/qmc-format.md 5.3.3). The
// region not yet encoded is tracked with two flags only: quads processed,
// and vertices already on a boundary ("marked"); the boundary loops
// themselves never need to be stored.
#include "encoder/quad_traversal_encoder.h"

#include "encoder/opposite_edge_table.h"

namespace qmc {
namespace {

using T = OppositeEdgeTable;

enum class Where : uint8_t { kFree, kAdjacent, kFar };

// Spec 5.3.3, table of types by the status of y (left) and x (right).
int classify(Where y, Where x, bool opposite_on_boundary) {
  switch (y) {
    case Where::kAdjacent:
      if (x == Where::kAdjacent) return opposite_on_boundary ? 1 : 4;
      if (x == Where::kFar) return opposite_on_boundary ? 2 : 3;
      return 5;
    case Where::kFree:
      return x == Where::kAdjacent ? 12 : x == Where::kFar ? 11 : 13;
    case Where::kFar:
      if (x == Where::kAdjacent) return opposite_on_boundary ? 6 : 9;
      if (x == Where::kFar) return opposite_on_boundary ? 7 : 8;
      return 10;
  }
  return 0;
}

class Traversal {
 public:
  Traversal(const Mesh& mesh, const OppositeEdgeTable& table, QuadTraversal* out)
      : mesh_(mesh), t_(table), out_(out), processed_(mesh.face_count(), false),
        label_(mesh.vertex_count(), kNoEdge) {}

  std::string run();

 private:
  uint32_t origin(uint32_t e) const { return mesh_.corners[e]; }
  bool outside(uint32_t e) const { return t_.across[e] == kNoEdge || processed_[T::quad_of(t_.across[e])]; }
  void give_label(uint32_t v) {
    if (label_[v] != kNoEdge) return;
    label_[v] = uint32_t(out_->file_vertex.size());
    out_->file_vertex.push_back(v);
  }
  uint32_t first_gate();
  std::string encode_quad(uint32_t gate, std::vector<uint32_t>* gates, uint32_t* next_gate);
  void emit_face(uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t source) {
    out_->faces.insert(out_->faces.end(), {label_[a], label_[b], label_[c], label_[d]});
    out_->face_source.push_back(source);
  }

  const Mesh& mesh_;
  const OppositeEdgeTable& t_;
  QuadTraversal* out_;
  std::vector<bool> processed_;
  std::vector<uint32_t> label_;
};

// Spec 5.3.4: a closed mesh is cut open at quad 0; otherwise the gate is the
// first boundary edge in input order. The initial loop is labelled from the
// gate's origin on.
uint32_t Traversal::first_gate() {
  if (out_->closed) {
    processed_[0] = true;
    const uint32_t* c = &mesh_.corners[0];
    for (uint32_t v : {c[1], c[0], c[3], c[2]}) give_label(v);
    emit_face(c[0], c[1], c[2], c[3], 0);
    return t_.across[0];
  }
  uint32_t gate = 0;
  while (t_.across[gate] != kNoEdge) ++gate;
  uint32_t e = gate;
  do {
    give_label(origin(e));
    uint32_t n = T::next(e);
    while (t_.across[n] != kNoEdge) n = T::next(t_.across[n]);
    e = n;
  } while (e != gate);
  return gate;
}

// Classifies the quad behind `gate`, records it, and returns in *next_gate
// the gate to continue with (kNoEdge after Q1), pushing the gates of any
// further loops it splits off (spec 5.3.3: loops in L, O, R order, the last
// continues).
std::string Traversal::encode_quad(uint32_t gate, std::vector<uint32_t>* gates, uint32_t* next_gate) {
  const uint32_t right = T::next(gate), opposite = T::next(right), left = T::next(opposite);
  const uint32_t g0 = origin(gate), g1 = origin(right), x = origin(opposite), y = origin(left);
  const bool lb = outside(left), ob = outside(opposite), rb = outside(right);
  const Where wy = lb ? Where::kAdjacent : label_[y] != kNoEdge ? Where::kFar : Where::kFree;
  const Where wx = rb ? Where::kAdjacent : label_[x] != kNoEdge ? Where::kFar : Where::kFree;
  const int type = classify(wy, wx, ob);
  if (ob && (wx == Where::kFree || wy == Where::kFree)) return "internal: boundary edge at an unmarked vertex";
  if (wx == Where::kFree) give_label(x);
  if (wy == Where::kFree) give_label(y);
  emit_face(g0, g1, x, y, T::quad_of(gate));
  processed_[T::quad_of(gate)] = true;
  out_->types.push_back(uint8_t(type));
  const uint32_t l = t_.across[left], o = t_.across[opposite], r = t_.across[right];
  switch (type) {
    case 1: *next_gate = kNoEdge; break;
    case 2: case 5: case 13: *next_gate = r; break;
    case 4: case 12: *next_gate = o; break;
    case 6: *next_gate = l; break;
    case 3: case 11: gates->push_back(o); *next_gate = r; break;
    case 7: case 10: gates->push_back(l); *next_gate = r; break;
    case 9: gates->push_back(l); *next_gate = o; break;
    case 8: gates->push_back(l); gates->push_back(o); *next_gate = r; break;
  }
  return {};
}

std::string Traversal::run() {
  std::vector<uint32_t> gates;
  uint32_t gate = first_gate();
  while (gate != kNoEdge) {
    if (processed_[T::quad_of(gate)]) return "internal: a gate leads to a quad already encoded";
    uint32_t next = kNoEdge;
    if (std::string why = encode_quad(gate, &gates, &next); !why.empty()) return why;
    if (next == kNoEdge && !gates.empty()) {
      next = gates.back();
      gates.pop_back();
    }
    gate = next;
  }
  for (size_t i = 0; i + 1 < out_->types.size(); ++i) {
    const uint8_t t = out_->types[i];
    const bool claimed = t == 5 || t == 10 || t == 12 || t == 13;
    out_->claim_violations += claimed && out_->types[i + 1] <= 5;
  }
  for (uint32_t v = 0; v < mesh_.vertex_count(); ++v) give_label(v);  // unreferenced, input order
  return {};
}

}  // namespace

std::string encode_quad_traversal(const Mesh& mesh, QuadTraversal* out) {
  *out = QuadTraversal{};
  if (mesh.face_count() == 0) return "the mesh has no faces";
  OppositeEdgeTable table;
  if (std::string why = build_opposite_edge_table(mesh, &table); !why.empty()) return why;
  if (table.components != 1)
    return "the mesh has " + std::to_string(table.components) + " connected components";
  if (table.boundary_loops > 1) return "the mesh has " + std::to_string(table.boundary_loops) + " boundary loops";
  const int64_t expected = 2 - int64_t(table.boundary_loops);
  if (table.euler_characteristic != expected)
    return "the mesh has genus " + std::to_string((expected - table.euler_characteristic) / 2) + " (handles)";
  out->closed = table.boundary_loops == 0;
  if (out->closed && mesh.face_count() < 2) return "a closed mesh needs at least two quads";
  Traversal traversal(mesh, table, out);
  return traversal.run();
}

}  // namespace qmc
