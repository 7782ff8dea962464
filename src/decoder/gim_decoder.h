// The geometry-image chunks of spec/qmc-format.md section 13: GIMG (13.2),
// GMSK (13.4), GSEM (13.7), GFAC (13.8), GPLN (13.5), and the mesh of 13.9
// once plane 2 has arrived. The order rules of 13.1 live here too, so the
// container (stream_decoder.cc) only dispatches.
#pragma once

#include <cstdint>

#include "decoder/output_budget.h"
#include "qmc/decoder.h"
#include "qmc/status.h"

namespace qmc {

class GimChunkDecoder {
 public:
  // `file` receives the image (file->gim) and, after plane 2, the mesh;
  // `limits` and `budget` are the decoder's (section 8.1).
  GimChunkDecoder(DecodedFile* file, const DecoderLimits* limits, OutputBudget* budget)
      : file_(file), limits_(limits), budget_(budget) {}

  // 13.1: what the other chunks may do once GIMG has (not) been seen.
  bool active() const { return file_->gim.present; }
  Status header(const uint8_t* payload, uint32_t length, bool other_mesh_chunks_seen);
  Status mask(const uint8_t* payload, uint32_t length);
  Status seams(const uint8_t* payload, uint32_t length);
  Status faces(const uint8_t* payload, uint32_t length);
  Status plane(const uint8_t* payload, uint32_t length);
  // 13.1: QEND only after the P-th plane.
  Status check_end() const;
  bool mesh_ready() const { return mesh_built_; }

 private:
  Status require_image(const char* chunk) const;
  Status justify_size(const char* chunk, uint32_t length);
  Status build_mesh();

  DecodedFile* file_;
  const DecoderLimits* limits_;
  OutputBudget* budget_;
  bool mask_seen_ = false, seams_seen_ = false, faces_seen_ = false, mesh_built_ = false;
  bool size_justified_ = false;
};

}  // namespace qmc
