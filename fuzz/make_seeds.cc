// Builds each fuzz target's seed corpus from the conformance vectors:
// whole files for the file decoders, chunk payloads for the component
// decoders. Usage: make_seeds VECTORS_DIR OUT_DIR
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "common/byte_io.h"
#include "common/displacement_coding.h"
#include "common/polygon_symbol_coding.h"
#include "common/predicted_mapping.h"
#include "common/range_coder.h"
#include "qmc/format.h"

namespace fs = std::filesystem;

static void write(const fs::path& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

// quad_connectivity input: face_count as u16, then the method-1 data.
static void write_quad_seed(const fs::path& path, const uint8_t* payload, size_t size) {
  qmc::ByteReader in(payload, size);
  uint8_t method = 0;
  uint64_t vertices = 0, faces = 0;
  if (!in.get_u8(&method) || method != 1 || !in.get_varint(&vertices) || !in.get_varint(&faces) || faces > 0xFFFF)
    return;
  std::vector<uint8_t> seed{uint8_t(faces), uint8_t(faces >> 8)};
  seed.insert(seed.end(), in.cursor(), in.cursor() + in.remaining());
  write(path, seed.data(), seed.size());
}

// polygon_connectivity input: vertex and face counts as u16, then the
// method-2 data.
static void write_polygon_seed(const fs::path& path, const uint8_t* payload, size_t size) {
  qmc::ByteReader in(payload, size);
  uint8_t method = 0;
  uint64_t vertices = 0, faces = 0;
  if (!in.get_u8(&method) || method != 2 || !in.get_varint(&vertices) || !in.get_varint(&faces) ||
      vertices > 0xFFFF || faces > 0xFFFF)
    return;
  std::vector<uint8_t> seed{uint8_t(vertices), uint8_t(vertices >> 8), uint8_t(faces), uint8_t(faces >> 8)};
  seed.insert(seed.end(), in.cursor(), in.cursor() + in.remaining());
  write(path, seed.data(), seed.size());
  // polygon_coding7 and polygon_coding8 input: the same counts, then what
  // follows the flags and coding bytes of coding 7 or 8 (5.4.10), whose
  // layouts are the same.
  uint8_t flags = 0, coding = 0;
  if (!in.get_u8(&flags) || !in.get_u8(&coding) || !qmc::is_context_coding(coding)) return;
  seed.resize(4);
  seed.insert(seed.end(), in.cursor(), in.cursor() + in.remaining());
  for (const char* target : {"polygon_coding7", "polygon_coding8"})
    write(path.parent_path().parent_path() / target / path.filename(), seed.data(), seed.size());
}

// What gim_plane needs of a GIMG payload (spec 13.2): size, sample format
// and flags; `usable` when the size fits the target's 6-bit fields.
struct GimPlaneHeader {
  bool usable = false;
  uint8_t width_minus_1 = 0, height_minus_1 = 0, target_flags = 0;
};

static GimPlaneHeader read_gim_plane_header(const uint8_t* payload, size_t size) {
  qmc::ByteReader in(payload, size);
  uint64_t width = 0, height = 0;
  uint8_t format = 0, face_mode = 0, flags = 0;
  GimPlaneHeader h;
  if (!in.get_varint(&width) || !in.get_varint(&height) || !in.get_u8(&format) || !in.get_u8(&face_mode) ||
      !in.get_u8(&flags) || width < 1 || width > 64 || height < 1 || height > 64)
    return h;
  h.usable = true;
  h.width_minus_1 = uint8_t(width - 1);
  h.height_minus_1 = uint8_t(height - 1);
  // target flags: bit 0 float32 (format 1), bit 1 blank pixels stored, bit 2 mask present
  h.target_flags = uint8_t((format == 1 ? 1 : 0) | (flags & 2) | ((flags & 1) << 2));
  return h;
}

// gim_plane input: width - 1, height - 1, flags, [u16le mask length, mask],
// then the plane payload.
static void write_gim_plane_seed(const fs::path& path, const GimPlaneHeader& h, const std::vector<uint8_t>& mask,
                                 const uint8_t* plane, size_t size) {
  if (!h.usable || mask.size() > 0xFFFF) return;
  std::vector<uint8_t> seed{h.width_minus_1, h.height_minus_1, h.target_flags};
  if (h.target_flags & 4) {
    seed.insert(seed.end(), {uint8_t(mask.size()), uint8_t(mask.size() >> 8)});
    seed.insert(seed.end(), mask.begin(), mask.end());
  }
  seed.insert(seed.end(), plane, plane + size);
  write(path, seed.data(), seed.size());
}

// predicted_mapping input (fuzz/predicted_mapping_fuzzer.cc): soups of a few
// dozen faces with seams (a vertex's corners split between two values),
// values shared between vertices and values given per face, coded by the
// encoder's template (spec 15.11). No vector holds such a soup.
// A small linear congruential generator: seeds the same on every platform.
struct SeedRandom {
  uint32_t state;
  uint32_t operator()(uint32_t below) {
    state = state * 1103515245u + 12345u;
    return (state >> 8) % below;
  }
};

static void write_predicted_mapping_seeds(const fs::path& dir) {
  SeedRandom next{12345};
  for (int seed = 0; seed < 12; ++seed) {
    const uint32_t vertices = 6 + 5 * uint32_t(seed), faces = 8 + 7 * uint32_t(seed);
    std::vector<uint8_t> input{uint8_t(vertices - 1), uint8_t(faces - 1), 0, 0};
    std::vector<uint32_t> sizes, corners;
    for (uint32_t f = 0; f < faces; ++f) {
      const uint32_t degree = 3 + next(seed % 3 == 0 ? 1 : 3);
      input.push_back(uint8_t(degree - 3));
      sizes.push_back(degree);
      for (uint32_t i = 0; i < degree; ++i) {
        corners.push_back(next(vertices));
        input.push_back(uint8_t(corners.back()));
      }
    }
    // By first reference: per face (seed % 4 == 3), else the vertex's value,
    // a second one on some vertices (a seam), now and then any value met.
    std::vector<uint32_t> m, first(vertices, UINT32_MAX), second(vertices, UINT32_MAX);
    uint32_t met = 0;
    size_t k = 0;
    for (uint32_t f = 0; f < faces; ++f) {
      const uint32_t face_value = met;
      for (uint32_t i = 0; i < sizes[f]; ++i, ++k) {
        const uint32_t v = corners[k];
        uint32_t x;
        if (seed % 4 == 3) {
          x = face_value;
        } else if (met > 0 && next(16) == 0) {
          x = next(met);
        } else {
          uint32_t& slot = (v % 5 == 0 && f % 2 == 1) ? second[v] : first[v];
          x = slot == UINT32_MAX ? met : slot;
          slot = x;
        }
        if (x == met) ++met;
        m.push_back(x);
      }
    }
    input[2] = uint8_t(met);
    input[3] = uint8_t(met >> 8);
    const std::vector<uint8_t> single = qmc::single_value_vertices(corners, m, vertices);
    qmc::RangeEncoder rc;
    qmc::PredictedMappingModel model;
    qmc::PredictedMapping mapping;
    mapping.reset(vertices, sizes, corners);
    uint32_t coded = 0;
    for (size_t j = 0; j < m.size(); ++j) {
      qmc::MappingFault fault = qmc::MappingFault::kNone;
      mapping.code(&rc, &model, j, met, &coded, m.data(), &single, &fault);
    }
    const std::vector<uint8_t> stream = rc.finish();
    input.insert(input.end(), stream.begin(), stream.end());
    write(dir / ("soup_" + std::to_string(seed)), input.data(), input.size());
  }
}

// level_corrections input: the count byte, then a code-4 stream over the
// octahedron of the target (12 edges, a level of 18 vertices): displacements,
// then C corrections of pseudo-random gaps and offsets of every size.
static void write_level_corrections_seeds(const fs::path& dir) {
  SeedRandom next{777};
  for (uint32_t seed = 0; seed < 20; ++seed) {
    qmc::RangeEncoder rc;
    qmc::DisplacementModel displacements;
    for (int e = 0; e < 12; ++e)
      qmc::code_displacement(&rc, &displacements, qmc::DisplacementContext(0, 0, 0), int(next(9)) - 4);
    qmc::CorrectionModel corrections;
    const int32_t none[3] = {0, 0, 0};
    int32_t previous[3] = {0, 0, 0};
    uint32_t vertex = 0;
    const uint32_t count = seed % 19;
    for (uint32_t i = 0; i < count; ++i) {
      const uint32_t room = 18 - (i == 0 ? 0 : vertex + 1) - (count - 1 - i);
      const uint32_t gap = next(room);
      qmc::code_correction_gap(&rc, &corrections, gap);
      vertex = i == 0 ? gap : vertex + 1 + gap;
      int32_t offset[3];
      for (int a = 0; a < 3; ++a) {
        offset[a] = int32_t(next(1u << (1 + next(15)))) * (next(2) ? -1 : 1);
        qmc::code_correction_offset(&rc, &corrections, qmc::correction_bucket(i == 0 ? none : previous, offset, a), a,
                                    offset[a]);
      }
      std::copy(offset, offset + 3, previous);
    }
    std::vector<uint8_t> input{uint8_t(count)};
    const std::vector<uint8_t> stream = rc.finish();
    input.insert(input.end(), stream.begin(), stream.end());
    write(dir / ("corrections_" + std::to_string(seed)), input.data(), input.size());
  }
}

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_seeds VECTORS_DIR OUT_DIR\n");
    return 2;
  }
  const fs::path out = argv[2];
  for (const char* t : {"decode_file", "stream_decoder", "connectivity", "quad_connectivity", "polygon_connectivity", "polygon_coding7", "polygon_coding8", "positions",
                        "predicted_positions", "geometry_order",
                        "huffman", "roundtrip", "order", "loop_levels", "gim_file", "gim_plane", "attributes", "face_labels",
                        "predicted_mapping", "attribute_twins", "level_corrections", "c_api"})
    fs::create_directories(out / t);
  write_predicted_mapping_seeds(out / "predicted_mapping");
  write_level_corrections_seeds(out / "level_corrections");
  int n = 0;
  for (const auto& entry : fs::directory_iterator(argv[1])) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string name = entry.path().stem().string();
    write(out / "decode_file" / name, bytes.data(), bytes.size());
    write(out / "c_api" / name, bytes.data(), bytes.size());
    std::vector<uint8_t> streamed{uint8_t(n)};
    streamed.insert(streamed.end(), bytes.begin(), bytes.end());
    write(out / "stream_decoder" / name, streamed.data(), streamed.size());
    write(out / "roundtrip" / name, bytes.data(), bytes.size());
    // Walk the chunks as far as the framing allows; invalid vectors stop early.
    std::vector<uint8_t> conn;  // order input: CONN length as u16, CONN payload, oRDR payload
    std::vector<uint8_t> levels;  // loop_levels input: u16le-prefixed CONN, POSN, LEVL payloads
    bool progressive = false;
    std::vector<uint8_t> gim;  // gim_file input: selector byte, u16le length, payload per GIM chunk
    GimPlaneHeader gim_header;
    std::vector<uint8_t> gim_mask;
    int gim_planes = 0;
    for (size_t pos = 8; pos + 12 <= bytes.size();) {
      const uint32_t type = qmc::load_u32be(&bytes[pos]);
      const uint32_t length = qmc::load_u32le(&bytes[pos + 4]);
      if (length > bytes.size() - pos - 12) break;
      const uint8_t* payload = &bytes[pos + 8];
      if (type == qmc::kChunkConnectivity) {
        write(out / "connectivity" / name, payload, length);
        write_quad_seed(out / "quad_connectivity" / name, payload, length);
        write_polygon_seed(out / "polygon_connectivity" / name, payload, length);
        if (length > 3) {  // the bit stream starts with the degree table
          std::vector<uint8_t> h{33};
          h.insert(h.end(), payload + 3, payload + length);
          write(out / "huffman" / name, h.data(), h.size());
        }
      }
      if (type == qmc::kChunkPositions) {
        write(out / "positions" / name, payload, length);
        if (!conn.empty()) {  // predicted_positions input: u16le CONN length, CONN, POSN
          std::vector<uint8_t> pair{uint8_t(conn.size()), uint8_t(conn.size() >> 8)};
          pair.insert(pair.end(), conn.begin(), conn.end());
          pair.insert(pair.end(), payload, payload + length);
          write(out / "predicted_positions" / name, pair.data(), pair.size());
          write(out / "geometry_order" / name, pair.data(), pair.size());
        }
      }
      if (type == qmc::kChunkConnectivity && length <= 0xFFFF) conn.assign(payload, payload + length);
      if (type == qmc::kChunkLoop) progressive = true;
      if (progressive && length <= 0xFFFF &&
          (type == qmc::kChunkConnectivity || type == qmc::kChunkPositions || type == qmc::kChunkLevel)) {
        levels.push_back(uint8_t(length));
        levels.push_back(uint8_t(length >> 8));
        levels.insert(levels.end(), payload, payload + length);
      }
      const uint32_t gim_types[] = {qmc::kChunkGeometryImage, qmc::kChunkGimMask, qmc::kChunkGimSeams,
                                    qmc::kChunkGimFaces, qmc::kChunkGimPlane};
      for (uint8_t k = 0; k < 5; ++k)
        if (type == gim_types[k] && length <= 0xFFFF) {
          gim.insert(gim.end(), {k, uint8_t(length), uint8_t(length >> 8)});
          gim.insert(gim.end(), payload, payload + length);
        }
      if (type == qmc::kChunkGeometryImage) gim_header = read_gim_plane_header(payload, length);
      if (type == qmc::kChunkGimMask) gim_mask.assign(payload, payload + length);
      if (type == qmc::kChunkGimPlane)
        write_gim_plane_seed(out / "gim_plane" / (name + "_plane" + std::to_string(gim_planes++)), gim_header, gim_mask,
                             payload, length);
      if (type == qmc::kChunkAttribute && !conn.empty()) {  // attributes input: as order's
        std::vector<uint8_t> seed{uint8_t(conn.size()), uint8_t(conn.size() >> 8)};
        seed.insert(seed.end(), conn.begin(), conn.end());
        seed.insert(seed.end(), payload, payload + length);
        write(out / "attributes" / (name + "_" + std::to_string(pos)), seed.data(), seed.size());
        write(out / "attribute_twins" / (name + "_" + std::to_string(pos)), seed.data(), seed.size());
      }
      if (type == qmc::kChunkFaceLabels && length <= 0xFFFF) {  // face_labels input: u16le F, the payload
        qmc::ByteReader r(payload, length);
        uint64_t faces = 0;
        if (r.get_varint(&faces) && faces <= 0xFFFF) {
          std::vector<uint8_t> seed{uint8_t(faces), uint8_t(faces >> 8)};
          seed.insert(seed.end(), payload, payload + length);
          write(out / "face_labels" / (name + "_" + std::to_string(pos)), seed.data(), seed.size());
        }
      }
      if (type == qmc::kChunkOrder && !conn.empty()) {
        std::vector<uint8_t> seed{uint8_t(conn.size()), uint8_t(conn.size() >> 8)};
        seed.insert(seed.end(), conn.begin(), conn.end());
        seed.insert(seed.end(), payload, payload + length);
        write(out / "order" / name, seed.data(), seed.size());
      }
      pos += 12 + size_t(length);
    }
    if (!levels.empty()) write(out / "loop_levels" / name, levels.data(), levels.size());
    if (!gim.empty()) write(out / "gim_file" / name, gim.data(), gim.size());
    ++n;
  }
  std::printf("seeds from %d vectors in %s\n", n, argv[2]);
  return 0;
}
