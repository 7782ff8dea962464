// qmc_topology_bench: connectivity bits per vertex of qmc's structured
// coders (automatic choice: the quad coder, method 1, where the mesh is in
// its scope, else the polygon coder, method 2; and the polygon coder forced)
// against qmc's own indexed fallback (method 0) and against Draco 1.5.5, on
// every mesh given. Also lists the topology the polygon coder had to record
// (components, holes, handles, vertex identifications, loose faces) and what
// those records cost. Writes Markdown (docs/results/topology.md via
// scripts/bench.sh).
//
// Draco has no separate connectivity stream, so, as in qmc_quad_bench, its
// connectivity is measured as the size of a Draco file of the same mesh with
// every position set to (0,0,0): a constant attribute codes to a few bytes,
// leaving the edgebreaker stream, the polygon flags and Draco's header.
// Polygons are preserved (Draco's OBJ-style 'added_edges' attribute) where the
// mesh has a face of more than 3 corners; for such meshes Draco's plain
// triangle mode (it triangulates, so the polygons are lost) is shown too.
//
// Every qmc file is decoded and checked against the input (faces exactly
// under the encoder's vertex and face correspondence, positions within half a
// quantization step); a failed check is reported in the table, never hidden.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "bench_common.h"
#include "draco_runner.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"

