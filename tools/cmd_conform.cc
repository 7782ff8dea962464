// qmc conform: run this decoder over a conformance directory
// (spec/qmc-format.md section 10).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "qmc/decoder.h"
#include "sha256.h"

namespace qmc::cli {
namespace {

const char kHelp[] =
    "usage: qmc conform DIR [--verbose]\n"
    "\n"
    "Reads DIR/MANIFEST (spec section 10.1) and checks every vector: a valid vector\n"
    "must decode, whole and fed one byte at a time, to output whose SHA-256 is the\n"
    "listed one; an invalid vector must be rejected with the listed error code.\n"
    "Prints one line per vector and 'N passed, N failed'; exit 1 if any failed.\n";

struct Entry {
  std::string kind, path, expected;
  int line = 0;
};

// Decodes with the bytes arriving in pieces of `piece` bytes.
Status decode_in_pieces(const std::vector<uint8_t>& bytes, size_t piece, DecodedFile* out) {
  StreamDecoder decoder;
  for (size_t pos = 0; pos < bytes.size(); pos += piece) {
    const size_t n = std::min(piece, bytes.size() - pos);
    if (Status s = decoder.feed(bytes.data() + pos, n); !s.ok()) return s;
  }
  if (Status s = decoder.finish(); !s.ok()) return s;
  *out = decoder.take_file();
  return Status::Ok();
}

std::string check_valid(const std::vector<uint8_t>& bytes, const std::string& expected) {
  for (size_t piece : {bytes.size() + 1, size_t(1), size_t(7)}) {
    DecodedFile file;
    if (Status s = decode_in_pieces(bytes, piece, &file); !s.ok())
      return "rejected (" + s.to_string() + ")";
    const std::vector<uint8_t> out = canonical_output(file);
    const std::string hash = tools::sha256_hex(out.data(), out.size());
    if (hash != expected) return "output hash " + hash + " (pieces of " + std::to_string(piece) + " bytes)";
  }
  return {};
}

std::string check_invalid(const std::vector<uint8_t>& bytes, const std::string& expected) {
  for (size_t piece : {bytes.size() + 1, size_t(1)}) {
    DecodedFile file;
    const Status s = decode_in_pieces(bytes, piece, &file);
    if (s.ok()) return "accepted, should be rejected as " + expected;
    if (expected != error_code_name(s.code())) return "rejected as " + s.to_string() + ", expected " + expected;
  }
  return {};
}

Status read_manifest(const std::string& dir, std::vector<Entry>* entries) {
  const std::string path = dir + "/MANIFEST";
  std::ifstream in(path);
  if (!in) return Status(ErrorCode::kIo, "cannot open " + path);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Entry e;
    e.line = number;
    std::string extra;
    if (!(fields >> e.kind >> e.path >> e.expected) || (fields >> extra) ||
        (e.kind != "valid" && e.kind != "invalid"))
      return Status(ErrorCode::kInvalidArgument, path + ":" + std::to_string(number) +
                                                     ": expected 'valid PATH SHA256' or 'invalid PATH ERROR'");
    entries->push_back(e);
  }
  return Status::Ok();
}

}  // namespace

int run_conform(int argc, char** argv) {
  CommandLine cl;
  const CommandSpec spec{"conform", kHelp, {"--verbose"}, {}, 1, 1};
  if (int rc = parse_command_line(spec, argc, argv, &cl); rc >= 0) return rc;
  const std::string& dir = cl.positional[0];
  const bool verbose = cl.has("--verbose");
  std::vector<Entry> entries;
  if (Status s = read_manifest(dir, &entries); !s.ok()) return fail("conform", s);
  int passed = 0, failed = 0;
  for (const Entry& e : entries) {
    std::vector<uint8_t> bytes;
    std::string problem;
    if (Status s = read_file(dir + "/" + e.path, &bytes); !s.ok())
      problem = s.to_string();
    else
      problem = e.kind == "valid" ? check_valid(bytes, e.expected) : check_invalid(bytes, e.expected);
    if (problem.empty()) {
      ++passed;
      if (verbose) std::printf("PASS %s %s\n", e.kind.c_str(), e.path.c_str());
    } else {
      ++failed;
      std::printf("FAIL %s %s: %s\n", e.kind.c_str(), e.path.c_str(), problem.c_str());
    }
  }
  std::printf("conformance: %d passed, %d failed\n", passed, failed);
  return failed == 0 && passed > 0 ? kExitOk : kExitCheckFailed;
}

}  // namespace qmc::cli
