// qmc_compression_bench: issue 13's benchmark. qmc with default options
// against Draco 1.5.5 (compression levels 10 and 7) and meshoptimizer + zstd,
// all on Draco's grid (one step for all axes: the largest side of the box /
// (2^bits - 1)), per mesh and per bits. Reports positions and whole-file
// sizes, decode and encode times, and each of the targets with the
// meshes that meet it and the worst case; failures are shown, never tuned
// away. Writes Markdown (docs/results/compression.md via scripts/bench.sh).
//
// Timing: in each round every codec encodes and decodes once, in the same
// order, so that a slow moment of the machine hits all of them; medians over
// the rounds; ratios are of medians from the same run.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.h"
#include "cold_heap.h"
#include "draco_runner.h"
#include "mesh_io.h"
#include "meshopt_runner.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace {

using qmc::bench::format;
using qmc::bench::median;

constexpr double kPositionsTarget = 0.80;      // qmc POSN / Draco cl10 positions, at most
constexpr double kPolygonWholeTarget = 0.70;   // qmc / Draco cl10 whole file, quad/ meshes, at most
constexpr double kTriangleWholeTarget = 1.0;   // the same, triangle meshes
constexpr double kDecodeSpeedTarget = 2.0;     // Draco cl10 decode time / qmc's, at least
constexpr size_t kDecodeSpeedMinVertices = 10000;  // ... on meshes above this many vertices
constexpr double kEncodeTimeTarget = 1.5;      // qmc encode time / Draco cl10's, at most

// A round's sample of a codec is the mean of enough back-to-back repetitions
// to last this long (at least one), so that meshes of a few vertices are not
// timed at the clock's resolution; meshes above ~1k vertices take one.
constexpr double kMinSampleSeconds = 0.002;
constexpr int kMaxRepetitions = 1000;

[[noreturn]] void fail(const std::string& message) { qmc::bench::fail("qmc_compression_bench", message); }

struct Options {
  int runs = 5;
  bool fail_on_error = false;  // exit 1 if any codec failed on any mesh (the smoke test)
  std::vector<int> bits = {12, 14, 16};
  std::vector<std::string> meshes;
};

// ---------------------------------------------------------------------------
// One codec's figures for one mesh and bits

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / double(values.size());
}

// One sample per round (the mean of its repetitions), median over rounds.
struct Timings {
  std::vector<double> encode_s, decode_s;
  std::vector<double> cold_decode_s;  // one decode a round from a cold heap (bench/cold_heap.h)
  double encode_ms() const { return 1e3 * median(encode_s); }
  double decode_ms() const { return 1e3 * median(decode_s); }
  double cold_decode_ms() const { return 1e3 * median(cold_decode_s); }
  void add(const std::vector<double>& encode_repetitions, const std::vector<double>& decode_repetitions) {
    encode_s.push_back(mean(encode_repetitions));
    decode_s.push_back(mean(decode_repetitions));
  }
  // Repetitions for kMinSampleSeconds of the shorter of encode and decode.
  int repetitions() const {
    if (encode_s.empty()) return 1;
    const double shortest = std::min(encode_s.back(), decode_s.back());
    if (shortest <= 0) return kMaxRepetitions;
    return static_cast<int>(std::clamp(std::ceil(kMinSampleSeconds / shortest), 1.0, double(kMaxRepetitions)));
  }
};

struct QmcFigures {
  std::string error;  // empty: ok
  std::string grid;   // empty: qmc's grid is Draco's; else how it differs
  uint64_t file_bytes = 0, conn_bytes = 0, posn_bytes = 0;
  qmc::PositionStats positions;
  Timings time;
};

struct DracoFigures {
  std::string error;  // empty: ok
  size_t bytes = 0;
  std::string losses;  // what Draco did not store, which qmc does
  Timings time;
};

struct MeshoptFigures {
  std::string error;
  qmc::bench::MeshoptResult sizes;  // of the first round; the bytes are the same every round
  Timings time;
};

struct Case {
  std::string name;
  bool polygons = false;  // quad/ set: Draco preserves polygons, whole-file target 0.70
  int bits = 0;
  size_t vertices = 0;
  size_t unused_dropped = 0;  // vertices no face uses, left out for every codec
  QmcFigures qmc;
  DracoFigures cl10, cl10_connectivity, cl7;
  MeshoptFigures meshopt;
};

