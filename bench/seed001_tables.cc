// qmc_seed001: seed 001's chapter 5 experiments (Q. Jing's thesis, tables
// 5-1, 5-2, 5-3) rerun with qmc on our rebuild of its meshes -- the refined
// 60-quad sphere series and the Catmull-Clark-refined cow -- with the
// thesis's printed figures beside ours. Writes Markdown (docs/results/
// seed001.md via scripts/bench.sh).
//
// Sizes come from EncodeStats: coding_bits[c] is the exact length of the
// symbol stream under coding c, which the encoder computes to choose one, so
// all five codings are measured from a single encode.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "bench_common.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "subdivision.h"

namespace {

using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------
// The thesis's figures, transcribed exactly as printed (chapter 5). Row order
// is the thesis's: the cow sits between the 15360- and 61440-quad spheres.

constexpr int kThesisRows = 7;
constexpr int kCowRow = 5;

struct Table51Row {  // Table 5-1: times, Java on a Pentium 560
  int quads, vertices, compress_ms, decompress_ms, bytes;
  double bpv;
};
// Row 5 (the cow) prints 17414 quads and 17412 vertices, the reverse of
// table 5-2 and of the mesh; kept as printed.
constexpr Table51Row kTable51[kThesisRows] = {
    {60, 62, 280, 270, 28, 3.61},           {240, 242, 610, 610, 88, 2.91},
    {960, 962, 1320, 1100, 344, 2.86},      {3840, 3842, 3510, 4340, 1364, 2.84},
    {15360, 15362, 12090, 13350, 5440, 2.83}, {17414, 17412, 13409, 14340, 6172, 2.83},
    {61440, 61442, 44270, 47790, 21752, 2.83},
};

struct Table52Row {  // Table 5-2: connectivity under Codings I, II, III
  int quads, vertices;
  std::array<int, 3> bytes;
  std::array<double, 3> bpv;
};
constexpr Table52Row kTable52[kThesisRows] = {
    {60, 62, {28, 24, 20}, {3.61, 3.10, 2.58}},
    {240, 242, {88, 84, 72}, {2.91, 2.78, 2.38}},
    {960, 962, {344, 340, 284}, {2.86, 2.83, 2.36}},
    {3840, 3842, {1364, 1360, 1128}, {2.84, 2.83, 2.35}},
    {15360, 15362, {5440, 5436, 4493}, {2.83, 2.83, 2.34}},
    {17412, 17414, {6172, 6088, 5156}, {2.83, 2.80, 2.37}},
    {61440, 61442, {21752, 21748, 17944}, {2.83, 2.83, 2.34}},
};

struct Table53Row {  // Table 5-3: whole compressed output, 8-bit positions, Coding I
  int file_size, quads, vertices, connectivity, vertex_bin, huffman_table, bounding;
  double overall_bpv;
  const char* compression_ratio;
};
// Spheres only: the thesis gives no cow row in table 5-3.
constexpr Table53Row kTable53[] = {
    {3708, 60, 62, 28, 112, 436, 45, 10.02, "5.876"},
    {15662, 240, 242, 88, 560, 1136, 27, 7.48, "8.613"},
    {66888, 960, 962, 344, 2320, 1706, 27, 4.57, "15.196"},
    {288538, 3840, 3842, 1364, 8420, 1959, 29, 3.06, "24.50"},
    {1224604, 15360, 15362, 5440, 28876, 2035, 31, 2.33, "33.66"},
    {5197754, 61440, 61442, 21752, 93840, 2157, 31, 1.92, "44.13"},
};
constexpr int kTable53Rows = int(sizeof kTable53 / sizeof kTable53[0]);

int table53_index(int thesis_row) { return thesis_row < kCowRow ? thesis_row : thesis_row == kCowRow ? -1 : 5; }

// ---------------------------------------------------------------------------
// Small utilities

[[noreturn]] void fail(const std::string& message) { qmc::bench::fail("qmc_seed001", message); }
using qmc::bench::format;

// Median wall time in milliseconds of `runs` calls of f.
template <class F>
double median_ms(int runs, F&& f) {
  return 1e3 * qmc::bench::median_seconds(runs, f);
}

uint64_t ceil_bytes(int64_t bits) { return uint64_t(bits + 7) / 8; }
double bpv(double bytes, size_t vertices) { return qmc::bench::bits_per_vertex(bytes, vertices); }

// ---------------------------------------------------------------------------
// Meshes

struct TestMesh {
  std::string name;
  qmc::Mesh mesh;
  int thesis_row;  // index into kTable51 / kTable52
};

qmc::Mesh refined_cow(const std::string& path) {
  qmc::Mesh triangles, quads;
  if (qmc::Status s = qmc::bench::read_geometry(path, &triangles, nullptr); !s.ok()) fail(s.to_string());
  if (qmc::Status s = qmc::tools::catmull_clark(triangles, &quads); !s.ok()) fail(path + ": " + s.to_string());
  return quads;
}

std::vector<TestMesh> thesis_meshes(const std::string& cow_path) {
  std::vector<TestMesh> meshes;
  for (int level = 0; level <= 5; ++level) {
    const int row = level < kCowRow ? level : kThesisRows - 1;
    meshes.push_back({format("sphere %d", level), qmc::tools::make_refined_sphere(level), row});
  }
  meshes.insert(meshes.begin() + kCowRow, TestMesh{"cow, 1 CC step", refined_cow(cow_path), kCowRow});
  return meshes;
}

// "3:20 4:61410 5:12": how many vertices have each valence (faces around).
std::string valence_histogram(const qmc::Mesh& mesh) {
  std::vector<uint32_t> valence(mesh.vertex_count(), 0);
  for (uint32_t v : mesh.corners) ++valence[v];
  std::map<uint32_t, size_t> count;
  for (uint32_t d : valence) ++count[d];
  std::string out;
  for (const auto& [d, n] : count) out += format("%s%u:%zu", out.empty() ? "" : " ", d, n);
  return out;
}

// ---------------------------------------------------------------------------
// Measurement

struct Measurement {
  size_t quads = 0, vertices = 0;
  qmc::EncodeStats stats;
  uint64_t conn_bytes = 0, posn_bytes = 0;
  double encode_ms = 0, decode_ms = 0, conn_decode_ms = 0;
};

uint64_t chunk_bytes(const qmc::EncodeStats& stats, uint32_t type) {
  for (const qmc::ChunkStats& c : stats.chunks)
    if (c.type == type) return c.bytes;
  return 0;
}


Measurement measure(const TestMesh& test, int bits, int runs) {
  Measurement m;
  m.quads = test.mesh.face_count();
  m.vertices = test.mesh.vertex_count();
  qmc::EncodeOptions options;
  options.position_bits = bits;
  std::vector<uint8_t> file;
  m.encode_ms = median_ms(runs, [&] {
    const qmc::Status s = qmc::encode(test.mesh, options, &file, &m.stats);
    if (!s.ok()) fail(test.name + ": " + s.to_string());
  });
  if (m.stats.method != qmc::ConnectivityMethod::kQuad)
    fail(test.name + ": expected the quad coder (method 1), got indexed: " + m.stats.fallback_reason);
  m.conn_bytes = chunk_bytes(m.stats, qmc::kChunkConnectivity);
  m.posn_bytes = chunk_bytes(m.stats, qmc::kChunkPositions);
  qmc::DecodedFile decoded;
  m.decode_ms = median_ms(runs, [&] {
    const qmc::Status s = qmc::decode(file.data(), file.size(), &decoded, qmc::DecoderLimits::unlimited());
    if (!s.ok()) fail(test.name + ": " + s.to_string());
  });
  if (decoded.mesh.face_count() != m.quads || decoded.mesh.vertex_count() != m.vertices)
    fail(test.name + ": decoded mesh has the wrong size");
  const size_t conn_end = qmc::bench::end_of_connectivity(m.stats);
  if (conn_end == 0) fail("no CONN chunk in the encoder's statistics");
  m.conn_decode_ms = median_ms(runs, [&] {
    if (!qmc::bench::decode_connectivity_only(file, conn_end, m.quads))
      fail("connectivity-only decode did not produce the mesh's quads");
  });
  return m;
}

// ---------------------------------------------------------------------------
// Tables

const char* coding_label(int c) {
  static const char* const kLabels[qmc::kQuadCodingCount] = {"plain 4-bit", "I", "II", "III", "Huffman"};
  return c >= 0 && c < qmc::kQuadCodingCount ? kLabels[c] : "?";
}

// Bytes of the symbol stream under coding c, or "n/a" where the coding
// cannot express the sequence.
std::string coding_bytes(const Measurement& m, int c) {
  const int64_t bits = m.stats.quad.coding_bits[size_t(c)];
  return bits < 0 ? "n/a" : format("%llu", (unsigned long long)ceil_bytes(bits));
}

std::string coding_bpv(const Measurement& m, int c) {
  const int64_t bits = m.stats.quad.coding_bits[size_t(c)];
  return bits < 0 ? "n/a" : format("%.2f", bpv(double(ceil_bytes(bits)), m.vertices));
}

std::string table_a_bytes(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string t =
      "| mesh | quads | vertices | I | thesis I | II | thesis II | III | thesis III | plain 4-bit | Huffman | chosen | "
      "CONN chunk | claim violations |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: |\n";
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Measurement& m = ms[i];
    const Table52Row& th = kTable52[meshes[i].thesis_row];
    t += format("| %s | %zu | %zu | %s | %d | %s | %d | %s | %d | %s | %s | %s | %llu | %u |\n", meshes[i].name.c_str(),
                m.quads, m.vertices, coding_bytes(m, 1).c_str(), th.bytes[0], coding_bytes(m, 2).c_str(), th.bytes[1],
                coding_bytes(m, 3).c_str(), th.bytes[2], coding_bytes(m, 0).c_str(), coding_bytes(m, 4).c_str(),
                coding_label(m.stats.quad.coding), (unsigned long long)m.conn_bytes, m.stats.quad.claim_violations);
  }
  return t;
}

