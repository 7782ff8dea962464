// qmc decoder: whole-buffer and streaming decoding of .qmc files.
// Depends on the C++ standard library only. Never throws for bad input:
// every rejection is a Status naming the rule of spec/qmc-format.md it broke.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "qmc/format.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// One chunk as seen by the decoder (for `qmc info` and diagnostics).
struct ChunkInfo {
  uint32_t type = 0;
  uint64_t offset = 0;   // byte offset of the chunk's type field in the file
  uint32_t length = 0;   // payload bytes
  bool critical = false;
  bool known = false;    // understood by this decoder (unknown ancillary: skipped)
};

std::string chunk_type_name(uint32_t type);

struct QuantizationInfo {
  int method = 0;                 // POSN method: 0 deltas (section 6), 1 or 3 - 14 predicted (section 14)
  bool graded_start = false;      // method 3, and methods 4 - 13 with start 1: 14.4.1's class probabilities
  int bits = 0;                   // method 0: n of section 6.1; method 1: bit length of the largest top
  std::array<float, 3> min{};     // method 0: the stored box; method 1: the origin
  std::array<float, 3> max{};     // method 1: the grid's last point, float(min + top x step)
  std::array<double, 3> step{};   // x = min + q x step (6.4, 14.1), per axis
  std::array<uint32_t, 3> top{};  // the largest q per axis
  int features = 0;               // methods 4 - 13: 14.9's features (1 quad twist, 2 mask contexts, 4 triangle twist)
  int mirror_axis = -1;           // methods 9 - 13: 14.10's plane, q[axis] -> mirror_sum - q[axis]; -1: none
  uint32_t mirror_sum = 0;
  bool near_images = false;       // method 10, and 11 - 13 with plane 2: image vertices may lie a step from the image (14.11)
  int shear = 0;                  // methods 11 - 13: 14.12's weight k of the shear, 1 - 16 (k / 16); 0: none
  bool edge_extrapolation = false;  // methods 12 and 13: 14.13's edge extrapolation
  bool axis_classes = false;        // methods 13 and 14: 14.14's class probabilities per axis
  int lattice = 1;                  // method 14: 14.15's lattice factor k (2 - 16); 1: none
};

// Section 12: one level of a progressive file. Level 0 is the base mesh of
// CONN and POSN; level j >= 1 came from the j-th LEVL chunk.
struct LoopLevel {
  std::vector<double> positions;    // binary64, 3 per vertex (12.2, 12.7)
  std::vector<uint32_t> triangles;  // 3 per face, counter-clockwise
  uint64_t chunk_bytes = 0;         // bytes of the chunks that carried it (level 0: CONN and POSN)
  uint32_t edge_points = 0;         // level >= 1: displacements coded (edges of the level below)
  uint32_t zero_displacements = 0;  // level >= 1: of which 1-bit zeros
  double step = 0;                  // level >= 1: the chunk's step
  uint32_t corrected_vertices = 0;  // level >= 1: vertices moved by LEVL code 4's corrections (12.7.2)

  uint32_t vertex_count() const { return uint32_t(positions.size() / 3); }
  uint32_t face_count() const { return uint32_t(triangles.size() / 3); }
};

// The binary32 mesh of a level (section 12.8); empty if memory runs out.
Mesh level_mesh(const LoopLevel& level);

// Section 13: a geometry image as decoded so far.
struct GimPlaneData {
  uint8_t kind = 0;              // 13.2: 0..2 X Y Z, 3..5 normal, 6 curvature, 7 colour, 8 other
  double offset = 0, step = 0;   // format 0 (unsigned 16-bit): value = offset + s * step
  std::vector<uint32_t> samples; // W * H, raster order: u16 values or binary32 bit patterns
  uint64_t chunk_bytes = 0;      // the GPLN chunk, header and CRC included
};

