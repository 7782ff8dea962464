// qmc tools: SHA-256 (FIPS 180-4), used to fingerprint meshes and encoded
// files in benchmark reports and conformance manifests without pulling in a
// crypto library.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace qmc::tools {

std::array<uint8_t, 32> sha256(const uint8_t* data, size_t size);

// Lower-case hexadecimal digest, 64 characters.
std::string sha256_hex(const uint8_t* data, size_t size);

}  // namespace qmc::tools
