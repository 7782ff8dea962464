// Section 8.1: decoder-imposed limits.
#include "decoder/output_budget.h"

namespace qmc {

Status check_limit(const std::string& what, uint64_t count, uint64_t limit, const char* field) {
  if (count > limit)
    return Status(ErrorCode::kLimitExceeded, what + ": " + std::to_string(count) + " exceed this decoder's limit of " +
                                                 std::to_string(limit) + " (DecoderLimits::" + field + ", section 8.1)");
  if (count > kAddressableCount)
    return Status(ErrorCode::kLimitExceeded, what + ": " + std::to_string(count) + " exceed the " +
                                                 std::to_string(kAddressableCount) + " this build can address");
  return Status::Ok();
}

Status OutputBudget::charge(uint64_t bytes, const std::string& what) {
  if (Status s = check(bytes, what); !s.ok()) return s;
  used_ += bytes;
  return Status::Ok();
}

Status OutputBudget::check(uint64_t bytes, const std::string& what) const {
  // Charges stay below 2^56 (counts below 2^48, small factors), and the
  // comparison is written so that it cannot wrap.
  if (bytes > limit_ || used_ > limit_ - bytes)
    return Status(ErrorCode::kLimitExceeded, what + ": the output would reach " + std::to_string(used_ + bytes) +
                                                 " bytes, above this decoder's limit of " + std::to_string(limit_) +
                                                 " (DecoderLimits::max_output_bytes, section 8.1)");
  return Status::Ok();
}

Status OtherFaceCorners::take(uint64_t degree) {
  const uint64_t extra = degree - 3;
  if (extra > corners_left_)
    return Status(ErrorCode::kLimitExceeded, "CONN: a face of degree " + std::to_string(degree) +
                                                 ": the corners beyond 3 of the faces of symbol 18 exceed what is left"
                                                 " of this decoder's limit (DecoderLimits::max_output_bytes, section 8.1)");
  corners_left_ -= extra;
  return Status::Ok();
}

}  // namespace qmc
