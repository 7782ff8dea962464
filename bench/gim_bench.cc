// Geometry images against seeds 000 and 002, and lossless plane coding
// against zstd -19 and 16-bit PNG (docs/results/gim.md):
//  - seed 000 table 1: PSNR of regular, vertex-density-equalized and
//    Hausdorff-adjusted sampling at the seed's sampling rates, with the
//    Hausdorff error before and after the adjustment;
//  - seed 002 tables 1-2: topology-preserving images: PSNR with 16-bit
//    planes, exactness with binary32 planes, generation and decode time;
//  - plane bytes: qmc's GPLN chunks against zstd -19 of the raw planes and
//    against one 16-bit PNG per plane (zlib 9);
//  - pictures: the planes as an RGB geometry image and the decoded mesh.
// usage: qmc_gim_bench CORPUS_DIR PICTURE_DIR [RUNS]
#include <zstd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench_common.h"
#include "encoder/gim_writer.h"
#include "image_io.h"
#include "mesh_distance.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "mesh_render.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc::bench {
namespace {

const char* kProgram = "qmc_gim_bench";

struct Run {
  std::vector<uint8_t> file;
  EncodeStats stats;
  DecodedFile decoded;
  double encode_seconds = 0, decode_seconds = 0;
  tools::MeshDistance distance;
};

// The encoder's refusal, if any, goes to *error (null: fatal).
Run run(const Mesh& mesh, const EncodeOptions& options, int runs, std::string* error = nullptr) {
  Run r;
  {
    Status s = encode(mesh, options, &r.file, &r.stats);
    if (!s.ok() && error == nullptr) fail(kProgram, s.to_string());
    if (!s.ok()) {
      *error = s.to_string();
      return r;
    }
  }
  r.encode_seconds = median_seconds(runs, [&] {
    r.stats = EncodeStats{};
    if (Status s = encode(mesh, options, &r.file, &r.stats); !s.ok()) fail(kProgram, s.to_string());
  });
  r.decode_seconds = median_seconds(runs, [&] {
    if (Status s = decode(r.file.data(), r.file.size(), &r.decoded, DecoderLimits::unlimited()); !s.ok())
      fail(kProgram, s.to_string());
  });
  const Mesh triangles = tools::triangulated(mesh, nullptr);
  if (Status s = tools::measure_mesh_distance(triangles, r.decoded.mesh, {}, &r.distance); !s.ok())
    fail(kProgram, s.to_string());
  return r;
}

Mesh load(const std::string& corpus, const std::string& name) {
  Mesh mesh;
  std::vector<std::string> warnings;
  if (Status s = bench::read_geometry(corpus + "/" + name, &mesh, &warnings); !s.ok()) fail(kProgram, s.to_string());
  return mesh;
}

std::string picture_name(const std::string& mesh, const std::string& variant) {
  std::string base = mesh.substr(mesh.find('/') + 1);
  base = base.substr(0, base.find('.'));
  return base + "_" + variant;
}

// Markdown for the pictures of the rows printed so far, after the table.
std::vector<std::string> g_pictures;

void print_pictures() {
  if (g_pictures.empty()) return;
  std::printf("\n| planes (R, G, B = X, Y, Z) | decoded mesh |\n|---|---|\n");
  for (const std::string& name : g_pictures)
    std::printf("| ![%s planes](gim/%s_planes.png) | ![%s mesh](gim/%s_mesh.png) |\n", name.c_str(), name.c_str(),
                name.c_str(), name.c_str());
  g_pictures.clear();
}

// The planes as an RGB geometry image and the decoded mesh, side by side files.
void save_pictures(const Run& r, const std::string& dir, const std::string& name) {
  g_pictures.push_back(name);
  const GeometryImageData& g = r.decoded.gim;
  std::vector<double> planes[3];
  for (int a = 0; a < 3; ++a)
    for (uint32_t p = 0; p < g.width * g.height; ++p) planes[a].push_back(g.value(a, p));
  const std::vector<uint8_t>* mask = (g.flags & 1) ? &g.occupied : nullptr;
  if (Status s = tools::render_rgb_geometry_image(planes[0], planes[1], planes[2], g.width, g.height, mask,
                                                  dir + "/" + name + "_planes.png");
      !s.ok())
    fail(kProgram, s.to_string());
  tools::RenderOptions ro;
  ro.width = ro.height = 400;
  ro.wireframe = r.decoded.mesh.vertex_count() < 4000;
  if (Status s = tools::render_mesh_png(r.decoded.mesh, ro, dir + "/" + name + "_mesh.png"); !s.ok())
    fail(kProgram, s.to_string());
}

// --- Seed 000 table 1 ---------------------------------------------------------

struct Seed000Row {
  const char* mesh;
  uint32_t n;
  double regular, zhou, ours, before, after;  // the seed's columns
};

void seed000_table(const std::string& corpus, const std::string& pictures, int runs) {
  const Seed000Row rows[] = {{"tri/cathead.obj", 45, 47.1377, 47.6548, 51.7978, 0.1379, 0.0625},
                             {"tri/camelhead.off", 180, 61.4743, 56.6976, 71.2418, 0.0102, 0.0055}};
  std::printf("\n## Seed 000 table 1: sampled geometry images\n\n");
  std::printf("Binary32 planes, so the figures measure sampling alone. PSNR = 20 log10(bbox diagonal / "
              "L2), L2 the symmetric Metro RMS distance (seed 002 eq. 1). Hausdorff is seed 000 "
              "algorithm 1's own measure at its face sample points, in mesh units. Times: median of %d.\n\n",
              runs);
  std::printf("| mesh | faces | vertices | n x n | sampling | PSNR dB | seed: regular / Zhou / ours | Hausdorff before "
              "-> after | seed: before -> after | Metro Hausdorff | encode s | decode ms | bytes |\n");
  std::printf("|---|--:|--:|--:|---|--:|---|---|---|--:|--:|--:|--:|\n");
  for (const Seed000Row& row : rows) {
    const Mesh mesh = load(corpus, row.mesh);
    const struct {
      GimSampling sampling;
      const char* name;
    } kinds[] = {{GimSampling::kRegular, "regular"},
                 {GimSampling::kAdaptive, "adaptive (§3.1)"},
                 {GimSampling::kHausdorff, "Hausdorff (§3.1-3.3)"}};
    for (const auto& kind : kinds) {
      EncodeOptions o;
      o.gim.size = row.n;
      o.gim.sampling = kind.sampling;
      o.gim.float_samples = true;
      const Run r = run(mesh, o, kind.sampling == GimSampling::kHausdorff ? 1 : runs);
      const GimEncodeStats& g = r.stats.gim;
      std::string hausdorff = "-";
      if (g.hausdorff_before >= 0) hausdorff = format("%.4g -> %.4g (%u steps)", g.hausdorff_before, g.hausdorff_after, g.hausdorff_iterations);
      std::printf("| %s | %zu | %zu | %u | %s | %.2f | %.2f / %.2f / %.2f | %s | %.4g -> %.4g | %.4g | %.2f | %.1f | %zu |\n",
                  display_name(row.mesh).c_str(), mesh.face_count(), mesh.vertex_count(), row.n, kind.name,
                  r.distance.psnr_db, row.regular, row.zhou, row.ours, hausdorff.c_str(), row.before, row.after,
                  r.distance.hausdorff, r.encode_seconds, 1e3 * r.decode_seconds, r.file.size());
      std::fflush(stdout);
      save_pictures(r, pictures, picture_name(row.mesh, kind.sampling == GimSampling::kRegular      ? "regular"
                                                        : kind.sampling == GimSampling::kAdaptive ? "adaptive"
                                                                                                  : "hausdorff"));
    }
  }
  print_pictures();
}

// --- Seed 002 tables 1 and 2 -------------------------------------------------------

struct Seed002Row {
  const char* mesh;
  const char* seed_name;
  int seed_tris;
  double seed_psnr, seed_generation, seed_reconstruction;
};

void seed002_table(const std::string& corpus, const std::string& pictures, int runs) {
  const Seed002Row rows[] = {{"tri/bunny_small.off", "bunny", 22490, 103.1, 812, 4.14},
                             {"tri/cow.obj", "Cow", 23216, 99.1, 1362, 4.05},
                             {"tri/fertility.off", "Fertility", 24972, -1, 2146, 3.04},
                             {"tri/3holes.off", "Holes3", 4000, 105.2, 77, 0.58}};
  std::printf("\n## Seed 002 tables 1-2: topology-preserving geometry images\n\n");
  std::printf("PSNR with 16-bit planes (seed 002 eq. 1); with binary32 planes every triangle corner is checked "
              "bit for bit against the input. Times: median of %d (generation = the whole encode).\n\n", runs);
  std::printf("| mesh | genus | tris | image | PSNR 16-bit dB | binary32 exact | generation s | decode ms | bytes 16-bit "
              "| bytes binary32 | seed: tris, PSNR, generation s, reconstruction s |\n");
  std::printf("|---|--:|--:|--:|--:|---|--:|--:|--:|--:|---|\n");
  for (const Seed002Row& row : rows) {
    const Mesh mesh = load(corpus, row.mesh);
    EncodeOptions o;
    o.gim.size = 4096;
    o.gim.topology_preserving = true;
    std::string error;
    const Run r16 = run(mesh, o, runs, &error);
    if (!error.empty()) {
      std::printf("| %s | | %zu | not made: %s | | | | | | | %s: %d |\n", display_name(row.mesh).c_str(),
                  mesh.face_count(), error.c_str(), row.seed_name, row.seed_tris);
      continue;
    }
    o.gim.float_samples = true;
    const Run r32 = run(mesh, o, 1);
    const Mesh triangles = tools::triangulated(mesh, nullptr);
    bool exact = r32.decoded.mesh.corners.size() == triangles.corners.size();
    for (size_t c = 0; exact && c < triangles.corners.size(); ++c)
      exact = std::memcmp(&triangles.positions[3 * size_t(triangles.corners[c])],
                          &r32.decoded.mesh.positions[3 * size_t(r32.decoded.mesh.corners[c])], 12) == 0;
    const GimEncodeStats& g = r16.stats.gim;
    std::printf("| %s | %d | %zu | %u x %u | %.2f | %s | %.2f | %.1f | %zu | %zu | %s: %d, %s, %.0f, %.2f |\n",
                display_name(row.mesh).c_str(), g.genus, triangles.face_count(), g.width, g.height, r16.distance.psnr_db,
                exact ? "yes" : "NO", r16.encode_seconds, 1e3 * r16.decode_seconds, r16.file.size(), r32.file.size(),
                row.seed_name, row.seed_tris, row.seed_psnr > 0 ? format("%.1f", row.seed_psnr).c_str() : "-",
                row.seed_generation, row.seed_reconstruction);
    std::fflush(stdout);
    save_pictures(r16, pictures, picture_name(row.mesh, "topology_preserving"));
  }
  print_pictures();
}

// --- Lossless plane coding ----------------------------------------------------

size_t zstd19(const std::vector<uint8_t>& raw) {
  std::vector<uint8_t> out(ZSTD_compressBound(raw.size()));
  const size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 19);
  if (ZSTD_isError(n)) fail(kProgram, "zstd failed");
  return n;
}