namespace {

[[noreturn]] void fail(const std::string& message) { qmc::bench::fail("qmc_topology_bench", message); }
using qmc::bench::format;
using qmc::bench::median_seconds;
double bpv(double bytes, size_t vertices) { return qmc::bench::bits_per_vertex(bytes, vertices); }

void append_note(std::string* notes, const std::string& note) {
  if (!note.empty()) *notes += (notes->empty() ? "" : "; ") + note;
}

// ---------------------------------------------------------------------------
// qmc side

struct QmcRun {
  bool ok = false;
  std::string error;  // encode error or failed round-trip check
  qmc::EncodeStats stats;
  uint64_t conn_bytes = 0, file_bytes = 0;
  double encode_s = 0, decode_s = 0, conn_decode_s = 0;  // medians; 0 when not timed
};

// Encodes with `choice`, checks the decoded file against the input, and
// times encode, whole-file decode and CONN-only decode if `runs` > 0.
QmcRun run_qmc(const qmc::Mesh& mesh, qmc::ConnectivityChoice choice, int bits, int runs) {
  QmcRun q;
  qmc::EncodeOptions options;
  options.position_bits = bits;
  options.connectivity = choice;
  std::vector<uint8_t> file;
  if (qmc::Status s = qmc::encode(mesh, options, &file, &q.stats); !s.ok()) {
    q.error = "encode: " + s.to_string();
    return q;
  }
  q.file_bytes = file.size();
  for (const qmc::ChunkStats& c : q.stats.chunks)
    if (c.type == qmc::kChunkConnectivity) q.conn_bytes = c.bytes;
  qmc::DecodedFile decoded;
  if (qmc::Status s = qmc::decode(file.data(), file.size(), &decoded, qmc::DecoderLimits::unlimited()); !s.ok()) {
    q.error = "decode: " + s.to_string();
    return q;
  }
  const qmc::tools::Correspondence correspondence{q.stats.file_vertex, q.stats.face_source};
  const qmc::tools::RoundTripReport report = qmc::tools::check_round_trip(mesh, decoded, correspondence);
  if (!report.ok()) {
    q.error = "round trip: " + (report.faces_equal ? report.position_mismatch : report.face_mismatch);
    return q;
  }
  if (runs > 0) {
    std::vector<uint8_t> scratch;
    q.encode_s = median_seconds(runs, [&] {
      if (!qmc::encode(mesh, options, &scratch).ok()) fail("encode failed on a repeated run");
    });
    q.decode_s = median_seconds(runs, [&] {
      if (!qmc::decode(file.data(), file.size(), &decoded, qmc::DecoderLimits::unlimited()).ok())
        fail("decode failed on a repeated run");
    });
    const size_t end = qmc::bench::end_of_connectivity(q.stats);
    if (end == 0) fail("no CONN chunk in the encoder's statistics");
    q.conn_decode_s = median_seconds(runs, [&] {
      if (!qmc::bench::decode_connectivity_only(file, end, mesh.face_count()))
        fail("connectivity-only decode did not produce the mesh's faces");
    });
  }
  q.ok = true;
  return q;
}

// ---------------------------------------------------------------------------
// Draco side (through bench/draco_runner)

struct DracoConn {
  bool ok = false;
  std::string note;  // error, or what Draco lost
  size_t bytes = 0;
};

// What Draco dropped or could not rebuild makes its size incomparable, so it
// is spelled out.
std::string draco_losses(const qmc::bench::DracoResult& r, const qmc::Mesh& mesh, bool polygons) {
  std::string note;
  auto add = [&](size_t n, const char* what) {
    if (n) append_note(&note, format("%zu %s", n, what));
  };
  add(r.dropped_faces, "faces dropped");
  add(r.damaged_faces, "faces damaged");
  add(r.unreferenced_vertices, "unreferenced vertices not stored");
  add(r.unrecovered_polygons, "polygons not recovered");
  if (polygons && r.decoded.face_count() != mesh.face_count())
    append_note(&note, format("decoded %zu faces of %zu", r.decoded.face_count(), mesh.face_count()));
  return note;
}

// Draco's connectivity: a Draco file of the mesh with all positions at the origin.
DracoConn draco_connectivity(const qmc::Mesh& mesh, int bits, bool polygons) {
  qmc::Mesh origin = mesh;
  std::fill(origin.positions.begin(), origin.positions.end(), 0.f);
  qmc::bench::DracoOptions options;
  options.position_bits = bits;
  options.compression_level = 10;
  options.preserve_polygons = polygons;
  const qmc::bench::DracoResult r = qmc::bench::run_draco(origin, options, 1);
  DracoConn d;
  if (!r.ok) {
    d.note = r.error;
    return d;
  }
  d.ok = true;
  d.bytes = r.bytes;
  d.note = draco_losses(r, mesh, polygons);
  return d;
}

// ---------------------------------------------------------------------------
// Rows

struct Row {
  std::string name;
  size_t vertices = 0, faces = 0, triangles = 0, quads = 0, larger = 0;
  int runs = 0;
  QmcRun automatic, polygon, indexed;
  bool polygonal = false;  // some face has more than 3 corners
  DracoConn draco;         // polygons preserved if polygonal, else triangles
  DracoConn draco_triangles;  // polygonal meshes only: Draco's triangle mode
};

struct Options {
  int runs = 7, large_runs = 3, bits = 12;
  std::vector<std::string> meshes;
};

constexpr size_t kLargeVertices = 250000;  // meshes above this get --large-runs runs

Row bench_mesh(const std::string& name, const qmc::Mesh& mesh, const Options& opt) {
  Row row;
  row.name = name;
  row.vertices = mesh.vertex_count();
  row.faces = mesh.face_count();
  for (uint32_t n : mesh.face_sizes) {
    if (n == 3) row.triangles++;
    else if (n == 4) row.quads++;
    else row.larger++;
  }
  row.polygonal = row.quads + row.larger > 0;
  row.runs = row.vertices > kLargeVertices ? opt.large_runs : opt.runs;
  row.automatic = run_qmc(mesh, qmc::ConnectivityChoice::kAuto, opt.bits, row.runs);
  row.polygon = run_qmc(mesh, qmc::ConnectivityChoice::kPolygon, opt.bits, row.runs);
  row.indexed = run_qmc(mesh, qmc::ConnectivityChoice::kIndexed, opt.bits, 0);
  row.draco = draco_connectivity(mesh, opt.bits, row.polygonal);
  if (row.polygonal) row.draco_triangles = draco_connectivity(mesh, opt.bits, false);
  return row;
}

// ---------------------------------------------------------------------------
// Output

std::string method_name(const QmcRun& q) {
  if (!q.ok) return "-";
  switch (q.stats.method) {
    case qmc::ConnectivityMethod::kQuad: return "quad (1)";
    case qmc::ConnectivityMethod::kPolygon: return "polygon (2)";
    case qmc::ConnectivityMethod::kIndexed: return "**indexed (0)**";
  }
  return "?";
}

std::string conn_bpv_cell(const QmcRun& q, size_t vertices) {
  return q.ok ? format("%.2f", bpv(double(q.conn_bytes), vertices)) : "failed";
}

// "yes" when the automatic choice and the forced polygon coder are both
// smaller than the indexed coding; otherwise says which is not.
std::string structured_check(const Row& r) {
  if (!r.automatic.ok || !r.polygon.ok || !r.indexed.ok) return "**no** (a run failed)";
  std::string bad;
  if (r.automatic.conn_bytes >= r.indexed.conn_bytes) append_note(&bad, "auto");
  if (r.polygon.conn_bytes >= r.indexed.conn_bytes) append_note(&bad, "polygon");
  return bad.empty() ? "yes" : "**no** (" + bad + ")";
}

std::string draco_bpv_cell(const DracoConn& d, size_t vertices) {
  return d.ok ? format("%.2f", bpv(double(d.bytes), vertices)) : "failed";
}

std::string ratio_cell(const QmcRun& q, const DracoConn& d) {
  return q.ok && d.ok ? format("%.3f", double(q.conn_bytes) / double(d.bytes)) : "-";
}

std::string notes(const Row& r) {
  std::string n;
  const std::pair<const char*, const QmcRun*> runs[] = {
      {"qmc auto", &r.automatic}, {"qmc polygon", &r.polygon}, {"qmc indexed", &r.indexed}};
  for (const auto& [what, q] : runs)
    if (!q->ok) append_note(&n, format("%s: %s", what, q->error.c_str()));
  if (!r.draco.note.empty()) append_note(&n, "Draco: " + r.draco.note);
  if (!r.draco_triangles.note.empty()) append_note(&n, "Draco triangles: " + r.draco_triangles.note);
  return n;
}

std::string connectivity_table(const std::vector<Row>& rows) {
  std::string t =
      "| mesh | vertices | faces | qmc auto: method | qmc auto CONN bpv | qmc polygon (forced) CONN bpv | qmc "
      "indexed CONN bpv | structured < indexed | Draco mode | Draco bpv | qmc auto / Draco | Draco triangulated "
      "bpv | qmc auto / Draco triangulated | notes |\n"
      "| --- | ---: | ---: | --- | ---: | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | --- |\n";
  for (const Row& r : rows) {
    t += format("| %s | %zu | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(),
                r.vertices, r.faces, method_name(r.automatic).c_str(), conn_bpv_cell(r.automatic, r.vertices).c_str(),
                conn_bpv_cell(r.polygon, r.vertices).c_str(), conn_bpv_cell(r.indexed, r.vertices).c_str(),
                structured_check(r).c_str(), r.polygonal ? "polygons" : "triangles",
                draco_bpv_cell(r.draco, r.vertices).c_str(), ratio_cell(r.automatic, r.draco).c_str(),
                r.polygonal ? draco_bpv_cell(r.draco_triangles, r.vertices).c_str() : "(same)",
                r.polygonal ? ratio_cell(r.automatic, r.draco_triangles).c_str() : "(same)", notes(r).c_str());
  }
  return t;
}

std::string coding_name(const QmcRun& q) {
  if (!q.ok) return "-";
  const int c = q.stats.polygon.coding;
  if (c == qmc::kPolygonMixedHuffman) return "5 mixed Huffman";
  if (c == qmc::kPolygonContextCoded) return "7 context-modelled";
  if (c == qmc::kPolygonQuadContextCoded) return "8 context-modelled, quads by their neighbours";
  return format("%d %s", c, qmc::quad_coding_name(static_cast<qmc::QuadCoding>(c)));
}

std::string topology_table(const std::vector<Row>& rows) {
  std::string t =
      "| mesh | vertices | faces | triangles | quads | larger faces | non-quad faces (coder) | components | holes | "
      "handles | vertex identifications | loose faces | polygon coding | CONN bytes | record bits | records bpv | "
      "records / CONN |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | "
      "---: |\n";
  for (const Row& r : rows) {
    const QmcRun& q = r.polygon;
    if (!q.ok) {
      t += format("| %s | %zu | %zu | %zu | %zu | %zu | polygon coder failed: %s |||||||||||\n", r.name.c_str(),
                  r.vertices, r.faces, r.triangles, r.quads, r.larger, q.error.c_str());
      continue;
    }
    const qmc::PolygonCoderStats& p = q.stats.polygon;
    t += format("| %s | %zu | %zu | %zu | %zu | %zu | %u | %u | %u | %u | %u | %u | %s | %llu | %llu | %.2f | %.1f%% |\n",
                r.name.c_str(), r.vertices, r.faces, r.triangles, r.quads, r.larger, p.non_quad_faces, p.components,
                p.holes, p.handles, p.identifications, p.loose_faces, coding_name(q).c_str(),
                (unsigned long long)q.conn_bytes, (unsigned long long)p.record_bits,
                double(p.record_bits) / double(r.vertices),
                100.0 * double(p.record_bits) / (8.0 * double(q.conn_bytes)));
  }
  return t;
}

std::string ms(const QmcRun& q, double seconds) { return q.ok ? format("%.3f", 1e3 * seconds) : "-"; }

std::string timing_table(const std::vector<Row>& rows) {
  std::string t =
      "| mesh | vertices | runs | auto: method | auto encode ms | auto decode ms | auto CONN-only decode ms | polygon "
      "(forced) encode ms | polygon decode ms | polygon CONN-only decode ms |\n"
      "| --- | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (const Row& r : rows) {
    const QmcRun &a = r.automatic, &p = r.polygon;
    t += format("| %s | %zu | %d | %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(), r.vertices, r.runs,
                method_name(a).c_str(), ms(a, a.encode_s).c_str(), ms(a, a.decode_s).c_str(),
                ms(a, a.conn_decode_s).c_str(), ms(p, p.encode_s).c_str(), ms(p, p.decode_s).c_str(),
                ms(p, p.conn_decode_s).c_str());
  }
  return t;
}

