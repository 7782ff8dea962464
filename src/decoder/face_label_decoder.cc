// The fLBL chunk, spec/qmc-format.md section 16: the string tables (16.1)
// and the range-coded label of every face (16.2).
#include "decoder/face_label_decoder.h"

#include <string>

#include "common/byte_io.h"
#include "common/face_label_coding.h"
#include "common/range_coder.h"

namespace qmc {
namespace {

Status bad(const std::string& label, const std::string& message) {
  return Status(ErrorCode::kBadChunkPayload, label + ": " + message + " (section 16.1)");
}

// A count of strings, each at least its length byte: above the bytes left
// it cannot be there. Then 8.1: the strings so far (`earlier` and these) at 4
// bytes each of the output against what is left of the limit, before the
// table is reserved (a string takes more memory than it charges).
Status read_strings(ByteReader* in, const std::string& label, const char* what, uint64_t earlier,
                    const OutputBudget& budget, std::vector<std::string>* out) {
  uint64_t count = 0;
  if (!in->get_varint(&count) || count > in->remaining())
    return bad(label, std::string(what) + " count missing, malformed or above the bytes left");
  if (Status s = budget.check(4 * (earlier + count), label); !s.ok()) return s;
  out->resize(size_t(count));
  for (std::string& s : *out) {
    uint64_t length = 0;
    if (!in->get_varint(&length) || length > in->remaining())
      return bad(label, std::string("a string of the ") + what + " is cut short");
    s.assign(reinterpret_cast<const char*>(in->cursor()), size_t(length));
    in->skip(size_t(length));
  }
  return Status::Ok();
}

Status read_tables(ByteReader* in, uint64_t face_count, const std::vector<FaceLabels>& earlier,
                   const OutputBudget& budget, std::string* label, FaceLabels* out) {
  uint64_t faces = 0;
  if (!in->get_varint(&faces) || faces != face_count)
    return bad(*label, "face_count missing, malformed or not CONN's " + std::to_string(face_count));
  uint8_t length = 0;
  if (!in->get_u8(&length) || length == 0) return bad(*label, "name_length missing or 0");
  if (in->remaining() < length) return bad(*label, "the name is cut short");
  out->name.assign(reinterpret_cast<const char*>(in->cursor()), length);
  in->skip(length);
  *label = "fLBL \"" + out->name + "\"";
  for (const FaceLabels& e : earlier)
    if (e.name == out->name) return bad(*label, "a second label of this name");
  if (Status s = read_strings(in, *label, "references", 0, budget, &out->references); !s.ok()) return s;
  return read_strings(in, *label, "values", out->references.size(), budget, &out->values);
}

}  // namespace

uint64_t face_label_output_bytes(const FaceLabels& labels) {
  uint64_t bytes = 20 + labels.name.size() + 4 * uint64_t(labels.face_values.size());
  for (const auto* table : {&labels.references, &labels.values})
    for (const std::string& s : *table) bytes += 4 + s.size();
  return bytes;
}

Status decode_face_labels(const uint8_t* payload, size_t size, uint64_t face_count,
                          const std::vector<FaceLabels>& earlier, OutputBudget* budget, FaceLabels* out) {
  *out = FaceLabels{};
  ByteReader in(payload, size);
  std::string label = "fLBL";
  if (Status s = read_tables(&in, face_count, earlier, *budget, &label, out); !s.ok()) return s;
  if (!range_stream_justifies(face_count, in.remaining()))
    return Status(ErrorCode::kLimitExceeded, label + ": " + std::to_string(face_count) + " faces for " +
                                                 std::to_string(in.remaining()) +
                                                 " stream bytes, above 512 (L + 8) (section 16.2)");
  // The tables alone so far (face_values is still empty): no copy of them.
  if (Status s = budget->charge(face_label_output_bytes(*out) + 4 * face_count, label); !s.ok()) return s;
  RangeDecoder rc(in.cursor(), in.remaining());
  if (rc.bad_start())
    return Status(ErrorCode::kBadChunkPayload, label + ": the stream starts with 0xFFFFFFFF (section 13.5.2)");
  const uint32_t none = out->none();
  out->face_values.resize(size_t(face_count));
  uint16_t same = kRangeProbabilityInit;
  uint32_t previous = none;
  for (uint64_t f = 0; f < face_count; ++f) {
    const uint32_t l = code_face_label(&rc, &same, f, previous, none, 0);
    if (rc.overrun())
      return Status(ErrorCode::kTruncated,
                    label + ": the stream ends inside face " + std::to_string(f) + " (section 16.2)");
    if (l > none)
      return Status(ErrorCode::kBadSymbol, label + ": face " + std::to_string(f) + " has label " + std::to_string(l) +
                                               " of a table of " + std::to_string(none) + " (section 16.2)");
    out->face_values[size_t(f)] = previous = l;
  }
  if (rc.unread() != 0)
    return Status(ErrorCode::kBadChunkPayload,
                  label + ": " + std::to_string(rc.unread()) + " bytes after the coded data (section 13.5.2)");
  return Status::Ok();
}

}  // namespace qmc
