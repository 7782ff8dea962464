// qmc_quad_bench: qmc's quad coder (connectivity method 1) against Draco
// 1.5.5 with polygons preserved, on the quad meshes qmc codes with method 1
// and on a ~1M-quad sphere. Measures connectivity size and decode
// throughput, and reports them against the project's targets (decoder at
// least 2x Draco's throughput; connectivity at most half of Draco's). The
// targets are reported, never tuned for. Writes Markdown
// (docs/results/quad_vs_draco.md via scripts/bench.sh).
//
// Draco has no separate connectivity stream, so its connectivity cost is
// measured as the size of a Draco file of the same mesh with every position
// set to (0,0,0): a constant attribute codes to a few bytes, leaving the
// edgebreaker stream and the polygon flags (plus Draco's fixed header).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "bench_common.h"
#include "draco_runner.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kThroughputTarget = 2.0;    // qmc decode at least 2x Draco's vertices per second
constexpr double kConnectivityTarget = 0.5;  // qmc connectivity at most 1/2 of Draco's
constexpr size_t kLargeVertices = 250000;    // meshes above this get --large-runs runs

[[noreturn]] void fail(const std::string& message) { qmc::bench::fail("qmc_quad_bench", message); }
using qmc::bench::format;
using qmc::bench::median_seconds;
double bpv(double bytes, size_t vertices) { return qmc::bench::bits_per_vertex(bytes, vertices); }

// ---------------------------------------------------------------------------
// qmc side

struct QmcSide {
  uint64_t file_bytes = 0, conn_bytes = 0;
  double decode_s = 0, conn_decode_s = 0;
};

QmcSide measure_qmc(const qmc::Mesh& mesh, const std::vector<uint8_t>& file, const qmc::EncodeStats& stats,
                    int runs) {
  QmcSide q;
  q.file_bytes = file.size();
  for (const qmc::ChunkStats& c : stats.chunks)
    if (c.type == qmc::kChunkConnectivity) q.conn_bytes = c.bytes;
  qmc::DecodedFile decoded;
  q.decode_s = median_seconds(runs, [&] {
    if (qmc::Status s = qmc::decode(file.data(), file.size(), &decoded, qmc::DecoderLimits::unlimited()); !s.ok())
      fail(s.to_string());
  });
  if (decoded.mesh.face_count() != mesh.face_count() || decoded.mesh.vertex_count() != mesh.vertex_count())
    fail("qmc decoded a mesh of the wrong size");
  const size_t end = qmc::bench::end_of_connectivity(stats);
  if (end == 0) fail("no CONN chunk in the encoder's statistics");
  q.conn_decode_s = median_seconds(runs, [&] {
    if (!qmc::bench::decode_connectivity_only(file, end, mesh.face_count()))
      fail("connectivity-only decode did not produce the mesh's faces");
  });
  return q;
}

// ---------------------------------------------------------------------------
// Draco side

struct DracoSide {
  bool ok = false;
  std::string note;  // error, or what Draco lost
  size_t bytes = 0;
  double decode_s = 0;
};

// Anything that makes Draco's decoded mesh differ from the input's faces
// would make its size or speed incomparable, so it is spelled out.
std::string losses(const qmc::bench::DracoResult& r, const qmc::Mesh& mesh, bool polygons) {
  std::string note;
  auto add = [&](size_t n, const char* what) {
    if (n) note += format("%s%zu %s", note.empty() ? "" : "; ", n, what);
  };
  add(r.dropped_faces, "faces dropped");
  add(r.damaged_faces, "faces damaged");
  add(r.unreferenced_vertices, "unreferenced vertices not stored");
  add(r.unrecovered_polygons, "polygons not recovered");
  if (polygons && r.decoded.face_count() != mesh.face_count())
    note += format("%sdecoded %zu faces of %zu", note.empty() ? "" : "; ", r.decoded.face_count(), mesh.face_count());
  return note;
}

