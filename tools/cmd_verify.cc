// qmc verify: decode a .qmc file and check it against the original mesh.
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "qmc/decoder.h"
#include "roundtrip_check.h"

namespace qmc::cli {

static const char kVerifyHelp[] =
    "usage: qmc verify IN OUT.qmc\n"
    "\n"
    "Decodes OUT.qmc and checks it against IN: the same faces after the vertex\n"
    "relabelling of spec section 5.2.1, and every coordinate within half a\n"
    "quantization step. Exit 0 if both hold, 1 if not, 3 on unreadable input.\n";

int run_verify(int argc, char** argv) {
  std::string original_path, qmc_path;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::fputs(kVerifyHelp, stdout);
      return kExitOk;
    } else if (!arg.empty() && arg[0] == '-') {
      return usage_error("verify", "unknown option '" + arg + "'");
    } else if (original_path.empty()) {
      original_path = arg;
    } else if (qmc_path.empty()) {
      qmc_path = arg;
    } else {
      return usage_error("verify", "too many arguments");
    }
  }
  if (qmc_path.empty()) return usage_error("verify", "needs IN and OUT.qmc");
  Mesh original;
  if (Status s = load_mesh(original_path, &original); !s.ok()) return fail("verify", s);
  std::vector<uint8_t> bytes;
  if (Status s = read_file(qmc_path, &bytes); !s.ok()) return fail("verify", s);
  DecodedFile decoded;
  if (Status s = decode(bytes.data(), bytes.size(), &decoded); !s.ok())
    return fail("verify", Status(s.code(), qmc_path + ": " + s.message()));
  const tools::RoundTripReport r = tools::check_round_trip(original, decoded);
  std::printf("faces     %s\n", r.faces_equal ? "identical after relabelling" : r.face_mismatch.c_str());
  std::printf("positions %s; max error %.6g, rms %.6g\n",
              r.positions_within_bound ? "within half a quantization step" : r.position_mismatch.c_str(),
              r.max_error, r.rms_error);
  std::printf("%s\n", r.ok() ? "verify: OK" : "verify: FAILED");
  return r.ok() ? kExitOk : kExitCheckFailed;
}

}  // namespace qmc::cli