std::string summary(const std::vector<Row>& rows) {
  size_t structured_ok = 0, quad = 0, polygon = 0, other = 0, draco_n = 0, qmc_smaller = 0;
  std::string failures;
  for (const Row& r : rows) {
    if (structured_check(r) == "yes") structured_ok++;
    else append_note(&failures, r.name);
    if (r.automatic.ok && r.automatic.stats.method == qmc::ConnectivityMethod::kQuad) quad++;
    else if (r.automatic.ok && r.automatic.stats.method == qmc::ConnectivityMethod::kPolygon) polygon++;
    else other++;
    if (r.automatic.ok && r.draco.ok) draco_n++, qmc_smaller += r.automatic.conn_bytes < r.draco.bytes;
  }
  std::string s = format("- Automatic choice: quad coder on %zu meshes, polygon coder on %zu, anything else on %zu.\n",
                         quad, polygon, other);
  s += format("- Structured CONN smaller than indexed CONN (auto and forced polygon coder): %zu of %zu meshes%s.\n",
              structured_ok, rows.size(), failures.empty() ? "" : (" (**not on: " + failures + "**)").c_str());
  s += format("- qmc auto CONN smaller than Draco's connectivity (same face structure): %zu of %zu meshes.\n",
              qmc_smaller, draco_n);
  return s;
}

