// qmc encode: compress, then decode in memory and report size and error.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "mesh_distance.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "progressive_rate.h"
#include "surface_lattice_choice.h"
#include "roundtrip_check.h"

namespace qmc::cli {
namespace {

const char kHelp[] =
    "usage: qmc encode IN OUT.qmc [options]\n"
    "\n"
    "Compresses IN (.obj .off .ply .stl, any polygon mesh) into OUT.qmc, then decodes\n"
    "the result in memory and reports sizes and position error.\n"
    "\n"
    "options:\n"
    "  -q, --bits N        position quantization bits per axis, 1..30 (default 12:\n"
    "                      every vertex stays within 1/4096 of the largest\n"
    "                      bounding-box side; see spec sections 6.2, 14.1)\n"
    "  --grid G            uniform (default): one step on every axis, the largest\n"
    "                      bounding-box side / (2^bits - 1), as Draco and\n"
    "                      meshoptimizer; per-axis: each axis over its own range\n"
    "                      (spec 6.1)\n"
    "  --step S            round positions to a uniform grid of step S (model\n"
    "                      units) instead of --bits\n"
    "  --max-error E       the coarsest uniform grid that keeps every vertex\n"
    "                      within distance E (model units) of its input, binary32\n"
    "                      rounding included; instead of --bits\n"
    "  --surface-lattice F|auto  positions keep the grid's step along the axis nearest\n"
    "                      the surface's normal and take steps of F (2..16)\n"
    "                      along the other two (POSN method 14, spec 14.15),\n"
    "                      where that codes smaller than the grid (the report\n"
    "                      says): on dense scans smaller files at about the\n"
    "                      same distance between the surfaces, but a vertex\n"
    "                      may move up to F steps per axis along the surface\n"
    "                      (verify allows that); auto: the F of the smallest\n"
    "                      file no farther from the input (L2) than the\n"
    "                      grid's, each F of 2, 3, 4, 6 coded and measured\n"
    "  --positions M       auto (default): predicted positions (spec 14), or on\n"
    "                      the per-axis grid the smaller of them and deltas;\n"
    "                      predicted; deltas: spec 6's deltas (--grid per-axis)\n"
    "  --connectivity M    auto (default): the quad coder of seed 001 for closed\n"
    "                      genus-0 or one-boundary pure-quad manifold meshes, the\n"
    "                      polygon coder (spec 5.4) for every other mesh (the\n"
    "                      reason is printed); indexed: always indexed; quad: quad\n"
    "                      coder or an error; polygon: always the polygon coder\n"
    "  --start-faces N     of the polygon coder: code the whole file from N first\n"
    "                      faces per component (spec 5.4.2, the encoder's\n"
    "                      choice; 1..256, default 1) and keep the smallest: N\n"
    "                      times the encode time, files up to 4 % smaller\n"
    "                      (1 % on average on the corpus at 64 starts)\n"
    "  --text KEY=VALUE    store a teXt chunk (repeatable)\n"
    "  --keep-order        store an oRDR chunk (spec 4.5) so that decoding restores\n"
    "                      the input's order of vertices, faces and face corners\n"
    "                      exactly (by default they come out in the coder's order)\n"
    "  --progressive       write a progressive file (spec 12, seed 003): a coarse\n"
    "                      base mesh plus Loop levels, each refining the one\n"
    "                      before; lossy: the output is a semi-regular remesh of\n"
    "                      the input surface. Polygons are split into triangles\n"
    "                      first; a mesh that is not manifold and consistently\n"
    "                      oriented is cut where it is not (faces of no area\n"
    "                      left out); the surface stays, and both are reported\n"
    "  --levels K          levels of --progressive, 1..8; the base mesh has\n"
    "                      about 1/4^K of the input's triangles, at least 32\n"
    "                      (or half the input's), so the finest level\n"
    "                      may have more than the input (default: the most\n"
    "                      levels that keep 1,000 of them in the base, at\n"
    "                      least 1; smaller bases lose accuracy fast)\n"
    "  --finest-step-scale F  of --progressive, 1..64 (default 1): the finest\n"
    "                      level's displacement step is the least-error step\n"
    "                      times F, the level below's times sqrt(F): fewer\n"
    "                      bytes, more error (spec 12.10)\n"
    "  --target-error E    of --progressive: the smallest file whose finest level\n"
    "                      is within relative L2 E of the input (L2 / bounding-box\n"
    "                      diagonal, as qmc compare reports it): tries K, base\n"
    "                      bits 8..13 and step scales 1, 2, 4, ..., 64, refined\n"
    "                      to a factor of 2^(1/4) where the error crosses E (each\n"
    "                      one that --levels, --bits or --finest-step-scale does\n"
    "                      not fix), decodes and measures the candidates that\n"
    "                      can still win; prints what it tried\n"
    "  --target-hausdorff E  as --target-error, for the Hausdorff distance\n"
    "  --max-deviation E   of --progressive: where the finest level strays\n"
    "                      farther than E (relative to the bounding-box diagonal)\n"
    "                      from the input surface, or leaves input points that far\n"
    "                      from itself, move its vertices back and code the moves\n"
    "                      as corrections (LEVL code 4, format 1.14; spec 12.7.2):\n"
    "                      more bytes, a smaller Hausdorff distance; reports how\n"
    "                      near the fit came\n"
    "  --max-bytes N       of --progressive: the file of least L2 error within\n"
    "                      N bytes, searched as for --target-error\n"
    "  --gim N             write a geometry image (spec 13, seeds 000 and 002)\n"
    "                      instead: the surface cut into a disk, laid on an\n"
    "                      N x N pixel grid by Floater's mean-value coordinates\n"
    "                      and sampled; lossy, a regular remesh of the input\n"
    "                      (with --topology-preserving, N bounds the image side)\n"
    "  --sampling S        regular (default); adaptive: seed 000's vertex-density\n"
    "                      equalization; hausdorff: adaptive, then seed 000's\n"
    "                      Hausdorff-driven adjustment of the samples\n"
    "  --roi FILE          more samples in a region of interest (seed 000 sec. 4):\n"
    "                      lines 'vertex I...', 'face I...' or 'box X0 Y0 Z0 X1 Y1 Z1'\n"
    "  --topology-preserving  seed 002: every vertex on its own pixel, the input's\n"
    "                      triangles kept; exact with --gim-float\n"
    "  --gim-float         binary32 samples instead of 16-bit\n"
    "  --gim-quads         grid faces as quads instead of triangles\n"
    "  --gim-normals       add three planes of unit normals (attribute kinds 3-5)\n"
    "  --gim-store-blank   also code the samples of blank pixels (smooth planes\n"
    "                      for image tools, at some cost in bytes)\n"
    "  --format 1.N        write nothing that decoders older than 1.N cannot read:\n"
    "                      1.18 has no --surface-lattice (POSN method 14),\n"
    "                      1.17 codes quads in the gate's context alone (polygon\n"
    "                      coding 7, not 8), 1.16 also\n"
    "                      codes the three axes' classes with one set of\n"
    "                      probabilities (POSN methods 4 - 12, not 13),\n"
    "                      1.15 continues no edge to a vertex without\n"
    "                      candidates (POSN methods 4 - 11, not 12),\n"
    "                      1.14 shears no parallelogram either (POSN methods\n"
    "                      4 - 10, not 11), 1.13 also refuses --max-deviation (LEVL\n"
    "                      code 4),\n"
    "                      1.12 takes no mirror image a step away (POSN\n"
    "                      method 9, not 10) and no attribute twins (aTTR\n"
    "                      coding 9), 1.11 predicts no vertex by its mirror\n"
    "                      image (POSN\n"
    "                      methods 4 - 8, not 9), 1.10 predicts triangles\n"
    "                      without their neighbours'\n"
    "                      twist (POSN methods 4 - 7, not 8), 1.9 selects\n"
    "                      candidates without 14.8's contexts\n"
    "                      (POSN methods 4 and 5, not 6 and 7), 1.8 predicts\n"
    "                      quads without their neighbours' twist\n"
    "                      (POSN method 4, not 5), 1.7 writes predicted\n"
    "                      positions in the label order\n"
    "                      (method 1 or 3, not 4) and attribute values with\n"
    "                      coding 0 (not 4), 1.6 as method 1 only, 1.5\n"
    "                      also leaves out polygon coding 7, 1.4 also predicted\n"
    "                      positions (deltas on the per-axis grid); default 1.19\n"
    "  --uv-bits N         texture coordinates (spec 15) on a grid of 2^N - 1 steps\n"
    "                      over their range (default 12: 1/4 texel of a 1024\n"
    "                      texture)\n"
    "  --normal-bits N     normals likewise (default 10: within 0.1 degree)\n"
    "  --color-bits N      colours likewise (default 10)\n"
    "  --exact-attributes  keep every attribute value bit for bit (binary32)\n"
    "  --drop NAME         leave attribute or face labels NAME out (texcoord,\n"
    "                      normal, object, group, material, smoothing), saying\n"
    "                      so; progressive files and geometry images carry none\n"
    "  --drop-unsupported  encode without what the file format cannot carry yet\n"
    "                      (colours, PLY properties, attributes of a\n"
    "                      progressive file or geometry image...), listing it;\n"
    "                      without it such input is an error that names what\n"
    "                      would be lost\n"
    "  --allow-empty       accept an input without vertices or faces (an empty\n"
    "                      mesh file); without it such an input is an error\n"
    "  --quiet             print nothing on success, not even the notes about\n"
    "                      what the reader ignored (texture coordinates, groups)\n";

// The newest format minor version this encoder writes, and the oldest that
// --format accepts: 1.4 decoders read method-0 positions, 1.5 decoders
// predicted positions (method 1) and LEVL code 2 but not polygon coding 7,
// 1.6 decoders that but not POSN method 3, 1.7 decoders not method 4, 1.8
// decoders not method 5, 1.9 decoders not methods 6 and 7 (spec 11).
constexpr int kNewestMinor = kFormatMinor, kOldestTargetMinor = 4;

struct EncodeArgs {
  std::string input, output;
  EncodeOptions options;
  bool quiet = false, progressive = false, allow_empty = false, drop_unsupported = false;
  std::vector<std::string> drop;  // --drop NAME: attributes left out (spec 15)
  std::string roi_path;
  int newest_minor = kNewestMinor;  // --format 1.N: no feature newer than 1.N (spec 11)
  // Rate control of --progressive (--target-error, --max-bytes), and which
  // of its parameters the user fixed.
  tools::RateTarget rate;
  bool levels_given = false, bits_given = false, step_scale_given = false;
  bool lattice_auto = false;  // --surface-lattice auto (tools/lib/surface_lattice_choice.h)
};

const CommandSpec kSpec{"encode",
                        kHelp,
                        {"--quiet", "--allow-empty", "--drop-unsupported", "--keep-order", "--progressive", "--topology-preserving",
                         "--gim-float", "--gim-quads", "--gim-store-blank", "--gim-normals", "--exact-attributes"},
                        {{"--bits", "-q"}, {"--text"}, {"--connectivity"}, {"--levels"}, {"--gim"}, {"--sampling"},
                         {"--roi"}, {"--grid"}, {"--step"}, {"--max-error"}, {"--surface-lattice"}, {"--positions"}, {"--format"},
                         {"--uv-bits"}, {"--normal-bits"}, {"--color-bits"}, {"--drop"},
                         {"--finest-step-scale"}, {"--target-error"}, {"--target-hausdorff"}, {"--max-bytes"},
                         {"--max-deviation"}, {"--start-faces"}},
                        2,
                        2};

// Section 13 options; returns -1 when they are consistent.
int parse_gim(const CommandLine& cl, EncodeArgs* args) {
  GeometryImageOptions& g = args->options.gim;
  g.topology_preserving = cl.has("--topology-preserving");
  g.float_samples = cl.has("--gim-float");
  g.quads = cl.has("--gim-quads");
  g.store_blank_pixels = cl.has("--gim-store-blank");
  g.normal_planes = cl.has("--gim-normals");
  bool sampling_given = false;
  for (const auto& [name, value] : cl.options) {
    if (name == "--gim") {
      long n = 0;
      if (!parse_int(value, 2, 65535, &n))
        return usage_error("encode", "--gim takes a whole number from 2 to 65535, got '" + value + "'");
      g.size = uint32_t(n);
    } else if (name == "--sampling") {
      sampling_given = true;
      if (value == "regular") g.sampling = GimSampling::kRegular;
      else if (value == "adaptive") g.sampling = GimSampling::kAdaptive;
      else if (value == "hausdorff") g.sampling = GimSampling::kHausdorff;
      else return usage_error("encode", "--sampling takes regular, adaptive or hausdorff, got '" + value + "'");
    } else if (name == "--roi") {
      args->roi_path = value;
    }
  }
  const bool any = g.topology_preserving || g.float_samples || g.quads || g.store_blank_pixels || g.normal_planes ||
                   sampling_given ||
                   !args->roi_path.empty();
  if (any && g.size == 0) return usage_error("encode", "geometry-image options need --gim N");
  if (g.size > 0 && args->progressive) return usage_error("encode", "--gim and --progressive exclude each other");
  if (g.topology_preserving && (sampling_given || !args->roi_path.empty() || g.quads))
    return usage_error("encode", "--topology-preserving keeps the input's vertices: no --sampling, --roi or --gim-quads");
  return -1;
}

// A finite number > 0 in model units.
bool parse_length(const std::string& text, double* out) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(v) || !(v > 0)) return false;
  *out = v;
  return true;
}

