// qmc gim export / import: a geometry image (spec section 13) as ordinary
// image files, so image tools can look at and process it, and back.
//
// DIR/gim.txt describes the image; each plane is DIR/plane<i>.png (16-bit
// gray, format 0) or DIR/plane<i>.pfm (binary32, format 1); the mask is
// DIR/mask.png (16-bit gray, 0 blank, 65535 occupied); seams and triangles
// are text files of raster indices. Offsets and steps are written as
// hexadecimal floats, so nothing is rounded on the way.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "atomic_file.h"
#include "cli_common.h"
#include "commands.h"
#include "encoder/gim_writer.h"
#include "image_io.h"
#include "qmc/decoder.h"

namespace qmc::cli {
namespace {

const char kHelp[] =
    "usage: qmc gim export IN.qmc DIR [--max-output-mb N]\n"
    "       qmc gim import DIR OUT.qmc\n"
    "\n"
    "export writes the geometry image of IN.qmc (spec 13) into DIR: gim.txt (size,\n"
    "sample format, face mode, plane kinds and scales), one image per plane\n"
    "(plane<i>.png, 16-bit gray, or plane<i>.pfm for binary32 samples), mask.png\n"
    "(0 blank, 65535 occupied), seams.txt and triangles.txt (raster indices).\n"
    "import reads such a directory (edited or not) and writes OUT.qmc.\n"
    "\n"
    "options:\n";

std::string plane_file(int i, uint8_t format) { return "plane" + std::to_string(i) + (format == 0 ? ".png" : ".pfm"); }

Status write_text(const std::string& path, const std::string& text) {
  return tools::write_file_atomically(path, text.data(), text.size());
}

Status export_image(const GeometryImageData& g, const std::string& dir) {
  std::ostringstream txt;
  char number[64];
  txt << "qmc-geometry-image 1\nwidth " << g.width << "\nheight " << g.height << "\nformat " << int(g.format)
      << "\nface_mode " << int(g.face_mode) << "\nstore_blank " << ((g.flags & 2) ? 1 : 0) << "\n";
  const size_t pixels = size_t(g.width) * g.height;
  for (size_t i = 0; i < g.planes.size(); ++i) {
    const GimPlaneData& p = g.planes[i];
    txt << "plane " << i << " " << int(p.kind);
    std::snprintf(number, sizeof number, " %a", p.offset);
    txt << number;
    std::snprintf(number, sizeof number, " %a", p.step);
    txt << number << " " << plane_file(int(i), g.format) << "\n";
    const std::string path = dir + "/" + plane_file(int(i), g.format);
    Status s;
    if (g.format == 0) {
      std::vector<uint16_t> samples(p.samples.begin(), p.samples.end());
      s = tools::write_png_gray16(path, g.width, g.height, samples);
    } else {
      std::vector<float> samples(pixels);
      std::memcpy(samples.data(), p.samples.data(), pixels * sizeof(float));
      s = tools::write_pfm_gray(path, g.width, g.height, samples);
    }
    if (!s.ok()) return s;
  }
  if (g.flags & 1) {
    std::vector<uint16_t> mask(pixels);
    for (size_t p = 0; p < pixels; ++p) mask[p] = g.occupied[p] ? 65535 : 0;
    if (Status s = tools::write_png_gray16(dir + "/mask.png", g.width, g.height, mask); !s.ok()) return s;
    txt << "mask mask.png\n";
  }
  std::ostringstream seams, triangles;
  for (size_t i = 0; i + 1 < g.seam_pairs.size(); i += 2) seams << g.seam_pairs[i] << " " << g.seam_pairs[i + 1] << "\n";
  for (size_t i = 0; i + 2 < g.triangles.size(); i += 3)
    triangles << g.triangles[i] << " " << g.triangles[i + 1] << " " << g.triangles[i + 2] << "\n";
  if (!g.seam_pairs.empty()) {
    if (Status s = write_text(dir + "/seams.txt", seams.str()); !s.ok()) return s;
    txt << "seams seams.txt\n";
  }
  if (g.face_mode == 2) {
    if (Status s = write_text(dir + "/triangles.txt", triangles.str()); !s.ok()) return s;
    txt << "triangles triangles.txt\n";
  }
  return write_text(dir + "/gim.txt", txt.str());
}

Status bad(const std::string& path, const std::string& what) {
  return Status(ErrorCode::kInvalidArgument, path + ": " + what);
}

Status read_numbers(const std::string& path, size_t group, std::vector<uint32_t>* out) {
  std::ifstream f(path);
  if (!f) return Status(ErrorCode::kIo, path + ": cannot read");
  uint64_t v = 0;
  while (f >> v) {
    if (v > UINT32_MAX) return bad(path, "a raster index above 2^32 - 1");
    out->push_back(uint32_t(v));
  }
  if (!f.eof()) return bad(path, "expected whole numbers only");
  if (out->size() % group != 0) return bad(path, "expected groups of " + std::to_string(group) + " numbers");
  return Status::Ok();
}

Status read_plane(const std::string& path, const GimRawImage& g, std::vector<uint32_t>* out) {
  uint32_t w = 0, h = 0;
  if (g.format == 0) {
    std::vector<uint16_t> samples;
    if (Status s = tools::read_png_gray16(path, &w, &h, &samples); !s.ok()) return s;
    out->assign(samples.begin(), samples.end());
  } else {
    std::vector<float> samples;
    if (Status s = tools::read_pfm_gray(path, &w, &h, &samples); !s.ok()) return s;
    out->resize(samples.size());
    std::memcpy(out->data(), samples.data(), samples.size() * sizeof(float));
  }
  if (w != g.width || h != g.height)
    return bad(path, std::to_string(w) + " x " + std::to_string(h) + ", gim.txt says " + std::to_string(g.width) +
                         " x " + std::to_string(g.height));
  return Status::Ok();
}

// One line of gim.txt; the file it names (if any) is added to `files`.
Status read_line(const std::string& dir, const std::string& key, std::istringstream& line, GimRawImage* g,
                 std::vector<std::string>* files) {
  const std::string manifest = dir + "/gim.txt";
  uint64_t v = 0;
  if (key == "width" || key == "height" || key == "format" || key == "face_mode" || key == "store_blank") {
    if (!(line >> v) || v > 65535) return bad(manifest, "bad value for " + key);
    if (key == "width") g->width = uint32_t(v);
    if (key == "height") g->height = uint32_t(v);
    if (key == "format") g->format = uint8_t(v);
    if (key == "face_mode") g->face_mode = uint8_t(v);
    if (key == "store_blank") g->store_blank = v != 0;
    return Status::Ok();
  }
  std::string file;
  if (key == "plane") {
    uint64_t index = 0, kind = 0;
    std::string offset, step;
    if (!(line >> index >> kind >> offset >> step >> file) || index != g->kinds.size() || kind > 255)
      return bad(manifest, "plane lines are 'plane I KIND OFFSET STEP FILE', in order");
    g->kinds.push_back(uint8_t(kind));
    g->offsets.push_back(std::strtod(offset.c_str(), nullptr));
    g->steps.push_back(std::strtod(step.c_str(), nullptr));
    g->planes.emplace_back();
    files->push_back(dir + "/" + file);
    return read_plane(files->back(), *g, &g->planes.back());
  }
  if (!(line >> file)) return bad(manifest, key + " needs a file name");
  files->push_back(dir + "/" + file);
  if (key == "mask") {
    std::vector<uint32_t> mask;
    GimRawImage mask_image;  // a 16-bit plane of the image's size
    mask_image.width = g->width;
    mask_image.height = g->height;
    mask_image.format = 0;
    if (Status s = read_plane(files->back(), mask_image, &mask); !s.ok()) return s;
    g->occupied.resize(mask.size());
    for (size_t p = 0; p < mask.size(); ++p) g->occupied[p] = mask[p] != 0;
    return Status::Ok();
  }
  if (key == "seams") {
    std::vector<uint32_t> pairs;
    if (Status s = read_numbers(dir + "/" + file, 2, &pairs); !s.ok()) return s;
    for (size_t i = 0; i < pairs.size(); i += 2) g->seams.push_back({pairs[i], pairs[i + 1]});
    return Status::Ok();
  }
  if (key == "triangles") return read_numbers(dir + "/" + file, 3, &g->triangles);
  return bad(manifest, "unknown line '" + key + "'");
}

// `files` gets every file read, gim.txt first.
Status import_image(const std::string& dir, GimRawImage* g, std::vector<std::string>* files) {
  const std::string manifest = dir + "/gim.txt";
  files->push_back(manifest);
  std::ifstream f(manifest);
  if (!f) return Status(ErrorCode::kIo, manifest + ": cannot read");
  std::string text;
  if (!std::getline(f, text) || text != "qmc-geometry-image 1")
    return bad(manifest, "the first line must be 'qmc-geometry-image 1'");
  while (std::getline(f, text)) {
    std::istringstream line(text);
    std::string key;
    if (!(line >> key)) continue;
    if (Status s = read_line(dir, key, line, g, files); !s.ok()) return s;
  }
  if (g->format == 1) g->offsets.clear(), g->steps.clear();
  return Status::Ok();
}

// Every file export_image may write into `dir`.
std::vector<std::string> export_paths(const GeometryImageData& g, const std::string& dir) {
  std::vector<std::string> paths{dir + "/gim.txt", dir + "/mask.png", dir + "/seams.txt", dir + "/triangles.txt"};
  for (size_t i = 0; i < g.planes.size(); ++i) paths.push_back(dir + "/" + plane_file(int(i), g.format));
  return paths;
}

int run_export(const DecoderLimits& limits, const std::string& input, const std::string& dir) {
  std::vector<uint8_t> bytes;
  if (Status s = read_file(input, &bytes); !s.ok()) return fail("gim export", s);
  DecodedFile file;
  if (Status s = decode_with_limits(limits, bytes, &file); !s.ok())
    return fail("gim export", Status(s.code(), input + ": " + s.message()));
  if (!file.gim.present)
    return fail("gim export", Status(ErrorCode::kInvalidArgument, input + " is not a geometry image (no GIMG chunk)"));
  for (const std::string& path : export_paths(file.gim, dir))
    if (int rc = refuse_overwriting_input("gim export", input, path); rc >= 0) return rc;
  if (Status s = export_image(file.gim, dir); !s.ok()) return fail("gim export", s);
  std::printf("exported %s: %u x %u, %u planes -> %s/gim.txt\n", input.c_str(), file.gim.width, file.gim.height,
              unsigned(file.gim.plane_count), dir.c_str());
  return kExitOk;
}

int run_import(const std::string& dir, const std::string& output) {
  GimRawImage image;
  std::vector<std::string> inputs;
  if (Status s = import_image(dir, &image, &inputs); !s.ok()) return fail("gim import", s);
  for (const std::string& input : inputs)
    if (int rc = refuse_overwriting_input("gim import", input, output); rc >= 0) return rc;
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  if (Status s = write_raw_geometry_image(image, {}, &bytes, &stats); !s.ok()) return fail("gim import", s);
  if (Status s = write_file(output, bytes); !s.ok()) return fail("gim import", s);
  std::printf("imported %s: %u x %u, %zu planes -> %s (%zu bytes)\n", dir.c_str(), image.width, image.height,
              image.planes.size(), output.c_str(), bytes.size());
  return kExitOk;
}

}  // namespace

int run_gim(int argc, char** argv) {
  CommandLine cl;
  static const std::string help = std::string(kHelp) + kMaxOutputHelp;
  const CommandSpec spec{"gim", help.c_str(), {}, {{kMaxOutputOption}}, 3, 3};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  const std::string& verb = cl.positional[0];
  DecoderLimits limits;
  if (Status s = decoder_limits(cl, &limits); !s.ok()) return usage_error("gim", s.message());
  if (verb == "export") return run_export(limits, cl.positional[1], cl.positional[2]);
  if (verb == "import") return run_import(cl.positional[1], cl.positional[2]);
  return usage_error("gim", "the first argument is export or import, got '" + verb + "'");
}

}  // namespace qmc::cli