struct GeometryImageData {
  bool present = false;          // the file has GIMG
  uint32_t width = 0, height = 0;
  uint8_t format = 0;            // 0 unsigned 16-bit, 1 binary32
  uint8_t face_mode = 0;         // 0 grid quads, 1 grid triangles, 2 GFAC triangles
  uint8_t flags = 0;             // bit 0 mask, bit 1 blank samples stored
  uint8_t plane_count = 0;       // P of GIMG
  std::vector<GimPlaneData> planes;      // decoded so far, GIMG's kinds and scales for all P
  std::vector<uint8_t> occupied;         // W * H, 0/1 (all 1 without GMSK)
  std::vector<uint32_t> seam_pairs;      // a0 b0 a1 b1 ...: pixels joined by GSEM
  std::vector<uint32_t> triangles;       // face mode 2: 3 raster indices per triangle
  std::vector<uint32_t> vertex_pixels;   // 13.9: each output vertex's representative pixel
  uint64_t mask_bytes = 0, seam_bytes = 0, face_bytes = 0;  // chunk sizes, header and CRC included
  int planes_decoded() const {
    int n = 0;
    for (const GimPlaneData& p : planes) n += p.samples.empty() ? 0 : 1;
    return n;
  }
  // The value of sample s of plane i (13.2), in binary64.
  double value(int plane, uint32_t pixel) const;
};

// Section 15: how one decoded attribute was coded (mesh.attributes[i] is
// described by attribute_codings[i]).
struct AttributeCoding {
  uint8_t mapping = 0;  // 0 per vertex, 1 per corner (15.3), 3 per corner predicted from the faces (15.11)
  uint8_t coding = 0;   // 0 predicted on a grid (15.4), 1 exact binary32 (15.5), 3 octahedral normals (15.7),
                        // 4 as 0 in the geometry order (15.9), 5 and 6 as 0 and 4 with a graded start (15.10),
                        // 7 guided by the positions (15.12), 8 as 3 with angle weights (15.13),
                        // 9 with twins across a mirror plane (15.14)
  uint8_t options = 0;  // codings 7 and 9: bit 0 the geometry order, bit 1 the graded start (15.12);
                        // coding 9: bit 2 the guided rule (15.14)
  int mirror_axis = -1;    // coding 9: the plane of the positions' grid (15.14); -1 otherwise
  uint32_t mirror_sum = 0;
  std::array<float, 3> origin{};   // codings 0, 4 - 7 and 9: value = origin + q x step, per component
  std::array<double, 3> step{};
  std::array<uint32_t, 3> top{};   // coding 3: 2^B - 1 twice, then 0
  uint64_t chunk_bytes = 0;  // the aTTR chunk, header and CRC included
  // Codings 0, 4 - 7 and 9: values on the grid of origin, step and top.
  bool on_grid() const { return coding == 0 || (coding >= 4 && coding <= 7) || coding == 9; }
  // Codings 3 and 8: unit normals on the octahedral grid of top[0] + 1 points a side.
  bool octahedral() const { return coding == 3 || coding == 8; }
};

struct DecodedFile {
  // Positions dequantized per section 6.4; for a progressive file the mesh
  // of the finest level decoded so far (section 12.8).
  Mesh mesh;
  std::vector<uint32_t> quantized;    // the integers q of section 6.1, 3 per vertex
  QuantizationInfo quantization;
  ConnectivityMethod method = ConnectivityMethod::kIndexed;
  int quad_coding = -1;      // method 1: the coding of section 5.3.5 (QuadCoding)
  bool quad_closed = false;  // method 1: a quad was cut open (closed mesh)
  // Method 2 (section 5.4): coding (5.4.4) and what the records carried.
  int polygon_coding = -1;
  uint32_t polygon_components = 0, polygon_virtual_faces = 0, polygon_seams = 0, polygon_identifications = 0,
           polygon_loose_faces = 0;
  uint8_t version_major = 0, version_minor = 0;
  std::vector<ChunkInfo> chunks;
  std::vector<std::string> texts;     // payloads of teXt chunks, "key=value"
  // Section 4.5: an oRDR chunk was decoded and applied, so vertices, faces
  // and each face's first corner are in the encoder input's order, not the
  // coder's; order_flags says which maps it carried (bit 0 faces, bit 1
  // vertices, bit 2 rotations; a clear bit is the identity).
  bool order_restored = false;
  uint8_t order_flags = 0;
  std::vector<AttributeCoding> attribute_codings;  // section 15, one per mesh.attributes
  // Section 12: LOOP's level count K (0: not a progressive file), and the
  // levels decoded so far, levels[0] the base mesh.
  uint8_t loop_level_count = 0;
  std::vector<LoopLevel> levels;
  // Section 13: the geometry image of a file with GIMG; mesh is its 13.9 mesh
  // once plane 2 has arrived.
  GeometryImageData gim;
};

