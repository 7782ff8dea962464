// qmc verify: decode a .qmc file and check it against the original mesh.
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "qmc/decoder.h"
#include "roundtrip_check.h"

namespace qmc::cli {

static const char kVerifyHelp[] =
    "usage: qmc verify IN OUT.qmc [--max-output-mb N]\n"
    "\n"
    "Decodes OUT.qmc and checks it against IN: the same faces after the vertex\n"
    "relabelling of spec section 5.2.1, every coordinate within half a\n"
    "quantization step (k steps on POSN method 14's surface lattice of factor\n"
    "k, spec 14.15), and every attribute (spec 15: texture coordinates,\n"
    "normals) at every corner within half its step, or bit for bit if exact. A file with an oRDR chunk (qmc encode --keep-order,\n"
    "spec 4.5) must match IN exactly in IN's order: vertex order, face order and\n"
    "each face's first corner. Exit 0 if both hold, 1 if not, 3 on unreadable input.\n"
    "\n"
    "options:\n";

int run_verify(int argc, char** argv) {
  CommandLine cl;
  static const std::string help = std::string(kVerifyHelp) + kMaxOutputHelp;
  const CommandSpec spec{"verify", help.c_str(), {}, {{kMaxOutputOption}}, 2, 2};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  DecoderLimits limits;
  if (Status s = decoder_limits(cl, &limits); !s.ok()) return usage_error("verify", s.message());
  const std::string& original_path = cl.positional[0];
  const std::string& qmc_path = cl.positional[1];
  Mesh original;
  if (Status s = load_mesh(original_path, &original); !s.ok()) return fail("verify", s);
  std::vector<uint8_t> bytes;
  if (Status s = read_file(qmc_path, &bytes); !s.ok()) return fail("verify", s);
  DecodedFile decoded;
  if (Status s = decode_with_limits(limits, bytes, &decoded); !s.ok())
    return fail("verify", Status(s.code(), qmc_path + ": " + s.message()));
  if (decoded.loop_level_count) {  // spec 12: a remesh has other vertices and faces by design
    std::printf("verify: %s is a progressive file (spec 12), a remesh of the input surface with other vertices\n"
                "and faces: there is nothing to verify exactly. Measure it with: qmc compare %s DECODED\n",
                qmc_path.c_str(), original_path.c_str());
    return kExitCheckFailed;
  }
  const tools::RoundTripReport r = tools::check_round_trip(original, decoded);
  const char* same = decoded.order_restored ? "identical in the input's order (oRDR)" : "identical after relabelling";
  std::printf("faces     %s\n", r.faces_equal ? same : r.face_mismatch.c_str());
  for (size_t i = 0; r.faces_equal && i < decoded.mesh.attributes.size(); ++i)
    std::printf("attribute %s: at every corner, %s\n", decoded.mesh.attributes[i].name.c_str(),
                decoded.attribute_codings[i].on_grid() ? "within half its step"
                : decoded.attribute_codings[i].octahedral() ? "within its octahedral cell"
                                                           : "bit for bit");
  for (size_t i = 0; r.faces_equal && i < decoded.mesh.face_labels.size(); ++i)
    std::printf("labels    %s: on every face, %zu values\n", decoded.mesh.face_labels[i].name.c_str(),
                decoded.mesh.face_labels[i].values.size());
  const int lattice = decoded.quantization.lattice;
  const std::string bound = lattice > 1 ? "within " + std::to_string(lattice) +
                                              " quantization steps per axis (the surface lattice, spec 14.15)"
                                        : "within half a quantization step";
  std::printf("positions %s; max error %.6g, rms %.6g\n",
              r.positions_within_bound ? bound.c_str() : r.position_mismatch.c_str(), r.max_error, r.rms_error);
  std::printf("%s\n", r.ok() ? "verify: OK" : "verify: FAILED");
  return r.ok() ? kExitOk : kExitCheckFailed;
}

}  // namespace qmc::cli
