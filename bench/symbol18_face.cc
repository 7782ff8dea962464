// A crafted, invalid file for spec 8.1's check of symbol 18's corners
// (docs/results/hardening.md): QHDR 1.18, a CONN of polygon coding 7
// (5.4.10) whose one component is a pentagon and one face of symbol 18 with
// D corners, every status an anchor and every gap an edge (decisions the
// counted probabilities make nearly free: some 180 corners a byte), QEND.
// Spirale Reversi cannot apply such a face (the anchors are not there); the
// question is what the decoder reserves before it finds out.
// Usage: qmc_symbol18_face D OUT.qmc
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "chunk_list.h"
#include "polygon_payloads.h"
#include "qmc/format.h"

namespace {

std::vector<uint8_t> conn_payload(uint64_t d) {
  // Symbol 18 is the only group, so it costs no decision.
  const std::vector<uint8_t> symbols =
      qmc::tools::coding7_symbols(qmc::kGroupOther, [d](qmc::RangeEncoder* range, qmc::PolygonSymbolModel* model) {
        uint32_t extra = uint32_t(d - 5);
        qmc::code_other_degree(range, &extra);
        std::vector<uint8_t> anchors(d - 2, 1), edges(d - 1, 1);
        qmc::code_other_shape(range, model, uint32_t(d - 2), anchors.data(), edges.data());
      });
  return qmc::tools::coding7_conn(8, 2, qmc::kGroupOther, symbols, [](qmc::BitWriter* stream) {
    for (uint32_t v : {1, 0, 2, 0, 0, 0, 0}) stream->write_exp_golomb(v);  // C = 1, n - 2, d - 3, H, S, I, L
  });
}

}  // namespace

int main(int argc, char** argv) {
  const uint64_t d = argc == 3 ? std::strtoull(argv[1], nullptr, 10) : 0;
  if (d < 5 || d > UINT32_MAX) {
    std::fprintf(stderr, "usage: qmc_symbol18_face D OUT.qmc (5 <= D < 2^32)\n");
    return 2;
  }
  const std::vector<uint8_t> file = qmc::tools::join_chunks(
      {{qmc::kChunkHeader, {1, 18}}, {qmc::kChunkConnectivity, conn_payload(d)}, {qmc::kChunkEnd, {}}});
  FILE* out = std::fopen(argv[2], "wb");
  if (out == nullptr || std::fwrite(file.data(), 1, file.size(), out) != file.size() || std::fclose(out) != 0) {
    std::perror(argv[2]);
    return 3;
  }
  std::printf("%s: %zu bytes, one face of %llu corners\n", argv[2], file.size(), (unsigned long long)d);
  return 0;
}
