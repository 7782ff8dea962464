// Every committed fuzz regression input and conformance vector goes through
// the decoder, whole and streamed byte by byte: each must either decode or
// be rejected with an error, the same way both times (spec 3.5, 9).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "qmc/decoder.h"

namespace qmc {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void check_consistent(const fs::path& path) {
  const std::vector<uint8_t> bytes = read_bytes(path);
  DecodedFile whole;
  const Status a = decode(bytes.data(), bytes.size(), &whole);
  StreamDecoder s;
  Status b;
  for (size_t i = 0; i < bytes.size() && b.ok(); ++i) b = s.feed(&bytes[i], 1);
  if (b.ok()) b = s.finish();
  EXPECT_EQ(a.code(), b.code()) << path << ": " << a.to_string() << " vs " << b.to_string();
  if (a.ok() && b.ok()) {
    EXPECT_EQ(canonical_output(whole), canonical_output(s.file())) << path;
  }
  if (!a.ok()) {
    EXPECT_FALSE(a.message().empty()) << path;
  }
}

TEST(DecoderRobustness, FuzzRegressionsAndConformanceVectors) {
  size_t checked = 0;
  for (const char* dir : {"fuzz/regressions", "conformance/vectors"}) {
    const fs::path root = fs::path(QMC_SOURCE_DIR) / dir;
    if (!fs::is_directory(root)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (!e.is_regular_file()) continue;
      check_consistent(e.path());
      ++checked;
    }
  }
  EXPECT_GT(checked, 30u);
}

TEST(DecoderRobustness, RandomBytesAfterTheSignatureAreRejectedCleanly) {
  uint64_t state = 12345;
  for (int round = 0; round < 20000; ++round) {
    std::vector<uint8_t> bytes(kSignature, kSignature + 8);
    const size_t n = size_t(round % 64);
    for (size_t i = 0; i < n; ++i) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      bytes.push_back(uint8_t(state >> 56));
    }
    DecodedFile f;
    const Status s = decode(bytes.data(), bytes.size(), &f);
    EXPECT_FALSE(s.ok());
  }
}

}  // namespace
}  // namespace qmc