// Sections 6 and 14: the grid and the POSN method; returns -1 when consistent.
int parse_positions(const CommandLine& cl, EncodeArgs* args) {
  EncodeOptions& o = args->options;
  for (const auto& [name, value] : cl.options) {
    if (name == "--grid") {
      if (value == "uniform") o.position_grid = PositionGrid::kUniform;
      else if (value == "per-axis") o.position_grid = PositionGrid::kPerAxis;
      else return usage_error("encode", "--grid takes uniform or per-axis, got '" + value + "'");
    } else if (name == "--step") {
      if (!parse_length(value, &o.position_step))
        return usage_error("encode", "--step takes a number > 0 in model units, got '" + value + "'");
    } else if (name == "--max-error") {
      if (!parse_length(value, &o.max_position_error))
        return usage_error("encode", "--max-error takes a number > 0 in model units, got '" + value + "'");
    } else if (name == "--surface-lattice") {
      long k = 0;
      if (value == "auto")
        args->lattice_auto = true;
      else if (!parse_int(value, 2, 16, &k))
        return usage_error("encode", "--surface-lattice takes a factor 2..16 (spec 14.15) or auto, got '" + value + "'");
      o.surface_lattice = args->lattice_auto ? 1 : int(k);
    } else if (name == "--positions") {
      if (value == "auto") o.position_method = PositionMethod::kAuto;
      else if (value == "deltas") o.position_method = PositionMethod::kDeltas;
      else if (value == "predicted") o.position_method = PositionMethod::kPredicted;
      else return usage_error("encode", "--positions takes auto, deltas or predicted, got '" + value + "'");
    }
  }
  bool bits_or_grid = false;
  for (const auto& option : cl.options)
    bits_or_grid = bits_or_grid || option.first == "--bits" || option.first == "-q" || option.first == "--grid";
  const int grids = int(bits_or_grid) + int(o.position_step > 0) + int(o.max_position_error > 0);
  bool grid_given = o.position_step > 0 || o.max_position_error > 0;
  for (const auto& option : cl.options) grid_given = grid_given || option.first == "--grid";
  if (grid_given && (args->progressive || args->options.gim.size > 0))
    return usage_error("encode", "--grid, --step and --max-error are for plain files: a progressive base takes "
                                 "--bits on spec 6.1's grid, a geometry image its own planes");
  if (grids > 1) return usage_error("encode", "give one of --bits/--grid, --step or --max-error");
  const bool lattice = o.surface_lattice > 1 || args->lattice_auto;
  if (lattice && (args->progressive || args->options.gim.size > 0))
    return usage_error("encode", "--surface-lattice (POSN method 14) is for plain files, not progressive ones or "
                                 "geometry images");
  if (lattice && (o.position_method == PositionMethod::kDeltas || !o.geometry_order))
    return usage_error("encode", "--surface-lattice (POSN method 14) needs predicted positions in the geometry "
                                 "order");
  if (o.position_method == PositionMethod::kDeltas && !args->progressive &&
      (o.position_grid != PositionGrid::kPerAxis || o.position_step > 0 || o.max_position_error > 0))
    return usage_error("encode", "--positions deltas (spec 6) carries only the grid of --grid per-axis");
  return -1;
}

