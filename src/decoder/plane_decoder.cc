// Plane and mask payloads of geometry images (spec/qmc-format.md 13.5 and
// 13.6): pixels in raster order, each predicted from decoded neighbours and
// corrected by a range-coded residual.
#include "decoder/plane_decoder.h"

#include <string>

#include "common/plane_prediction.h"
#include "common/range_coder.h"

namespace qmc {
namespace {

std::string pixel(uint32_t x, uint32_t y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

// Every coded decision shrinks the range by a factor of at most about
// 2017/2048, so a byte of stream carries fewer than 364 decisions; 512 per
// byte (plus one byte's worth) is a bound no encoder output reaches.
Status check_decision_count(const char* what, uint64_t decisions, size_t stream_bytes) {
  if (decisions > 512 * (uint64_t(stream_bytes) + 1))
    return Status(ErrorCode::kLimitExceeded, std::string(what) + ": " + std::to_string(decisions) +
                                                 " coded pixels cannot fit in " + std::to_string(stream_bytes) +
                                                 " bytes");
  return Status::Ok();
}

Status check_start(const char* what, const RangeDecoder& rc) {
  if (rc.bad_start())
    return Status(ErrorCode::kBadChunkPayload, std::string(what) + ": range-coded data starts with FF FF FF FF");
  return Status::Ok();
}

Status check_end(const char* what, const RangeDecoder& rc) {
  if (rc.overrun())
    return Status(ErrorCode::kTruncated, std::string(what) + ": range-coded data ends " +
                                             std::to_string(rc.invented()) + " bytes early");
  if (rc.unread() != 0)
    return Status(ErrorCode::kBadChunkPayload,
                  std::string(what) + ": " + std::to_string(rc.unread()) + " bytes after the range-coded data");
  return Status::Ok();
}

}  // namespace

Status decode_plane(const uint8_t* data, size_t size, const PlaneLayout& layout, std::vector<uint32_t>* samples) {
  const uint32_t w = layout.width, h = layout.height;
  const size_t count = size_t(w) * h;
  if (layout.occupied && layout.occupied->size() != count)
    return Status(ErrorCode::kInvalidArgument, "plane: mask size differs from width * height");
  if (size == 0) return Status(ErrorCode::kTruncated, "plane: payload has no predictor byte");
  const int predictor = data[0];
  if (predictor >= kPlanePredictorCount)
    return Status(ErrorCode::kUnsupportedFeature, "plane: unknown predictor " + std::to_string(predictor));
  const bool is_float = layout.format == GimSampleFormat::kFloat32;
  const int k = is_float ? 32 : 16;
  const uint32_t top = is_float ? 0xFFFFFFFFu : 0xFFFFu;
  const uint32_t half = (top >> 1) + 1;
  const std::vector<uint8_t>* mask = layout.blank_stored ? nullptr : layout.occupied;
  uint64_t coded = count;
  if (mask) {
    coded = 0;
    for (uint8_t o : *mask) coded += o != 0;
  }
  if (Status s = check_decision_count("plane", coded, size - 1); !s.ok()) return s;

  RangeDecoder rc(data + 1, size - 1);
  if (Status s = check_start("plane", rc); !s.ok()) return s;
  PlaneResidualModel model;
  // Residual magnitudes of the row above and of this row, for the contexts.
  std::vector<uint32_t> above(w, 0), row(w, 0);
  samples->assign(count, 0);
  uint32_t* v = samples->data();
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const uint32_t pred = predict_sample(v, w, x, y, predictor, top);
      if (mask && (*mask)[i] == 0) {
        v[i] = pred;
        row[x] = 0;
        continue;
      }
      const int bucket = plane_bucket(x > 0 ? row[x - 1] : 0, y > 0 ? above[x] : 0,
                                      x > 0 && y > 0 ? above[x - 1] : 0, y > 0 && x + 1 < w ? above[x + 1] : 0);
      const SignedResidual r = code_residual(&rc, &model, bucket, k, SignedResidual());
      if (rc.overrun()) return check_end("plane", rc);
      if (r.magnitude > half || (r.magnitude == half && !r.negative))
        return Status(ErrorCode::kBadSymbol, "plane: residual at pixel " + pixel(x, y) + " overflows " +
                                                 std::to_string(k) + " bits");
      v[i] = (r.negative ? pred - r.magnitude : pred + r.magnitude) & top;
      row[x] = r.magnitude;
    }
    above.swap(row);
  }
  if (Status s = check_end("plane", rc); !s.ok()) return s;
  if (is_float)
    for (uint32_t& s : *samples) s = ordered_to_float_bits(s);
  return Status::Ok();
}

Status decode_mask(const uint8_t* data, size_t size, uint32_t width, uint32_t height, std::vector<uint8_t>* occupied) {
  const size_t count = size_t(width) * height;
  if (Status s = check_decision_count("mask", count, size); !s.ok()) return s;
  RangeDecoder rc(data, size);
  if (Status s = check_start("mask", rc); !s.ok()) return s;
  uint16_t probs[16];
  for (uint16_t& p : probs) p = kRangeProbabilityInit;
  occupied->assign(count, 0);
  uint8_t* o = occupied->data();
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t i = size_t(y) * width + x;
      const int context = (x > 0 ? o[i - 1] : 0) | (y > 0 ? o[i - width] : 0) << 1 |
                          (x > 0 && y > 0 ? o[i - width - 1] : 0) << 2 |
                          (y > 0 && x + 1 < width ? o[i - width + 1] : 0) << 3;
      o[i] = uint8_t(rc.code(0, &probs[context]));
    }
    if (rc.overrun()) return check_end("mask", rc);
  }
  return check_end("mask", rc);
}

}  // namespace qmc