// ---------------------------------------------------------------------------
// Running the codecs

uint64_t chunk_bytes(const qmc::EncodeStats& stats, uint32_t type) {
  uint64_t bytes = 0;
  for (const qmc::ChunkStats& c : stats.chunks)
    if (c.type == type) bytes += c.bytes;
  return bytes;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// qmc with its default options but the bits, `repetitions` encodes then as
// many decodes.
void qmc_round(const qmc::Mesh& mesh, int bits, int repetitions, QmcFigures* q) {
  if (!q->error.empty()) return;
  qmc::EncodeOptions options;
  options.position_bits = bits;
  std::vector<uint8_t> file;
  qmc::EncodeStats stats;
  std::vector<double> encode_s, decode_s;
  for (int r = 0; r < repetitions; ++r) {
    file.clear();
    stats = {};
    const auto start = std::chrono::steady_clock::now();
    const qmc::Status status = qmc::encode(mesh, options, &file, &stats);
    encode_s.push_back(seconds_since(start));
    if (!status.ok()) {
      q->error = "encode: " + status.to_string();
      return;
    }
  }
  qmc::DecodedFile decoded;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const qmc::Status status = qmc::decode(file.data(), file.size(), &decoded, qmc::DecoderLimits::unlimited());
    decode_s.push_back(seconds_since(start));
    if (!status.ok()) {
      q->error = "decode: " + status.to_string();
      return;
    }
  }
  if (decoded.mesh.vertex_count() != mesh.vertex_count() || decoded.mesh.face_count() != mesh.face_count()) {
    q->error = "decoded a mesh of another size";
    return;
  }
  decoded = {};
  qmc::bench::hand_heap_back();
  const auto start = std::chrono::steady_clock::now();
  const qmc::Status cold = qmc::decode(file.data(), file.size(), &decoded, qmc::DecoderLimits::unlimited());
  q->time.cold_decode_s.push_back(seconds_since(start));
  if (!cold.ok()) {
    q->error = "decode from a cold heap: " + cold.to_string();
    return;
  }
  q->time.add(encode_s, decode_s);
  q->file_bytes = file.size();
  q->conn_bytes = chunk_bytes(stats, qmc::kChunkConnectivity);
  q->posn_bytes = chunk_bytes(stats, qmc::kChunkPositions);
  q->positions = stats.positions;
}

std::string draco_losses(const qmc::bench::DracoResult& r) {
  std::string note;
  const std::pair<size_t, const char*> counts[] = {{r.dropped_triangles, "triangles dropped"},
                                                   {r.unreferenced_vertices, "unreferenced vertices not stored"},
                                                   {r.unrecovered_polygons, "polygons not recovered"}};
  for (const auto& [n, what] : counts)
    if (n) note += format("%s%zu %s", note.empty() ? "" : ", ", n, what);
  return note;
}

void draco_round(const qmc::Mesh& mesh, const qmc::bench::DracoOptions& options, int repetitions,
                 DracoFigures* d) {
  if (!d->error.empty()) return;
  const qmc::bench::DracoResult r = qmc::bench::run_draco(mesh, options, repetitions);
  if (!r.ok) {
    d->error = r.error;
    return;
  }
  d->bytes = r.bytes;
  d->losses = draco_losses(r);
  d->time.add(r.encode_seconds, r.decode_seconds);
  if (options.cold_heap_decode) d->time.cold_decode_s.push_back(r.cold_decode_seconds);
}

qmc::bench::DracoOptions draco_options(int bits, int level, bool polygons, bool at_origin) {
  qmc::bench::DracoOptions options;
  options.position_bits = bits;
  options.compression_level = level;
  options.preserve_polygons = polygons;
  options.positions_at_origin = at_origin;
  return options;
}

void meshopt_round(const qmc::Mesh& mesh, int bits, int repetitions, MeshoptFigures* m) {
  if (!m->error.empty()) return;
  qmc::bench::MeshoptOptions options;
  options.position_bits = bits;
  const qmc::bench::MeshoptResult r = qmc::bench::run_meshopt(mesh, options, repetitions);
  if (!r.ok) {
    m->error = r.error;
    return;
  }
  m->sizes = r;
  m->time.add(r.encode_seconds, r.decode_seconds);
}