// --format 1.N: the options that keep every feature within 1.N, or a usage
// error naming the option that needs a newer version.
int limit_to_format(const CommandLine& cl, EncodeArgs* args) {
  EncodeOptions& o = args->options;
  if (args->newest_minor >= 19) return -1;
  if (o.surface_lattice > 1 || args->lattice_auto)
    return usage_error("encode", "--surface-lattice (POSN method 14, spec 14.15) needs --format 1.19");
  if (args->newest_minor >= 18) return -1;
  o.polygon_quad_contexts = false;  // CONN coding 8 (5.4.10) came with 1.18
  if (args->newest_minor >= 17) return -1;
  o.axis_class_probabilities = false;  // POSN method 13 (14.14) came with 1.17
  if (args->newest_minor >= 16) return -1;
  o.edge_extrapolation = false;  // POSN method 12 (14.13) came with 1.16
  if (args->newest_minor >= 15) return -1;
  o.shear = false;  // POSN method 11 (14.12) came with 1.15
  if (args->newest_minor >= 14) return -1;
  if (o.max_deviation > 0) return usage_error("encode", "--max-deviation (LEVL code 4, spec 12.7.2) needs --format 1.14");
  if (args->newest_minor >= 13) return -1;
  o.near_mirror = false;      // POSN method 10 (14.11) came with 1.13,
  o.attribute_twins = false;  // and aTTR coding 9 (15.14) with it
  if (args->newest_minor >= 12) return -1;
  o.mirror_symmetry = false;  // POSN method 9 (14.10) came with 1.12
  if (args->newest_minor >= 11) return -1;
  o.triangle_twist = false;  // POSN method 8 (14.9) came with 1.11
  if (args->newest_minor >= 10) return -1;
  o.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came with 1.10
  if (args->newest_minor >= 9) return -1;
  o.quad_twist = false;  // POSN method 5 (14.7) came with 1.9
  if (args->newest_minor >= 8) return -1;
  o.geometry_order = false;
  o.attribute_geometry_order = false;  // aTTR coding 4 (15.9) came with 1.8
  o.attribute_graded_start = false;    // and codings 5 and 6 (15.10) after it,
  o.attribute_predicted_mapping = false;  // and mapping 3 (15.11)
  o.attribute_guided = false;             // and coding 7 (15.12)
  o.angle_weighted_normals = false;       // and coding 8 (15.13)
  if (args->newest_minor >= 7) return -1;
  o.graded_class_start = false;
  if (args->newest_minor >= 6) return -1;
  if (o.polygon_coding == kPolygonContextCoded) return usage_error("encode", "polygon coding 7 needs --format 1.6");
  o.polygon_context_coding = false;
  if (args->newest_minor >= 5) return -1;
  if (o.position_method == PositionMethod::kPredicted)
    return usage_error("encode", "--positions predicted (spec 14) needs --format 1.5 or later");
  bool uniform_asked = false;
  for (const auto& [name, value] : cl.options) uniform_asked = uniform_asked || (name == "--grid" && value == "uniform");
  if (o.position_step > 0 || o.max_position_error > 0 || uniform_asked)
    return usage_error("encode", "--grid uniform, --step and --max-error (spec 14's grids) need --format 1.5 or later");
  o.position_method = PositionMethod::kDeltas;
  o.position_grid = PositionGrid::kPerAxis;
  o.displacement_code = 0;
  return -1;
}

// --finest-step-scale, --target-error, --max-bytes (spec 12.10), --max-deviation
// (12.7.2); -1 when valid.
int parse_rate_option(const std::string& name, const std::string& value, EncodeArgs* args) {
  if (!args->progressive) return usage_error("encode", name + " needs --progressive");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(value.c_str(), &end);
  const bool number = !value.empty() && end && *end == 0 && errno == 0 && std::isfinite(v);
  if (name == "--finest-step-scale") {
    if (!number || v < 1 || v > 64) return usage_error("encode", "--finest-step-scale takes a number from 1 to 64, got '" + value + "'");
    args->options.finest_step_scale = v;
    args->step_scale_given = true;
  } else if (name == "--max-deviation") {
    if (!number || !(v > 0) || v >= 1)
      return usage_error("encode", "--max-deviation takes a relative distance above 0 and below 1 (e.g. 1e-3), got '" +
                                       value + "'");
    args->options.max_deviation = v;
  } else if (name == "--target-error" || name == "--target-hausdorff") {
    if (!number || !(v > 0) || v >= 1)
      return usage_error("encode", name + " takes a relative error above 0 and below 1 (e.g. 1e-4), got '" + value + "'");
    (name == "--target-error" ? args->rate.max_relative_l2 : args->rate.max_relative_hausdorff) = v;
  } else {
    long n = 0;
    if (!parse_int(value, 1, 2147483647, &n))
      return usage_error("encode", "--max-bytes takes a whole number of bytes from 1, got '" + value + "'");
    args->rate.max_bytes = uint64_t(n);
  }
  return -1;
}

