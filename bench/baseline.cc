// qmc_baseline: qmc and Draco side by side on the same meshes, in one
// process and one run, so the ratios are measured under the same machine
// load. Writes a Markdown table (docs/results/baseline.md via
// scripts/bench.sh).
//
// Both codecs quantize positions to the same number of bits; Draco runs at
// compression level 10 (edgebreaker), with and without polygon preservation.
// Errors are measured the same way for both: for every input vertex, the
// distance to the nearest decoded vertex (Draco reorders and splits
// vertices, so there is no exact correspondence to use).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "bench_common.h"
#include "draco_runner.h"
#include "mesh_io.h"
#include "mesh_metrics.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace {

using Clock = std::chrono::steady_clock;
using qmc::bench::cpu_model;
using qmc::bench::median;

struct CodecRow {
  std::string codec;
  bool ok = false;
  std::string note;
  size_t bytes = 0;
  double encode_ms = 0, decode_ms = 0;
  qmc::tools::ErrorMetrics error;
};

CodecRow run_qmc(const qmc::Mesh& mesh, int bits, int runs) {
  CodecRow row;
  row.codec = "qmc";
  qmc::EncodeOptions options;
  options.position_bits = bits;
  std::vector<uint8_t> bytes;
  std::vector<double> enc, dec;
  qmc::DecodedFile decoded;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    const qmc::Status s = qmc::encode(mesh, options, &bytes);
    const auto t1 = Clock::now();
    if (!s.ok()) {
      row.note = s.to_string();
      return row;
    }
    enc.push_back(std::chrono::duration<double>(t1 - t0).count());
  }
  for (int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    const qmc::Status s = qmc::decode(bytes.data(), bytes.size(), &decoded, qmc::DecoderLimits::unlimited());
    const auto t1 = Clock::now();
    if (!s.ok()) {
      row.note = s.to_string();
      return row;
    }
    dec.push_back(std::chrono::duration<double>(t1 - t0).count());
  }
  row.ok = true;
  row.bytes = bytes.size();
  row.encode_ms = 1e3 * median(enc);
  row.decode_ms = 1e3 * median(dec);
  row.error = qmc::tools::nearest_vertex_error(mesh, decoded.mesh);
  row.note = std::string(qmc::connectivity_method_name(decoded.method)) + " connectivity";
  return row;
}

std::string draco_note(const qmc::bench::DracoResult& r) {
  std::string note;
  auto add = [&](size_t n, const char* what) {
    if (n == 0) return;
    if (!note.empty()) note += "; ";
    note += std::to_string(n) + " " + what;
  };
  add(r.unreferenced_vertices, "unreferenced vertices not stored");
  add(r.dropped_faces, "faces dropped");
  add(r.damaged_faces, "faces damaged");
  add(r.dropped_triangles, "triangles dropped");
  add(r.unrecovered_polygons, "polygons not recovered");
  return note;
}

CodecRow run_draco_row(const qmc::Mesh& mesh, int bits, int runs, bool polygons) {
  CodecRow row;
  row.codec = polygons ? "Draco, polygons" : "Draco, triangles";
  qmc::bench::DracoOptions options;
  options.position_bits = bits;
  options.compression_level = 10;
  options.preserve_polygons = polygons;
  const qmc::bench::DracoResult r = qmc::bench::run_draco(mesh, options, runs);
  if (!r.ok) {
    row.note = r.error;
    return row;
  }
  row.ok = true;
  row.bytes = r.bytes;
  row.encode_ms = 1e3 * median(r.encode_seconds);
  row.decode_ms = 1e3 * median(r.decode_seconds);
  row.error = qmc::tools::nearest_vertex_error(mesh, r.decoded);
  row.note = draco_note(r);
  return row;
}

bool has_polygons(const qmc::Mesh& mesh) {
  return std::any_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](uint32_t d) { return d != 3; });
}

std::string format_row(const std::string& mesh, size_t vertices, const CodecRow& row, size_t qmc_bytes) {
  char buf[512];
  if (!row.ok) {
    std::snprintf(buf, sizeof buf, "| %s | %s | failed: %s | | | | | | |\n", mesh.c_str(), row.codec.c_str(),
                  row.note.c_str());
    return buf;
  }
  const double side = row.error.max_bbox_side > 0 ? row.error.max_bbox_side : 1;
  std::snprintf(buf, sizeof buf, "| %s | %s | %zu | %.2f | %.2f | %.3f | %.3f | %.2e | %.2e | %s |\n", mesh.c_str(),
                row.codec.c_str(), row.bytes, 8.0 * double(row.bytes) / double(vertices ? vertices : 1),
                double(qmc_bytes) / double(row.bytes), row.encode_ms, row.decode_ms, row.error.max_error / side,
                row.error.rms_error / side, row.note.c_str());
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 7, bits = 12;
  std::string out_path;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--bits" && i + 1 < argc) bits = std::atoi(argv[++i]);
    else if (arg == "--out" && i + 1 < argc) out_path = argv[++i];
    else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "usage: qmc_baseline [--runs N] [--bits B] [--out FILE.md] MESH...\n");
      return 2;
    } else meshes.push_back(arg);
  }
  const bool progress = isatty(STDERR_FILENO);
  std::string table;
  table += "| mesh | codec | bytes | bits/vertex | qmc / this | encode ms | decode ms | max err / side | rms err / side | notes |\n";
  table += "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
  for (size_t m = 0; m < meshes.size(); ++m) {
    const std::string& path = meshes[m];
    // Folder and file name: corpus/quad/x and corpus/tri/x stay apart.
    const size_t slash = path.find_last_of('/');
    const size_t parent = slash == std::string::npos || slash == 0 ? std::string::npos : path.find_last_of('/', slash - 1);
    const std::string name = parent == std::string::npos ? path : path.substr(parent + 1);
    if (progress) std::fprintf(stderr, "\r[%zu/%zu] %-40s", m + 1, meshes.size(), name.c_str());
    qmc::Mesh mesh;
    std::vector<std::string> warnings;
    if (qmc::Status s = qmc::bench::read_geometry(path, &mesh, &warnings); !s.ok()) {
      std::fprintf(stderr, "\nqmc_baseline: %s\n", s.to_string().c_str());
      return 3;
    }
    const CodecRow q = run_qmc(mesh, bits, runs);
    std::vector<CodecRow> rows = {q, run_draco_row(mesh, bits, runs, false)};
    if (has_polygons(mesh)) rows.push_back(run_draco_row(mesh, bits, runs, true));
    for (const CodecRow& row : rows) table += format_row(name, mesh.vertex_count(), row, q.bytes);
  }
  if (progress) std::fprintf(stderr, "\r%60s\r", "");

  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::string doc;
  doc += "Measured " + std::string(date) + " on " + cpu_model() + ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) +
         " cores. Positions quantized to " + std::to_string(bits) + " bits per axis by both codecs; Draco 1.5.5 at "
         "compression level 10 (edgebreaker). Times are medians of " + std::to_string(runs) +
         " runs, in process, of encode-to-buffer and decode-from-buffer only (no file I/O). Errors: for every input "
         "vertex the distance to the nearest decoded vertex, relative to the largest bounding-box side. "
         "'qmc / this' is qmc's bytes over the row's bytes (below 1: qmc is smaller).\n\n";
  doc += table;
  if (out_path.empty()) {
    std::fputs(doc.c_str(), stdout);
  } else {
    std::ofstream out(out_path);
    out << doc;
  }
  return 0;
}
