// libFuzzer target: a polygon soup built from the input goes through the
// encoder and back; the decoded faces must match the input's under the
// file's correspondence (spec 5.2.1, 5.3.4) and the encoder must accept every
// valid soup, from any of the first faces EncodeOptions::start_faces tries. Small soups are often pure-quad disks, so both connectivity
// methods are exercised.
#include <cstddef>
#include <cstdint>

#include "qmc/decoder.h"
#include "qmc/encoder.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const uint32_t vertices = uint32_t(data[0]) + 1;
  const int bits = 1 + data[1] % 30;
  qmc::Mesh mesh;
  for (uint32_t v = 0; v < vertices; ++v)
    for (int a = 0; a < 3; ++a) mesh.positions.push_back(float(int(v * 7 + a * 13) % 101) - 50.f);
  for (size_t pos = 2; pos < size;) {
    const uint32_t degree = 3 + data[pos++] % 6;
    if (pos + degree > size) break;
    mesh.face_sizes.push_back(degree);
    for (uint32_t i = 0; i < degree; ++i) mesh.corners.push_back(data[pos++] % vertices);
  }
  qmc::EncodeOptions options;
  options.position_bits = bits;
  // The polygon coder from up to 4 first faces (5.4.2), the smallest kept.
  options.start_faces = 1 + (data[1] / 30) % 4;
  std::vector<uint8_t> bytes;
  qmc::EncodeStats stats;
  if (!qmc::encode(mesh, options, &bytes, &stats).ok()) __builtin_trap();
  qmc::DecodedFile file;
  if (!qmc::decode(bytes.data(), bytes.size(), &file).ok()) __builtin_trap();
  // Faces come back in the file's order (spec 5.2.1, 5.3.4): decoded face f
  // is input face face_source[f], possibly starting at another corner.
  if (file.mesh.face_count() != mesh.face_count() || stats.face_source.size() != mesh.face_count()) __builtin_trap();
  std::vector<size_t> first(mesh.face_count() + 1, 0);
  for (size_t f = 0; f < mesh.face_count(); ++f) first[f + 1] = first[f] + mesh.face_sizes[f];
  size_t k = 0;
  for (size_t f = 0; f < file.mesh.face_count(); ++f) {
    const uint32_t source = stats.face_source[f], n = file.mesh.face_sizes[f];
    if (source >= mesh.face_count() || mesh.face_sizes[source] != n) __builtin_trap();
    bool matched = false;
    for (uint32_t r = 0; r < n && !matched; ++r) {
      matched = true;
      for (uint32_t i = 0; i < n && matched; ++i)
        matched = stats.file_vertex[file.mesh.corners[k + i]] == mesh.corners[first[source] + (i + r) % n];
    }
    if (!matched) __builtin_trap();
    k += n;
  }
  return 0;
}