int parse(int argc, char** argv, EncodeArgs* args) {
  CommandLine cl;
  if (int rc = parse_command_line(kSpec, argc, argv, &cl); rc >= 0) return rc;
  args->input = cl.positional[0];
  args->output = cl.positional[1];
  args->quiet = cl.has("--quiet");
  args->allow_empty = cl.has("--allow-empty");
  args->drop_unsupported = cl.has("--drop-unsupported");
  args->options.keep_order = cl.has("--keep-order");
  args->options.exact_attributes = cl.has("--exact-attributes");
  args->progressive = cl.has("--progressive");
  if (args->progressive) args->options.progressive_levels = 3;
  if (int rc = parse_gim(cl, args); rc >= 0) return rc;
  if (int rc = parse_positions(cl, args); rc >= 0) return rc;
  for (const auto& [name, value] : cl.options) {
    if (name == "--gim" || name == "--sampling" || name == "--roi") continue;  // parse_gim
    if (name == "--grid" || name == "--step" || name == "--max-error" || name == "--positions" ||
        name == "--surface-lattice")
      continue;
    if (name == "--format") {
      long minor = 0;
      if (value.compare(0, 2, "1.") != 0 || !parse_int(value.substr(2), kOldestTargetMinor, kNewestMinor, &minor) ||
          value.substr(2) != std::to_string(minor))
        return usage_error("encode", "--format takes 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 1.10, 1.11, 1.12, 1.13, 1.14, 1.15, 1.16, 1.17, 1.18 or 1.19, got '" +
                                         value + "'");
      args->newest_minor = int(minor);
      continue;
    }
    if (name == "--levels") {
      long levels = 0;
      if (!args->progressive) return usage_error("encode", "--levels needs --progressive");
      if (!parse_int(value, 1, 8, &levels))
        return usage_error("encode", "--levels takes a whole number from 1 to 8, got '" + value + "'");
      args->options.progressive_levels = int(levels);
      args->levels_given = true;
      continue;
    }
    if (name == "--finest-step-scale" || name == "--target-error" || name == "--target-hausdorff" ||
        name == "--max-bytes" || name == "--max-deviation") {
      if (int rc = parse_rate_option(name, value, args); rc >= 0) return rc;
      continue;
    }
    if (name == "--start-faces") {
      long starts = 0;
      if (args->progressive || args->options.gim.size > 0)
        return usage_error("encode", "--start-faces is for plain files, not progressive ones or geometry images");
      if (!parse_int(value, 1, 256, &starts))
        return usage_error("encode", "--start-faces takes a whole number from 1 to 256, got '" + value + "'");
      args->options.start_faces = uint32_t(starts);
      continue;
    }
    if (name == "--text") {
      args->options.texts.push_back(value);
      continue;
    }
    if (name == "--drop") {
      args->drop.push_back(value);
      continue;
    }
    if (name == "--uv-bits" || name == "--normal-bits" || name == "--color-bits") {
      long attribute_bits = 0;
      if (!parse_int(value, 1, 30, &attribute_bits))
        return usage_error("encode", name + " takes a whole number from 1 to 30, got '" + value + "'");
      int* field = name == "--uv-bits"       ? &args->options.texcoord_bits
                   : name == "--normal-bits" ? &args->options.normal_bits
                                             : &args->options.colour_bits;
      *field = int(attribute_bits);
      continue;
    }
    if (name == "--connectivity") {
      if (value == "auto") args->options.connectivity = ConnectivityChoice::kAuto;
      else if (value == "indexed") args->options.connectivity = ConnectivityChoice::kIndexed;
      else if (value == "quad") args->options.connectivity = ConnectivityChoice::kQuad;
      else if (value == "polygon") args->options.connectivity = ConnectivityChoice::kPolygon;
      else return usage_error("encode", "--connectivity takes auto, indexed, quad or polygon, got '" + value + "'");
      continue;
    }
    long bits = 0;
    if (!parse_int(value, kMinPositionBits, kMaxPositionBits, &bits))
      return usage_error("encode", "--bits takes a whole number from 1 to 30, got '" + value + "'");
    args->options.position_bits = int(bits);
    args->bits_given = true;
  }
  if ((args->rate.max_relative_l2 > 0) + (args->rate.max_relative_hausdorff > 0) + (args->rate.max_bytes > 0) > 1)
    return usage_error("encode", "--target-error, --target-hausdorff and --max-bytes exclude each other");
  return limit_to_format(cl, args);
}

std::string shortest_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

size_t vertices_of_no_face(const Mesh& mesh) {
  std::vector<uint8_t> used(mesh.vertex_count(), 0);
  for (uint32_t v : mesh.corners)
    if (v < used.size()) used[v] = 1;
  return size_t(std::count(used.begin(), used.end(), uint8_t(0)));
}