// Observations computed from the rows, so that regenerating the file keeps
// them true: ranges per kind of mesh, never hand-written numbers.
struct Range {
  double lo = 0, hi = 0;
  size_t n = 0;
  void add(double v) {
    lo = n ? std::min(lo, v) : v;
    hi = n ? std::max(hi, v) : v;
    n++;
  }
  std::string str(const char* fmt) const {
    const std::string a = format(fmt, lo), b = format(fmt, hi);
    return a == b ? a : a + "–" + b;
  }
};

std::string observations(const std::vector<Row>& rows) {
  Range poly_ratio, poly_tri_ratio, tri_qmc, tri_draco, tri_ratio, forced_bytes, forced_bpv, empty_bits, record_bits;
  size_t poly_n = 0, poly_smaller = 0, tri_n = 0, tri_smaller = 0, tri_polygon_coder = 0, tri_all_triangle_symbols = 0;
  size_t quad_scope_polygon = 0;  // all-quad meshes the quad coder took, where coding 7 or 8 was smaller
  double share_max = -1;
  std::string share_max_mesh;
  for (const Row& r : rows) {
    const QmcRun &a = r.automatic, &p = r.polygon;
    if (a.ok && r.draco.ok) {
      const double ratio = double(a.conn_bytes) / double(r.draco.bytes);
      if (r.polygonal) {
        poly_n++, poly_smaller += ratio < 1, poly_ratio.add(ratio);
        if (r.draco_triangles.ok) poly_tri_ratio.add(double(a.conn_bytes) / double(r.draco_triangles.bytes));
      } else {
        tri_n++, tri_smaller += ratio < 1, tri_ratio.add(ratio);
        tri_qmc.add(bpv(double(a.conn_bytes), r.vertices));
        tri_draco.add(bpv(double(r.draco.bytes), r.vertices));
      }
    }
    if (!r.polygonal && a.ok && a.stats.method == qmc::ConnectivityMethod::kPolygon) {
      tri_polygon_coder++;
      tri_all_triangle_symbols +=
          a.stats.polygon.non_quad_faces == r.faces && a.stats.polygon.coding == qmc::kPolygonContextCoded;
    }
    quad_scope_polygon += a.ok && a.stats.method == qmc::ConnectivityMethod::kPolygon &&
                          a.stats.fallback_reason.find("smaller") != std::string::npos;
    if (a.ok && p.ok && a.stats.method == qmc::ConnectivityMethod::kQuad) {
      forced_bytes.add(double(p.conn_bytes) - double(a.conn_bytes));
      forced_bpv.add(bpv(double(p.conn_bytes) - double(a.conn_bytes), r.vertices));
    }
    if (p.ok) {
      const qmc::PolygonCoderStats& st = p.stats.polygon;
      if (st.holes + st.handles + st.identifications + st.loose_faces == 0) {
        empty_bits.add(double(st.record_bits));
        continue;
      }
      record_bits.add(double(st.record_bits));
      const double share = 100.0 * double(st.record_bits) / (8.0 * double(p.conn_bytes));
      if (share > share_max) share_max = share, share_max_mesh = r.name;
    }
  }
  std::string s;
  if (poly_n)
    s += format("- Meshes with faces of more than 3 corners (%zu): qmc's CONN is %s of Draco's connectivity with "
                "polygons preserved (smaller on %zu of %zu), and %s of Draco's triangulated output, which loses "
                "the polygons.\n",
                poly_n, poly_ratio.str("%.2f").c_str(), poly_smaller, poly_n, poly_tri_ratio.str("%.2f").c_str());
  if (tri_n)
    s += format("- Triangle meshes (%zu): the automatic choice gives %zu of them to the polygon coder (on %zu with "
                "coding 7, context-modelled (spec 5.4.10): their real faces are the triangle symbols 13..17): %s bits per vertex against %s "
                "for Draco, i.e. %s of Draco's, smaller on %zu of %zu.\n",
                tri_n, tri_polygon_coder, tri_all_triangle_symbols, tri_qmc.str("%.2f").c_str(),
                tri_draco.str("%.2f").c_str(), tri_ratio.str("%.2f").c_str(), tri_smaller, tri_n);
  if (quad_scope_polygon)
    s += format("- All-quad meshes in the quad coder's scope on which the automatic choice keeps the polygon coder "
                "because its CONN is smaller (coding 7 or 8): %zu.\n",
                quad_scope_polygon);
  if (forced_bytes.n)
    s += format("- On the %zu meshes the automatic choice gives to the quad coder, forcing the polygon coder "
                "costs %s bytes more (%s bits per vertex).\n",
                forced_bytes.n, forced_bytes.str("%.0f").c_str(), forced_bpv.str("%.2f").c_str());
  if (empty_bits.n + record_bits.n) {
    s += "- Records of the polygon coder (spec 5.4.7, 5.4.8):";
    if (empty_bits.n)
      s += format(" %s bits on the %zu meshes with no hole, handle, identification or loose face (the empty counts);",
                  empty_bits.str("%.0f").c_str(), empty_bits.n);
    if (record_bits.n)
      s += format(" %s bits on the other %zu, at most %.1f%% of CONN (%s)", record_bits.str("%.0f").c_str(),
                  record_bits.n, share_max, share_max_mesh.c_str());
    s += ". Not counted there: the face symbols of the virtual faces that close holes and seams, which are coded "
         "with the real faces.\n";
  }
  return s;
}

