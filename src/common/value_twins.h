// Section 15.14 of spec/qmc-format.md (aTTR coding 9): the twin candidate
// of an attribute value. A mesh modelled with a mirror usually has its
// texture mirrored too: the value at a vertex's corner is, up to a flip of
// some components and a shift, the value at the mirrored corner of its twin
// vertex. Both are found from the decoded positions and the faces alone:
// the twin of CONN vertex x is the first vertex at x's mirror image, and the
// mirrored corner is the twin's corner between the twins of x's two
// neighbours there. The values next to both corners give the flip and the
// shift. Nothing but the plane is transmitted.
#pragma once

#include <cstdint>
#include <vector>

#include "common/mirror_prediction.h"
#include "common/vertex_prediction.h"
#include "qmc/mesh.h"

namespace qmc {

// What 15.14 reads besides the values: the mirror plane of the positions'
// grid, CONN's faces (the vertex label of each corner) and the positions'
// integers (3 per vertex, vertex_count vertices).
struct AttributeTwins {
  MirrorPlane plane;
  const Mesh* faces = nullptr;
  const uint32_t* positions = nullptr;
  uint32_t vertex_count = 0;
};

// 15.14's search over the attribute mesh `values` (CONN's faces with each
// corner's value for its vertex), shared by the encoder and the decoder.
// find() is called once per value, in the order the values are visited:
// the flips it carries from value to value depend on it.
class ValueTwins final : public MirrorSource {
 public:
  ValueTwins(const VertexCorners& values, const AttributeTwins& twins, const uint32_t top[3]);
  bool find(uint32_t v, const uint32_t* q, const VertexPrediction& p, int64_t out[3]) const override;
  void decoded(uint32_t v, const uint32_t*) override { decoded_[v] = 1; }

 private:
  // The twin's corner of corner k (between the twins of k's neighbours, the
  // other way round), or kNone.
  uint32_t mirrored_corner(uint32_t k) const;
  bool is_decoded(uint32_t value) const { return decoded_[value] != 0; }
  const VertexCorners& values_;
  VertexCorners vertices_;           // CONN's faces
  std::vector<uint32_t> twin_;       // per CONN vertex: the first vertex at its image point, or kNone
  std::vector<uint8_t> decoded_;     // per value
  uint32_t top_[3];
  // Per component, the sign the last candidate took (+1 at the start):
  // 15.14's carried flip, which each candidate found updates.
  mutable int sign_[3] = {1, 1, 1};
};

}  // namespace qmc