void print_report(const EncodeArgs& args, const Mesh& mesh, const EncodeStats& stats,
                  const tools::RoundTripReport& check, uint64_t input_bytes) {
  const double v = mesh.vertex_count() ? double(mesh.vertex_count()) : 1.0;
  std::printf("input       %s: %zu vertices, %zu faces, %s\n", args.input.c_str(), mesh.vertex_count(),
              mesh.face_count(), human_bytes(input_bytes).c_str());
  if (const size_t unused = vertices_of_no_face(mesh); unused > 0)
    std::printf("            %zu vertices no face uses: kept, with the last labels%s\n", unused,
                stats.method == ConnectivityMethod::kPolygon && args.options.unused_vertices_along_curve
                    ? ", along a curve (spec 5.4.9)"
                    : "");
  if (stats.method == ConnectivityMethod::kQuad) {
    const QuadCoderStats& q = stats.quad;
    std::printf("connectivity quad coder (seed 001: Q1-Q13, Spirale Reversi), %s, %s:",
                q.closed ? "closed (one quad cut open)" : "one boundary", quad_coding_name(QuadCoding(q.coding)));
    for (int c = 0; c < kQuadCodingCount; ++c) {
      if (q.coding_bits[c] < 0) std::printf(" %s n/a", quad_coding_name(QuadCoding(c)));
      else std::printf(" %s %.3f", quad_coding_name(QuadCoding(c)), double(q.coding_bits[c]) / v);
    }
    std::printf(" bits/vertex\n");
    if (q.claim_violations)
      std::printf("             %u times a Q5/Q10/Q12/Q13 was followed by Q1-Q5 (seed 001 4.1 claim fails)\n",
                  q.claim_violations);
  } else if (stats.method == ConnectivityMethod::kPolygon) {
    const PolygonCoderStats& p = stats.polygon;
    if (!stats.fallback_reason.empty()) std::printf("connectivity quad coder not used: %s\n", stats.fallback_reason.c_str());
    std::printf("connectivity polygon coder (spec 5.4), coding %u:", p.coding);
    for (int c = 0; c < kPolygonCodingCount; ++c) {
      if (c == kPolygonUnassignedCoding) continue;
      if (p.coding_bits[c] < 0) std::printf(" %d n/a", c);
      else std::printf(" %d %.3f", c, double(p.coding_bits[c]) / v);
    }
    std::printf(" bits/vertex\n");
    std::printf("             %u components, %u holes closed, %u handles cut, %u vertex identifications, %u loose "
                "faces, %u faces not quads; records %.3f bits/vertex\n",
                p.components, p.holes, p.handles, p.identifications, p.loose_faces, p.non_quad_faces,
                double(p.record_bits) / v);
    if (p.start_trials > 1)
      std::printf("             --start-faces %u: kept start %u of %u (0: the usual start, %llu bytes)\n",
                  p.start_trials, p.start_kept, p.start_trials, (unsigned long long)p.usual_start_bytes);
  } else {
    std::printf("connectivity indexed coding%s%s\n", stats.fallback_reason.empty() ? "" : "; quad coder not used: ",
                stats.fallback_reason.c_str());
    if (!stats.polygon_fallback_reason.empty())
      std::printf("             polygon coder not used: %s\n", stats.polygon_fallback_reason.c_str());
  }
  for (const ChunkStats& c : stats.chunks)
    std::printf("  %-4s %10llu bytes  %8.2f bits/vertex\n", chunk_type_name(c.type).c_str(),
                static_cast<unsigned long long>(c.bytes), 8.0 * double(c.bytes) / v);
  if (args.options.keep_order) {
    bool written = false;
    for (const ChunkStats& c : stats.chunks) written = written || c.type == kChunkOrder;
    std::printf("order       %s\n", written ? "the input's order, restored by the oRDR chunk"
                                            : "the coder's order already is the input's: no oRDR chunk needed");
  }
  std::printf("output      %s: %llu bytes, %.2f bits/vertex, %.1fx smaller than the input file\n",
              args.output.c_str(), static_cast<unsigned long long>(stats.total_bytes),
              8.0 * double(stats.total_bytes) / v, double(input_bytes) / double(stats.total_bytes));
  const double side = check.max_bbox_side > 0 ? check.max_bbox_side : 1.0;
  const PositionStats& ps = stats.positions;
  const std::string positions_method =
      ps.method == 0 ? "deltas (spec 6)"
                     : "predicted (spec 14, method " + std::to_string(ps.method) + position_method_traits(ps.method, ps.features, ps.mirror, ps.shear, ps.lattice) +
                           (ps.graded_start ? (ps.method >= 4 ? ", graded start" : ": graded start") : "") + ")";
  std::printf("positions   %s, %s grid, step %.6g%s; bound %.6g, max error %.6g (%.3g of largest bbox side), "
              "rms %.6g\n",
              positions_method.c_str(),
              ps.step[0] == ps.step[1] && ps.step[1] == ps.step[2] ? "uniform" : "per-axis", ps.step[0],
              ps.step[0] == ps.step[1] && ps.step[1] == ps.step[2] ? "" : " (x)", ps.error_bound, check.max_error,
              check.max_error / side, check.rms_error);
  if (ps.lattice_payload_bytes > 0)
    std::printf("             surface lattice of %d steps (spec 14.15): %s; its POSN payload %llu bytes, the grid's %llu\n",
                args.options.surface_lattice,
                ps.lattice > 1 ? "kept" : "not kept, the grid's is smaller (and nearer the input)",
                static_cast<unsigned long long>(ps.lattice_payload_bytes),
                static_cast<unsigned long long>(ps.grid_payload_bytes));
  if (ps.method >= 1) {
    static const char* const kKinds[5] = {"previous vertex", "neighbour mean", "one rule", "several rules",
                                         "mirror"};
    std::printf("             by prediction (spec 14.3):");
    for (int k = 0; k < 5; ++k)
      if (ps.vertices_by_kind[k])
        std::printf(" %s %u vertices %.2f bits each;", kKinds[k], ps.vertices_by_kind[k],
                    ps.bits_by_kind[k] / ps.vertices_by_kind[k]);
    std::printf("\n");
  }
  for (const AttributeStats& a : stats.attributes)
    std::printf("attribute   %s (spec 15): %u values, %s, %s; %llu bytes (mapping %llu, values %llu), %.2f bits/value\n",
                a.name.c_str(), a.value_count,
                !a.per_corner         ? "one per vertex"
                : a.predicted_mapping ? "per corner, predicted from the faces (spec 15.11)"
                                      : "per corner",
                a.exact        ? "exact binary32"
                : a.angle_weighted ? "unit normals, octahedral, faces weighted by angle (spec 15.13)"
                : a.octahedral ? "unit normals, octahedral (spec 15.7)"
                               : ("grid step " + shortest_number(a.step) +
                                  (a.guided ? ", guided by the positions (spec 15.12)" : "") +
                                  (a.geometry_order ? ", geometry order (spec 15.9)" : "") +
                                  (a.graded_start ? ", graded start (spec 15.10)" : "") +
                                  (a.twins ? ", twins across the mirror plane (spec 15.14)" : ""))
                                     .c_str(),
                static_cast<unsigned long long>(a.chunk_bytes), static_cast<unsigned long long>(a.mapping_bytes),
                static_cast<unsigned long long>(a.value_bytes),
                a.value_count ? 8.0 * double(a.value_bytes) / a.value_count : 0.0);
}

// Section 12: what a viewer has after level j arrives: the bytes read when
// its LEVL chunk completes (all but the later levels and QEND) and the
// level's distance to the input (the finest level's is `finest`).
struct LevelCurve {
  std::vector<uint64_t> bytes_read;
  std::vector<tools::MeshDistance> distance;
};

Status level_curve(const Mesh& input, const EncodeStats& stats, const DecodedFile& decoded,
                   const tools::MeshDistance& finest, LevelCurve* curve) {
  const std::vector<LoopLevelStats>& levels = stats.loop.levels;
  uint64_t later = 12;  // QEND
  curve->bytes_read.assign(levels.size(), 0);
  for (size_t j = levels.size(); j-- > 0;) {
    curve->bytes_read[j] = stats.total_bytes - later;
    later += levels[j].bytes;
  }
  curve->distance.assign(levels.size(), finest);
  Progress progress(true);
  for (size_t j = 0; j + 1 < levels.size() && j < decoded.levels.size(); ++j) {
    progress.stage("measuring level " + std::to_string(j));
    if (Status s = tools::measure_mesh_distance(input, level_mesh(decoded.levels[j]), {}, &curve->distance[j]); !s.ok())
      return s;
  }
  progress.done();
  return Status::Ok();
}

// Levels no nearer the input than the level before them (spec 12.10: the
// encoder's levels need not approach it, e.g. from a very coarse base, or
// where Loop's boundary rules round a flat grid's corners): said, with what
// can give levels that do.
void print_rising_levels(const LoopEncodeStats& ls, const LevelCurve& curve) {
  std::string rising;
  for (size_t j = 1; j < curve.distance.size(); ++j) {
    const tools::MeshDistance &d = curve.distance[j], &before = curve.distance[j - 1];
    if (d.relative(d.l2) >= before.relative(before.l2)) rising += (rising.empty() ? "" : ", ") + std::to_string(j);
  }
  if (rising.empty()) return;
  std::printf("note        level(s) %s no nearer the input than the level before (L2 above; a base of %u vertices, "
              "%zu levels); fewer --levels, or --target-error E, can give levels that approach it\n",
              rising.c_str(), ls.levels.empty() ? 0u : ls.levels[0].vertices, ls.levels.size() - 1);
}

// LoopLevelStats::targets, as the report names it.
const char* target_rule_name(uint8_t targets) {
  switch (targets) {
    case 1: return "misses stay";
    case 2: return "5x reach";
    case 3: return "closest points";
    default: return "no displacement";
  }
}

