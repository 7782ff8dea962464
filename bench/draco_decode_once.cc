// qmc bench: bench/decode_once.cc for a Draco file. One decode of a .drc
// file in this (fresh) process, then REPEAT more in the same process, by
// Draco's DecodeMeshFromBuffer; prints the first decode's milliseconds and
// minor page faults and the median of the repeats, in qmc_decode_once's
// words, so that the two run in turns compare the codecs under the same
// allocator (docs/results/decode_profile.md).
//
//   qmc_draco_decode_once FILE.drc [REPEAT]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "bench_common.h"
#include "first_and_repeats.h"
#include "draco/compression/decode.h"

namespace {

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "qmc_draco_decode_once: %s\n", message.c_str());
  std::exit(3);
}

// Milliseconds of one decode, the mesh freed after the clock stops; exits on
// a decoding error.
double decode_ms(const std::vector<char>& file) {
  const auto start = std::chrono::steady_clock::now();
  draco::DecoderBuffer buffer;
  buffer.Init(file.data(), file.size());
  draco::Decoder decoder;
  auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!mesh.ok()) fail(mesh.status().error_msg_string());
  return ms;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) fail("usage: qmc_draco_decode_once FILE.drc [REPEAT]");
  std::ifstream in(argv[1], std::ios::binary);
  if (!in) fail(std::string("cannot read ") + argv[1]);
  const std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int repeat = argc == 3 ? std::atoi(argv[2]) : 0;
  const qmc::bench::FirstAndRepeats t = qmc::bench::first_and_repeats(repeat, [&] { return decode_ms(file); });
  std::printf("first %.3f ms, %ld minor faults; repeats median %.3f ms\n", t.first_ms, t.first_faults,
              qmc::bench::median(t.repeat_ms));
  return 0;
}