DracoSide draco_side(const qmc::Mesh& mesh, int bits, bool polygons, int runs) {
  qmc::bench::DracoOptions options;
  options.position_bits = bits;
  options.compression_level = 10;
  options.preserve_polygons = polygons;
  const qmc::bench::DracoResult r = qmc::bench::run_draco(mesh, options, runs);
  DracoSide d;
  if (!r.ok) {
    d.note = r.error;
    return d;
  }
  d.ok = true;
  d.bytes = r.bytes;
  d.decode_s = qmc::bench::median(r.decode_seconds);
  d.note = losses(r, mesh, polygons);
  return d;
}

qmc::Mesh at_origin(qmc::Mesh mesh) {
  std::fill(mesh.positions.begin(), mesh.positions.end(), 0.f);
  return mesh;
}

// ---------------------------------------------------------------------------
// Rows

struct Row {
  std::string name;
  size_t quads = 0, vertices = 0;
  int runs = 0;
  QmcSide qmc;
  DracoSide polygons, polygons_at_origin, triangles, triangles_at_origin;
};

struct Fallback {
  std::string name;
  size_t faces = 0, vertices = 0;
  std::string reason;
};

struct Options {
  int runs = 7, large_runs = 3, bits = 12, sphere_levels = 7;
  std::string out;
  std::vector<std::string> meshes;
};

// Either a row (method 1) or a fallback (indexed), never both.
void bench_mesh(const std::string& name, const qmc::Mesh& mesh, const Options& opt, std::vector<Row>* rows,
                std::vector<Fallback>* fallbacks) {
  qmc::EncodeOptions options;
  options.position_bits = opt.bits;
  std::vector<uint8_t> file;
  qmc::EncodeStats stats;
  if (qmc::Status s = qmc::encode(mesh, options, &file, &stats); !s.ok()) fail(name + ": " + s.to_string());
  if (stats.method != qmc::ConnectivityMethod::kQuad) {
    fallbacks->push_back({name, mesh.face_count(), mesh.vertex_count(), stats.fallback_reason});
    return;
  }
  Row row;
  row.name = name;
  row.quads = mesh.face_count();
  row.vertices = mesh.vertex_count();
  row.runs = mesh.vertex_count() > kLargeVertices ? opt.large_runs : opt.runs;
  row.qmc = measure_qmc(mesh, file, stats, row.runs);
  row.polygons = draco_side(mesh, opt.bits, true, row.runs);
  row.triangles = draco_side(mesh, opt.bits, false, row.runs);
  const qmc::Mesh origin = at_origin(mesh);
  row.polygons_at_origin = draco_side(origin, opt.bits, true, 1);
  row.triangles_at_origin = draco_side(origin, opt.bits, false, 1);
  rows->push_back(std::move(row));
}

// ---------------------------------------------------------------------------
// Output

std::string verdict(bool pass) { return pass ? "pass" : "**fail**"; }

// "-" where the Draco side failed (its note says why).
std::string number_cell(bool ok, const char* fmt, double value) { return ok ? format(fmt, value) : "-"; }
std::string verdict_cell(bool ok, bool pass) { return ok ? verdict(pass) : "-"; }

double connectivity_ratio(const Row& r) { return double(r.qmc.conn_bytes) / double(r.polygons_at_origin.bytes); }
double throughput_ratio(const Row& r) { return r.polygons.decode_s / r.qmc.decode_s; }
double mverts_per_s(size_t vertices, double seconds) { return double(vertices) / seconds / 1e6; }

std::string draco_cell(const DracoSide& d, size_t vertices) {
  return d.ok ? format("%zu (%.2f)", d.bytes, bpv(double(d.bytes), vertices)) : "failed: " + d.note;
}

std::string notes(const Row& r) {
  std::string n;
  const std::pair<const char*, const DracoSide*> sides[] = {{"polygons", &r.polygons},
                                                            {"polygons at origin", &r.polygons_at_origin},
                                                            {"triangles", &r.triangles},
                                                            {"triangles at origin", &r.triangles_at_origin}};
  for (const auto& [what, side] : sides)
    if (!side->note.empty()) n += format("%sDraco %s: %s", n.empty() ? "" : "; ", what, side->note.c_str());
  return n;
}

