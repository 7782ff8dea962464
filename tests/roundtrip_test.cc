// Round trips: every corpus mesh (../shared/corpus, skipped with a message
// when absent) and thousands of generated polygon soups. The decoded faces
// must equal the input's after the relabelling of spec 5.2.1 and every
// coordinate must lie within half a quantization step.
#include <gtest/gtest.h>

#include <filesystem>

#include "mesh_generators.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"
#include "corpus_dir.h"

namespace qmc {
namespace {

namespace fs = std::filesystem;

using testing::corpus_dir;

std::vector<fs::path> corpus_files() {
  std::vector<fs::path> files;
  for (const char* sub : {"quad", "tri"}) {
    const fs::path dir = corpus_dir() / sub;
    if (!fs::is_directory(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

tools::RoundTripReport encode_decode(const Mesh& mesh, int bits, size_t* bytes_out = nullptr) {
  EncodeOptions o;
  o.position_bits = bits;
  std::vector<uint8_t> bytes;
  Status s = encode(mesh, o, &bytes);
  EXPECT_TRUE(s.ok()) << s.to_string();
  if (bytes_out) *bytes_out = bytes.size();
  DecodedFile d;
  s = decode(bytes.data(), bytes.size(), &d);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return tools::check_round_trip(mesh, d);
}

TEST(CorpusRoundTrip, EveryCorpusMesh) {
  const std::vector<fs::path> files = corpus_files();
  if (files.empty()) GTEST_SKIP() << "corpus not found at " << corpus_dir() << " (set QMC_CORPUS_DIR)";
  EXPECT_GE(files.size(), 21u);
  for (const fs::path& path : files) {
    Mesh mesh;
    std::vector<std::string> warnings;
    const Status read = tools::read_mesh(path.string(), &mesh, &warnings);
    ASSERT_TRUE(read.ok()) << read.to_string();
    for (int bits : {8, 12, 16}) {
      size_t bytes = 0;
      const tools::RoundTripReport r = encode_decode(mesh, bits, &bytes);
      EXPECT_TRUE(r.faces_equal) << path << ": " << r.face_mismatch;
      EXPECT_TRUE(r.positions_within_bound) << path << " at " << bits << " bits: " << r.position_mismatch;
      if (bits == 12) {
        EXPECT_LT(r.max_error, r.max_bbox_side / 4096) << path;
      }
    }
  }
}

TEST(GeneratedRoundTrip, ThousandsOfRandomSoups) {
  for (uint64_t seed = 1; seed <= 2000; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = uint32_t(1 + seed % 97);
    o.faces = uint32_t(seed % 131);
    o.unreferenced = uint32_t(seed % 5);
    o.min_degree = 3;
    o.max_degree = uint32_t(3 + seed % 9);
    const Mesh mesh = tools::make_random_soup(seed, o);
    const tools::RoundTripReport r = encode_decode(mesh, int(1 + seed % 30));
    ASSERT_TRUE(r.ok()) << "seed " << seed << ": " << r.face_mismatch << r.position_mismatch;
  }
}

TEST(GeneratedRoundTrip, LargeSoupExercisesLongBackReferences) {
  tools::RandomSoupOptions o;
  o.vertices = 200000;
  o.faces = 150000;
  const Mesh mesh = tools::make_random_soup(99, o);
  EXPECT_TRUE(encode_decode(mesh, 20).ok());
}

TEST(GeneratedRoundTrip, RegularMeshes) {
  for (const Mesh& m : {tools::make_tetrahedron(), tools::make_cube(), tools::make_quad_sphere(10),
                        tools::make_torus(30, 12), tools::make_grid(17, 9), tools::make_prism(3),
                        tools::make_prism(64)})
    EXPECT_TRUE(encode_decode(m, 12).ok());
}

}  // namespace
}  // namespace qmc
