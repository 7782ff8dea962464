// libFuzzer target: an fLBL payload (spec section 16) for a face count taken
// from the input's first two bytes (u16le). An accepted chunk must give every
// face a label no larger than its table; coded again by the encoder (faces
// in the same order) it must decode to the same labels.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/face_label_decoder.h"
#include "encoder/face_label_encoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const uint64_t faces = data[0] | uint64_t(data[1]) << 8;
  qmc::OutputBudget budget(uint64_t(64) << 20);
  qmc::FaceLabels labels;
  if (!qmc::decode_face_labels(data + 2, size - 2, faces, {}, &budget, &labels).ok()) return 0;
  if (labels.face_values.size() != faces) __builtin_trap();
  for (uint32_t l : labels.face_values)
    if (l > labels.none()) __builtin_trap();
  std::vector<uint32_t> identity(faces);
  for (uint32_t f = 0; f < faces; ++f) identity[f] = f;
  const std::vector<uint8_t> again = qmc::encode_face_labels(labels, identity);
  qmc::OutputBudget second(uint64_t(64) << 20);
  qmc::FaceLabels round_trip;
  if (!qmc::decode_face_labels(again.data(), again.size(), faces, {}, &second, &round_trip).ok() ||
      round_trip.face_values != labels.face_values || round_trip.values != labels.values ||
      round_trip.references != labels.references || round_trip.name != labels.name)
    __builtin_trap();
  return 0;
}
