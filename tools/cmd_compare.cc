// qmc compare: surface-to-surface error between two meshes (Metro-style
// Hausdorff, L2 and mean distances, PSNR of seed 002 eq. (1)).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <cstdlib>

#include "attribute_distance.h"
#include "cli_common.h"
#include "commands.h"
#include "mesh_distance.h"

namespace qmc::cli {
namespace {

const char kHelp[] =
    "usage: qmc compare A B [--samples N] [--seed S] [--match-distance D] [--json]\n"
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
    "When A or B has attributes (texture coordinates, normals, colours), their\n"
    "values are compared at corresponding corners: each vertex of B is matched\n"
    "to the nearest vertex of A within D (model units; default 1/1000 of A's\n"
    "bounding-box diagonal: raise it for positions quantized below 10 bits),\n"
    "each face of B to the face of A with those corners (B's triangles may lie\n"
    "in A's polygons), and per attribute of the same name (or kind):\n"
    "\n"
    "  distance   max and RMS over corners of |value in B - value in A|\n"
    "  angle      normals: max, mean and RMS angle between the directions\n"
    "  stretch    texture coordinates: of each triangle, the map from A's to B's\n"
    "             texture coordinates, singular values s1 >= s2 (Sander et al.\n"
    "             2001): L2 = sqrt((s1^2 + s2^2) / 2) area-weighted over A's\n"
    "             texture (1: unchanged), max = largest max(s1, 1/s2), and the\n"
    "             value 99% of A's texture area stays within; triangles whose\n"
    "             texture turned over (flipped) or lost its area (collapsed)\n"
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
    std::printf("null");
  else
    std::printf("%.6f", d.psnr_db);
}

const char* kind_name(AttributeKind kind) {
  switch (kind) {
    case AttributeKind::kTextureCoordinate: return "texture coordinate";
    case AttributeKind::kNormal: return "normal";
    case AttributeKind::kColour: return "colour";
    default: return "generic";
  }
}

bool has_attributes(const Mesh& a, const Mesh& b) { return !a.attributes.empty() || !b.attributes.empty(); }

void print_attributes_text(const tools::AttributeComparison& c, double diagonal) {
  std::printf("attributes B's faces matched to A's: %zu of %zu (vertices within %.6g = %.3g of the bbox diagonal: "
              "the farthest a vertex of B is from its nearest of A, searched up to %.6g",
              c.faces_matched, c.faces_b, c.match_radius, diagonal > 0 ? c.match_radius / diagonal : 0.0,
              c.vertex_tolerance);
  if (c.vertices_unmatched) std::printf("; %zu vertices of B have none", c.vertices_unmatched);
  std::printf(")");
  if (c.faces_ambiguous) std::printf("; %zu left out as several faces of A fit them", c.faces_ambiguous);
  std::printf("\n");
  for (const tools::AttributeDistance& d : c.attributes) {
    std::printf("%-10s %s, %u components", d.name.c_str(), kind_name(d.kind), d.components);
    if (d.name_in_b != d.name) std::printf(" (B's \"%s\")", d.name_in_b.c_str());
    std::printf(", %zu corners: distance max %.6e, rms %.6e\n", d.corners, d.distance_max, d.distance_rms);
    if (d.kind == AttributeKind::kNormal && d.components == 3) {
      std::printf("%-10s angle max %.4f, mean %.4f, rms %.4f degrees", "", d.angle_max_degrees, d.angle_mean_degrees,
                  d.angle_rms_degrees);
      if (d.zero_normals) std::printf(" (%zu corners with a zero normal left out)", d.zero_normals);
      std::printf("\n");
    }
    if (d.kind == AttributeKind::kTextureCoordinate && d.components == 2) {
      std::printf("%-10s stretch over %zu triangles: L2 %.6f, max %.6g, 99%% of the area within %.6g; %zu flipped, "
                  "%zu collapsed",
                  "", d.stretch_triangles, d.stretch_l2, d.stretch_max, d.stretch_p99, d.flipped, d.collapsed);
      if (d.no_area_in_a) std::printf(" (%zu without texture area in A left out)", d.no_area_in_a);
      std::printf("\n");
    }
  }
  for (const std::string& name : c.only_in_a) std::printf("%-10s only in A\n", name.c_str());
  for (const std::string& name : c.only_in_b) std::printf("%-10s only in B\n", name.c_str());
}

void print_attributes_json(const tools::AttributeComparison& c) {
  std::printf(",\"attributes\":{\"vertex_tolerance\":%.9g,\"faces_b\":%zu,\"faces_matched\":%zu,"
              "\"faces_ambiguous\":%zu,\"vertices_unmatched\":%zu,\"match_radius\":%.9g,\"compared\":[",
              c.vertex_tolerance, c.faces_b, c.faces_matched, c.faces_ambiguous, c.vertices_unmatched,
              c.match_radius);
  for (size_t i = 0; i < c.attributes.size(); ++i) {
    const tools::AttributeDistance& d = c.attributes[i];
    std::printf("%s{\"name\":\"%s\",\"name_in_b\":\"%s\",\"kind\":\"%s\",\"components\":%u,\"corners\":%zu,"
                "\"distance_max\":%.9g,\"distance_rms\":%.9g",
                i ? "," : "", json_escape(d.name).c_str(), json_escape(d.name_in_b).c_str(), kind_name(d.kind),
                d.components, d.corners, d.distance_max, d.distance_rms);
    if (d.kind == AttributeKind::kNormal && d.components == 3)
      std::printf(",\"angle_max_degrees\":%.9g,\"angle_mean_degrees\":%.9g,\"angle_rms_degrees\":%.9g,"
                  "\"zero_normals\":%zu",
                  d.angle_max_degrees, d.angle_mean_degrees, d.angle_rms_degrees, d.zero_normals);
    if (d.kind == AttributeKind::kTextureCoordinate && d.components == 2)
      std::printf(",\"stretch_triangles\":%zu,\"stretch_l2\":%.9g,\"stretch_max\":%.9g,\"stretch_p99\":%.9g,"
                  "\"flipped\":%zu,\"collapsed\":%zu,\"no_area_in_a\":%zu",
                  d.stretch_triangles, d.stretch_l2, d.stretch_max, d.stretch_p99, d.flipped, d.collapsed,
                  d.no_area_in_a);
    std::printf("}");
  }
  const auto names = [](const std::vector<std::string>& list) {
    for (size_t i = 0; i < list.size(); ++i) std::printf("%s\"%s\"", i ? "," : "", json_escape(list[i]).c_str());
  };
  std::printf("],\"only_in_a\":[");
  names(c.only_in_a);
  std::printf("],\"only_in_b\":[");
  names(c.only_in_b);
  std::printf("]}");
}

}  // namespace

