// qmc decode: .qmc to a mesh file.
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "mesh_io.h"
#include "qmc/decoder.h"

namespace qmc::cli {

static const char kDecodeHelp[] =
    "usage: qmc decode IN.qmc OUT.{obj,off,ply} [--level J] [--quiet]\n"
    "\n"
    "Decodes IN.qmc and writes the mesh, vertices in the file's order (spec 5.2.1).\n"
    "\n"
    "options:\n"
    "  --level J   progressive files (spec 12): write level J, 0 = the base mesh\n"
    "              (default: the finest level)\n";

int run_decode(int argc, char** argv) {
  CommandLine cl;
  const CommandSpec spec{"decode", kDecodeHelp, {"--quiet"}, {{"--level"}}, 2, 2};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  const std::string& input = cl.positional[0];
  const std::string& output = cl.positional[1];
  if (int rc = refuse_overwriting_input("decode", input, output); rc >= 0) return rc;
  std::vector<uint8_t> bytes;
  if (Status s = read_file(input, &bytes); !s.ok()) return fail("decode", s);
  DecodedFile file;
  if (Status s = decode(bytes.data(), bytes.size(), &file); !s.ok())
    return fail("decode", Status(s.code(), input + ": " + s.message()));
  std::string level_note;
  for (const auto& [name, value] : cl.options) {  // --level
    long level = 0;
    if (file.loop_level_count == 0)
      return usage_error("decode", input + " is not a progressive file: it has no levels to choose from");
    if (!parse_int(value, 0, file.loop_level_count, &level))
      return usage_error("decode", "--level takes 0.." + std::to_string(file.loop_level_count) + " for " + input +
                                       ", got '" + value + "'");
    file.mesh = level_mesh(file.levels[size_t(level)]);
    level_note = ", level " + std::to_string(level) + " of " + std::to_string(file.loop_level_count);
  }
  if (level_note.empty() && file.loop_level_count)
    level_note = ", finest level " + std::to_string(file.loop_level_count);
  if (Status s = tools::write_mesh(output, file.mesh); !s.ok()) return fail("decode", s);
  const std::string source = file.gim.present ? "a " + std::to_string(file.gim.width) + " x " +
                                                    std::to_string(file.gim.height) + " geometry image"
                                              : std::string(connectivity_method_name(file.method)) + " connectivity";
  if (!cl.has("--quiet"))
    std::printf("decoded %s: %zu vertices, %zu faces (%s%s) -> %s\n", input.c_str(), file.mesh.vertex_count(),
                file.mesh.face_count(), source.c_str(), level_note.c_str(), output.c_str());
  return kExitOk;
}

}  // namespace qmc::cli