std::string table_a_bpv(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string t =
      "| mesh | quads | vertices | I | thesis I | II | thesis II | III | thesis III | plain 4-bit | Huffman | "
      "CONN chunk |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Measurement& m = ms[i];
    const Table52Row& th = kTable52[meshes[i].thesis_row];
    t += format("| %s | %zu | %zu | %s | %.2f | %s | %.2f | %s | %.2f | %s | %s | %.2f |\n", meshes[i].name.c_str(),
                m.quads, m.vertices, coding_bpv(m, 1).c_str(), th.bpv[0], coding_bpv(m, 2).c_str(), th.bpv[1],
                coding_bpv(m, 3).c_str(), th.bpv[2], coding_bpv(m, 0).c_str(), coding_bpv(m, 4).c_str(),
                bpv(double(m.conn_bytes), m.vertices));
  }
  return t;
}

double thesis_sum_bytes(const Table53Row& r) {
  return double(r.connectivity) + r.vertex_bin + r.huffman_table + r.bounding;
}

std::string table_b(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string t =
      "| mesh | vertices | qmc file bytes | qmc file bpv | qmc CONN+POSN bpv | thesis 'Overall (bpv)' as printed | "
      "thesis sum of outputs / V | thesis sum x 8 / V | thesis (connectivity + vertex.bin) x 8 / V | "
      "thesis compression ratio |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Measurement& m = ms[i];
    t += format("| %s | %zu | %llu | %.2f | %.2f |", meshes[i].name.c_str(), m.vertices,
                (unsigned long long)m.stats.total_bytes, bpv(double(m.stats.total_bytes), m.vertices),
                bpv(double(m.conn_bytes + m.posn_bytes), m.vertices));
    const int r = table53_index(meshes[i].thesis_row);
    if (r < 0) {
      t += " - | - | - | - | - |\n";
      continue;
    }
    const Table53Row& th = kTable53[r];
    const double sum = thesis_sum_bytes(th);
    t += format(" %.2f | %.2f | %.2f | %.2f | %s |\n", th.overall_bpv, sum / th.vertices, 8 * sum / th.vertices,
                bpv(double(th.connectivity + th.vertex_bin), size_t(th.vertices)), th.compression_ratio);
  }
  return t;
}

