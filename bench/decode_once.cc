// qmc bench: one decode of a .qmc file in this (fresh) process, as `qmc
// decode` or a viewer opening its first file does it, then REPEAT more in
// the same process. Prints the first decode's milliseconds and minor page
// faults, and the median of the repeats. Run it in a loop: each run is a new
// process, so the first decode always starts from an empty heap.
//
//   qmc_decode_once FILE.qmc [REPEAT]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "first_and_repeats.h"
#include "qmc/decoder.h"

namespace {

// Only the decoder library: the same source builds against any revision's.
[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "qmc_decode_once: %s\n", message.c_str());
  std::exit(3);
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// Milliseconds of one decode; exits on a decoding error.
double decode_ms(const std::vector<uint8_t>& file) {
  qmc::DecodedFile out;
  const auto start = std::chrono::steady_clock::now();
  const qmc::Status status = qmc::decode(file.data(), file.size(), &out, qmc::DecoderLimits::unlimited());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!status.ok()) fail(status.to_string());
  return ms;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) fail("usage: qmc_decode_once FILE.qmc [REPEAT]");
  std::ifstream in(argv[1], std::ios::binary);
  if (!in) fail(std::string("cannot read ") + argv[1]);
  const std::vector<uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const int repeat = argc == 3 ? std::atoi(argv[2]) : 0;
  const qmc::bench::FirstAndRepeats t = qmc::bench::first_and_repeats(repeat, [&] { return decode_ms(file); });
  std::printf("first %.3f ms, %ld minor faults; repeats median %.3f ms\n", t.first_ms, t.first_faults,
              median(t.repeat_ms));
  return 0;
}