// What an embedder lets one file cost (spec section 8.1). Each limit is
// checked before memory is reserved for what it counts; a file beyond one is
// rejected with kLimitExceeded, naming the limit. The defaults let a browser
// tab survive any file: at most 256 MiB of output, a mesh of about 9 M
// triangles. Raise them for bigger meshes (`qmc ... --max-output-mb`);
// kNoLimit switches one off.
inline constexpr uint64_t kNoLimit = UINT64_MAX;
struct DecoderLimits {
  // Largest chunk payload this decoder buffers. The format allows 2^31 - 1.
  uint32_t max_chunk_length = kMaxChunkLength;
  // Vertices and faces of any mesh the file yields: CONN's counts (5.1),
  // every progressive level (12.5), a geometry image's mesh (13.9).
  uint64_t max_vertices = uint64_t(1) << 24;
  uint64_t max_faces = uint64_t(1) << 25;
  // W x H of a geometry image (13.2); the format allows 2^24.
  uint64_t max_pixels = uint64_t(1) << 24;
  // LEVL chunks decoded; the levels before the limit stay in file().
  uint32_t max_levels = 8;
  // The size of the canonical output (10.2, 12.9, 13.10) of everything the
  // file yields; the decoder's memory is a small multiple of it.
  uint64_t max_output_bytes = uint64_t(256) << 20;

  static DecoderLimits unlimited();
};

// What a file's first chunks say it will cost, read without decoding
// (spec 8.1): from QHDR, LOOP, the CONN header and the GIMG header. Counts a
// file does not have yet are 0.
struct FileSummary {
  uint8_t version_major = 0, version_minor = 0;
  bool has_connectivity = false;      // the CONN header was read
  ConnectivityMethod method = ConnectivityMethod::kIndexed;
  uint64_t vertex_count = 0, face_count = 0;  // CONN (the base mesh of a progressive file)
  uint8_t loop_level_count = 0;       // LOOP's K
  uint64_t finest_face_count = 0;     // progressive: 4^K faces of the base
  bool has_geometry_image = false;
  uint32_t gim_width = 0, gim_height = 0;
  uint8_t gim_plane_count = 0;
  // A lower bound of the canonical output's size, what max_output_bytes
  // is compared with.
  uint64_t min_output_bytes = 0;
};

// Reads the chunks of `data` up to the CONN or GIMG header: kOk with the
// summary, kTruncated if more bytes are needed, or the error of a chunk read
// so far (signature, framing, CRC, QHDR, LOOP, those headers).
Status peek(const uint8_t* data, size_t size, FileSummary* out);

// Decodes a complete file held in memory. Never throws: running out of
// memory is kLimitExceeded.
Status decode(const uint8_t* data, size_t size, DecodedFile* out, const DecoderLimits& limits = {});

// Decodes a file whose bytes arrive in pieces (section 3.5). Each complete
// chunk is validated and decoded the moment its last byte arrives; a viewer
// can poll `file()` as chunks land. An oRDR chunk (section 4.5), after POSN,
// reorders the mesh in `file()` into the input's order when it arrives.
class StreamDecoder {
 public:
  explicit StreamDecoder(const DecoderLimits& limits = {});
  ~StreamDecoder();
  StreamDecoder(const StreamDecoder&) = delete;
  StreamDecoder& operator=(const StreamDecoder&) = delete;

  // Consumes the bytes. After an error, every further call returns it again.
  Status feed(const uint8_t* data, size_t size);
  // Call once the input has ended: a file that stopped before QEND is kTruncated.
  Status finish();

  bool complete() const;          // QEND seen and valid
  bool has_connectivity() const;  // CONN decoded: faces are available
  bool has_positions() const;     // POSN decoded: positions are available
  // Section 12: the finest level whose chunk has been decoded (0 = base mesh
  // once POSN is in), or -1 before that or for a file without LOOP. The mesh
  // of level j is level_mesh(file().levels[j]); file().mesh is the finest.
  int complete_level() const;
  int level_count() const;        // LOOP's K, 0 if no LOOP (yet)
  const DecodedFile& file() const;
  DecodedFile take_file();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The canonical byte serialization of a decoded mesh (section 10.2), whose
// SHA-256 the conformance manifest records; empty if memory runs out.
std::vector<uint8_t> canonical_output(const DecodedFile& file);

}  // namespace qmc