std::string connectivity_table(const std::vector<Row>& rows) {
  std::string t =
      "| mesh | quads | vertices | qmc CONN bytes | qmc CONN bpv | Draco polygons, positions at origin: bytes "
      "(bpv) | qmc / Draco | target <= 0.5 | Draco triangles, positions at origin: bytes (bpv) | qmc file bytes "
      "(bpv) | Draco polygons file bytes (bpv) | notes |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | --- |\n";
  for (const Row& r : rows) {
    const bool ok = r.polygons_at_origin.ok;
    t += format("| %s | %zu | %zu | %llu | %.2f | %s | %s | %s | %s | %llu (%.2f) | %s | %s |\n", r.name.c_str(),
                r.quads, r.vertices, (unsigned long long)r.qmc.conn_bytes, bpv(double(r.qmc.conn_bytes), r.vertices),
                draco_cell(r.polygons_at_origin, r.vertices).c_str(),
                number_cell(ok, "%.3f", ok ? connectivity_ratio(r) : 0).c_str(),
                verdict_cell(ok, ok && connectivity_ratio(r) <= kConnectivityTarget).c_str(),
                draco_cell(r.triangles_at_origin, r.vertices).c_str(), (unsigned long long)r.qmc.file_bytes,
                bpv(double(r.qmc.file_bytes), r.vertices), draco_cell(r.polygons, r.vertices).c_str(),
                notes(r).c_str());
  }
  return t;
}

std::string draco_speed_cell(const DracoSide& d, size_t vertices) {
  return d.ok ? format("%.3f | %.2f", 1e3 * d.decode_s, mverts_per_s(vertices, d.decode_s)) : "failed | -";
}

std::string throughput_table(const std::vector<Row>& rows) {
  std::string t =
      "| mesh | vertices | runs | qmc decode ms | qmc Mvertices/s | qmc CONN-only decode ms | Draco polygons "
      "decode ms | Draco polygons Mvertices/s | qmc / Draco polygons | target >= 2 | Draco triangles decode ms | "
      "Draco triangles Mvertices/s | qmc / Draco triangles |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: |\n";
  for (const Row& r : rows) {
    const bool ok = r.polygons.ok;
    t += format("| %s | %zu | %d | %.3f | %.2f | %.3f | %s | %s | %s | %s | %s |\n", r.name.c_str(), r.vertices,
                r.runs, 1e3 * r.qmc.decode_s, mverts_per_s(r.vertices, r.qmc.decode_s), 1e3 * r.qmc.conn_decode_s,
                draco_speed_cell(r.polygons, r.vertices).c_str(),
                number_cell(ok, "%.2f", ok ? throughput_ratio(r) : 0).c_str(),
                verdict_cell(ok, ok && throughput_ratio(r) >= kThroughputTarget).c_str(),
                draco_speed_cell(r.triangles, r.vertices).c_str(),
                number_cell(r.triangles.ok, "%.2f", r.triangles.decode_s / r.qmc.decode_s).c_str());
  }
  return t;
}

std::string fallback_list(const std::vector<Fallback>& fallbacks) {
  if (fallbacks.empty()) return "None: every mesh given was coded with method 1.\n";
  std::string t = "| mesh | faces | vertices | qmc's fallback reason (EncodeStats::fallback_reason) |\n"
                  "| --- | ---: | ---: | --- |\n";
  for (const Fallback& f : fallbacks)
    t += format("| %s | %zu | %zu | %s |\n", f.name.c_str(), f.faces, f.vertices, f.reason.c_str());
  return t;
}

std::string summary(const std::vector<Row>& rows) {
  size_t conn_pass = 0, conn_n = 0, speed_pass = 0, speed_n = 0;
  for (const Row& r : rows) {
    if (r.polygons_at_origin.ok) conn_n++, conn_pass += connectivity_ratio(r) <= kConnectivityTarget;
    if (r.polygons.ok) speed_n++, speed_pass += throughput_ratio(r) >= kThroughputTarget;
  }
  return format("- Connectivity at most 1/2 of Draco's (polygons preserved): met on %zu of %zu meshes.\n"
                "- Decoder throughput at least 2x Draco's (polygons preserved): met on %zu of %zu meshes.\n",
                conn_pass, conn_n, speed_pass, speed_n);
}

