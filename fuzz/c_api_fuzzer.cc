// libFuzzer target: the C API (include/qmc/qmc.h) over a whole file, and what
// an embedder then asks of it: the mesh, every corner attribute (spec 15) and
// the mesh split for drawing (qmc_decoder_split_mesh). Any input decodes or
// is rejected with a code and a message; what a decoded file gives must be
// consistent: every index within its array, every split vertex standing for
// a corner of the mesh vertex the triangle names. Inputs are mutated as
// chunks with valid CRCs (chunk_mutator_hooks.cc).
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "chunk_mutator.h"
#include "fuzz_limits.h"
#include "qmc/qmc.h"

const size_t qmc::fuzz::kFilePrefixSize = 0;

namespace {

void check_corner_attributes(const qmc_decoder* d, const qmc_mesh& mesh) {
  for (int i = 0; i < qmc_decoder_corner_attribute_count(d); ++i) {
    qmc_corner_attribute a;
    if (qmc_decoder_corner_attribute(d, i, &a) != QMC_OK) __builtin_trap();
    if (a.corner_count != mesh.corner_count || a.components < 1 || a.components > 3) __builtin_trap();
    for (uint32_t k = 0; k < a.corner_count; ++k)
      if (a.corner_values[k] >= a.value_count) __builtin_trap();
    qmc_corner_attribute_free(&a);
  }
}

void check_split_mesh(const qmc_decoder* d, const qmc_mesh& mesh) {
  qmc_split_mesh split;
  if (qmc_decoder_split_mesh(d, &split) != QMC_OK) __builtin_trap();
  if (split.vertex_count > mesh.corner_count || split.triangle_count != mesh.triangle_count) __builtin_trap();
  for (uint32_t i = 0; i < split.vertex_count; ++i)
    if (split.first_corner[i] >= mesh.corner_count) __builtin_trap();
  for (uint32_t t = 0; t < 3 * split.triangle_count; ++t) {
    if (split.triangles[t] >= split.vertex_count) __builtin_trap();
    if (mesh.corners[split.first_corner[split.triangles[t]]] != mesh.triangles[t]) __builtin_trap();
  }
  qmc_split_mesh_free(&split);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc_limits limits;
  qmc_limits_default(&limits);
  limits.max_output_bytes = qmc::fuzz::small_output_limits().max_output_bytes;
  qmc_decoder* d = qmc_decoder_create(&limits);
  if (!d) return 0;
  const int error = qmc_decoder_decode(d, data, size);
  if (error != QMC_OK) {
    if (error != qmc_decoder_error(d) || std::strlen(qmc_decoder_message(d)) == 0) __builtin_trap();
    qmc_split_mesh split;
    if (qmc_decoder_split_mesh(d, &split) != error) __builtin_trap();  // a rejected file gives nothing
  } else if (qmc_decoder_has_mesh(d)) {
    qmc_mesh mesh;
    if (qmc_decoder_mesh(d, QMC_FINEST, &mesh) != QMC_OK) __builtin_trap();
    check_corner_attributes(d, mesh);
    check_split_mesh(d, mesh);
    qmc_mesh_free(&mesh);
  }
  qmc_decoder_destroy(d);
  return 0;
}
