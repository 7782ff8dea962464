// qmc encode: compress, then decode in memory and report size and error.
#include <cstdio>
#include <cstring>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
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
    "                      bounding-box side; see spec section 6.2)\n"
    "  --text KEY=VALUE    store a teXt chunk (repeatable)\n"
    "  --quiet             print nothing on success\n";

struct EncodeArgs {
  std::string input, output;
  EncodeOptions options;
  bool quiet = false;
};

const CommandSpec kSpec{"encode", kHelp, {"--quiet"}, {{"--bits", "-q"}, {"--text"}}, 2, 2};

int parse(int argc, char** argv, EncodeArgs* args) {
  CommandLine cl;
  if (int rc = parse_command_line(kSpec, argc, argv, &cl); rc >= 0) return rc;
  args->input = cl.positional[0];
  args->output = cl.positional[1];
  args->quiet = cl.has("--quiet");
  for (const auto& [name, value] : cl.options) {
    if (name == "--text") {
      args->options.texts.push_back(value);
      continue;
    }
    long bits = 0;
    if (!parse_int(value, kMinPositionBits, kMaxPositionBits, &bits))
      return usage_error("encode", "--bits takes a whole number from 1 to 30, got '" + value + "'");
    args->options.position_bits = int(bits);
  }
  return -1;
}

void print_report(const EncodeArgs& args, const Mesh& mesh, const EncodeStats& stats,
                  const tools::RoundTripReport& check, uint64_t input_bytes) {
  const double v = mesh.vertex_count() ? double(mesh.vertex_count()) : 1.0;
  std::printf("input       %s: %zu vertices, %zu faces, %s\n", args.input.c_str(), mesh.vertex_count(),
              mesh.face_count(), human_bytes(input_bytes).c_str());
  std::printf("connectivity %s coding (universal fallback for any polygon mesh)\n",
              connectivity_method_name(stats.method));
  for (const ChunkStats& c : stats.chunks)
    std::printf("  %-4s %10llu bytes  %8.2f bits/vertex\n", chunk_type_name(c.type).c_str(),
                static_cast<unsigned long long>(c.bytes), 8.0 * double(c.bytes) / v);
  std::printf("output      %s: %llu bytes, %.2f bits/vertex, %.1fx smaller than the input file\n",
              args.output.c_str(), static_cast<unsigned long long>(stats.total_bytes),
              8.0 * double(stats.total_bytes) / v, double(input_bytes) / double(stats.total_bytes));
  const double side = check.max_bbox_side > 0 ? check.max_bbox_side : 1.0;
  std::printf("positions   %d bits/axis; max error %.6g (%.3g of largest bbox side), rms %.6g\n",
              args.options.position_bits, check.max_error, check.max_error / side, check.rms_error);
}

}  // namespace

int run_encode(int argc, char** argv) {
  EncodeArgs args;
  if (int rc = parse(argc, argv, &args); rc >= 0) return rc;
  std::vector<uint8_t> input_bytes;
  if (Status s = read_file(args.input, &input_bytes); !s.ok()) return fail("encode", s);
  Mesh mesh;
  if (Status s = load_mesh(args.input, &mesh); !s.ok()) return fail("encode", s);
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  if (Status s = encode(mesh, args.options, &bytes, &stats); !s.ok()) return fail("encode", s);
  // Decode what was written: the report's error figures are measured, not derived.
  DecodedFile decoded;
  if (Status s = decode(bytes.data(), bytes.size(), &decoded); !s.ok())
    return fail("encode", Status(s.code(), "internal error, own output does not decode: " + s.message()));
  const tools::RoundTripReport check = tools::check_round_trip(mesh, decoded);
  if (!check.ok())
    return fail("encode", Status(ErrorCode::kInvalidArgument, "internal error, round trip mismatch: " +
                                                                  check.face_mismatch + check.position_mismatch));
  if (Status s = write_file(args.output, bytes); !s.ok()) return fail("encode", s);
  if (!args.quiet) print_report(args, mesh, stats, check, input_bytes.size());
  return kExitOk;
}

}  // namespace qmc::cli