std::string table_c(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string t =
      "| mesh | quads | vertices | qmc encode ms | qmc decode ms | qmc CONN-only decode ms | qmc decode ns/quad | "
      "thesis quads | thesis vertices | thesis compression ms | thesis decompression ms |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Measurement& m = ms[i];
    const Table51Row& th = kTable51[meshes[i].thesis_row];
    t += format("| %s | %zu | %zu | %.3f | %.3f | %.3f | %.1f | %d | %d | %d | %d |\n", meshes[i].name.c_str(), m.quads,
                m.vertices, m.encode_ms, m.decode_ms, m.conn_decode_ms, 1e6 * m.decode_ms / double(m.quads), th.quads,
                th.vertices, th.compress_ms, th.decompress_ms);
  }
  return t;
}

std::string table_d(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string t = "| mesh | vertex valences (valence:count) |";
  for (int q = 1; q <= 13; ++q) t += format(" Q%d |", q);
  t += "\n| --- | --- |";
  for (int q = 1; q <= 13; ++q) t += " ---: |";
  t += "\n";
  for (size_t i = 0; i < meshes.size(); ++i) {
    t += "| " + meshes[i].name + " | " + valence_histogram(meshes[i].mesh) + " |";
    for (int q = 1; q <= 13; ++q) t += format(" %u |", ms[i].stats.quad.type_counts[size_t(q)]);
    t += "\n";
  }
  return t;
}

