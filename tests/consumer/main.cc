// Decodes a .qmc file with nothing but qmc::decoder.
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include <qmc/decoder.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::ifstream in(argv[1], std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  qmc::DecodedFile file;
  const qmc::Status s = qmc::decode(bytes.data(), bytes.size(), &file);
  if (!s.ok()) {
    std::fprintf(stderr, "%s\n", s.to_string().c_str());
    return 1;
  }
  std::printf("%zu vertices, %zu faces\n", file.mesh.vertex_count(), file.mesh.face_count());
  return 0;
}
