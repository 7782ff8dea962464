// Helpers shared by the qmc subcommands.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "qmc/decoder.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc::cli {

// Exit codes: 0 success, 1 the check asked for failed (verify, conform),
// 2 bad usage, 3 input or output error (unreadable file, rejected stream).
inline constexpr int kExitOk = 0, kExitCheckFailed = 1, kExitUsage = 2, kExitError = 3;

Status read_file(const std::string& path, std::vector<uint8_t>* bytes);
Status write_file(const std::string& path, const std::vector<uint8_t>& bytes);

// Reads a mesh and prints the reader's notes to stderr unless `quiet`.
// Reads a mesh file; prints the reader's notes (what it ignored) unless
// `quiet`, and returns them in *notes when given.
Status load_mesh(const std::string& path, Mesh* mesh, bool quiet = false, std::vector<std::string>* notes = nullptr);

// Refuses (returns the usage exit code, having said why) when `output` is
// the same file as `input` however spelled (device and inode); -1 otherwise.
int refuse_overwriting_input(const char* command, const std::string& input, const std::string& output);

// Prints "qmc CMD: message" to stderr and returns kExitError.
int fail(const char* command, const Status& status);
int usage_error(const char* command, const std::string& message);

// The arguments of one subcommand: switches, options with values, and
// positional arguments, in the forms `--name`, `--name VALUE`, `--name=VALUE`.
struct CommandLine {
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> options;  // canonical name, value
  std::vector<std::string> switches;
  bool has(const std::string& name) const;
  // The value of an option given with a value, or null.
  const std::string* value(const std::string& name) const;
};

struct CommandSpec {
  const char* name;                      // "encode"
  const char* help;                      // printed for --help
  std::vector<std::string> switches;     // e.g. {"--quiet"}
  std::vector<std::vector<std::string>> valued;  // each: canonical name, then aliases
  size_t min_positional, max_positional;
};

// Returns -1 to go on, or the exit code to return now (after --help or a
// usage error, which it has already reported).
int parse_command_line(const CommandSpec& spec, int argc, char** argv, CommandLine* out);
bool parse_int(const std::string& text, long min, long max, long* out);

// Spec 8.1: the decoder limits of a command that decodes. The library's
// defaults, or with `--max-output-mb N` (kMaxOutputOption) an output of up
// to N MiB and no separate count limits; 0 removes every limit.
inline const char kMaxOutputOption[] = "--max-output-mb";
inline const char kMaxOutputHelp[] =
    "  --max-output-mb N  refuse files whose decoded output (spec 8.1) exceeds N MiB\n"
    "                     (default 256, at most 2^24 vertices; 0: no limit)\n";
Status decoder_limits(const CommandLine& cl, DecoderLimits* limits);

// A refusal by one of the decoder's limits (spec 8.1) with the option that
// raises it appended; any other status as it is.
Status name_limit_option(const Status& s);
// decode() with those limits; a refusal by a limit names the option.
Status decode_with_limits(const DecoderLimits& limits, const std::vector<uint8_t>& bytes, DecodedFile* out);

// --drop NAME (encode, decode): removes the attribute, else the face
// labels, called `name` from *mesh; false if it has neither.
bool drop_named(Mesh* mesh, const std::string& name);
// Drops each of `names` from *mesh as drop_named does, printing each (stderr)
// unless `quiet`; a name the mesh does not have is a usage error of
// `command` naming `input`. Returns -1 to go on, else the exit code.
int drop_each_named(const char* command, const std::vector<std::string>& names, const std::string& input, bool quiet,
                    Mesh* mesh);

// Largest per-axis quantization step of a decoded file (section 6.4).
double max_quantization_step(const QuantizationInfo& q);

// What a predicted POSN method (section 14.1) adds to method 1: "" for 1
// and 3, else ": geometry order" and the additions its features name
// (14.7 - 14.9; methods 5 - 7 have the features their selector implies).
std::string position_method_traits(int method, int features, int mirror, int shear, int lattice = 1);

std::string human_bytes(uint64_t bytes);

// `s` as the inside of a JSON string literal.
std::string json_escape(const std::string& s);

// Stage messages for long runs on big inputs: shown on stderr only when it
// is a terminal, each replacing the previous one, cleared by done().
class Progress {
 public:
  explicit Progress(bool enabled);
  void stage(const std::string& what);
  void done();

 private:
  bool enabled_;
};

}  // namespace qmc::cli