// ---------------------------------------------------------------------------
// Differences: sentences built from the measured numbers. Each states a
// comparison the tables support; none explains beyond what was measured.

double share(const Measurement& m, std::initializer_list<int> types) {
  uint64_t n = 0, all = 0;
  for (int q = 1; q <= 13; ++q) all += m.stats.quad.type_counts[size_t(q)];
  for (int q : types) n += m.stats.quad.type_counts[size_t(q)];
  return all ? 100.0 * double(n) / double(all) : 0;
}

std::string size_differences(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string s;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Measurement& m = ms[i];
    const Table52Row& th = kTable52[meshes[i].thesis_row];
    s += format("%s%s: ", i ? "; " : "", meshes[i].name.c_str());
    for (int c = 1; c <= 3; ++c) {
      const int64_t bits = m.stats.quad.coding_bits[size_t(c)];
      s += c > 1 ? ", " : "";
      s += bits < 0 ? format("%s n/a", coding_label(c))
                    : format("%s %.2f", coding_label(c), double(ceil_bytes(bits)) / th.bytes[size_t(c - 1)]);
    }
  }
  return s;
}

std::string coding_gap_note(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  // Codings I and II differ only in Q10 (II one bit shorter) and in Q11
  // followed by a class-A quad (II one bit longer): I - II = #Q10 - #(Q11, A).
  std::string ours, thesis;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const auto& bits = ms[i].stats.quad.coding_bits;
    const Table52Row& th = kTable52[meshes[i].thesis_row];
    ours += format("%s%lld", i ? ", " : "", (long long)(bits[1] - bits[2]));
    thesis += format("%s%d", i ? ", " : "", th.bytes[0] - th.bytes[1]);
  }
  return "**Coding I minus Coding II:** ours in bits: " + ours + "; thesis in bytes: " + thesis +
         " (rows in table order; the thesis's is 4 bytes on every sphere whatever its size). The two codings "
         "differ only in Q10 (II is 1 bit shorter) and in Q11 followed by a class-A quad (II is 1 bit longer), so "
         "the difference is #Q10 minus #(Q11 before Q1-Q5).";
}