std::string document(const std::vector<Row>& rows, const std::vector<Fallback>& fallbacks, const Options& opt) {
  std::string doc = format(
      "Both codecs quantize positions to %d bits per axis; Draco 1.5.5 at compression level 10 (edgebreaker), run "
      "in memory through bench/draco_runner (polygons preserved: Draco's OBJ-style per-corner 'added_edges' "
      "attribute). qmc with automatic connectivity; only meshes it codes with method 1 (the quad coder) are "
      "measured, the others are listed below with qmc's reason. The sphere is `make_refined_sphere(%d)`. Timings "
      "are medians of %d runs (%d for meshes above %zu vertices), in process, from memory; Draco's decode is "
      "`DecodeMeshFromBuffer` only (turning its triangles back into polygons is not timed). Vertices per second use "
      "the input's vertex count for both codecs.\n\n",
      opt.bits, opt.sphere_levels, opt.runs, opt.large_runs, kLargeVertices);
  doc += "## Summary against the targets\n\n" + summary(rows) + "\n";
  doc += "## Connectivity size\n\n"
         "qmc: the whole CONN chunk (12 bytes of framing included) x 8 / V. Draco has no separate connectivity "
         "stream, so **Draco's connectivity is measured as the bytes of a Draco file of the same mesh with every "
         "position replaced by (0,0,0)**: a constant attribute costs a few bytes, so the file is essentially the "
         "edgebreaker connectivity, the polygon flags and Draco's header. Also shown: the same for Draco without "
         "polygons (triangles only, for scale), and both codecs' whole files with the real positions.\n\n";
  doc += connectivity_table(rows) + "\n";
  doc += "## Decode throughput\n\n"
         "Whole-file decode (`qmc::decode`; Draco `DecodeMeshFromBuffer`). 'qmc CONN-only' feeds `qmc::StreamDecoder` "
         "the file up to the end of CONN, which decodes signature, QHDR and CONN (CRCs included) but not POSN. The "
         "target compares qmc with Draco preserving polygons (the same output: quads); Draco producing triangles is "
         "shown for reference.\n\n";
  doc += throughput_table(rows) + "\n";
  doc += "## Quad meshes qmc does not code with method 1\n\n" + fallback_list(fallbacks);
  return doc;
}


[[noreturn]] void usage() {
  std::fprintf(stderr,
               "usage: qmc_quad_bench [--runs N] [--large-runs N] [--bits B] [--sphere-levels L (-1: none)] "
               "[--out FILE.md] MESH...\n");
  std::exit(2);
}

Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--runs" && has_value) o.runs = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--large-runs" && has_value) o.large_runs = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--bits" && has_value) o.bits = std::atoi(argv[++i]);
    else if (arg == "--sphere-levels" && has_value) o.sphere_levels = std::atoi(argv[++i]);
    else if (arg == "--out" && has_value) o.out = argv[++i];
    else if (!arg.empty() && arg[0] != '-') o.meshes.push_back(arg);
    else usage();
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse_args(argc, argv);
  const bool progress = isatty(STDERR_FILENO);
  const size_t total = opt.meshes.size() + (opt.sphere_levels >= 0 ? 1 : 0);
  std::vector<Row> rows;
  std::vector<Fallback> fallbacks;
  size_t done = 0;
  auto bench = [&](const std::string& name, const qmc::Mesh& mesh) {
    if (progress) std::fprintf(stderr, "\r[%zu/%zu] %-40s", ++done, total, name.c_str());
    bench_mesh(name, mesh, opt, &rows, &fallbacks);
  };
  for (const std::string& path : opt.meshes) {
    qmc::Mesh mesh;
    if (qmc::Status s = qmc::bench::read_geometry(path, &mesh, nullptr); !s.ok()) fail(s.to_string());
    bench(qmc::bench::display_name(path), mesh);
  }
  if (opt.sphere_levels >= 0) {
    const std::string name = format("sphere %d (make_refined_sphere)", opt.sphere_levels);
    bench(name, qmc::tools::make_refined_sphere(opt.sphere_levels));
  }
  if (progress) std::fprintf(stderr, "\r%60s\r", "");
  const std::string doc = document(rows, fallbacks, opt);
  if (opt.out.empty()) {
    std::fputs(doc.c_str(), stdout);
  } else if (!(std::ofstream(opt.out) << doc)) {
    fail("cannot write " + opt.out);
  }
  return 0;
}
