// qmc: error reporting shared by the encoder and the decoder. No exceptions
// cross the library boundary; every failure is a Status with a specific code
// and a message that names what was wrong and where.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace qmc {

// Stable identifiers for failures. The decoder codes map to the rejection
// rules of spec/qmc-format.md section 9; conformance manifests name them.
enum class ErrorCode : uint8_t {
  kOk = 0,
  kBadSignature,        // the first 8 bytes are not the qmc signature
  kUnsupportedVersion,  // QHDR major version is not one this decoder reads
  kTruncated,           // the input ended inside a chunk or before QEND
  kBadCrc,              // a chunk's CRC-32 does not match
  kBadChunkLength,      // a chunk length above the format's limit
  kBadChunkType,        // chunk type bytes are not four ASCII letters
  kUnknownCriticalChunk,
  kChunkOrder,          // a chunk missing, repeated or out of the required order
  kTrailingData,        // bytes after QEND
  kBadChunkPayload,     // a field out of range, or payload size inconsistent
  kUnsupportedFeature,  // a method or sample format this decoder does not implement
  kBadHuffmanTable,     // code lengths over-subscribed, incomplete or too long
  kBadSymbol,           // a decoded symbol or value outside its allowed range
  kLimitExceeded,       // a count larger than the input can justify
  kInvalidArgument,     // encoder: input mesh or option it cannot represent
  kIo,                  // tools: file could not be read or written
};

const char* error_code_name(ErrorCode code);

class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(ErrorCode code, std::string message) : code_(code), message_(std::move(message)) {}
  static Status Ok() { return Status(); }

  bool ok() const { return code_ == ErrorCode::kOk; }
  ErrorCode code() const { return code_; }
  const std::string& message() const { return message_; }
  // "bad_crc: chunk POSN at byte 120: stored CRC ... computed ..."
  std::string to_string() const;

 private:
  ErrorCode code_ = ErrorCode::kOk;
  std::string message_;
};

}  // namespace qmc