void print_progressive_report(const EncodeArgs& args, const Mesh& input, const EncodeStats& stats,
                              const LevelCurve& curve, const tools::MeshDistance& distance, uint64_t input_bytes) {
  const LoopEncodeStats& ls = stats.loop;
  std::printf("input       %s: %zu vertices, %zu triangles, %s\n", args.input.c_str(), input.vertex_count(),
              input.face_count(), human_bytes(input_bytes).c_str());
  if (ls.unreferenced_vertices_dropped)
    std::printf("            %u vertices no face uses were left out (a remesh covers faces only)\n",
                ls.unreferenced_vertices_dropped);
  if (ls.faces_without_area_dropped || ls.duplicate_faces_dropped)
    std::printf("            left out (no area of their own): faces that repeat a vertex %u, second copies of a face %u\n",
                ls.faces_without_area_dropped, ls.duplicate_faces_dropped);
  if (ls.edges_cut || ls.vertices_added)
    std::printf("            not manifold, cut (the surface is the same): edges of 3+ faces or run one way by two %u, "
                "vertices added where faces meet in separate fans %u\n",
                ls.edges_cut, ls.vertices_added);
  std::printf("pipeline    simplify %.2f s, fit %.2f s, subdivide+displace+inverse %.2f s, code %.2f s\n",
              ls.seconds_simplify, ls.seconds_fit, ls.seconds_remesh, ls.seconds_code);
  std::printf("levels      level  vertices     faces  edge points  zero %%     step        bytes  code   bytes read  "
              "L2 / diag  Hausdorff / diag\n");
  for (size_t j = 0; j < ls.levels.size(); ++j) {
    const LoopLevelStats& l = ls.levels[j];
    const tools::MeshDistance& d = curve.distance[j];
    if (j == 0)
      std::printf("            base  %9u %9u  %11s  %6s  %9s  %10llu     -", l.vertices, l.faces, "-", "-", "-",
                  static_cast<unsigned long long>(l.bytes));
    else
      std::printf("            %4zu  %9u %9u  %11u  %6.2f  %9.3g  %10llu  %4u", j, l.vertices, l.faces, l.edge_points,
                  100.0 * l.zeros / (l.edge_points ? l.edge_points : 1), l.step, static_cast<unsigned long long>(l.bytes),
                  unsigned(l.code));
    std::printf("  %11llu  %9.3g  %16.3g", static_cast<unsigned long long>(curve.bytes_read[j]), d.relative(d.l2),
                d.relative(d.hausdorff));
    if (j == 0)
      std::printf("  (CONN + POSN: %s coder, %s positions)\n", connectivity_method_name(stats.method),
                  stats.positions.method >= 1 ? "predicted" : "delta");
    else
      std::printf("%s%s\n", l.clamped ? (" (" + std::to_string(l.clamped) + " clamped to 127)").c_str() : "",
                  l.targets ? (std::string(" (closed loop: ") + target_rule_name(l.targets) + ")").c_str() : "");
  }
  if (args.options.max_deviation > 0) {
    const LoopLevelStats& finest = ls.levels.back();
    if (finest.code == 4)
      std::printf("deviation   finest level, largest distance either way over the fit's samples: %.3g of the diagonal "
                  "before its corrections, %.3g after (asked: %.3g); %u vertices corrected, %.2f s\n",
                  ls.deviation_before, ls.deviation_after, args.options.max_deviation, finest.corrected_vertices,
                  ls.seconds_deviation);
    else if (ls.deviation_before > args.options.max_deviation)
      std::printf("deviation   finest level %.3g of the diagonal from the input, over the asked %.3g: the corrections "
                  "were left out, as they would not leave it nearer the input (L2) than the level below\n",
                  ls.deviation_before, args.options.max_deviation);
    else
      std::printf("deviation   finest level within %.3g of the input (asked: %.3g): no corrections needed\n",
                  ls.deviation_before, args.options.max_deviation);
  }
  if (!ls.levels.empty() && ls.levels.back().targets == 0)
    std::printf("            finest level along its normals: %u hit the input surface, %u missed it within the reach\n",
                ls.ray_hits, ls.ray_misses);
  std::printf("output      %s: %llu bytes, %.1fx smaller than the input file\n", args.output.c_str(),
              static_cast<unsigned long long>(stats.total_bytes), double(input_bytes) / double(stats.total_bytes));
  std::printf("error       finest level vs input (Metro-style, %zu samples): L2 %.6g (%.3g of bbox diagonal), "
              "Hausdorff %.6g (%.3g), PSNR %.2f dB\n",
              distance.a_to_b.area_samples, distance.l2, distance.relative(distance.l2), distance.hausdorff,
              distance.relative(distance.hausdorff), distance.psnr_db);
  print_rising_levels(ls, curve);
}

// Lossy modes (sections 12, 13): encode with progress on a terminal, decode
// the result, and measure the surface distance to `reference`.
struct RemeshResult {
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  DecodedFile decoded;
  tools::MeshDistance distance;
};

Status encode_remesh(const EncodeArgs& args, const Mesh& mesh, const Mesh& reference, const std::string& label,
                     RemeshResult* r) {
  Progress progress(true);
  EncodeOptions options = args.options;
  options.progress = [&](const char* stage, double) { progress.stage(label + stage); };
  if (Status s = encode(mesh, options, &r->bytes, &r->stats); !s.ok()) return s;
  progress.stage("decoding to measure the error");
  if (Status s = tools::decode_and_measure(reference, r->bytes, tools::MeshDistanceOptions{}.samples, &r->decoded,
                                           &r->distance);
      !s.ok())
    return s;
  progress.done();
  return Status::Ok();
}

// Section 12: triangles in, progressive file out, error measured by decoding it.
// The file's QHDR minor (spec 4.1: QHDR is the first chunk, after the
// 8-byte signature and its 8 bytes of type and length) against --format.
int refuse_newer_format(const EncodeArgs& args, const std::vector<uint8_t>& bytes) {
  const size_t minor_at = 8 + 8 + 1;
  if (bytes.size() > minor_at && bytes[minor_at] <= args.newest_minor) return -1;
  return fail("encode", Status(ErrorCode::kInvalidArgument, "internal error: the file needs a format newer than --format 1." +
                                                                std::to_string(args.newest_minor)));
}

// What the reader ignored ("ignored ..." notes) is data the file would not
// carry: an error naming it, unless the user asked to drop it
// (--drop-unsupported), and then a list of what was dropped; the reader's
// other notes are printed as notes. Returns -1 to go on, else the exit code.
int refuse_dropping(const EncodeArgs& args, const std::vector<std::string>& notes) {
  std::vector<std::string> ignored;
  for (const std::string& note : notes) {
    if (note.rfind("ignored", 0) == 0)
      ignored.push_back(note);
    else if (!args.quiet)
      std::fprintf(stderr, "note: %s: %s\n", args.input.c_str(), note.c_str());
  }
  if (ignored.empty()) return -1;
  if (!args.drop_unsupported) {
    std::fprintf(stderr, "qmc encode: %s holds what format 1.%d cannot carry yet:\n", args.input.c_str(),
                 int(kFormatMinor));
    for (const std::string& what : ignored) std::fprintf(stderr, "  %s\n", what.c_str());
    std::fprintf(stderr, "qmc encode: pass --drop-unsupported to encode the mesh without it\n");
    return kExitError;
  }
  if (!args.quiet)
    for (const std::string& what : ignored)
      std::fprintf(stderr, "dropped (--drop-unsupported): %s: %s\n", args.input.c_str(), what.c_str());
  return -1;
}

// --drop NAME leaves an attribute or face labels (spec 16) out, and
// --drop-unsupported all of them for a progressive file or a geometry image
// (spec 15.1, 16.1: they carry none); what is left out is printed. What
// those files would lose without either is an error naming the flags.
// Returns -1 to go on, else the exit code.
int drop_attributes(const EncodeArgs& args, Mesh* mesh) {
  if (int rc = drop_each_named("encode", args.drop, args.input, args.quiet, mesh); rc >= 0) return rc;
  const bool carries_none = args.progressive || args.options.gim.size > 0;
  if (!carries_none || (mesh->attributes.empty() && mesh->face_labels.empty())) return -1;
  std::string names;
  for (const MeshAttribute& a : mesh->attributes) names += (names.empty() ? "" : ", ") + a.name;
  for (const FaceLabels& l : mesh->face_labels) names += (names.empty() ? "" : ", ") + l.name;
  const char* what = args.progressive ? "a progressive file" : "a geometry image";
  if (!args.drop_unsupported)
    return fail("encode", Status(ErrorCode::kInvalidArgument,
                                 std::string(what) + " carries no attributes or face labels (spec 15.1, 16.1); " +
                                     args.input + " has " + names + ": pass --drop NAME for each, or --drop-unsupported"));
  if (!args.quiet)
    std::fprintf(stderr, "dropped (--drop-unsupported): %s: %s (%s carries none)\n", args.input.c_str(), names.c_str(),
                 what);
  mesh->attributes.clear();
  mesh->face_labels.clear();
  return -1;
}

