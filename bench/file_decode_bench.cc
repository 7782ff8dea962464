// qmc bench: decode time of a .qmc file against a Draco file of the same
// mesh, both read from memory in this process, in interleaved rounds (each
// round decodes one, then the other), so that both see the same moments of
// a noisy machine. For files with attributes (docs/results/attributes.md),
// which the in-memory runner of compression.md does not carry.
//
//   qmc_file_decode_bench [--runs N] A.qmc A.drc [B.qmc B.drc ...]
//
// Prints one line per pair: the median milliseconds of qmc::decode and of
// Draco's DecodeMeshFromBuffer, and Draco's / qmc's (the speed-up). A sample
// is the mean of enough back-to-back decodes to last 2 ms, as the clock
// cannot time a small mesh's one decode; one untimed decode of each file
// first sets that number and warms the caches.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "draco/compression/decode.h"
#include "qmc/decoder.h"

namespace {

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "qmc_file_decode_bench: %s\n", message.c_str());
  std::exit(3);
}

std::vector<char> read_file(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(std::string("cannot read ") + path);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

void decode_qmc(const std::vector<char>& file) {
  qmc::DecodedFile out;
  const qmc::Status s = qmc::decode(reinterpret_cast<const uint8_t*>(file.data()), file.size(), &out,
                                    qmc::DecoderLimits::unlimited());
  if (!s.ok()) fail("qmc: " + s.to_string());
}

void decode_draco(const std::vector<char>& file) {
  draco::DecoderBuffer buffer;
  buffer.Init(file.data(), file.size());
  draco::Decoder decoder;
  auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  if (!mesh.ok()) fail(std::string("Draco: ") + mesh.status().error_msg());
}

// Milliseconds per decode: the mean of `repeat` back-to-back decodes.
template <class Decode>
double sample_ms(Decode decode, const std::vector<char>& file, int repeat) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeat; ++i) decode(file);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / repeat;
}

// How many back-to-back decodes last 2 ms, from one timed decode.
template <class Decode>
int repeats_for_2ms(Decode decode, const std::vector<char>& file) {
  const double one = sample_ms(decode, file, 1);
  return std::max(1, int(2.0 / std::max(one, 1e-4)));
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 7, first = 1;
  if (argc > 2 && std::string(argv[1]) == "--runs") {
    runs = std::atoi(argv[2]);
    first = 3;
  }
  if (runs < 1 || argc <= first || (argc - first) % 2 != 0)
    fail("usage: qmc_file_decode_bench [--runs N] A.qmc A.drc [B.qmc B.drc ...]");
  for (int i = first; i < argc; i += 2) {
    const std::vector<char> qmc_file = read_file(argv[i]), draco_file = read_file(argv[i + 1]);
    const int qmc_repeat = repeats_for_2ms(decode_qmc, qmc_file);
    const int draco_repeat = repeats_for_2ms(decode_draco, draco_file);
    std::vector<double> qmc_ms, draco_ms;
    for (int r = 0; r < runs; ++r) {
      qmc_ms.push_back(sample_ms(decode_qmc, qmc_file, qmc_repeat));
      draco_ms.push_back(sample_ms(decode_draco, draco_file, draco_repeat));
    }
    const double q = median(qmc_ms), d = median(draco_ms);
    std::printf("%s %s qmc_ms %.4f draco_ms %.4f speedup %.3f\n", argv[i], argv[i + 1], q, d, d / q);
  }
  return 0;
}
