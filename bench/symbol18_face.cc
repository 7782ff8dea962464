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
#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/polygon_symbol_coding.h"
#include "common/range_coder.h"
#include "qmc/format.h"

namespace {

std::vector<uint8_t> one_face_symbols(uint64_t d) {
  qmc::RangeEncoder range;
  qmc::PolygonSymbolModel model;
  model.groups = qmc::kGroupOther;  // the only group: symbol 18 costs no decision
  uint32_t extra = uint32_t(d - 5);
  qmc::code_other_degree(&range, &extra);
  std::vector<uint8_t> anchors(d - 2, 1), edges(d - 1, 1);
  qmc::code_other_shape(&range, &model, uint32_t(d - 2), anchors.data(), edges.data());
  return range.finish();
}

std::vector<uint8_t> conn_payload(uint64_t d) {
  const std::vector<uint8_t> symbols = one_face_symbols(d);
  std::vector<uint8_t> conn{uint8_t(qmc::ConnectivityMethod::kPolygon), 8, 2, 0, qmc::kPolygonContextCoded,
                            qmc::kGroupOther};  // V 8, F 2, flags, coding 7, groups
  qmc::put_varint(&conn, symbols.size());
  conn.insert(conn.end(), symbols.begin(), symbols.end());
  qmc::BitWriter stream;
  for (uint32_t v : {1, 0, 2, 0, 0, 0, 0}) stream.write_exp_golomb(v);  // C = 1, n - 2, d - 3, H, S, I, L
  const std::vector<uint8_t> bits = stream.finish();
  conn.insert(conn.end(), bits.begin(), bits.end());
  return conn;
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
