// qmc tools: image files for geometry images (seeds 000, 002) -- 16-bit
// grayscale PNG planes, 8-bit pictures, and PFM float planes.
//
// A geometry image stores X, Y and Z as separate planes. The benchmark
// compares qmc against the planes saved as 16-bit PNG (lossless, the usual
// storage in the geometry-image papers), so the PNG writer compresses with
// zlib level 9 and can encode to memory to measure the size without a file.
// PFM carries unquantized float planes bit for bit (NaN payloads, -0 and
// infinities included), which keeps test fixtures and debugging dumps exact.
//
// Every image here is stored row-major with row 0 at the TOP: sample (x, y)
// is samples[y * width + x]. (PFM files store rows bottom to top; the PFM
// functions flip rows on the way in and out, so callers never see that.)
//
// Sizes: width and height are at least 1 and width * height is at most
// kMaxImagePixels (2^26); readers check this before allocating anything for
// the pixels. Unreadable or unwritable files give ErrorCode::kIo; malformed
// or unsuitable content and bad arguments give ErrorCode::kInvalidArgument
// with a message that starts with the path and names the problem.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/status.h"

namespace qmc::tools {

constexpr uint64_t kMaxImagePixels = uint64_t{1} << 26;

// 16-bit grayscale PNG, zlib level 9 (adaptive row filters), no ancillary
// chunks, so equal input gives equal bytes. samples.size() must be w * h.
qmc::Status write_png_gray16(const std::string& path, uint32_t width, uint32_t height,
                             const std::vector<uint16_t>& samples);

// The bytes write_png_gray16 would write, without touching the disk. Returns
// an empty vector if the arguments are invalid (see write_png_gray16).
std::vector<uint8_t> encode_png_gray16_to_memory(uint32_t width, uint32_t height,
                                                 const std::vector<uint16_t>& samples);

// Reads a 16-bit grayscale PNG (interlaced or not). Any other bit depth or
// colour type is rejected by name ("plane.png: 8-bit RGB PNG; a
// geometry-image plane must be 16-bit gray"), as are corrupt files (libpng's
// own message). On failure the outputs are left unchanged.
qmc::Status read_png_gray16(const std::string& path, uint32_t* width, uint32_t* height,
                            std::vector<uint16_t>* samples);

// 8-bit pictures (results figures): gray, one byte per pixel, and RGB, three
// bytes per pixel (r g b, rows top to bottom). Default zlib level.
qmc::Status write_png_gray8(const std::string& path, uint32_t width, uint32_t height,
                            const std::vector<uint8_t>& samples);
qmc::Status write_png_rgb8(const std::string& path, uint32_t width, uint32_t height,
                           const std::vector<uint8_t>& rgb);

// Greyscale PFM: header "Pf\n<width> <height>\n-1.0\n" (negative scale =
// little-endian), then the floats, rows stored bottom to top as PFM requires.
// The float bits are copied, never converted, so every value round-trips.
qmc::Status write_pfm_gray(const std::string& path, uint32_t width, uint32_t height,
                           const std::vector<float>& samples);

// Reads a greyscale PFM of either endianness (scale < 0 little-endian,
// scale > 0 big-endian; the magnitude is ignored, values are returned as
// stored). Rejects colour PFM ("PF"), malformed headers, sizes over the
// limit, and data shorter or longer than width * height floats. On failure
// the outputs are left unchanged.
qmc::Status read_pfm_gray(const std::string& path, uint32_t* width, uint32_t* height,
                          std::vector<float>* samples);

}  // namespace qmc::tools