// qmc's default grid must be Draco's for the comparison to hold: the same
// step on every axis that has an extent (a flat axis has step 0 in qmc).
std::string grid_difference(const qmc::PositionStats& qmc_grid, double draco_step) {
  for (int a = 0; a < 3; ++a) {
    const double step = qmc_grid.step[a];
    if (step != 0 && std::fabs(step - draco_step) > 1e-6 * draco_step)
      return format("axis %d step %.9g, Draco's %.9g", a, step, draco_step);
  }
  return {};
}

bool has_polygon(const qmc::Mesh& mesh) {
  return std::any_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](uint32_t n) { return n > 3; });
}

bool qmc_ok(const Case& c) { return c.qmc.error.empty(); }

struct Repetitions {
  int qmc = 1, cl10 = 1, cl7 = 1, meshopt = 1;
};

// Every codec once, in a fixed order.
void run_round(const qmc::Mesh& mesh, const Repetitions& n, Case* c) {
  qmc_round(mesh, c->bits, n.qmc, &c->qmc);
  qmc::bench::DracoOptions cl10 = draco_options(c->bits, 10, c->polygons, false);
  cl10.cold_heap_decode = true;
  draco_round(mesh, cl10, n.cl10, &c->cl10);
  draco_round(mesh, draco_options(c->bits, 7, c->polygons, false), n.cl7, &c->cl7);
  meshopt_round(mesh, c->bits, n.meshopt, &c->meshopt);
}

Case measure(const std::string& name, const qmc::Mesh& mesh, size_t unused_dropped, int bits, int runs) {
  Case c;
  c.name = name;
  c.unused_dropped = unused_dropped;
  c.polygons = name.rfind("quad/", 0) == 0 || has_polygon(mesh);
  c.bits = bits;
  c.vertices = mesh.vertex_count();
  // A warm-up round, not reported: it fills the caches and tells how many
  // repetitions make a sample of each codec.
  Case warm_up = c;
  run_round(mesh, Repetitions{}, &warm_up);
  const Repetitions n = {warm_up.qmc.time.repetitions(), warm_up.cl10.time.repetitions(),
                         warm_up.cl7.time.repetitions(), warm_up.meshopt.time.repetitions()};
  for (int r = 0; r < runs; ++r) run_round(mesh, n, &c);
  // Deterministic bytes: once.
  draco_round(mesh, draco_options(bits, 10, c.polygons, true), 1, &c.cl10_connectivity);
  if (qmc_ok(c)) c.qmc.grid = grid_difference(c.qmc.positions, qmc::bench::draco_grid_step(mesh, bits));
  return c;
}

// ---------------------------------------------------------------------------
// Ratios and targets. A ratio is absent (nullopt-like: < 0) where a side failed.

bool draco_positions_ok(const Case& c) { return c.cl10.error.empty() && c.cl10_connectivity.error.empty(); }

long long draco_positions(const Case& c) {
  return static_cast<long long>(c.cl10.bytes) - static_cast<long long>(c.cl10_connectivity.bytes);
}
double positions_ratio(const Case& c) {
  if (!qmc_ok(c) || !draco_positions_ok(c) || draco_positions(c) <= 0) return -1;
  return double(c.qmc.posn_bytes) / double(draco_positions(c));
}
double whole_ratio(const Case& c) {
  return qmc_ok(c) && c.cl10.error.empty() ? double(c.qmc.file_bytes) / double(c.cl10.bytes) : -1;
}
double decode_speed_ratio(const Case& c) {
  return qmc_ok(c) && c.cl10.error.empty() ? c.cl10.time.decode_ms() / c.qmc.time.decode_ms() : -1;
}
double cold_decode_speed_ratio(const Case& c) {
  return qmc_ok(c) && c.cl10.error.empty() ? c.cl10.time.cold_decode_ms() / c.qmc.time.cold_decode_ms() : -1;
}
double encode_time_ratio(const Case& c) {
  return qmc_ok(c) && c.cl10.error.empty() ? c.qmc.time.encode_ms() / c.cl10.time.encode_ms() : -1;
}

struct Target {
  std::string what;
  bool at_least = false;  // false: the ratio must be at most the bound
  double bound = 0;
  std::function<bool(const Case&)> applies;
  std::function<double(const Case&)> ratio;
  bool met(double r) const { return at_least ? r >= bound : r <= bound; }
};

