// Decodes every vector of a conformance MANIFEST (spec 10.1) with the decoder
// compiled however the embedder's build compiles it, and checks each result:
// the SHA-256 of the canonical output, or the rejection's identifier.
// Prints "N passed, N failed" and exits non-zero on any failure.
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "qmc/decoder.h"
#include "sha256.h"

namespace {

bool check(const std::string& dir, const std::string& kind, const std::string& path, const std::string& expected) {
  std::ifstream in(dir + "/" + path, std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  qmc::DecodedFile file;
  const qmc::Status s = qmc::decode(bytes.data(), bytes.size(), &file);
  std::string got;
  if (kind == "valid") {
    const std::vector<uint8_t> canonical = qmc::canonical_output(file);
    got = s.ok() ? qmc::tools::sha256_hex(canonical.data(), canonical.size()) : s.to_string();
  } else {
    got = s.ok() ? "accepted" : qmc::error_code_name(s.code());
  }
  if (got == expected) return true;
  std::printf("FAIL %s: expected %s, got %s\n", path.c_str(), expected.c_str(), got.c_str());
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: check_vectors CONFORMANCE_DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  std::ifstream manifest(dir + "/MANIFEST");
  int passed = 0, failed = 0;
  for (std::string line; std::getline(manifest, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string kind, path, expected;
    fields >> kind >> path >> expected;
    (check(dir, kind, path, expected) ? passed : failed)++;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 && passed > 0 ? 0 : 1;
}
