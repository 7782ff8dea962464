// Names of the error codes of include/qmc/status.h; these spellings are the
// ones conformance manifests use (spec/qmc-format.md section 9).
#include "qmc/status.h"

namespace qmc {

const char* error_code_name(ErrorCode code) {
  switch (code) {
    case ErrorCode::kOk: return "ok";
    case ErrorCode::kBadSignature: return "bad_signature";
    case ErrorCode::kUnsupportedVersion: return "unsupported_version";
    case ErrorCode::kTruncated: return "truncated";
    case ErrorCode::kBadCrc: return "bad_crc";
    case ErrorCode::kBadChunkLength: return "bad_chunk_length";
    case ErrorCode::kBadChunkType: return "bad_chunk_type";
    case ErrorCode::kUnknownCriticalChunk: return "unknown_critical_chunk";
    case ErrorCode::kChunkOrder: return "chunk_order";
    case ErrorCode::kTrailingData: return "trailing_data";
    case ErrorCode::kBadChunkPayload: return "bad_chunk_payload";
    case ErrorCode::kUnsupportedFeature: return "unsupported_feature";
    case ErrorCode::kBadHuffmanTable: return "bad_huffman_table";
    case ErrorCode::kBadSymbol: return "bad_symbol";
    case ErrorCode::kLimitExceeded: return "limit_exceeded";
    case ErrorCode::kInvalidArgument: return "invalid_argument";
    case ErrorCode::kIo: return "io";
  }
  return "unknown";
}

std::string Status::to_string() const {
  if (ok()) return "ok";
  return std::string(error_code_name(code_)) + ": " + message_;
}

}  // namespace qmc
