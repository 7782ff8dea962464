// Helpers shared by the qmc subcommands.
#pragma once

#include <cstdint>
#include <string>
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

// Reads a mesh and prints the reader's warnings to stderr.
Status load_mesh(const std::string& path, Mesh* mesh);

// Prints "qmc CMD: message" to stderr and returns kExitError.
int fail(const char* command, const Status& status);
int usage_error(const char* command, const std::string& message);

// True if `arg` is --NAME=VALUE or --NAME followed by a value; advances i.
bool take_option(int argc, char** argv, int* i, const std::string& name, std::string* value);
bool parse_int(const std::string& text, long min, long max, long* out);

// Largest per-axis quantization step of a decoded file (section 6.4).
double max_quantization_step(const QuantizationInfo& q);

std::string human_bytes(uint64_t bytes);

}  // namespace qmc::cli
