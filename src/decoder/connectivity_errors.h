// The rejections of the polygon coder's CONN payload (spec/qmc-format.md
// 5.4, section 9's identifiers), each message starting with the chunk.
#pragma once

#include <cstdint>
#include <string>

#include "decoder/output_budget.h"
#include "qmc/status.h"

namespace qmc {

inline Status payload_error(const std::string& why) { return Status(ErrorCode::kBadChunkPayload, "CONN: " + why); }
inline Status symbol_error(const std::string& why) { return Status(ErrorCode::kBadSymbol, "CONN: " + why); }
inline Status limit_error(const std::string& why) { return Status(ErrorCode::kLimitExceeded, "CONN: " + why); }
inline Status truncated() { return Status(ErrorCode::kTruncated, "CONN: polygon stream ends early"); }
// 5.4.3, 5.4.8, 5.4.10: no face has more than 2^32 - 1 corners (10.2 writes
// a degree as u32); `face` names the kind of face.
Status check_face_degree(uint64_t d, const char* face);
// Symbol 18's checks in their order (5.4.3, 5.4.10, 8.1): d, whether the
// stream `fits` its d - 2 statuses, its corners against the output's limit.
// Out of line, so that the messages are built in the code compiled for size
// (web/CMakeLists.txt), not in codings 7 and 8's fast loop.
Status check_other_face(uint64_t d, bool fits, OtherFaceCorners* corners);

}  // namespace qmc