std::string mix_note(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string s;
  for (size_t i = 0; i < meshes.size(); ++i)
    s += format("%s%s %.1f%% Q12, %.1f%% Q13, %.1f%% Q6", i ? "; " : "", meshes[i].name.c_str(), share(ms[i], {12}),
                share(ms[i], {13}), share(ms[i], {6}));
  return s;
}

// (mesh, coding) pairs where our byte count equals the thesis's.
std::string exact_matches(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::string s;
  for (size_t i = 0; i < meshes.size(); ++i)
    for (int c = 1; c <= 3; ++c) {
      const int64_t bits = ms[i].stats.quad.coding_bits[size_t(c)];
      const int thesis = kTable52[meshes[i].thesis_row].bytes[size_t(c - 1)];
      if (bits >= 0 && ceil_bytes(bits) == uint64_t(thesis))
        s += format("%s%s under Coding %s (%d bytes)", s.empty() ? "" : "; ", meshes[i].name.c_str(), coding_label(c),
                    thesis);
    }
  return s;
}

// Our sphere sequences are Q12, Q13 and Q6 with #Q6 = #Q13, plus one Q1 and
// one Q5. If the thesis's were of the same kind with a Q13 share b, Coding I
// would cost 3a + 1b + 4b = 3 - b bits per quad (a = 1 - 2b) and Coding III
// 2a + 2b + 4b = 2 + 2b: its Coding I figure then predicts its Coding III.
std::string model_note(const Measurement& big, const Table52Row& thesis) {
  const auto& n = big.stats.quad.type_counts;
  uint64_t others = 0;
  for (int q = 1; q <= 13; ++q) others += (q == 6 || q == 12 || q == 13) ? 0 : n[size_t(q)];
  if (n[6] != n[13] || others > 2) return {};
  const double b = 3.0 - thesis.bpv[0];
  return format("- **A sequence model:** apart from %llu quads, our sphere sequences consist of Q12, Q13 and Q6 with "
                "as many Q6 as Q13. Such a sequence with a Q13 share b costs 3 - b bits per quad under Coding I (Q12 "
                "3 bits, Q13 1, Q6 4) and 2 + 2b under Coding III (2, 2, 4). The thesis's Coding I figure for the "
                "%d-quad sphere, %.2f bpv, gives b = %.2f, which predicts %.2f bpv under Coding III; the thesis "
                "prints %.2f. Our b on that sphere is %.4f. So the thesis's I and III figures are consistent with "
                "such a sequence with about %.0f times our share of Q13 (bits per quad and per vertex differ by "
                "V = F + 2). The model has no Q10 or Q11, so it leaves out the thesis's gap between Codings I "
                "and II (next point).\n",
                (unsigned long long)others, thesis.quads, thesis.bpv[0], b, 2 + 2 * b, thesis.bpv[2],
                share(big, {13}) / 100, b / (share(big, {13}) / 100));
}

// "Huffman on 6 meshes, III on sphere 0": the coding the encoder chose.
std::string choices(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  std::map<int, std::vector<std::string>> by_coding;
  for (size_t i = 0; i < meshes.size(); ++i) by_coding[ms[i].stats.quad.coding].push_back(meshes[i].name);
  std::string s;
  for (const auto& [coding, names] : by_coding) {
    s += format("%s%s on ", s.empty() ? "" : "; ", coding_label(coding));
    if (names.size() > 2) {
      s += format("%zu meshes", names.size());
      continue;
    }
    for (size_t k = 0; k < names.size(); ++k) s += (k ? " and " : "") + names[k];
  }
  return s;
}

int thesis_overall_is_bytes(int* rows) {
  int match = 0;
  *rows = kTable53Rows;
  for (const Table53Row& r : kTable53) match += std::fabs(thesis_sum_bytes(r) / r.vertices - r.overall_bpv) < 0.006;
  return match;
}

