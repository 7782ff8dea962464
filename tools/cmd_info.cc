// qmc info: what a .qmc file holds and where its bytes go.
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "encoder/position_encoder.h"
#include "qmc/decoder.h"

namespace qmc::cli {
namespace {

const char kHelp[] =
    "usage: qmc info IN.qmc [--json] [--max-output-mb N]\n"
    "\n"
    "Lists the chunks of IN.qmc with their sizes and bits per vertex, the format\n"
    "version, the connectivity coding and the quantization. A file that fails to\n"
    "decode is listed up to the failing chunk, then the error (exit code 3).\n"
    "\n"
    "options:\n";


std::map<uint32_t, size_t> degree_histogram(const Mesh& mesh) {
  std::map<uint32_t, size_t> h;
  for (uint32_t d : mesh.face_sizes) ++h[d];
  return h;
}

// Spec 4.5: which of the oRDR maps the file carries.
std::string order_description(uint8_t flags) {
  std::string s = "input order restored by oRDR (";
  const char* sep = "";
  const char* names[] = {"faces", "vertices", "corners"};
  for (int b = 0; b < 3; ++b)
    if (flags & (1u << b)) {
      s += sep;
      s += names[b];
      sep = ", ";
    }
  return s + (*sep ? " reordered)" : "identity)");
}

// Section 14: the grid, its error bound, and what each prediction kind
// costs as this encoder would code the decoded values (information content;
// only of a file that decoded, as a rejected one's integers may be missing).
void print_predicted_positions(const DecodedFile& f, bool decoded) {
  const QuantizationInfo& q = f.quantization;
  const bool uniform = q.step[0] == q.step[1] && q.step[1] == q.step[2];
  // 14.1: half a step per axis; 14.15's lattice: the encoder's k steps.
  const double within = q.lattice > 1 ? double(q.lattice) : 0.5;
  const double bound = within * std::sqrt(q.step[0] * q.step[0] + q.step[1] * q.step[1] + q.step[2] * q.step[2]);
  std::printf("positions    predicted (spec 14, method %d%s%s), %s grid, step %.9g", q.method,
              position_method_traits(q.method, q.features, q.mirror_axis < 0 ? 0 : q.near_images ? 2 : 1, q.shear, q.lattice).c_str(), q.graded_start ? ": graded start" : "",
              uniform ? "uniform" : "per-axis", q.step[0]);
  if (!uniform) std::printf(" %.9g %.9g", q.step[1], q.step[2]);
  std::printf(", tops %u %u %u, origin (%g %g %g); error bound %.6g\n", q.top[0], q.top[1], q.top[2], q.min[0],
              q.min[1], q.min[2], bound);
  if (!decoded || f.order_restored || f.loop_level_count > 0) return;  // faces no longer in the coder's order
  if (q.lattice > 1) return;  // 14.15: where the encoder placed a vertex depended on its input, not kept
  QuantizedPositions grid;
  grid.min = q.min;
  grid.step = q.step;
  grid.top = q.top;
  grid.q = f.quantized;
  PositionStats stats;
  const MirrorPlane plane{q.mirror_axis, q.mirror_sum, q.near_images};
  const size_t payload =
      encode_predicted_positions(grid, f.mesh, &stats, CandidateChoice::kFewestBits,
                                 q.graded_start ? ClassStart::kGraded : ClassStart::kFlat,
                                 q.method >= 4 ? PredictionOrder::kGeometry : PredictionOrder::kLabels,
                                 q.features & 1, q.features & 2, q.features & 4,
                                 q.mirror_axis >= 0 ? &plane : nullptr, q.shear, q.edge_extrapolation,
                                 q.axis_classes)
          .size();
  static const char* const kKinds[5] = {"previous vertex", "neighbour mean", "one rule", "several rules",
                                         "mirror"};
  std::printf("             re-encoded here: %zu bytes;", payload);
  for (int k = 0; k < 5; ++k)
    if (stats.vertices_by_kind[k])
      std::printf(" %s %u vertices %.2f bits each;", kKinds[k], stats.vertices_by_kind[k],
                  stats.bits_by_kind[k] / stats.vertices_by_kind[k]);
  std::printf("\n");
}


// How an aTTR's values are coded (spec 15.4 - 15.14), in words.
std::string attribute_coding_text(const AttributeCoding& c) {
  if (c.coding == 1) return "exact binary32";
  if (c.coding == 3) return "unit normals, octahedral";
  if (c.coding == 8) return "unit normals, octahedral, faces weighted by angle";
  const bool guided = c.coding == 7 || (c.coding == 9 && (c.options & 4));
  const bool geometry = c.coding == 4 || c.coding == 6 || ((c.coding == 7 || c.coding == 9) && (c.options & 1));
  const bool graded = c.coding == 5 || c.coding == 6 || ((c.coding == 7 || c.coding == 9) && (c.options & 2));
  std::string text = "predicted on a grid";
  if (guided) text += ", guided by the positions";
  if (geometry) text += ", geometry order";
  if (graded) text += ", graded start";
  if (c.coding == 9)
    text += ", twins across the plane axis " + std::to_string(c.mirror_axis) + " sum " + std::to_string(c.mirror_sum);
  return text;
}

void print_text(const std::string& path, const DecodedFile& f, uint64_t size, const Status& status) {
  const double v = f.mesh.vertex_count() ? double(f.mesh.vertex_count()) : 1.0;
  std::printf("file         %s, %llu bytes, format %u.%u\n", path.c_str(), static_cast<unsigned long long>(size),
              f.version_major, f.version_minor);
  std::printf("mesh         %zu vertices, %zu faces", f.mesh.vertex_count(), f.mesh.face_count());
  const char* sep = " (";
  for (const auto& [degree, count] : degree_histogram(f.mesh)) {
    std::printf("%s%zu of degree %u", sep, count, degree);
    sep = ", ";
  }
  std::printf("%s\n", f.mesh.face_count() ? ")" : "");
  if (f.method == ConnectivityMethod::kQuad)
    std::printf("connectivity quad coder (spec 5.3), %s, %s\n", quad_coding_name(QuadCoding(f.quad_coding)),
                f.quad_closed ? "closed (one quad cut open)" : "one boundary");
  else if (f.method == ConnectivityMethod::kPolygon)
    std::printf("connectivity polygon coder (spec 5.4), coding %d; %u components, %u virtual faces "
                "(%u seams for handles, the rest close holes), %u vertex identifications, %u loose faces\n",
                f.polygon_coding, f.polygon_components, f.polygon_virtual_faces, f.polygon_seams,
                f.polygon_identifications, f.polygon_loose_faces);
  else if (f.gim.present)
    std::printf("geometry     %u x %u image (spec 13), %s samples, %s, %u planes, %zu seam pairs%s\n", f.gim.width,
                f.gim.height, f.gim.format == 0 ? "16-bit" : "binary32",
                f.gim.face_mode == 0 ? "grid quads" : f.gim.face_mode == 1 ? "grid triangles" : "triangles over pixels",
                unsigned(f.gim.plane_count), f.gim.seam_pairs.size() / 2, (f.gim.flags & 1) ? ", masked" : "");
  else
    std::printf("connectivity %s\n", connectivity_method_name(f.method));
  if (f.quantization.bits && f.quantization.method == 0)
    std::printf("positions    deltas (spec 6), %d bits/axis, box (%g %g %g) - (%g %g %g)\n", f.quantization.bits,
                f.quantization.min[0], f.quantization.min[1], f.quantization.min[2], f.quantization.max[0],
                f.quantization.max[1], f.quantization.max[2]);
  if (f.quantization.method >= 1) print_predicted_positions(f, status.ok());
  if (!f.gim.present)
    std::printf("order        %s\n", f.order_restored ? order_description(f.order_flags).c_str()
                                                     : "coder order (no oRDR chunk)");
  for (const FaceLabels& l : f.mesh.face_labels)
    std::printf("face labels  \"%s\" (spec 16): %zu values, %zu references\n", l.name.c_str(), l.values.size(),
                l.references.size());
  for (size_t i = 0; i < f.mesh.attributes.size() && i < f.attribute_codings.size(); ++i) {
    const MeshAttribute& a = f.mesh.attributes[i];
    const AttributeCoding& c = f.attribute_codings[i];
    static const char* const kKinds[4] = {"generic", "texture coordinate", "normal", "colour"};
    std::printf("attribute    \"%s\" (spec 15): %s, %u component(s), %zu values, %s, %s; %llu bytes, %.2f bits/value\n",
                a.name.c_str(), uint8_t(a.kind) < 4 ? kKinds[uint8_t(a.kind)] : "kind unknown to this revision",
                a.components, a.value_count(), c.mapping == 0   ? "one per vertex"
                : c.mapping == 3 ? "per corner, predicted from the faces"
                                 : "per corner",
                attribute_coding_text(c).c_str(),
                static_cast<unsigned long long>(c.chunk_bytes),
                a.value_count() ? 8.0 * double(c.chunk_bytes) / double(a.value_count()) : 0.0);
  }
  if (f.loop_level_count) {
    std::printf("progressive  %u Loop levels (spec 12), %zu decoded\n", f.loop_level_count,
                f.levels.empty() ? 0 : f.levels.size() - 1);
    std::printf("levels       level  vertices     faces      bytes  cumulative  zero displacements   step   corrected\n");
    uint64_t sum = 0;
    for (size_t j = 0; j < f.levels.size(); ++j) {
      const LoopLevel& l = f.levels[j];
      sum += l.chunk_bytes;
      if (j == 0)
        std::printf("             base  %8u  %8u  %9llu  %10llu  (CONN + POSN)\n", l.vertex_count(), l.face_count(),
                    static_cast<unsigned long long>(l.chunk_bytes), static_cast<unsigned long long>(sum));
      else
        std::printf("             %4zu  %8u  %8u  %9llu  %10llu  %8u of %8u  %-5.3g  %9u\n", j, l.vertex_count(),
                    l.face_count(), static_cast<unsigned long long>(l.chunk_bytes),
                    static_cast<unsigned long long>(sum), l.zero_displacements, l.edge_points, l.step,
                    l.corrected_vertices);
    }
  }
  std::printf("chunks       type  offset      bytes  bits/vertex\n");
  for (const ChunkInfo& c : f.chunks)
    std::printf("             %-4s %7llu %10llu %12.2f  %s%s\n", chunk_type_name(c.type).c_str(),
                static_cast<unsigned long long>(c.offset), static_cast<unsigned long long>(c.length) + 12,
                8.0 * (double(c.length) + 12) / v, c.critical ? "critical" : "ancillary",
                c.known ? "" : ", unknown: skipped");
  std::printf("total        %.2f bits/vertex (signature included)\n", 8.0 * double(size) / v);
  for (const std::string& t : f.texts) std::printf("text         %s\n", t.c_str());
  if (!status.ok()) std::printf("error        %s\n", status.to_string().c_str());
}

void print_json(const std::string& path, const DecodedFile& f, uint64_t size, const Status& status) {
  std::printf("{\"file\":\"%s\",\"bytes\":%llu,\"version\":\"%u.%u\",\"vertices\":%zu,\"faces\":%zu,",
              json_escape(path).c_str(), static_cast<unsigned long long>(size), f.version_major, f.version_minor,
              f.mesh.vertex_count(), f.mesh.face_count());
  std::printf("\"connectivity\":\"%s\",\"quad_coding\":%d,\"position_bits\":%d,\"position_method\":%d,", connectivity_method_name(f.method),
              f.quad_coding, f.quantization.bits, f.quantization.method);
  // Spec 14.9's features (methods 5 - 7 say theirs without the byte): 1 quad twist, 2 contexts, 4 triangle twist.
  std::printf("\"position_features\":%d,", f.quantization.features);
  // Spec 14.10's plane (methods 9 and 10): the axis, or -1, and the sum.
  std::printf("\"position_mirror_axis\":%d,\"position_mirror_sum\":%u,", f.quantization.mirror_axis,
              f.quantization.mirror_sum);
  // Spec 14.12's shear weight k (method 11), or 0.
  std::printf("\"position_shear\":%d,", f.quantization.shear);
  // Spec 14.15's lattice factor k (method 14), or 1.
  std::printf("\"position_lattice\":%d,", f.quantization.lattice);
  std::printf("\"order_restored\":%s,\"order_flags\":%u,", f.order_restored ? "true" : "false", f.order_flags);
  std::printf("\"loop_levels\":%u,\"levels\":[", f.loop_level_count);
  for (size_t j = 0; j < f.levels.size(); ++j) {
    const LoopLevel& l = f.levels[j];
    std::printf("%s{\"level\":%zu,\"vertices\":%u,\"faces\":%u,\"bytes\":%llu,\"edge_points\":%u,"
                "\"zero_displacements\":%u,\"step\":%.17g,\"corrected_vertices\":%u}",
                j ? "," : "", j, l.vertex_count(), l.face_count(), static_cast<unsigned long long>(l.chunk_bytes),
                l.edge_points, l.zero_displacements, l.step, l.corrected_vertices);
  }
  std::printf("],");
  if (f.gim.present)
    std::printf("\"geometry_image\":{\"width\":%u,\"height\":%u,\"format\":%u,\"face_mode\":%u,\"flags\":%u,"
                "\"planes\":%u,\"seam_pairs\":%zu},",
                f.gim.width, f.gim.height, unsigned(f.gim.format), unsigned(f.gim.face_mode), unsigned(f.gim.flags),
                unsigned(f.gim.plane_count), f.gim.seam_pairs.size() / 2);
  else
    std::printf("\"geometry_image\":null,");
  std::printf("\"attributes\":[");
  for (size_t i = 0; i < f.mesh.attributes.size() && i < f.attribute_codings.size(); ++i) {
    const MeshAttribute& a = f.mesh.attributes[i];
    const AttributeCoding& c = f.attribute_codings[i];
    std::printf("%s{\"name\":\"%s\",\"kind\":%u,\"components\":%u,\"values\":%zu,\"mapping\":%u,\"coding\":%u,"
                "\"bytes\":%llu}",
                i ? "," : "", json_escape(a.name).c_str(), unsigned(a.kind), a.components, a.value_count(),
                unsigned(c.mapping), unsigned(c.coding), static_cast<unsigned long long>(c.chunk_bytes));
  }
  std::printf("],");
  std::printf("\"bits_per_vertex\":%.4f,\"chunks\":[",
              f.mesh.vertex_count() ? 8.0 * double(size) / double(f.mesh.vertex_count()) : 0.0);
  for (size_t i = 0; i < f.chunks.size(); ++i) {
    const ChunkInfo& c = f.chunks[i];
    std::printf("%s{\"type\":\"%s\",\"offset\":%llu,\"bytes\":%llu,\"critical\":%s,\"known\":%s}", i ? "," : "",
                json_escape(chunk_type_name(c.type)).c_str(), static_cast<unsigned long long>(c.offset),
                static_cast<unsigned long long>(c.length) + 12, c.critical ? "true" : "false",
                c.known ? "true" : "false");
  }
  std::printf("],\"texts\":[");
  for (size_t i = 0; i < f.texts.size(); ++i)
    std::printf("%s\"%s\"", i ? "," : "", json_escape(f.texts[i]).c_str());
  std::printf("],\"error\":%s%s%s}\n", status.ok() ? "" : "\"", status.ok() ? "null" : json_escape(status.to_string()).c_str(),
              status.ok() ? "" : "\"");
}

}  // namespace

int run_info(int argc, char** argv) {
  CommandLine cl;
  static const std::string help = std::string(kHelp) + kMaxOutputHelp;
  const CommandSpec spec{"info", help.c_str(), {"--json"}, {{kMaxOutputOption}}, 1, 1};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  const std::string& input = cl.positional[0];
  const bool json = cl.has("--json");
  std::vector<uint8_t> bytes;
  if (Status s = read_file(input, &bytes); !s.ok()) return fail("info", s);
  DecoderLimits limits;
  if (Status s = decoder_limits(cl, &limits); !s.ok()) return usage_error("info", s.message());
  StreamDecoder decoder(limits);
  Status status = decoder.feed(bytes.data(), bytes.size());
  if (status.ok()) status = decoder.finish();
  status = name_limit_option(status);
  if (json)
    print_json(input, decoder.file(), bytes.size(), status);
  else
    print_text(input, decoder.file(), bytes.size(), status);
  return status.ok() ? kExitOk : kExitError;
}

}  // namespace qmc::cli
