// The fLBL chunk, spec/qmc-format.md section 16, on the encoder side: the
// string tables as given, then each face's label in file order (16.2).
#include "encoder/face_label_encoder.h"

#include "common/byte_io.h"
#include "common/face_label_coding.h"
#include "common/range_coder.h"

namespace qmc {
namespace {

void put_strings(std::vector<uint8_t>* out, const std::vector<std::string>& strings) {
  put_varint(out, strings.size());
  for (const std::string& s : strings) {
    put_varint(out, s.size());
    out->insert(out->end(), s.begin(), s.end());
  }
}

}  // namespace

std::string face_label_problem(const Mesh& mesh, size_t i) {
  const FaceLabels& l = mesh.face_labels[i];
  const std::string which = "face labels " + std::to_string(i) + " (\"" + l.name + "\")";
  if (l.name.empty() || l.name.size() > 255) return which + ": a name needs 1 to 255 bytes";
  for (size_t j = 0; j < i; ++j)
    if (mesh.face_labels[j].name == l.name) return which + ": a second label of this name";
  if (l.values.size() >= UINT32_MAX) return which + ": too many values";
  if (l.face_values.size() != mesh.face_count())
    return which + ": " + std::to_string(l.face_values.size()) + " labels for " + std::to_string(mesh.face_count()) +
           " faces";
  for (size_t f = 0; f < l.face_values.size(); ++f)
    if (l.face_values[f] > l.none())
      return which + ": face " + std::to_string(f) + " has label " + std::to_string(l.face_values[f]) + " of " +
             std::to_string(l.values.size());
  return {};
}

std::vector<uint8_t> encode_face_labels(const FaceLabels& labels, const std::vector<uint32_t>& face_source) {
  std::vector<uint8_t> payload;
  put_varint(&payload, face_source.size());
  put_u8(&payload, uint8_t(labels.name.size()));
  payload.insert(payload.end(), labels.name.begin(), labels.name.end());
  put_strings(&payload, labels.references);
  put_strings(&payload, labels.values);
  RangeEncoder rc;
  uint16_t same = kRangeProbabilityInit;
  uint32_t previous = labels.none();
  for (size_t j = 0; j < face_source.size(); ++j)
    previous = code_face_label(&rc, &same, j, previous, labels.none(), labels.face_values[face_source[j]]);
  const std::vector<uint8_t> stream = rc.finish();
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

}  // namespace qmc
