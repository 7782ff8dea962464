// Decoder of the POSN chunk (spec/qmc-format.md sections 6 and 14).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/position_coding.h"
#include "common/geometry_order.h"
#include "common/mirror_prediction.h"
#include "common/value_twins.h"
#include "qmc/decoder.h"
#include "qmc/status.h"

namespace qmc {

// Decodes a POSN payload; `vertex_count` is the count CONN declared and
// `faces` CONN's faces (method 1 predicts from them, section 14.3).
// Fills quantized (3 per vertex), positions (sections 6.4, 14.1) and the
// stored quantization parameters.
Status decode_positions(const uint8_t* payload, size_t size, const Mesh& faces, uint32_t vertex_count,
                        QuantizationInfo* info, std::vector<uint32_t>* quantized, std::vector<float>* positions);

// How the messages of decode_predicted_grid name the chunk and its items.
struct PredictedGridNames {
  std::string chunk;  // "POSN", or "aTTR \"normal\""
  const char* item;   // "vertex" / "value"
  const char* items;  // "vertices" / "values"
  const char* axis;   // "axis" / "component"
};

// Sections 14.2 - 14.4 over any faces whose corners are below `count`: the
// integers of POSN methods 1 and 3 or of an aTTR's values (15.4), 3 per
// item, from the range-coded stream that ends the payload; with a guide,
// 15.12's guided rule too (its orientation starting at +1); with quad_twist
// (geometry order only), POSN method 5's twist of quads (14.7); with
// mask_contexts, methods 6 and 7's contexts of the candidate decisions (14.8);
// with triangle_twist (geometry order only), method 8's triangle twist (14.9);
// with a mirror plane (geometry order only), method 9's mirror candidate (14.10);
// with twins, aTTR coding 9's twin candidate (15.14); with a shear k
// (geometry order only), method 11's sheared parallelograms (14.12); with
// extrapolate (geometry order only), method 12's edge extrapolation (14.13);
// with axis_classes, method 13's class probabilities per axis (14.14).
Status decode_predicted_grid(const uint8_t* stream, size_t size, const Mesh& faces, uint32_t count,
                             const uint32_t top[3], const PredictedGridNames& names, std::vector<uint32_t>* quantized,
                             ClassStart start = ClassStart::kFlat, PredictionOrder order = PredictionOrder::kLabels,
                             const PositionGuide* guide = nullptr, bool quad_twist = false,
                             bool mask_contexts = false, bool triangle_twist = false,
                             const MirrorPlane* mirror = nullptr, const AttributeTwins* twins = nullptr,
                             int shear = 0, bool extrapolate = false, bool axis_classes = false, int lattice = 1);

// Sections 6.4 and 14.1: per axis, the binary64 min and step of x = min + q * step.
void dequantization_steps(const QuantizationInfo& info, double lo[3], double step[3]);

}  // namespace qmc
