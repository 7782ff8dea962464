// qmc bench: encodes of one mesh in this process, read as the compression
// benchmark reads it (positions and faces, unused vertices dropped), with
// qmc::encode's default options at BITS. Prints the first encode's
// milliseconds and minor page faults, then the median and the least of
// REPEAT more, and the file's bytes. Built at two revisions and run in turns,
// it compares an encoder change on the same moments of the machine
// (docs/results/decode_profile.md).
//
// A process that only encodes gives its memory back between encodes and
// faults it in again; the benchmark's process does not. To time the encoder
// alone, keep the allocator's memory:
//   GLIBC_TUNABLES=glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=1073741824
//
// START_FACES: EncodeOptions::start_faces (default 1).
//
//   qmc_encode_once MESH BITS [REPEAT [START_FACES]]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_common.h"
#include "first_and_repeats.h"
#include "qmc/encoder.h"

namespace {

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "qmc_encode_once: %s\n", message.c_str());
  std::exit(3);
}

// Milliseconds of one encode; exits on an encoding error.
double encode_ms(const qmc::Mesh& mesh, const qmc::EncodeOptions& options, size_t* bytes) {
  std::vector<uint8_t> out;
  qmc::EncodeStats stats;
  const auto start = std::chrono::steady_clock::now();
  const qmc::Status status = qmc::encode(mesh, options, &out, &stats);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!status.ok()) fail(status.to_string());
  *bytes = out.size();
  return ms;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 5) fail("usage: qmc_encode_once MESH BITS [REPEAT [START_FACES]]");
  qmc::Mesh mesh;
  std::vector<std::string> notes;
  if (const qmc::Status s = qmc::bench::read_geometry(argv[1], &mesh, &notes); !s.ok()) fail(s.to_string());
  qmc::bench::drop_unused_vertices(&mesh);
  qmc::EncodeOptions options;
  options.position_bits = std::atoi(argv[2]);
  const int repeat = argc >= 4 ? std::atoi(argv[3]) : 0;
  if (argc == 5) options.start_faces = uint32_t(std::atoi(argv[4]));
  size_t bytes = 0;
  const qmc::bench::FirstAndRepeats t =
      qmc::bench::first_and_repeats(repeat, [&] { return encode_ms(mesh, options, &bytes); });
  const double least = t.repeat_ms.empty() ? 0.0 : *std::min_element(t.repeat_ms.begin(), t.repeat_ms.end());
  std::printf("first %.3f ms, %ld minor faults; repeats median %.3f ms, least %.3f ms; %zu bytes\n", t.first_ms,
              t.first_faults, qmc::bench::median(t.repeat_ms), least, bytes);
  return 0;
}