std::vector<Target> targets() {
  const auto every = [](const Case&) { return true; };
  return {
      {format("Positions: qmc POSN <= %.2fx Draco cl10's positions", kPositionsTarget), false, kPositionsTarget,
       every, positions_ratio},
      {format("Whole file, quad/ (polygons preserved): qmc <= %.2fx Draco cl10", kPolygonWholeTarget), false,
       kPolygonWholeTarget, [](const Case& c) { return c.polygons; }, whole_ratio},
      {format("Whole file, triangle meshes: qmc <= %.2fx Draco cl10", kTriangleWholeTarget), false,
       kTriangleWholeTarget, [](const Case& c) { return !c.polygons; }, whole_ratio},
      {format("Decode: qmc >= %.0fx Draco cl10's speed (meshes above %zu vertices)", kDecodeSpeedTarget,
              kDecodeSpeedMinVertices),
       true, kDecodeSpeedTarget, [](const Case& c) { return c.vertices > kDecodeSpeedMinVertices; },
       decode_speed_ratio},
      {format("Encode: qmc's time <= %.1fx Draco cl10's", kEncodeTimeTarget), false, kEncodeTimeTarget, every,
       encode_time_ratio},
  };
}

std::string verdict(const Target& t, const Case& c) {
  if (!t.applies(c)) return "n/a";
  const double r = t.ratio(c);
  if (r < 0) return "-";
  return t.met(r) ? "pass" : "**FAIL**";
}

// Not a target of the issue: the same speed-up for a decode from a cold heap.
std::string cold_heap_summary(const std::vector<Case>& cases) {
  size_t above = 0, measured = 0;
  double log_sum = 0;
  for (const Case& c : cases) {
    const double r = cold_decode_speed_ratio(c);
    if (c.vertices <= kDecodeSpeedMinVertices || r < 0) continue;
    ++measured;
    above += r >= kDecodeSpeedTarget;
    log_sum += std::log(r);
  }
  if (measured == 0) return {};
  return format("- Decode from a cold heap (not a target; the first decode of a process, see below): qmc >= %.0fx "
                "Draco cl10's speed in %zu of %zu cases above %zu vertices; geometric mean %.3f.\n",
                kDecodeSpeedTarget, above, measured, kDecodeSpeedMinVertices, std::exp(log_sum / double(measured)));
}

std::string summary(const std::vector<Case>& cases) {
  std::string s;
  for (const Target& t : targets()) {
    size_t met = 0, measured = 0, missing = 0;
    double log_sum = 0;
    const Case* worst = nullptr;
    for (const Case& c : cases) {
      if (!t.applies(c)) continue;
      const double r = t.ratio(c);
      if (r < 0) {
        ++missing;
        continue;
      }
      ++measured;
      met += t.met(r);
      log_sum += std::log(r);
      if (!worst || (t.at_least ? r < t.ratio(*worst) : r > t.ratio(*worst))) worst = &c;
    }
    s += format("- %s: **met in %zu of %zu** (mesh, bits) cases", t.what.c_str(), met, measured);
    if (worst)
      s += format("; worst: %s at %d bits, %.3f; geometric mean %.3f", worst->name.c_str(), worst->bits,
                  t.ratio(*worst), std::exp(log_sum / double(measured)));
    if (missing) s += format("; %zu not measured (a codec failed: see the notes)", missing);
    s += ".\n";
  }
  return s + cold_heap_summary(cases);
}

// ---------------------------------------------------------------------------
// Tables

std::string bytes_cell(const std::string& error, unsigned long long bytes) {
  return error.empty() ? format("%llu", bytes) : "failed";
}
std::string ratio_cell(double r) { return r < 0 ? "-" : format("%.3f", r); }
std::string ms_cell(const std::string& error, double ms) { return error.empty() ? format("%.3f", ms) : "-"; }

