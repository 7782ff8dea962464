// qmc compare: surface-to-surface error between two meshes (Metro-style
// Hausdorff, L2 and mean distances, PSNR of seed 002 eq. (1)).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "mesh_distance.h"

namespace qmc::cli {
namespace {

const char kHelp[] =
    "usage: qmc compare A B [--samples N] [--seed S] [--json]\n"
    "\n"
    "Measures how far the surfaces of two meshes (.obj .off .ply .stl) are from\n"
    "each other, as Metro does (Cignoni, Rocchini, Scopigno 1998). Faces are\n"
    "fan-triangulated; N points (default 200000) are spread area-uniformly over\n"
    "each surface, and every referenced vertex is added; each point's distance to\n"
    "the other surface is exact. A should be the original: relative values are\n"
    "divided by its bounding-box diagonal.\n"
    "\n"
    "  Hausdorff  max over both directions of the largest point distance\n"
    "  L2         max over both directions of the RMS distance of the area samples\n"
    "  mean       max over both directions of the mean distance of the area samples\n"
    "  PSNR       20 log10(bbox diagonal of A / L2) dB (seed 002 eq. 1); inf (JSON:\n"
    "             null) when L2 is 0\n"
    "\n"
    "The sampling is deterministic for a given seed (default 1). Exit 0 when the\n"
    "distances were measured, 2 on bad usage, 3 if a mesh cannot be read or has no\n"
    "face of non-zero area.\n";


void print_text(const std::string& path_a, const Mesh& a, const std::string& path_b, const Mesh& b,
                const tools::MeshDistanceOptions& options, const tools::MeshDistance& d) {
  auto mesh_line = [](const char* label, const std::string& path, const Mesh& m, const tools::SurfaceInfo& s) {
    std::printf("%-10s %s: %zu vertices, %zu faces, %zu triangles", label, path.c_str(), m.vertex_count(),
                m.face_count(), s.triangles);
    if (s.degenerate) std::printf(" (%zu of zero area skipped)", s.degenerate);
    std::printf(", area %.9g\n", s.area);
  };
  mesh_line("A", path_a, a, d.a);
  mesh_line("B", path_b, b, d.b);
  std::printf("samples    %zu per surface (area-uniform, seed %llu) plus the referenced vertices (%zu, %zu)\n",
              options.samples, static_cast<unsigned long long>(options.seed), d.a.referenced_vertices,
              d.b.referenced_vertices);
  std::printf("bbox diag  %.9g (of A; relative = absolute / this)\n", d.bbox_diagonal);
  std::printf("%-22s %15s %15s\n", "", "absolute", "relative");
  auto row = [&](const char* name, double v) { std::printf("%-22s %15.6e %15.6e\n", name, v, d.relative(v)); };
  row("A->B max", d.a_to_b.max);
  row("A->B mean", d.a_to_b.mean);
  row("A->B rms", d.a_to_b.rms);
  row("B->A max", d.b_to_a.max);
  row("B->A mean", d.b_to_a.mean);
  row("B->A rms", d.b_to_a.rms);
  row("Hausdorff", d.hausdorff);
  row("L2 (symmetric rms)", d.l2);
  row("mean (symmetric)", d.mean);
  if (std::isinf(d.psnr_db))
    std::printf("PSNR                   inf (the surfaces coincide at every sample)\n");
  else
    std::printf("PSNR                   %.3f dB (20 log10(bbox diagonal / L2))\n", d.psnr_db);
}

void print_json(const std::string& path_a, const Mesh& a, const std::string& path_b, const Mesh& b,
                const tools::MeshDistanceOptions& options, const tools::MeshDistance& d) {
  auto mesh = [](const std::string& path, const Mesh& m, const tools::SurfaceInfo& s) {
    std::printf(
        "{\"file\":\"%s\",\"vertices\":%zu,\"faces\":%zu,\"triangles\":%zu,\"degenerate_triangles\":%zu,"
        "\"referenced_vertices\":%zu,\"area\":%.9g}",
        json_escape(path).c_str(), m.vertex_count(), m.face_count(), s.triangles, s.degenerate,
        s.referenced_vertices, s.area);
  };
  auto one_sided = [](const tools::OneSidedDistance& o) {
    std::printf("{\"max\":%.9g,\"mean\":%.9g,\"rms\":%.9g,\"area_samples\":%zu,\"vertex_samples\":%zu}", o.max, o.mean,
                o.rms, o.area_samples, o.vertex_samples);
  };
  std::printf("{\"a\":");
  mesh(path_a, a, d.a);
  std::printf(",\"b\":");
  mesh(path_b, b, d.b);
  std::printf(",\"samples\":%zu,\"seed\":%llu,\"bbox_diagonal\":%.9g,\"a_to_b\":", options.samples,
              static_cast<unsigned long long>(options.seed), d.bbox_diagonal);
  one_sided(d.a_to_b);
  std::printf(",\"b_to_a\":");
  one_sided(d.b_to_a);
  std::printf(",\"hausdorff\":%.9g,\"hausdorff_relative\":%.9g,\"l2\":%.9g,\"l2_relative\":%.9g,", d.hausdorff,
              d.relative(d.hausdorff), d.l2, d.relative(d.l2));
  std::printf("\"mean\":%.9g,\"mean_relative\":%.9g,\"psnr_db\":", d.mean, d.relative(d.mean));
  if (std::isinf(d.psnr_db))
    std::printf("null}\n");
  else
    std::printf("%.6f}\n", d.psnr_db);
}

}  // namespace

int run_compare(int argc, char** argv) {
  CommandLine cl;
  const CommandSpec spec{"compare", kHelp, {"--json"}, {{"--samples"}, {"--seed"}}, 2, 2};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  tools::MeshDistanceOptions options;
  for (const auto& [name, value] : cl.options) {
    long v = 0;
    if (name == "--samples") {
      if (!parse_int(value, 1, 100000000, &v)) return usage_error("compare", "--samples must be 1 to 100000000");
      options.samples = size_t(v);
    } else if (name == "--seed") {
      if (!parse_int(value, 0, 2147483647, &v)) return usage_error("compare", "--seed must be 0 to 2147483647");
      options.seed = uint64_t(v);
    }
  }
  const std::string& path_a = cl.positional[0];
  const std::string& path_b = cl.positional[1];
  Mesh a, b;
  if (Status s = load_mesh(path_a, &a); !s.ok()) return fail("compare", s);
  if (Status s = load_mesh(path_b, &b); !s.ok()) return fail("compare", s);

  // Progress only once a run has taken long enough to wonder about; Progress
  // itself stays quiet unless stderr is a terminal.
  Progress progress(true);
  const auto start = std::chrono::steady_clock::now();
  bool shown = false;
  options.progress = [&](size_t done, size_t total) {
    if (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(500)) return;
    shown = true;
    progress.stage("qmc compare: " + std::to_string(done * 100 / (total ? total : 1)) + "% of the distances");
  };
  tools::MeshDistance d;
  Status status = tools::measure_mesh_distance(a, b, options, &d);
  if (shown) progress.done();
  if (!status.ok()) return fail("compare", status);
  if (cl.has("--json"))
    print_json(path_a, a, path_b, b, options, d);
  else
    print_text(path_a, a, path_b, b, options, d);
  return kExitOk;
}

}  // namespace qmc::cli
