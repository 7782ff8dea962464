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
  if (budget_ == nullptr) return Status::Ok();
  // Every d - 2 is justified by the chunk's bits (5.4.3) or 512 per byte of
  // its symbols (5.4.10), and a chunk is below 2^31 bytes: 4 corners_ < 2^44.
  corners_ += degree - 3;
  if (4 * corners_ <= budget_->left()) return Status::Ok();
  return budget_->check(4 * corners_, "CONN: a face of degree " + std::to_string(degree) +
                                          ", with the corners beyond 3 of the faces of symbol 18 before it");
}

}  // namespace qmc