// What the rate control tried, one line per candidate (spec 12.10).
void print_rate_curve(const tools::RateTarget& target, const tools::RateChoice& choice) {
  if (target.max_bytes > 0)
    std::printf("rate        the least L2 error within %llu bytes; tried:\n", static_cast<unsigned long long>(target.max_bytes));
  else if (target.max_relative_hausdorff > 0)
    std::printf("rate        the smallest file within relative Hausdorff %.3g; tried:\n", target.max_relative_hausdorff);
  else
    std::printf("rate        the smallest file within relative L2 %.3g; tried:\n", target.max_relative_l2);
  std::printf("            K  base bits  finest step scale       bytes  L2 / diagonal  Hausdorff / diagonal\n");
  size_t unmeasured = 0;
  for (size_t i = 0; i < choice.tried.size(); ++i) {
    const tools::RatePoint& p = choice.tried[i];
    if (!p.failure.empty())
      std::printf("            %d  cannot be coded: %s\n", p.levels, p.failure.c_str());
    else if (p.relative_l2 < 0)
      ++unmeasured;
    else
      std::printf("            %d  %9d  %17.3g  %10llu  %13.4g  %20.4g%s\n", p.levels, p.position_bits, p.step_scale,
                  static_cast<unsigned long long>(p.bytes), p.relative_l2, p.relative_hausdorff,
                  int(i) == choice.chosen ? "  <- chosen" : "");
  }
  if (unmeasured)
    std::printf("            and %zu more coded but not measured: %s\n", unmeasured,
                target.max_bytes > 0 ? "larger than the limit" : "not smaller than the best");
}

// The search space: what --levels, --bits and --finest-step-scale fix stays fixed.
tools::RateSearch rate_search_of(const EncodeArgs& args, const Mesh& mesh) {
  tools::RateSearch search = tools::default_rate_search(mesh);
  if (args.levels_given) search.levels = {args.options.progressive_levels};
  if (args.bits_given) search.position_bits = {args.options.position_bits};
  if (args.step_scale_given) search.step_scales = {args.options.finest_step_scale};
  return search;
}

// A progressive file out: refused if newer than --format, its level curve
// measured (unless --quiet) before it is written, so that a failure writes
// nothing, then the report.
int write_progressive(const EncodeArgs& args, const Mesh& mesh, const std::vector<uint8_t>& bytes,
                      const EncodeStats& stats, const DecodedFile& decoded, const tools::MeshDistance& distance,
                      uint64_t input_bytes) {
  if (int refused = refuse_newer_format(args, bytes); refused >= 0) return refused;
  LevelCurve curve;
  if (!args.quiet)
    if (Status c = level_curve(mesh, stats, decoded, distance, &curve); !c.ok()) return fail("encode", c);
  if (Status w = write_file(args.output, bytes); !w.ok()) return fail("encode", w);
  if (!args.quiet) print_progressive_report(args, mesh, stats, curve, distance, input_bytes);
  return kExitOk;
}

int encode_progressive_to_target(const EncodeArgs& args, const Mesh& mesh, uint64_t input_bytes) {
  Progress progress(true);
  tools::RateChoice choice;
  const Status s = tools::choose_progressive(mesh, args.options, args.rate, rate_search_of(args, mesh),
                                             [&](const std::string& what) { progress.stage("progressive: " + what); },
                                             &choice);
  progress.done();
  if (!s.ok()) return fail("encode", s);
  if (!args.quiet) print_rate_curve(args.rate, choice);
  if (choice.chosen < 0)
    return fail("encode", Status(ErrorCode::kInvalidArgument,
                                 args.rate.max_bytes > 0 ? "no candidate fits in " + std::to_string(args.rate.max_bytes) +
                                                               " bytes (the list above); nothing written"
                                                         : "no candidate reaches the target error (the list above): "
                                                           "allow more levels or bits, or a larger error; nothing written"));
  return write_progressive(args, mesh, choice.bytes, choice.stats, choice.decoded, choice.distance, input_bytes);
}

int encode_progressive(EncodeArgs& args, Mesh mesh, uint64_t input_bytes) {
  size_t split = 0;
  mesh = tools::triangulated(mesh, &split);
  if (split && !args.quiet)
    std::printf("triangulated %zu polygons (fan from their first corner): --progressive takes triangles\n", split);
  if (args.rate.error_target() || args.rate.max_bytes > 0) return encode_progressive_to_target(args, mesh, input_bytes);
  if (!args.levels_given) {
    args.options.progressive_levels = tools::default_progressive_levels(mesh.face_count());
    if (!args.quiet)
      std::printf("levels      %d: the most whose base keeps 1,000 of the %zu triangles (--levels sets it)\n",
                  args.options.progressive_levels, mesh.face_count());
  }
  RemeshResult r;
  if (Status s = encode_remesh(args, mesh, mesh, "progressive: ", &r); !s.ok()) return fail("encode", s);
  return write_progressive(args, mesh, r.bytes, r.stats, r.decoded, r.distance, input_bytes);
}

void print_gim_report(const EncodeArgs& args, const Mesh& input, const EncodeStats& stats,
                      const tools::MeshDistance& distance, uint64_t input_bytes, const std::string& exactness) {
  const GimEncodeStats& g = stats.gim;
  std::printf("input       %s: %zu vertices, %zu faces, %s; genus %d, %d boundary loops\n", args.input.c_str(),
              input.vertex_count(), input.face_count(), human_bytes(input_bytes).c_str(), g.genus, g.boundary_loops);
  if (g.polygons_split) std::printf("            %u polygons split into triangles (fan from their first corner)\n", g.polygons_split);
  if (g.unreferenced_vertices)
    std::printf("            %u vertices no face uses are not in the image\n", g.unreferenced_vertices);
  std::printf("cut         %u cut nodes, %u cut paths, %u seam pixel pairs\n", g.cut_nodes, g.cut_paths, g.seam_pairs);
  std::printf("image       %u x %u pixels, %u occupied, %s samples, %s\n", g.width, g.height, g.occupied,
              args.options.gim.float_samples ? "binary32" : "16-bit",
              args.options.gim.topology_preserving ? "input triangles (GFAC)"
                                                   : args.options.gim.quads ? "grid quads" : "grid triangles");
  std::printf("pipeline    cut %.2f s, parametrize %.2f s, sample/place %.2f s, adjust %.2f s, code %.2f s\n",
              g.seconds_cut, g.seconds_parametrize, g.seconds_sample, g.seconds_adjust, g.seconds_code);
  if (g.hausdorff_before >= 0)
    std::printf("hausdorff   seed 000 algorithm 1: %u steps, %.6g -> %.6g\n", g.hausdorff_iterations,
                g.hausdorff_before, g.hausdorff_after);
  std::printf("chunks      mask %llu, seams %llu, faces %llu bytes; planes", static_cast<unsigned long long>(g.mask_bytes),
              static_cast<unsigned long long>(g.seam_bytes), static_cast<unsigned long long>(g.face_bytes));
  for (size_t i = 0; i < g.plane_bytes.size(); ++i)
    std::printf(" %llu (predictor %d)", static_cast<unsigned long long>(g.plane_bytes[i]), g.plane_predictors[i]);
  std::printf("\noutput      %s: %llu bytes, %.1fx smaller than the input file\n", args.output.c_str(),
              static_cast<unsigned long long>(stats.total_bytes), double(input_bytes) / double(stats.total_bytes));
  std::printf("error       decoded vs input (Metro-style): L2 %.6g (%.3g of bbox diagonal), Hausdorff %.6g (%.3g), "
              "PSNR %.2f dB%s\n",
              distance.l2, distance.relative(distance.l2), distance.hausdorff, distance.relative(distance.hausdorff),
              distance.psnr_db, exactness.c_str());
}

