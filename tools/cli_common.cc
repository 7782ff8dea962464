#include "cli_common.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include <unistd.h>

#include "atomic_file.h"
#include "common/position_coding.h"
#include "mesh_io.h"

namespace qmc::cli {

Status read_file(const std::string& path, std::vector<uint8_t>* bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(ErrorCode::kIo, "cannot open " + path + ": " + std::strerror(errno));
  bytes->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return Status(ErrorCode::kIo, "error reading " + path);
  return Status::Ok();
}

Status write_file(const std::string& path, const std::vector<uint8_t>& bytes) {
  return tools::write_file_atomically(path, bytes.data(), bytes.size());
}

Status load_mesh(const std::string& path, Mesh* mesh, bool quiet, std::vector<std::string>* notes) {
  std::vector<std::string> warnings;
  Status s = tools::read_mesh(path, mesh, &warnings);
  if (!quiet)
    for (const std::string& w : warnings) std::fprintf(stderr, "note: %s: %s\n", path.c_str(), w.c_str());
  if (notes) *notes = std::move(warnings);
  return s;
}

int refuse_overwriting_input(const char* command, const std::string& input, const std::string& output) {
  if (!tools::same_file(input, output)) return -1;
  return usage_error(command, "the output " + output + " is the input file " + input + "; refusing to overwrite it");
}

int fail(const char* command, const Status& status) {
  std::fprintf(stderr, "qmc %s: %s\n", command, status.to_string().c_str());
  return kExitError;
}

int usage_error(const char* command, const std::string& message) {
  std::fprintf(stderr, "qmc %s: %s (see 'qmc %s --help')\n", command, message.c_str(), command);
  return kExitUsage;
}

bool CommandLine::has(const std::string& name) const {
  for (const std::string& s : switches)
    if (s == name) return true;
  return false;
}

const std::string* CommandLine::value(const std::string& name) const {
  for (const auto& [option, value] : options)
    if (option == name) return &value;
  return nullptr;
}

Status decoder_limits(const CommandLine& cl, DecoderLimits* limits) {
  *limits = DecoderLimits{};
  const std::string* mib = cl.value(kMaxOutputOption);
  if (mib == nullptr) return Status::Ok();
  long n = 0;
  if (!parse_int(*mib, 0, 1L << 40, &n))
    return Status(ErrorCode::kInvalidArgument, std::string(kMaxOutputOption) + " takes a number of MiB, got '" + *mib + "'");
  *limits = DecoderLimits::unlimited();
  if (n > 0) limits->max_output_bytes = uint64_t(n) << 20;
  return Status::Ok();
}

Status name_limit_option(const Status& s) {
  // Spec 8.1's limits are the decoder's own, and their messages name the
  // DecoderLimits field; the other limit_exceeded rules are counts the file
  // cannot justify (section 8), which no option changes.
  if (s.code() != ErrorCode::kLimitExceeded || s.message().find("(DecoderLimits::") == std::string::npos) return s;
  return Status(s.code(), s.message() + " [" + kMaxOutputOption + " raises it]");
}

Status decode_with_limits(const DecoderLimits& limits, const std::vector<uint8_t>& bytes, DecodedFile* out) {
  return name_limit_option(decode(bytes.data(), bytes.size(), out, limits));
}

static const std::vector<std::string>* find_valued(const CommandSpec& spec, const std::string& name) {
  for (const std::vector<std::string>& names : spec.valued)
    for (const std::string& n : names)
      if (n == name) return &names;
  return nullptr;
}

int parse_command_line(const CommandSpec& spec, int argc, char** argv, CommandLine* out) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::fputs(spec.help, stdout);
      return kExitOk;
    }
    if (arg.size() < 2 || arg[0] != '-') {
      out->positional.push_back(arg);
      continue;
    }
    const size_t eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    if (const std::vector<std::string>* names = find_valued(spec, name)) {
      if (eq != std::string::npos) {
        out->options.push_back({names->front(), arg.substr(eq + 1)});
      } else if (i + 1 < argc) {
        out->options.push_back({names->front(), argv[++i]});
      } else {
        return usage_error(spec.name, name + " needs a value");
      }
    } else if (eq == std::string::npos &&
               std::find(spec.switches.begin(), spec.switches.end(), arg) != spec.switches.end()) {
      out->switches.push_back(arg);
    } else {
      return usage_error(spec.name, "unknown option '" + arg + "'");
    }
  }
  if (out->positional.size() < spec.min_positional) return usage_error(spec.name, "missing arguments");
  if (out->positional.size() > spec.max_positional) return usage_error(spec.name, "too many arguments");
  return -1;
}

bool parse_int(const std::string& text, long min, long max, long* out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < min || v > max) return false;
  *out = v;
  return true;
}

bool drop_named(Mesh* mesh, const std::string& name) {
  const auto attribute = std::find_if(mesh->attributes.begin(), mesh->attributes.end(),
                                      [&](const MeshAttribute& a) { return a.name == name; });
  if (attribute != mesh->attributes.end()) {
    mesh->attributes.erase(attribute);
    return true;
  }
  const auto labels = std::find_if(mesh->face_labels.begin(), mesh->face_labels.end(),
                                   [&](const FaceLabels& l) { return l.name == name; });
  if (labels == mesh->face_labels.end()) return false;
  mesh->face_labels.erase(labels);
  return true;
}

int drop_each_named(const char* command, const std::vector<std::string>& names, const std::string& input, bool quiet,
                    Mesh* mesh) {
  for (const std::string& name : names) {
    if (!drop_named(mesh, name))
      return usage_error(command, "--drop " + name + ": " + input + " has no attribute or face labels of that name");
    if (!quiet) std::fprintf(stderr, "dropped (--drop %s): %s: %s\n", name.c_str(), input.c_str(), name.c_str());
  }
  return -1;
}

double max_quantization_step(const QuantizationInfo& q) {
  return std::max({q.step[0], q.step[1], q.step[2]});
}

std::string position_method_traits(int method, int features, int mirror, int shear, int lattice) {
  if (method < 4) return "";
  std::string traits = ": geometry order";
  if (features & kQuadTwistFeature) traits += ", quads' twist";
  if (features & kTriangleTwistFeature) traits += ", triangles' twist";
  if (features & kMaskContextsFeature) traits += ", candidate contexts";
  if (mirror == 1) traits += ", mirror images";
  if (mirror == 2) traits += ", mirror images a step away";
  if (shear > 0) traits += ", parallelograms sheared by " + std::to_string(shear) + "/16";
  if (method >= 12) traits += ", edges extrapolated";
  if (method >= 13) traits += ", class probabilities per axis";
  if (lattice > 1) traits += ", surface lattice of " + std::to_string(lattice) + " steps";
  return traits;
}

std::string human_bytes(uint64_t bytes) {
  char buf[64];
  if (bytes < 10 * 1024)
    std::snprintf(buf, sizeof buf, "%llu B", static_cast<unsigned long long>(bytes));
  else if (bytes < 10 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f KiB", double(bytes) / 1024);
  else
    std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / (1024 * 1024));
  return buf;
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += char(c);
    }
  }
  return out;
}

Progress::Progress(bool enabled) : enabled_(enabled && isatty(STDERR_FILENO)) {}

void Progress::stage(const std::string& what) {
  if (enabled_) std::fprintf(stderr, "\r\033[K%s ...", what.c_str());
}

void Progress::done() {
  if (enabled_) std::fprintf(stderr, "\r\033[K");
}

}  // namespace qmc::cli