std::string differences(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms) {
  uint32_t violations = 0;
  for (const Measurement& m : ms) violations += m.stats.quad.claim_violations;
  int rows = 0;
  const int bytes_rows = thesis_overall_is_bytes(&rows);
  const size_t last = size_t(kThesisRows - 1);
  const Measurement& big = ms[last];
  const Measurement& small = ms[0];
  const auto& bits = big.stats.quad.coding_bits;
  std::string d = "## Differences\n\n";
  d += "- **Sizes, ours over the thesis's (Codings I, II, III):** " + size_differences(meshes, ms) +
       ". The thesis leaves its traversal's orientation, gate rules and vertex order implicit (its figures are "
       "lost); ours are fixed by spec section 5.3.3, so the same mesh can give a different type sequence.\n";
  if (const std::string same = exact_matches(meshes, ms); !same.empty())
    d += "- **Equal totals:** " + same +
         ". Only the totals agree: the other codings differ on the same mesh, so (with the same code tables) the type "
         "sequences are not the same.\n";
  d += "- **Type mix (share of coded quads):** " + mix_note(meshes, ms) +
       format(". As the spheres grow, Q12 takes over our sequences, so our Codings I and II approach Q12's 3-bit code "
              "word (%.2f bpv on %s) and Coding III its 2-bit one (%.2f); the thesis's settle at 2.83 and 2.34.\n",
              bpv(double(ceil_bytes(bits[1])), big.vertices), meshes[last].name.c_str(),
              bpv(double(ceil_bytes(bits[3])), big.vertices));
  d += model_note(big, kTable52[meshes[last].thesis_row]);
  d += "- " + coding_gap_note(meshes, ms) + "\n";
  d += format("- **Huffman** (qmc's coding 4, not in the thesis) codes (type, next class) pairs with one code per "
              "class; no code word is shorter than 1 bit, and it reaches %.2f bpv on %s, tables included. The "
              "encoder's choice: %s.\n",
              bpv(double(ceil_bytes(bits[4])), big.vertices), meshes[last].name.c_str(), choices(meshes, ms).c_str());
  d += "- **Meshes:** every closed genus-0 quad mesh has V = F + 2, so equal quad and vertex counts do not show that "
       "the thesis's spheres are ours; table D lists our valences. The thesis prints the cow as 17414 quads / 17412 "
       "vertices in table 5-1 and 17412 / 17414 in table 5-2; ours has " +
       format("%zu quads and %zu vertices", ms[size_t(kCowRow)].quads, ms[size_t(kCowRow)].vertices) + ".\n";
  d += format("- **Claim violations (seed 001 section 4.1):** %u in total over the %zu meshes.\n", violations,
              meshes.size());
  d += format("- **Table 5-3's 'Overall (bpv)':** in %d of its %d rows it equals (connectivity + vertex.bin + Huffman "
              "table + bounding) / V to the printed precision, i.e. bytes per vertex; table B gives the thesis's "
              "bits per vertex as 8 times that sum over V.\n",
              bytes_rows, rows);
  d += format("- **Times:** the thesis's are Java programs on a Pentium 560 under Windows 98 with other programs "
              "running, a pipeline of separate programs exchanging files (its section 5.1.1; whether the times include "
              "that I/O is not stated); ours are in-process C++ on buffers. Our decode costs %.1f ns per quad on the "
              "smallest mesh and %.1f on the largest sphere.\n",
              1e6 * small.decode_ms / double(small.quads), 1e6 * big.decode_ms / double(big.quads));
  return d;
}