void plane_table(const std::string& corpus, int runs) {
  (void)runs;
  struct Case {
    const char* mesh;
    uint32_t n;
    bool topology_preserving;
  } cases[] = {{"tri/cathead.obj", 45, false},   {"tri/camelhead.off", 180, false}, {"tri/bunny_small.off", 256, false},
               {"tri/fertility.off", 256, false}, {"tri/bunny_small.off", 0, true},   {"tri/3holes.off", 0, true}};
  std::printf("\n## Lossless plane coding\n\n");
  std::printf("The X, Y, Z planes of 16-bit images (sampled: regular sampling; topology-preserving: every pixel, "
              "blank ones as the decoder defines them). qmc = the three GPLN chunks; zstd -19 of the raw "
              "little-endian u16 planes, all three in one frame; PNG = three 16-bit gray PNGs, zlib level 9. "
              "For the sparse topology-preserving images qmc codes only occupied pixels (mask in GMSK, not counted "
              "here; listed separately), while zstd and PNG see every pixel.\n\n");
  std::printf("| image | pixels | raw bytes | qmc planes | zstd -19 | PNG | qmc / zstd | qmc / PNG | GMSK bytes |\n");
  std::printf("|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const Case& c : cases) {
    const Mesh mesh = load(corpus, c.mesh);
    EncodeOptions o;
    o.gim.size = c.topology_preserving ? 4096 : c.n;
    o.gim.topology_preserving = c.topology_preserving;
    std::vector<uint8_t> file;
    EncodeStats stats;
    if (Status s = encode(mesh, o, &file, &stats); !s.ok()) {
      std::printf("| %s topology-preserving | not made: %s | | | | | | | |\n", display_name(c.mesh).c_str(),
                  s.to_string().c_str());
      continue;
    }
    DecodedFile d;
    if (Status s = decode(file.data(), file.size(), &d, DecoderLimits::unlimited()); !s.ok())
      fail(kProgram, s.to_string());
    const GeometryImageData& g = d.gim;
    std::vector<uint8_t> raw;
    size_t png = 0, ours = 0;
    for (int a = 0; a < 3; ++a) {
      std::vector<uint16_t> plane(g.planes[size_t(a)].samples.begin(), g.planes[size_t(a)].samples.end());
      for (uint16_t v : plane) raw.push_back(uint8_t(v)), raw.push_back(uint8_t(v >> 8));
      png += tools::encode_png_gray16_to_memory(g.width, g.height, plane).size();
      ours += size_t(stats.gim.plane_bytes[size_t(a)]);
    }
    const size_t z = zstd19(raw);
    std::printf("| %s %s | %u x %u | %zu | %zu | %zu | %zu | %.3f | %.3f | %llu |\n", display_name(c.mesh).c_str(),
                c.topology_preserving ? "topology-preserving" : format("%u x %u regular", c.n, c.n).c_str(), g.width,
                g.height, raw.size(), ours, z, png, double(ours) / double(z), double(ours) / double(png),
                static_cast<unsigned long long>(stats.gim.mask_bytes));
    std::fflush(stdout);
  }
}

}  // namespace
}  // namespace qmc::bench

int main(int argc, char** argv) {
  using namespace qmc::bench;
  if (argc < 3) {
    std::fprintf(stderr, "usage: qmc_gim_bench CORPUS_DIR PICTURE_DIR [RUNS] [seed000|seed002|planes]\n");
    return 2;
  }
  const int runs = argc > 3 ? std::atoi(argv[3]) : 3;
  const std::string only = argc > 4 ? argv[4] : "";
  std::printf("Pictures (the planes as RGB = normalised X, Y, Z, and the decoded mesh) are in `docs/results/gim/`, "
              "named MESH_VARIANT_planes.png and MESH_VARIANT_mesh.png.\n");
  if (only.empty() || only == "seed000") seed000_table(argv[1], argv[2], runs);
  if (only.empty() || only == "seed002") seed002_table(argv[1], argv[2], runs);
  if (only.empty() || only == "planes") plane_table(argv[1], runs);
  return 0;
}
