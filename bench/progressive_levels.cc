// Issue 17's criterion that every level of a progressive file is nearer the
// input than the level before, on every mesh given at K = 2..6: each mesh
// (positions and faces, polygons fanned into triangles) encoded by
// qmc::encode with progressive_levels = K and default options, decoded, and
// every level measured against the input Metro-style (tools/lib/
// mesh_distance.h). Prints a Markdown report on stdout; progress on a
// terminal only.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_common.h"
#include "mesh_distance.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace {

constexpr int kFirstK = 2, kLastK = 6;

struct Options {
  size_t samples = 50000;
  std::vector<std::string> meshes;
};

struct Run {
  int k = 0;
  std::string error;                // empty if encoded and decoded
  uint32_t base_vertices = 0;
  uint64_t bytes = 0;
  std::vector<double> relative_l2;  // [0] = base
  std::vector<int> targets;         // LoopLevelStats::targets, [0] unused
  std::vector<int> rising;          // levels no nearer than the one before
};

Run run(const qmc::Mesh& triangles, int k, const Options& opt) {
  Run r;
  r.k = k;
  qmc::EncodeOptions options;
  options.progressive_levels = k;
  std::vector<uint8_t> file;
  qmc::EncodeStats stats;
  if (qmc::Status s = qmc::encode(triangles, options, &file, &stats); !s.ok()) {
    r.error = s.message();
    return r;
  }
  qmc::DecodedFile decoded;
  if (qmc::Status s = qmc::decode(file.data(), file.size(), &decoded); !s.ok()) {
    r.error = "decode: " + s.to_string();
    return r;
  }
  r.bytes = file.size();
  r.base_vertices = stats.loop.levels.empty() ? 0 : stats.loop.levels[0].vertices;
  qmc::tools::MeshDistanceOptions distance_options;
  distance_options.samples = opt.samples;
  distance_options.seed = 1;
  for (size_t j = 0; j < decoded.levels.size(); ++j) {
    qmc::tools::MeshDistance d;
    if (qmc::Status s = qmc::tools::measure_mesh_distance(triangles, qmc::level_mesh(decoded.levels[j]),
                                                          distance_options, &d);
        !s.ok()) {
      r.error = "distance: " + s.to_string();
      return r;
    }
    r.relative_l2.push_back(d.relative(d.l2));
    r.targets.push_back(j < stats.loop.levels.size() ? stats.loop.levels[j].targets : 0);
    if (j > 0 && !(r.relative_l2[j] < r.relative_l2[j - 1])) r.rising.push_back(int(j));
  }
  return r;
}

std::string levels_cell(const Run& r) {
  std::string cell;
  for (size_t j = 0; j < r.relative_l2.size(); ++j) {
    bool rising = false;
    for (int level : r.rising) rising = rising || size_t(level) == j;
    char text[48];
    std::snprintf(text, sizeof text, "%s%.3g%s%s", j ? ", " : "", r.relative_l2[j], r.targets[j] ? "*" : "",
                  rising ? " **up**" : "");
    cell += text;
  }
  return cell;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--samples" && i + 1 < argc)
      o.samples = size_t(std::max(1000, std::atoi(argv[++i])));
    else
      o.meshes.push_back(arg);
  }
  if (o.meshes.empty()) qmc::bench::fail("qmc_progressive_levels", "usage: qmc_progressive_levels [--samples N] MESH...");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse(argc, argv);
  std::printf("Every mesh given, positions and faces (texture coordinates, normals and the like left out; polygons "
              "fanned into triangles), encoded by `qmc::encode` with `progressive_levels` = K and default options "
              "otherwise, decoded, and each level measured against the input: relative L2 (Metro-style, %zu area "
              "samples per surface plus the vertices, seed 1; L2 / bounding-box diagonal, as `qmc encode` reports). "
              "Level 0 is the base. `*`: the level's displacements aim at an alternative of the encoder's closed loop "
              "(spec 12.10, `LoopLevelStats::targets`); **up**: no nearer the input than the level before "
              "(issue 17 wants none).\n\n",
              opt.samples);
  std::printf("| mesh | K | base vertices | bytes | L2 / diagonal, level 0 .. K |\n| --- | ---: | ---: | ---: | --- |\n");
  int runs = 0, approaching = 0;
  std::string rising_list, failed_list;
  for (const std::string& path : opt.meshes) {
    const std::string name = qmc::bench::display_name(path);
    qmc::Mesh input;
    if (qmc::Status s = qmc::bench::read_geometry(path, &input, nullptr); !s.ok())
      qmc::bench::fail("qmc_progressive_levels", path + ": " + s.to_string());
    const qmc::Mesh triangles = qmc::tools::triangulated(input);
    for (int k = kFirstK; k <= kLastK; ++k) {
      qmc::bench::progress(name + ": K = " + std::to_string(k));
      const Run r = run(triangles, k, opt);
      if (!r.error.empty()) {
        std::printf("| %s | %d | - | - | not encoded: %s |\n", name.c_str(), k, r.error.c_str());
        failed_list += (failed_list.empty() ? "" : ", ") + name + " K = " + std::to_string(k);
        continue;
      }
      ++runs;
      approaching += r.rising.empty();
      if (!r.rising.empty()) rising_list += (rising_list.empty() ? "" : ", ") + name + " K = " + std::to_string(k);
      std::printf("| %s | %d | %u | %llu | %s |\n", name.c_str(), k, r.base_vertices,
                  static_cast<unsigned long long>(r.bytes), levels_cell(r).c_str());
    }
  }
  qmc::bench::progress("");
  std::printf("\n**Every level nearer than the one before: %d of %d** (mesh, K) encoded.", approaching, runs);
  if (!rising_list.empty()) std::printf(" Not: %s.", rising_list.c_str());
  if (!failed_list.empty()) std::printf(" Not encoded: %s.", failed_list.c_str());
  std::printf("\n");
  return 0;
}
