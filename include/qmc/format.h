// qmc: constants of the container format (spec/qmc-format.md sections 3-6).
// Public so that tools and other implementations can name chunks and methods
// the same way the specification does.
#pragma once

#include <cstdint>

namespace qmc {

// Section 3.1: the 8-byte file signature.
inline constexpr uint8_t kSignature[8] = {0x89, 'Q', 'M', 'C', '\r', '\n', 0x1A, '\n'};

// Section 4.1: the format version this library writes and reads. Minor 1
// added connectivity method 1, minor 2 method 2, minor 3 the progressive
// chunks LOOP and LEVL, minor 4 the geometry-image chunks, minor 5 POSN
// method 1, minor 6 polygon coding 7, minor 7 POSN method 3, minor 8 POSN
// method 4, minor 9 POSN method 5, minor 10 POSN methods 6 and 7, minor 11 POSN
// method 8, minor 12 POSN method 9, minor 13 POSN method 10, minor 14 LEVL
// code 4, minor 15 POSN method 11, minor 16 POSN method 12, minor 17 POSN method 13, minor 18
// polygon coding 8, minor 19 POSN method 14 (section 11);
// a file says the lowest minor version that defines everything it uses.
inline constexpr uint8_t kFormatMajor = 1;
inline constexpr uint8_t kFormatMinor = 19;

// Section 3.2: a chunk payload is at most 2^31 - 1 bytes.
inline constexpr uint32_t kMaxChunkLength = 0x7FFFFFFFu;

// Section 3.3: chunk types as 32-bit big-endian packing of their 4 ASCII letters.
constexpr uint32_t chunk_type(char a, char b, char c, char d) {
  return (uint32_t(uint8_t(a)) << 24) | (uint32_t(uint8_t(b)) << 16) | (uint32_t(uint8_t(c)) << 8) |
         uint32_t(uint8_t(d));
}
inline constexpr uint32_t kChunkHeader = chunk_type('Q', 'H', 'D', 'R');
inline constexpr uint32_t kChunkConnectivity = chunk_type('C', 'O', 'N', 'N');
inline constexpr uint32_t kChunkPositions = chunk_type('P', 'O', 'S', 'N');
inline constexpr uint32_t kChunkEnd = chunk_type('Q', 'E', 'N', 'D');
inline constexpr uint32_t kChunkText = chunk_type('t', 'e', 'X', 't');
// Section 4.5: the input's order of vertices, faces and corners (ancillary).
inline constexpr uint32_t kChunkOrder = chunk_type('o', 'R', 'D', 'R');
// Section 15: one attribute of the corners (ancillary).
inline constexpr uint32_t kChunkAttribute = chunk_type('a', 'T', 'T', 'R');
// Section 16: a label per face from a table of strings (ancillary).
inline constexpr uint32_t kChunkFaceLabels = chunk_type('f', 'L', 'B', 'L');
// Section 12: progressive Loop levels, the header and one chunk per level.
inline constexpr uint32_t kChunkLoop = chunk_type('L', 'O', 'O', 'P');
inline constexpr uint32_t kChunkLevel = chunk_type('L', 'E', 'V', 'L');
// Section 13: geometry images: header, occupancy mask, seams, triangles over
// pixels, and one chunk per plane.
inline constexpr uint32_t kChunkGeometryImage = chunk_type('G', 'I', 'M', 'G');
inline constexpr uint32_t kChunkGimMask = chunk_type('G', 'M', 'S', 'K');
inline constexpr uint32_t kChunkGimSeams = chunk_type('G', 'S', 'E', 'M');
inline constexpr uint32_t kChunkGimFaces = chunk_type('G', 'F', 'A', 'C');
inline constexpr uint32_t kChunkGimPlane = chunk_type('G', 'P', 'L', 'N');

// Section 3.3: bit 5 of the first type byte clear (upper-case letter) = critical.
constexpr bool chunk_is_critical(uint32_t type) { return ((type >> 24) & 0x20u) == 0; }

// Section 5.1: connectivity coding methods recorded in CONN.
enum class ConnectivityMethod : uint8_t {
  kIndexed = 0,  // universal fallback: any polygon soup (section 5.2)
  kQuad = 1,     // seed 001 quad coder: Q1..Q13, Spirale Reversi (section 5.3)
  kPolygon = 2,  // any polygon mesh: holes, handles, components, n-gons (section 5.4)
};
const char* connectivity_method_name(ConnectivityMethod method);

// Section 5.3.5: how method 1 codes its interaction types.
enum class QuadCoding : uint8_t {
  kPlain4 = 0,     // 4 bits per type (seed 001 §4.1), always applicable
  kCodingI = 1,    // seed 001 table 4-2
  kCodingII = 2,   // table 4-6
  kCodingIII = 3,  // table 4-8
  kHuffman = 4,    // canonical Huffman per current class, tables in the stream
};
inline constexpr int kQuadCodingCount = 5;
const char* quad_coding_name(QuadCoding coding);

// Section 5.4.4: method 2 uses the quad codings 0..4 when every coded face
// is a quad, 5, a Huffman code over all face symbols, or 7, the symbols range
// coded in contexts of Spirale Reversi's state (5.4.10, format 1.6), or 8, the
// same with the quads' contexts from the gate's neighbours too (format 1.18).
// Coding 6 is unassigned (the vector invalid_polygon_unknown_coding uses it).
inline constexpr int kPolygonMixedHuffman = 5;
inline constexpr int kPolygonUnassignedCoding = 6;
inline constexpr int kPolygonContextCoded = 7;
inline constexpr int kPolygonQuadContextCoded = 8;
inline constexpr int kPolygonCodingCount = 9;

// Section 6.1: position quantization bits.
inline constexpr int kMinPositionBits = 1;
inline constexpr int kMaxPositionBits = 30;
// Default keeps the largest per-vertex error below 1/4096 of the largest
// bounding-box side (section 6.2 derives the bound).
inline constexpr int kDefaultPositionBits = 12;

}  // namespace qmc