std::string document(const std::vector<TestMesh>& meshes, const std::vector<Measurement>& ms, int bits, int runs) {
  std::string doc;
  doc += format("Meshes: `make_refined_sphere(0..5)` (the deltoidal hexecontahedron and its Catmull-Clark "
                "refinements, projected to the unit sphere) and the triangle cow after one Catmull-Clark step. qmc "
                "with automatic connectivity (every mesh took method 1, the quad coder), positions at %d bits per "
                "axis (the thesis quantized to 8). Thesis figures are transcribed exactly from its tables 5-1, 5-2 and "
                "5-3, rows matched by mesh (the thesis lists the cow between the 15360- and 61440-quad spheres).\n\n",
                bits);
  doc += "## Table A: connectivity size (beside thesis table 5-2)\n\n";
  doc += "Columns I, II, III, plain 4-bit and Huffman are the exact sizes of the interaction-type symbol stream "
         "under each coding (`EncodeStats::quad.coding_bits`, computed by the encoder for its choice; the first-class "
         "bit and, for Huffman, the code tables included), rounded up to whole bytes; 'n/a' where the coding cannot "
         "express the sequence. 'CONN chunk' is the whole connectivity chunk as written: 12 bytes of framing, the "
         "method, counts, flags and coding bytes, and the stream under the chosen coding. 'claim violations': Q5, Q10, "
         "Q12 or Q13 followed by Q1-Q5, which seed 001 section 4.1 claims never happens.\n\n";
  doc += "### A1: bytes\n\n" + table_a_bytes(meshes, ms) + "\n";
  doc += "### A2: bits per vertex (bytes x 8 / V, the thesis's definition)\n\n" + table_a_bpv(meshes, ms) + "\n";
  doc += format("## Table B: whole file (beside thesis table 5-3)\n\n"
                "qmc at %d bits per axis: the whole .qmc file (signature, QHDR, CONN, POSN, QEND) and CONN + POSN "
                "alone, x 8 / V. The thesis's outputs are connectivity (Coding I), vertex.bin, a Huffman table and the "
                "bounding box, the last two as text.\n\n",
                bits);
  doc += table_b(meshes, ms) + "\n";
  doc += format("## Table C: times (beside thesis table 5-1)\n\n"
                "qmc: median of %d runs, in process, from and to memory. Encode is `qmc::encode` of the whole file "
                "(which also decodes its own CONN once as a self-check); decode is `qmc::decode` of the whole file "
                "(POSN included); CONN-only decode feeds `qmc::StreamDecoder` the file up to the end of CONN "
                "(signature, QHDR and CONN with their CRCs, no POSN). Thesis: Java on a Pentium 560 with other "
                "programs running (its note 1); the cow row's counts are printed swapped there, shown as printed.\n\n",
                runs);
  doc += table_c(meshes, ms) + "\n";
  doc += "## Table D: our meshes and interaction types\n\n" + table_d(meshes, ms) + "\n";
  doc += differences(meshes, ms);
  return doc;
}

struct Args {
  std::string cow, out;
  int runs = 7, bits = 8;
};

[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: qmc_seed001 [--runs N] [--bits B] [--out FILE.md] COW.obj\n");
  std::exit(2);
}

Args parse_args(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc) a.runs = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--bits" && i + 1 < argc) a.bits = std::atoi(argv[++i]);
    else if (arg == "--out" && i + 1 < argc) a.out = argv[++i];
    else if (!arg.empty() && arg[0] != '-' && a.cow.empty()) a.cow = arg;
    else usage();
  }
  if (a.cow.empty()) usage();
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse_args(argc, argv);
  const bool progress = isatty(STDERR_FILENO);
  const std::vector<TestMesh> meshes = thesis_meshes(args.cow);
  std::vector<Measurement> ms;
  for (const TestMesh& test : meshes) {
    if (progress) std::fprintf(stderr, "\r[%zu/%zu] %-30s", ms.size() + 1, meshes.size(), test.name.c_str());
    ms.push_back(measure(test, args.bits, args.runs));
  }
  if (progress) std::fprintf(stderr, "\r%50s\r", "");
  const std::string doc = document(meshes, ms, args.bits, args.runs);
  if (args.out.empty()) {
    std::fputs(doc.c_str(), stdout);
  } else if (!(std::ofstream(args.out) << doc)) {
    fail("cannot write " + args.out);
  }
  return 0;
}