// Seed 002: the decoded triangles are the input's, in order; how far their
// corners moved.
std::string topology_preserving_check(const Mesh& triangles, const Mesh& decoded) {
  if (decoded.face_count() != triangles.face_count()) return "; internal error: face count differs";
  double worst = 0;
  for (size_t c = 0; c < triangles.corners.size(); ++c)
    for (int a = 0; a < 3; ++a)
      worst = std::max(worst, double(std::fabs(triangles.positions[3 * size_t(triangles.corners[c]) + size_t(a)] -
                                                decoded.positions[3 * size_t(decoded.corners[c]) + size_t(a)])));
  if (worst == 0) return "; every triangle corner bit-identical to the input";
  char text[96];
  std::snprintf(text, sizeof text, "; input triangles kept, corners within %.3g", worst);
  return text;
}

int encode_gim(EncodeArgs& args, const Mesh& mesh, uint64_t input_bytes) {
  if (!args.roi_path.empty()) {
    std::vector<uint8_t> text;
    if (Status s = read_file(args.roi_path, &text); !s.ok()) return fail("encode", s);
    args.options.gim.roi.assign(text.begin(), text.end());
  }
  const Mesh triangles = tools::triangulated(mesh, nullptr);
  RemeshResult result;
  if (Status s = encode_remesh(args, mesh, triangles, "geometry image: ", &result); !s.ok()) return fail("encode", s);
  const std::vector<uint8_t>& bytes = result.bytes;
  const EncodeStats& stats = result.stats;
  const tools::MeshDistance& distance = result.distance;
  const std::string exactness =
      args.options.gim.topology_preserving ? topology_preserving_check(triangles, result.decoded.mesh) : "";
  if (int refused = refuse_newer_format(args, bytes); refused >= 0) return refused;
  if (Status s = write_file(args.output, bytes); !s.ok()) return fail("encode", s);
  if (!args.quiet) print_gim_report(args, mesh, stats, distance, input_bytes, exactness);
  return kExitOk;
}

// --surface-lattice auto: the file (bytes, stats) of the smallest file no
// farther from the input (L2) than the grid's, each candidate coded, decoded
// and measured with 50,000 samples; the trials printed; -1 to carry on.
int choose_lattice(EncodeArgs* args, const Mesh& mesh, Progress& progress, std::vector<uint8_t>* bytes,
                   EncodeStats* stats) {
  progress.stage("trying the surface lattice's factors");
  int factor = 1;
  std::vector<tools::LatticeTrial> trials;
  if (Status s = tools::choose_surface_lattice(mesh, args->options, 50000, &factor, bytes, stats, &trials); !s.ok())
    return fail("encode", s);
  args->options.surface_lattice = factor;
  if (args->quiet) return -1;
  std::printf("lattice     --surface-lattice auto (spec 14.15): L2 / bounding-box diagonal, 50,000 samples:");
  for (const tools::LatticeTrial& t : trials) {
    std::printf(" %s %llu bytes %.3g%s;", t.factor == 1 ? "grid" : ("F = " + std::to_string(t.factor)).c_str(),
                static_cast<unsigned long long>(t.bytes), t.l2,
                t.factor == 1 || t.on_lattice ? "" : " (grid kept)");
  }
  std::printf(" %s\n", factor == 1 ? "the grid kept: no lattice file smaller at its L2"
                                    : ("F = " + std::to_string(factor) + " kept").c_str());
  return -1;
}

}  // namespace

int run_encode(int argc, char** argv) {
  EncodeArgs args;
  if (int rc = parse(argc, argv, &args); rc >= 0) return rc;
  if (int rc = refuse_overwriting_input("encode", args.input, args.output); rc >= 0) return rc;
  if (!args.roi_path.empty())
    if (int rc = refuse_overwriting_input("encode", args.roi_path, args.output); rc >= 0) return rc;
  // Only the size is reported; the reader below opens the file (and says
  // why it cannot), so the file is not read twice.
  std::error_code size_error;
  const uint64_t input_size = std::filesystem::file_size(args.input, size_error);
  // Big inputs take seconds, as do N encodes of --start-faces.
  Progress progress(!size_error && (input_size > (16u << 20) || args.options.start_faces > 1));
  progress.stage("reading " + args.input);
  Mesh mesh;
  std::vector<std::string> ignored;
  if (Status s = load_mesh(args.input, &mesh, true, &ignored); !s.ok()) return fail("encode", s);
  if (int refused = refuse_dropping(args, ignored); refused >= 0) return refused;
  if (int refused = drop_attributes(args, &mesh); refused >= 0) return refused;
  // An empty mesh is a valid file (the valid_empty_mesh vector), but from a
  // mesh file it is far more often a mistake than an intention.
  if (mesh.vertex_count() == 0 && mesh.face_count() == 0 && !args.allow_empty)
    return fail("encode", Status(ErrorCode::kInvalidArgument,
                                 args.input + ": no vertices and no faces (pass --allow-empty to encode an empty mesh)"));
  if (args.progressive) return encode_progressive(args, std::move(mesh), input_size);
  if (args.options.gim.size > 0) return encode_gim(args, mesh, input_size);
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  if (args.lattice_auto) {
    if (int rc = choose_lattice(&args, mesh, progress, &bytes, &stats); rc >= 0) return rc;
  } else {
    progress.stage("encoding " + std::to_string(mesh.face_count()) + " faces");
    const uint32_t starts = args.options.start_faces;
    if (starts > 1)
      args.options.progress = [&](const char*, double fraction) {
        progress.stage("encoding " + std::to_string(mesh.face_count()) + " faces from start " +
                       std::to_string(uint32_t(fraction * starts + 0.5)) + " of " + std::to_string(starts));
      };
    if (Status s = encode(mesh, args.options, &bytes, &stats); !s.ok()) return fail("encode", s);
  }
  // Decode what was written: the report's error figures are measured, not
  // derived. Our own output: the decoder limits of spec 8.1 are for files of
  // unknown origin, so none apply.
  progress.stage("decoding to measure the error");
  DecodedFile decoded;
  if (Status s = decode(bytes.data(), bytes.size(), &decoded, DecoderLimits::unlimited()); !s.ok())
    return fail("encode", Status(s.code(), "internal error, own output does not decode: " + s.message()));
  // --keep-order: the decoder must return the input's order exactly (with or
  // without an oRDR chunk); otherwise the encoder's correspondence.
  const tools::RoundTripReport check = tools::check_round_trip(
      mesh, decoded,
      args.options.keep_order ? tools::identity_correspondence(mesh)
                             : tools::Correspondence{stats.file_vertex, stats.face_source});
  progress.done();
  if (!check.ok())
    return fail("encode", Status(ErrorCode::kInvalidArgument, "internal error, round trip mismatch: " +
                                                                  check.face_mismatch + check.position_mismatch));
  if (int refused = refuse_newer_format(args, bytes); refused >= 0) return refused;
  if (Status s = write_file(args.output, bytes); !s.ok()) return fail("encode", s);
  if (!args.quiet) print_report(args, mesh, stats, check, input_size);
  return kExitOk;
}

}  // namespace qmc::cli