std::string sizes_table(const std::vector<Case>& cases) {
  const std::vector<Target> t = targets();
  std::string s =
      "| mesh | bits | vertices | qmc POSN | Draco cl10 positions | POSN ratio | <= 0.80 | qmc whole | Draco cl10 "
      "whole | whole ratio | target | Draco cl7 whole | meshopt + zstd whole |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | --- | ---: | ---: |\n";
  for (const Case& c : cases) {
    const std::string draco_posn = draco_positions_ok(c) ? format("%lld", draco_positions(c)) : "failed";
    const std::string whole_verdict = c.polygons ? verdict(t[1], c) + " (0.70)" : verdict(t[2], c) + " (1.0)";
    s += format("| %s | %d | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.name.c_str(), c.bits,
                c.vertices, bytes_cell(c.qmc.error, c.qmc.posn_bytes).c_str(), draco_posn.c_str(),
                ratio_cell(positions_ratio(c)).c_str(), verdict(t[0], c).c_str(),
                bytes_cell(c.qmc.error, c.qmc.file_bytes).c_str(), bytes_cell(c.cl10.error, c.cl10.bytes).c_str(),
                ratio_cell(whole_ratio(c)).c_str(), whole_verdict.c_str(),
                bytes_cell(c.cl7.error, c.cl7.bytes).c_str(),
                bytes_cell(c.meshopt.error, c.meshopt.sizes.bytes).c_str());
  }
  return s;
}

std::string times_table(const std::vector<Case>& cases) {
  const std::vector<Target> t = targets();
  std::string s =
      "| mesh | bits | vertices | qmc decode ms | Draco cl10 decode ms | speed-up (Draco ms / qmc ms) | >= 2 (> 10k vertices) | "
      "cold heap: qmc / Draco cl10 decode ms | cold heap speed-up | qmc "
      "encode ms | Draco cl10 encode ms | qmc / Draco | <= 1.5 | Draco cl7 decode / encode ms | meshopt + zstd "
      "decode / encode ms |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: |\n";
  for (const Case& c : cases) {
    s += format("| %s | %d | %zu | %s | %s | %s | %s | %s / %s | %s | %s | %s | %s | %s | %s / %s | %s / %s |\n",
                c.name.c_str(), c.bits, c.vertices, ms_cell(c.qmc.error, c.qmc.time.decode_ms()).c_str(),
                ms_cell(c.cl10.error, c.cl10.time.decode_ms()).c_str(), ratio_cell(decode_speed_ratio(c)).c_str(),
                verdict(t[3], c).c_str(), ms_cell(c.qmc.error, c.qmc.time.cold_decode_ms()).c_str(),
                ms_cell(c.cl10.error, c.cl10.time.cold_decode_ms()).c_str(),
                ratio_cell(cold_decode_speed_ratio(c)).c_str(), ms_cell(c.qmc.error, c.qmc.time.encode_ms()).c_str(),
                ms_cell(c.cl10.error, c.cl10.time.encode_ms()).c_str(), ratio_cell(encode_time_ratio(c)).c_str(),
                verdict(t[4], c).c_str(), ms_cell(c.cl7.error, c.cl7.time.decode_ms()).c_str(),
                ms_cell(c.cl7.error, c.cl7.time.encode_ms()).c_str(),
                ms_cell(c.meshopt.error, c.meshopt.time.decode_ms()).c_str(),
                ms_cell(c.meshopt.error, c.meshopt.time.encode_ms()).c_str());
  }
  return s;
}

// Share of the vertices per prediction kind (section 14.3.2), in percent.
std::string kind_shares(const qmc::PositionStats& p) {
  uint64_t total = 0;
  for (uint32_t n : p.vertices_by_kind) total += n;
  if (total == 0) return "-";
  std::string s;
  for (uint32_t n : p.vertices_by_kind) s += format("%s%.0f", s.empty() ? "" : " / ", 100.0 * n / double(total));
  return s;
}

// Information content per vertex of each kind ("-" where no vertex is).
std::string kind_bits(const qmc::PositionStats& p) {
  std::string s;
  for (int k = 0; k < int(p.vertices_by_kind.size()); ++k) {
    const uint32_t n = p.vertices_by_kind[k];
    s += (k ? " / " : "") + (n ? format("%.1f", p.bits_by_kind[k] / n) : std::string("-"));
  }
  return s;
}

