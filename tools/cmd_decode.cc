// qmc decode: .qmc to a mesh file.
#include <cstdio>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "mesh_io.h"
#include "qmc/decoder.h"

namespace qmc::cli {

static const char kDecodeHelp[] =
    "usage: qmc decode IN.qmc OUT.{obj,off,ply} [--level J] [--drop NAME]... [--drop-unsupported]\n"
    "                  [--binary] [--max-output-mb N] [--quiet]\n"
    "       qmc decode --canonical IN.qmc OUT [--max-output-mb N] [--quiet]\n"
    "\n"
    "Decodes IN.qmc and writes the mesh, vertices in the file's order (spec 5.2.1).\n"
    "A rejected file exits with status 3 and prints the error identifier (spec 9).\n"
    "\n"
    "options:\n"
    "  --level J     progressive files (spec 12): write level J, 0 = the base mesh\n"
    "                (default: the finest level)\n"
    "  --drop NAME   leave the attribute or face labels NAME (spec 15, 16) out of\n"
    "                OUT (repeatable); printed\n"
    "  --drop-unsupported  leave out what OUT's format cannot hold (.off: every\n"
    "                attribute and face label; .ply: normals and colours that\n"
    "                differ between the corners of a vertex, face labels; .obj:\n"
    "                attributes beyond the first texture coordinates, normals\n"
    "                and vertex colours), each printed; without it such a file\n"
    "                is refused, naming what OUT would lose\n"
    "  --binary      write .ply as binary_little_endian (boat.obj's texture-\n"
    "                mapped mesh: 1.4 MB instead of 3.7 MB), floats bit for bit;\n"
    "                .obj and .off are text only\n"
    "  --canonical   write the canonical output (spec 10.2, 12.9, 13.10) that the\n"
    "                conformance manifest hashes, whatever the extension of OUT;\n"
    "                this is the decoder command conformance/run.py expects\n";

// The bytes the manifest hashes (spec 10.2): every level of a progressive
// file and every plane of a geometry image, so --level does not apply.
static int write_canonical(const CommandLine& cl, const DecodedFile& file, const std::string& input,
                           const std::string& output) {
  const std::vector<uint8_t> bytes = canonical_output(file);
  if (Status s = write_file(output, bytes); !s.ok()) return fail("decode", s);
  if (!cl.has("--quiet"))
    std::printf("decoded %s: canonical output, %zu bytes -> %s\n", input.c_str(), bytes.size(), output.c_str());
  return kExitOk;
}

// --drop NAME, then what OUT's format cannot hold: refused, naming the
// flags, or with --drop-unsupported left out. Each part left out is printed
// (stderr) unless --quiet. Returns -1 to go on, else the exit code.
static int drop_parts(const CommandLine& cl, const std::string& input, const std::string& output, Mesh* mesh) {
  const bool quiet = cl.has("--quiet");
  std::vector<std::string> named;
  for (const auto& [option, name] : cl.options)
    if (option == "--drop") named.push_back(name);
  if (int rc = drop_each_named("decode", named, input, quiet, mesh); rc >= 0) return rc;
  const std::vector<tools::UnwritablePart> parts = tools::unwritable_parts(*mesh, tools::mesh_format_of(output));
  if (parts.empty()) return -1;
  if (!cl.has("--drop-unsupported"))
    return fail("decode", Status(ErrorCode::kInvalidArgument, output + ": " + parts.front().reason +
                                                                  "; or pass --drop " + parts.front().name +
                                                                  " or --drop-unsupported to leave it out"));
  for (const tools::UnwritablePart& part : parts) {
    if (!quiet)
      std::fprintf(stderr, "dropped (--drop-unsupported): %s: %s (%s cannot hold it)\n", input.c_str(),
                   part.name.c_str(), output.c_str());
    drop_named(mesh, part.name);
  }
  return -1;
}

int run_decode(int argc, char** argv) {
  CommandLine cl;
  static const std::string help = std::string(kDecodeHelp) + kMaxOutputHelp;
  const CommandSpec spec{"decode",
                         help.c_str(),
                         {"--quiet", "--canonical", "--drop-unsupported", "--binary"},
                         {{"--level"}, {"--drop"}, {kMaxOutputOption}},
                         2,
                         2};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  if (cl.has("--canonical") && cl.value("--level"))
    return usage_error("decode", "--canonical covers every level; --level does not apply");
  if (cl.has("--canonical") && (cl.value("--drop") || cl.has("--drop-unsupported")))
    return usage_error("decode", "--canonical writes everything the file holds; --drop and --drop-unsupported do not apply");
  DecoderLimits limits;
  if (Status s = decoder_limits(cl, &limits); !s.ok()) return usage_error("decode", s.message());
  const std::string& input = cl.positional[0];
  const std::string& output = cl.positional[1];
  if (cl.has("--binary") && (cl.has("--canonical") || tools::mesh_format_of(output) != "ply"))
    return usage_error("decode", "--binary writes .ply files; " + output + " is not one");
  if (int rc = refuse_overwriting_input("decode", input, output); rc >= 0) return rc;
  std::vector<uint8_t> bytes;
  if (Status s = read_file(input, &bytes); !s.ok()) return fail("decode", s);
  DecodedFile file;
  if (Status s = decode_with_limits(limits, bytes, &file); !s.ok())
    return fail("decode", Status(s.code(), input + ": " + s.message()));
  if (cl.has("--canonical")) return write_canonical(cl, file, input, output);
  std::string level_note;
  if (const std::string* level_text = cl.value("--level")) {
    const std::string& value = *level_text;
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
  if (int rc = drop_parts(cl, input, output, &file.mesh); rc >= 0) return rc;
  tools::MeshWriteOptions write_options;
  write_options.binary_ply = cl.has("--binary");
  if (Status s = tools::write_mesh(output, file.mesh, write_options); !s.ok()) return fail("decode", s);
  const std::string source = file.gim.present ? "a " + std::to_string(file.gim.width) + " x " +
                                                    std::to_string(file.gim.height) + " geometry image"
                                              : std::string(connectivity_method_name(file.method)) + " connectivity";
  if (!cl.has("--quiet"))
    std::printf("decoded %s: %zu vertices, %zu faces (%s%s) -> %s\n", input.c_str(), file.mesh.vertex_count(),
                file.mesh.face_count(), source.c_str(), level_note.c_str(), output.c_str());
  return kExitOk;
}

}  // namespace qmc::cli
