// qmc decode: .qmc to a mesh file.
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "mesh_io.h"
#include "qmc/decoder.h"

namespace qmc::cli {

static const char kDecodeHelp[] =
    "usage: qmc decode IN.qmc OUT.{obj,off,ply} [--quiet]\n"
    "\n"
    "Decodes IN.qmc and writes the mesh, vertices in the file's order (spec 5.2.1).\n";

int run_decode(int argc, char** argv) {
  std::string input, output;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::fputs(kDecodeHelp, stdout);
      return kExitOk;
    } else if (arg == "--quiet") {
      quiet = true;
    } else if (!arg.empty() && arg[0] == '-') {
      return usage_error("decode", "unknown option '" + arg + "'");
    } else if (input.empty()) {
      input = arg;
    } else if (output.empty()) {
      output = arg;
    } else {
      return usage_error("decode", "too many arguments");
    }
  }
  if (output.empty()) return usage_error("decode", "needs IN.qmc and OUT");
  std::vector<uint8_t> bytes;
  if (Status s = read_file(input, &bytes); !s.ok()) return fail("decode", s);
  DecodedFile file;
  if (Status s = decode(bytes.data(), bytes.size(), &file); !s.ok())
    return fail("decode", Status(s.code(), input + ": " + s.message()));
  if (Status s = tools::write_mesh(output, file.mesh); !s.ok()) return fail("decode", s);
  if (!quiet)
    std::printf("decoded %s: %zu vertices, %zu faces (%s connectivity) -> %s\n", input.c_str(),
                file.mesh.vertex_count(), file.mesh.face_count(), connectivity_method_name(file.method),
                output.c_str());
  return kExitOk;
}

}  // namespace qmc::cli
