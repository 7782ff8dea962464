// Plane and mask payloads of geometry images (spec/qmc-format.md 13.5, 13.6):
// the mirror of decoder/plane_decoder.cc over the range encoder.
#include "encoder/plane_encoder.h"

#include <utility>

#include "common/plane_prediction.h"
#include "common/range_coder.h"

namespace qmc {

std::vector<uint8_t> encode_plane_with(const std::vector<uint32_t>& samples, const PlaneLayout& layout,
                                       int predictor) {
  const uint32_t w = layout.width, h = layout.height;
  const bool is_float = layout.format == GimSampleFormat::kFloat32;
  const int k = is_float ? 32 : 16;
  const uint32_t top = is_float ? 0xFFFFFFFFu : 0xFFFFu;
  const std::vector<uint8_t>* mask = layout.blank_stored ? nullptr : layout.occupied;
  // Values as the decoder will see them: ordered keys, blank pixels replaced
  // by their predictions as they come.
  std::vector<uint32_t> v(samples.size());
  for (size_t i = 0; i < samples.size(); ++i)
    v[i] = is_float ? float_bits_to_ordered(samples[i]) : samples[i] & top;
  RangeEncoder rc;
  PlaneResidualModel model;
  std::vector<uint32_t> above(w, 0), row(w, 0);
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const uint32_t pred = predict_sample(v.data(), w, x, y, predictor, top);
      if (mask && (*mask)[i] == 0) {
        v[i] = pred;
        row[x] = 0;
        continue;
      }
      const uint32_t r = (v[i] - pred) & top;  // residual mod 2^k
      SignedResidual s;
      s.negative = r > (top >> 1);
      s.magnitude = s.negative ? ((top - r) + 1) : r;  // 2^k - r, no overflow for k = 32
      const int bucket = plane_bucket(x > 0 ? row[x - 1] : 0, y > 0 ? above[x] : 0,
                                      x > 0 && y > 0 ? above[x - 1] : 0, y > 0 && x + 1 < w ? above[x + 1] : 0);
      code_residual(&rc, &model, bucket, k, s);
      row[x] = s.magnitude;
    }
    above.swap(row);
  }
  std::vector<uint8_t> out{uint8_t(predictor)};
  const std::vector<uint8_t> stream = rc.finish();
  out.insert(out.end(), stream.begin(), stream.end());
  return out;
}

std::vector<uint8_t> encode_plane(const std::vector<uint32_t>& samples, const PlaneLayout& layout,
                                  PlaneEncodeStats* stats) {
  std::vector<uint8_t> best;
  if (stats) stats->bytes_per_predictor.clear();
  for (int p = 0; p < kPlanePredictorCount; ++p) {
    std::vector<uint8_t> out = encode_plane_with(samples, layout, p);
    if (stats) stats->bytes_per_predictor.push_back(out.size());
    if (best.empty() || out.size() < best.size()) best = std::move(out);
  }
  if (stats) {
    stats->predictor = best[0];
    stats->bytes = best.size();
  }
  return best;
}

std::vector<uint8_t> encode_mask(const std::vector<uint8_t>& occupied, uint32_t width, uint32_t height) {
  RangeEncoder rc;
  uint16_t probs[16];
  for (uint16_t& p : probs) p = kRangeProbabilityInit;
  auto at = [&](uint32_t x, uint32_t y) { return occupied[size_t(y) * width + x] != 0 ? 1 : 0; };
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const int context = (x > 0 ? at(x - 1, y) : 0) | (y > 0 ? at(x, y - 1) : 0) << 1 |
                          (x > 0 && y > 0 ? at(x - 1, y - 1) : 0) << 2 |
                          (y > 0 && x + 1 < width ? at(x + 1, y - 1) : 0) << 3;
      rc.code(at(x, y), &probs[context]);
    }
  return rc.finish();
}

}  // namespace qmc