std::string notes(const Case& c) {
  std::string n;
  if (c.unused_dropped > 0) n = format("%zu vertices no face uses left out for every codec", c.unused_dropped);
  const std::pair<const char*, const std::string*> parts[] = {
      {"qmc", &c.qmc.error},          {"qmc's grid is not Draco's", &c.qmc.grid},
      {"Draco cl10", &c.cl10.error},  {"Draco cl10", &c.cl10.losses},
      {"Draco cl7", &c.cl7.error},    {"Draco at origin", &c.cl10_connectivity.error},
      {"meshopt", &c.meshopt.error}};
  for (const auto& [who, text] : parts)
    if (!text->empty()) n += format("%s%s: %s", n.empty() ? "" : "; ", who, text->c_str());
  return n;
}

// A codec failed, or qmc's grid is not Draco's: the figures do not compare.
bool failed(const Case& c) {
  return !c.qmc.error.empty() || !c.qmc.grid.empty() || !c.cl10.error.empty() || !c.cl7.error.empty() ||
         !c.cl10_connectivity.error.empty() || !c.meshopt.error.empty();
}

std::string parts_table(const std::vector<Case>& cases) {
  std::string s =
      "| mesh | bits | qmc CONN | qmc POSN bits/vertex | POSN method | vertices by kind 0/1/2/3 % | bits/vertex by kind "
      "0/1/2/3 | Draco cl10 at origin (connectivity) | meshopt index / vertex zstd | notes |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
  for (const Case& c : cases) {
    const bool q = qmc_ok(c);
    s += format("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s |\n", c.name.c_str(), c.bits,
                bytes_cell(c.qmc.error, c.qmc.conn_bytes).c_str(),
                q ? format("%.2f", qmc::bench::bits_per_vertex(double(c.qmc.posn_bytes), c.vertices)).c_str() : "-",
                q ? format("%d", c.qmc.positions.method).c_str() : "-",
                q ? kind_shares(c.qmc.positions).c_str() : "-", q ? kind_bits(c.qmc.positions).c_str() : "-",
                bytes_cell(c.cl10_connectivity.error, c.cl10_connectivity.bytes).c_str(),
                c.meshopt.error.empty()
                    ? format("%zu / %zu", c.meshopt.sizes.index_bytes, c.meshopt.sizes.vertex_bytes).c_str()
                    : "-",
                notes(c).c_str());
  }
  return s;
}

