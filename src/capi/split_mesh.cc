// qmc_decoder_split_mesh (include/qmc/qmc.h): the vertices a GPU draws a mesh
// with attributes per corner (spec 15) from, one per distinct (mesh vertex,
// value of every corner attribute) among the corners, so that a vertex is
// split only where a seam gives it several values. Built on the C API's own
// mesh and corner attributes, in a file of its own: the WebAssembly package,
// which does this in JavaScript (web/src/QMCLoader.js), leaves it out.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "decoder/no_throw.h"
#include "qmc/qmc.h"

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// The corner attributes' corner_values, freed with the object.
struct CornerValues {
  std::vector<uint32_t*> arrays;
  ~CornerValues() {
    for (uint32_t* a : arrays) qmc_free(a);
  }
  bool same(uint32_t a, uint32_t b) const {
    for (const uint32_t* values : arrays)
      if (values[a] != values[b]) return false;
    return true;
  }
  // Corner a before corner b: by their values, the first array first.
  bool less(uint32_t a, uint32_t b) const {
    for (const uint32_t* values : arrays)
      if (values[a] != values[b]) return values[a] < values[b];
    return false;
  }
};

int read_corner_values(const qmc_decoder* decoder, CornerValues* out) {
  for (int i = 0; i < qmc_decoder_corner_attribute_count(decoder); ++i) {
    qmc_corner_attribute a;
    if (int error = qmc_decoder_corner_attribute(decoder, i, &a); error != QMC_OK) return error;
    qmc_free(a.values);
    out->arrays.push_back(a.corner_values);
  }
  return QMC_OK;
}

// A vertex has at most this many split vertices found by comparing its
// corners with them; a corner of other values beyond them is set aside.
constexpr uint8_t kComparedVertices = 32;

// split's result where corners were set aside: those corners sorted by
// vertex, values and corner, so that each run of equal vertex and values is
// one split vertex led by its first corner (K log K); then every split
// vertex numbered again in the order of its first corner.
void split_set_aside(const qmc_mesh& mesh, const CornerValues& values, std::vector<uint32_t> sorted,
                     std::vector<uint32_t>* first_corner, std::vector<uint32_t>* of_corner) {
  const uint32_t* vertex = mesh.corners;
  std::vector<uint32_t> leader(mesh.corner_count);  // the first corner of each corner's split vertex
  for (uint32_t k = 0; k < mesh.corner_count; ++k)
    leader[k] = (*of_corner)[k] != kNone ? (*first_corner)[(*of_corner)[k]] : k;
  const auto same = [&](uint32_t a, uint32_t b) { return vertex[a] == vertex[b] && values.same(a, b); };
  const auto before = [&](uint32_t a, uint32_t b) { return vertex[a] != vertex[b] ? vertex[a] < vertex[b] : values.less(a, b); };
  std::sort(sorted.begin(), sorted.end(),
            [&](uint32_t a, uint32_t b) { return before(a, b) || (!before(b, a) && a < b); });
  for (size_t i = 1; i < sorted.size(); ++i)
    if (same(sorted[i - 1], sorted[i])) leader[sorted[i]] = leader[sorted[i - 1]];
  first_corner->clear();
  for (uint32_t k = 0; k < mesh.corner_count; ++k) {
    if (leader[k] == k) {
      (*of_corner)[k] = uint32_t(first_corner->size());
      first_corner->push_back(k);
    } else {
      (*of_corner)[k] = (*of_corner)[leader[k]];  // leader[k] < k: numbered already
    }
  }
}

// Split vertices numbered in the order of their first corners. The split
// vertices of one mesh vertex are chained from its first, so a corner is
// compared with those of its own vertex only, at most kComparedVertices;
// the corners whose values none of them has are set aside and sorted
// (split_set_aside), where comparing with every split vertex found before
// would take a fan of a million corners of distinct values 5 10^11 steps.
void split(const qmc_mesh& mesh, const CornerValues& values, std::vector<uint32_t>* first_corner,
           std::vector<uint32_t>* of_corner) {
  of_corner->assign(mesh.corner_count, kNone);
  std::vector<uint32_t> first_of(mesh.vertex_count, kNone), next_of, set_aside;
  std::vector<uint8_t> chained(mesh.vertex_count, 0);  // per mesh vertex, its split vertices so far
  for (uint32_t k = 0; k < mesh.corner_count; ++k) {
    const uint32_t v = mesh.corners[k];
    uint32_t s = first_of[v];
    while (s != kNone && !values.same(k, (*first_corner)[s])) s = next_of[s];
    if (s == kNone) {
      if (chained[v] == kComparedVertices) {
        set_aside.push_back(k);
        continue;
      }
      s = uint32_t(first_corner->size());
      first_corner->push_back(k);
      next_of.push_back(first_of[v]);
      first_of[v] = s;
      ++chained[v];
    }
    (*of_corner)[k] = s;
  }
  if (!set_aside.empty()) split_set_aside(mesh, values, std::move(set_aside), first_corner, of_corner);
}

// qmc_mesh's fans (each polygon from its first corner) over the split vertices.
std::vector<uint32_t> split_fans(const qmc_mesh& mesh, const std::vector<uint32_t>& of_corner) {
  std::vector<uint32_t> triangles;
  triangles.reserve(3 * size_t(mesh.triangle_count));
  for (uint32_t f = 0, first = 0; f < mesh.face_count; first += mesh.face_sizes[f++])
    for (uint32_t k = 1; k + 1 < mesh.face_sizes[f]; ++k) {
      triangles.push_back(of_corner[first]);
      triangles.push_back(of_corner[first + k]);
      triangles.push_back(of_corner[first + k + 1]);
    }
  return triangles;
}

template <typename T>
T* malloc_copy(const std::vector<T>& from) {
  T* to = static_cast<T*>(std::malloc(from.empty() ? 1 : from.size() * sizeof(T)));
  if (to && !from.empty()) std::memcpy(to, from.data(), from.size() * sizeof(T));
  return to;
}

}  // namespace

extern "C" {

void qmc_split_mesh_free(qmc_split_mesh* mesh) {
  if (!mesh) return;
  std::free(mesh->first_corner);
  std::free(mesh->triangles);
  std::memset(mesh, 0, sizeof(*mesh));
}

int qmc_decoder_split_mesh(const qmc_decoder* decoder, qmc_split_mesh* out) {
  if (!decoder || !out) return QMC_INVALID_ARGUMENT;
  std::memset(out, 0, sizeof(*out));
  qmc_mesh mesh;
  if (int error = qmc_decoder_mesh(decoder, QMC_FINEST, &mesh); error != QMC_OK) return error;
  int result = QMC_LIMIT_EXCEEDED;  // what an allocation that fails gives, as in qmc_decoder_mesh
  QMC_TRY {
    CornerValues values;
    result = read_corner_values(decoder, &values);
    if (result == QMC_OK) {
      std::vector<uint32_t> first_corner, of_corner;
      split(mesh, values, &first_corner, &of_corner);
      const std::vector<uint32_t> triangles = split_fans(mesh, of_corner);
      out->vertex_count = uint32_t(first_corner.size());
      out->triangle_count = uint32_t(triangles.size() / 3);
      out->first_corner = malloc_copy(first_corner);
      out->triangles = malloc_copy(triangles);
      if (!out->first_corner || !out->triangles) result = QMC_LIMIT_EXCEEDED;
    }
  }
  QMC_CATCH_ALL(result = QMC_LIMIT_EXCEEDED)
  qmc_mesh_free(&mesh);
  if (result != QMC_OK) qmc_split_mesh_free(out);
  return result;
}

}  // extern "C"
