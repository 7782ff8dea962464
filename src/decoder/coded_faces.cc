// Codings 7 and 8's face symbols, spec/qmc-format.md 5.4.10.
#include "decoder/coded_faces.h"

#include <string>

#include "decoder/connectivity_errors.h"

namespace qmc {
namespace {

// The fixed shapes of symbols 0 .. 17 (5.4.3), face f = symbol f.
FaceShapes fixed_symbol_shapes() {
  FaceShapes table;
  table.reserve(kPolygonOtherSymbol);
  for (int symbol = 0; symbol < kPolygonOtherSymbol; ++symbol) {
    uint8_t status[2], gaps[3];
    uint32_t gap_count = 0;
    const uint32_t d = symbol_shape(symbol, status, gaps, &gap_count);
    table.add(d, status, gaps, gap_count);
  }
  return table;
}

}  // namespace

CodedFaces::CodedFaces(const uint8_t* data, size_t size, uint8_t groups, bool quad_neighbours,
                       OtherFaceCorners* corners)
    : range_(data, size), corners_(corners), bytes_(size), fixed_(fixed_symbol_shapes()) {
  model_.groups = groups;
  model_.quad_neighbours = quad_neighbours;
}

Status CodedFaces::start() const {
  if (range_.bad_start()) return payload_error("face symbol stream starts with 0xFFFFFFFF");
  return Status::Ok();
}

Status CodedFaces::face(const GateContext& gate, size_t, const FaceShapes** shapes, size_t* index) {
  const int symbol = code_face_symbol(&range_, &model_, gate, 0);
  if (range_.overrun()) return truncated();
  if (symbol < 0) return symbol_error("quad code above 12 (5.4.10)");
  if (symbol != kPolygonOtherSymbol) {
    *shapes = &fixed_;
    *index = size_t(symbol);
    return Status::Ok();
  }
  if (Status s = other_shape(); !s.ok()) return s;
  *shapes = &shapes_;
  *index = shapes_.size() - 1;
  return Status::Ok();
}

Status CodedFaces::end() {
  if (range_.overrun()) return truncated();
  if (range_.unread() != 0) return payload_error("bytes after the face symbol stream's coded data");
  return Status::Ok();
}

// Symbol 18: its degree, then its statuses and gap kinds (5.4.10).
Status CodedFaces::other_shape() {
  uint32_t extra = 0;
  if (!code_other_degree(&range_, &extra))
    return range_.overrun() ? truncated() : payload_error("face degree code with 32 leading zeros");
  const uint64_t d = uint64_t(extra) + 5;
  if (Status s = check_other_face(d, range_stream_justifies(d - 2, bytes_), corners_); !s.ok()) return s;
  scratch_.resize(2 * size_t(d - 2) + 1);
  uint8_t* status = scratch_.data();
  uint8_t* gaps = status + (d - 2);
  const uint32_t gap_count = code_other_shape(&range_, &model_, uint32_t(d - 2), status, gaps);
  if (gap_count == 0) return truncated();
  shapes_.add(uint32_t(d), status, gaps, gap_count);
  return Status::Ok();
}

}  // namespace qmc