std::string document(const std::vector<Case>& cases, const Options& opt, double seconds) {
  // Built by concatenation: format() has a bounded buffer.
  std::string doc =
      "Every mesh is read as its positions and faces (bench/bench_common.h, `read_geometry`: texture "
      "coordinates, normals, colours and face labels are left out; attributes.md compares those), without "
      "the vertices no face uses (`drop_unused_vertices`): Draco's edgebreaker does not keep them (its decoder "
      "gives stanford-bunny's 34,834 vertices of faces, not the file's 35,947), qmc does, so the bytes compare "
      "the same mesh only without them (the parts table names the meshes that had some). "
      "Every codec rounds positions to the same grid, Draco's: one step for all axes, the largest side of the "
      "bounding box / (2^bits - 1). **qmc**: `qmc::encode` with default options but `position_bits` "
      "(uniform grid, automatic connectivity and POSN method), decoded by `qmc::decode` with "
      "`DecoderLimits::unlimited()`. **Draco 1.5.5** in memory through bench/draco_runner (edgebreaker; for "
      "quad/ meshes polygons preserved with draco_encoder's `added_edges` attribute, for triangle meshes plain "
      "triangles; its bytes equal `draco_encoder -qp B -cl L [-preserve_polygons]` on the same positions-only "
      "OBJ, checked on cow, bunny_small, 3holes, fandisk_quads and horse_quad at 12 bits, cl10 and cl7). **Draco's positions** = its whole cl10 file minus the cl10 file of the same mesh with every "
      "position at (0,0,0) (a constant attribute still costs a few bytes, so this slightly flatters Draco). "
      "**meshoptimizer 0.18 + zstd -19** as its users run it (bench/meshopt_runner.h): fan triangulation, "
      "optimizeVertexCache + optimizeVertexFetch, the grid integers as uint16 x 4 (uint32 x 3 above 16 bits), "
      "encodeIndexBuffer + encodeVertexBuffer, each stream zstd -19, plus a 28-byte header (counts, frame "
      "size, grid); polygons are not kept.\n\n";
  doc += "Bytes are whole chunks (12 bytes of framing included) and whole files. Times are medians of " +
         std::to_string(opt.runs) +
         " rounds after an unreported warm-up round; in each round every codec encodes and decodes the mesh in "
         "turn, so ratios compare the same moments of the machine. A codec's sample in a round is the mean of "
         "enough back-to-back repetitions to last " + format("%.0f", 1e3 * kMinSampleSeconds) +
         " ms for the shorter of its encode and decode (one repetition above ~1k vertices), as the clock "
         "cannot time an 8-vertex cube. qmc's encode time is all of `qmc::encode` from a `qmc::Mesh`; Draco's is "
         "`EncodeToBuffer` (building its `draco::Mesh` untimed), its decode `DecodeMeshFromBuffer` (turning "
         "triangles back into polygons untimed); meshopt's encode runs from the `qmc::Mesh` to the bytes, its "
         "decode is zstd plus its two decoders, to integer buffers. Decode ratio = Draco cl10 decode time / "
         "qmc's (higher is better); encode ratio = qmc / Draco cl10 (lower is better). Mesh sets: quad/ meshes "
         "(and any with a face of more than 3 corners) are held to the polygon target, the others to the "
         "triangle target.\n\n"
         "Decodes repeated in one process reuse the pages the previous one touched. The first decode of a "
         "process (a `qmc decode` run, a viewer opening its first file) takes a page fault for every page it "
         "writes first, which on this virtual machine costs microseconds each. The **cold heap** columns time "
         "one more decode per round and codec (qmc and Draco cl10) after `malloc_trim(0)` has handed every free "
         "page of the heap back to the system (bench/cold_heap.h), so that it faults in all the memory it "
         "touches, as in a new process.\n\n";
  doc += "## Summary against issue 13's targets\n\n" + summary(cases) + "\n";
  doc += "## Sizes (bytes)\n\n" + sizes_table(cases) + "\n";
  doc += "## Times (ms, medians)\n\n" + times_table(cases) + "\n";
  doc += "## Parts\n\n"
         "qmc's CONN and POSN chunks, POSN's method (0: deltas, 1: predicted), and per prediction kind of "
         "section 14.3.2 (method 1 only; kinds as the encoder reports them in `PositionStats`: 0 previous "
         "vertex, 1 mean of decoded neighbours, 2 one rule, 3 several) the share of vertices and the "
         "information content per vertex (`bits_by_kind` / `vertices_by_kind`: -log2 of the coded decisions' "
         "probabilities, before the coder's flush and framing); Draco's connectivity-only file; meshopt's two "
         "zstd frames. Notes say where a codec failed, where qmc's grid step differs from Draco's (checked on "
         "every row), or what Draco did not store (qmc keeps every face and vertex).\n\n";
  doc += parts_table(cases) + "\n";
  doc += format("Run time of the whole benchmark: %.0f s.\n", seconds);
  return doc;
}

// ---------------------------------------------------------------------------

[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: qmc_compression_bench [--runs N] [--bits B,B,...] [--fail-on-error] MESH...\n");
  std::exit(2);
}

std::vector<int> parse_bits(const std::string& list) {
  std::vector<int> bits;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    const int b = std::atoi(item.c_str());
    if (b < 1 || b > 30) usage();
    bits.push_back(b);
  }
  if (bits.empty()) usage();
  return bits;
}

Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--runs" && has_value) o.runs = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--bits" && has_value) o.bits = parse_bits(argv[++i]);
    else if (arg == "--fail-on-error") o.fail_on_error = true;
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
  const auto start = std::chrono::steady_clock::now();
  std::vector<Case> cases;
  for (const std::string& path : opt.meshes) {
    qmc::Mesh mesh;
    if (qmc::Status s = qmc::bench::read_geometry(path, &mesh, nullptr); !s.ok()) fail(path + ": " + s.to_string());
    const size_t unused = qmc::bench::drop_unused_vertices(&mesh);
    const std::string name = qmc::bench::display_name(path);
    for (int bits : opt.bits) {
      if (progress) std::fprintf(stderr, "\r%-40s %2d bits", name.c_str(), bits);
      cases.push_back(measure(name, mesh, unused, bits, opt.runs));
    }
  }
  if (progress) std::fprintf(stderr, "\r%60s\r", "");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fputs(document(cases, opt, seconds).c_str(), stdout);
  const bool any_failed = std::any_of(cases.begin(), cases.end(), failed);
  return opt.fail_on_error && any_failed ? 1 : 0;
}