int run_compare(int argc, char** argv) {
  CommandLine cl;
  const CommandSpec spec{"compare", kHelp, {"--json"}, {{"--samples"}, {"--seed"}, {"--match-distance"}}, 2, 2};
  double match_distance = 0;  // 0: 1/1000 of A's bounding-box diagonal
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
    } else if (name == "--match-distance") {
      char* end = nullptr;
      match_distance = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !(match_distance > 0) || !std::isfinite(match_distance))
        return usage_error("compare", "--match-distance must be a positive number");
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
  tools::AttributeComparison attributes;
  const bool with_attributes = has_attributes(a, b);
  if (with_attributes) {
    const double tolerance = match_distance > 0 ? match_distance : d.bbox_diagonal / 1000;
    if (tolerance > 0) status = tools::compare_attributes(a, b, tolerance, &attributes);
    if (!status.ok()) return fail("compare", status);
  }
  if (cl.has("--json")) {
    print_json(path_a, a, path_b, b, options, d);
    if (with_attributes) print_attributes_json(attributes);
    std::printf("}\n");
  } else {
    print_text(path_a, a, path_b, b, options, d);
    if (with_attributes) print_attributes_text(attributes, d.bbox_diagonal);
  }
  return kExitOk;
}

}  // namespace qmc::cli