std::string document(const std::vector<Row>& rows, const Options& opt) {
  std::string doc = format(
      "qmc with `EncodeOptions::connectivity` = kAuto (the quad coder, method 1, where the mesh is in its scope and "
      "its CONN is not larger than the polygon coder's, else the polygon coder, method 2), kPolygon (the polygon coder forced) and kIndexed (method 0, the "
      "fallback); positions at %d bits per axis. Every qmc file is decoded and checked against the input (faces "
      "exactly, positions within half a step). Draco 1.5.5 at compression level 10 (edgebreaker) through "
      "bench/draco_runner, %d-bit positions.\n\n",
      opt.bits, opt.bits);
  doc += "## Summary\n\n" + summary(rows) + observations(rows) + "\n";
  doc += "## Connectivity bits per vertex\n\n"
         "qmc: the whole CONN chunk (12 bytes of framing included) x 8 / V. Draco has no separate connectivity "
         "stream, so **Draco's connectivity is the size of a Draco file of the same mesh with every position "
         "replaced by (0,0,0)** (a constant attribute costs a few bytes; the rest is the edgebreaker stream, the "
         "polygon flags and Draco's header) x 8 / V, V being the input's vertex count for both codecs. Draco mode: "
         "'polygons' (polygons preserved, Draco's OBJ-style 'added_edges' attribute) where the mesh has a face of "
         "more than 3 corners, else 'triangles'; for polygon meshes Draco's plain triangle mode is also shown "
         "('triangulated': the polygons are lost, so it does not carry the same mesh; for scale only).\n\n";
  doc += connectivity_table(rows) + "\n";
  doc += "## Topology the polygon coder records (kPolygon forced)\n\n"
         "From `EncodeStats::polygon` of the forced polygon-coder run (for meshes the automatic choice gives to "
         "the quad coder too). Holes are closed by virtual faces, each handle is cut into a seam, non-manifold "
         "vertices are split and identified again, faces that repeat a vertex are loose faces (spec 5.4.7, "
         "5.4.8). 'record bits' are the bits of those records; 'records / CONN' is their share of the whole CONN "
         "chunk.\n\n";
  doc += topology_table(rows) + "\n";
  doc += format("## qmc encode and decode times\n\n"
                "Medians of the given number of runs (%d; %d above %zu vertices), in process, from memory. Encode is "
                "`qmc::encode` of the whole file (it includes the encoder's own decode check of the structured "
                "connectivity); decode is `qmc::decode` of the whole file; CONN-only feeds `qmc::StreamDecoder` the "
                "file up to the end of CONN (signature, QHDR, CONN, no POSN).\n\n",
                opt.runs, opt.large_runs, kLargeVertices);
  doc += timing_table(rows);
  return doc;
}


[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: qmc_topology_bench [--runs N] [--large-runs N] [--bits B] MESH...\n");
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
    else if (!arg.empty() && arg[0] != '-') o.meshes.push_back(arg);
    else usage();
  }
  if (o.meshes.empty()) usage();
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse_args(argc, argv);
  const bool progress = isatty(STDERR_FILENO);
  std::vector<Row> rows;
  for (size_t i = 0; i < opt.meshes.size(); ++i) {
    const std::string& path = opt.meshes[i];
    const std::string name = qmc::bench::display_name(path);
    if (progress) std::fprintf(stderr, "\r[%zu/%zu] %-40s", i + 1, opt.meshes.size(), name.c_str());
    qmc::Mesh mesh;
    if (qmc::Status s = qmc::bench::read_geometry(path, &mesh, nullptr); !s.ok()) fail(path + ": " + s.to_string());
    rows.push_back(bench_mesh(name, mesh, opt));
  }
  if (progress) std::fprintf(stderr, "\r%60s\r", "");
  std::fputs(document(rows, opt).c_str(), stdout);
  return 0;
}
