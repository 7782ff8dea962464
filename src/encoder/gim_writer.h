// Writing a geometry image as a .qmc file: spec/qmc-format.md section 13
// (GIMG, GMSK, GSEM, GFAC, GPLN). Takes the binary64 samples of the
// generators (gim_sampling.h, gim_topology_preserving.h), quantizes or
// rounds them, and codes every chunk; the result is decoded again and
// compared before it is returned.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/gim_types.h"
#include "qmc/encoder.h"
#include "qmc/status.h"

namespace qmc {

// Extra per-pixel planes (13.2 kinds 3..8), binary64 per pixel.
struct GimExtraPlane {
  uint8_t kind = 8;
  std::vector<double> values;  // width * height
};

// A geometry image as the file holds it (13.2): raw samples per plane.
struct GimRawImage {
  uint32_t width = 0, height = 0;
  uint8_t format = 0, face_mode = 1;
  bool store_blank = false;
  std::vector<uint8_t> kinds;                 // per plane; 0, 1, 2 first
  std::vector<double> offsets, steps;         // per plane, format 0
  std::vector<std::vector<uint32_t>> planes;  // W * H each: u16 values or binary32 bits
  std::vector<uint8_t> occupied;              // empty or W * H
  std::vector<SeamPair> seams;
  std::vector<uint32_t> triangles;            // face mode 2
};

// Codes the chunks of `image` (and decodes them again to check).
Status write_raw_geometry_image(const GimRawImage& image, const std::vector<std::string>& texts,
                                std::vector<uint8_t>* out, EncodeStats* stats);

// Quantizes (16-bit: one step for X, Y, Z over their common extent) or
// rounds (binary32) the samples, then writes them.
Status write_geometry_image(const GimSamples& samples, const std::vector<GimExtraPlane>& extra,
                            const GeometryImageOptions& options, const std::vector<std::string>& texts,
                            std::vector<uint8_t>* out, EncodeStats* stats);

// GFAC's payload (13.8): the triangle count and the range-coded corners.
std::vector<uint8_t> encode_gim_triangles(const std::vector<uint32_t>& triangles, uint32_t width);

// GSEM's runs (13.7) from a list of pairs, consecutive pairs with equal
// steps in one run; the payload.
std::vector<uint8_t> encode_seam_runs(const std::vector<SeamPair>& pairs);

}  // namespace qmc
