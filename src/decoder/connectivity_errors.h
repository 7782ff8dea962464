// The rejections of the polygon coder's CONN payload (spec/qmc-format.md
// 5.4, section 9's identifiers), each message starting with the chunk.
#pragma once

#include <string>

#include "qmc/status.h"

namespace qmc {

inline Status payload_error(const std::string& why) { return Status(ErrorCode::kBadChunkPayload, "CONN: " + why); }
inline Status symbol_error(const std::string& why) { return Status(ErrorCode::kBadSymbol, "CONN: " + why); }
inline Status limit_error(const std::string& why) { return Status(ErrorCode::kLimitExceeded, "CONN: " + why); }
inline Status truncated() { return Status(ErrorCode::kTruncated, "CONN: polygon stream ends early"); }

}  // namespace qmc
