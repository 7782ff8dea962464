// qmc tools: the seeded random polygon-mesh generator. See
// random_polygon_mesh.h for the construction; the comments here say why each
// step keeps the surface manifold and its topology as requested.
#include "random_polygon_mesh.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "mesh_generators.h"
#include "splitmix64.h"

namespace qmc {
namespace {

using tools::SplitMix64;
using Face = std::vector<uint32_t>;

constexpr uint32_t kNoFace = ~uint32_t{0};

uint64_t half_edge_key(uint32_t from, uint32_t to) { return uint64_t{from} << 32 | to; }

template <class T>
void shuffle(std::vector<T>* items, SplitMix64* rng) {
  for (size_t i = items->size(); i > 1; --i) std::swap((*items)[i - 1], (*items)[rng->below(static_cast<uint32_t>(i))]);
}

// Options after clamping (see the header).
struct Settings {
  int components, genus, holes, min_degree, max_degree, target_faces, isolated_vertices;
  bool valence_two, non_manifold;
};

Settings settings_from(const RandomPolygonMeshOptions& options) {
  Settings s{};
  s.components = std::max(options.components, 1);
  s.genus = std::max(options.genus, 0);
  s.holes = std::max(options.holes, 0);
  s.min_degree = std::clamp(options.min_degree, 3, 4);
  s.max_degree = std::max(options.max_degree, s.min_degree);
  s.target_faces = std::clamp(options.target_faces, 1, 1 << 20);
  s.isolated_vertices = std::max(options.isolated_vertices, 0);
  s.valence_two = options.valence_two;
  s.non_manifold = options.non_manifold;
  return s;
}

// ---------------------------------------------------------------------------
// One component under construction: an oriented manifold polygon surface.
// Every directed edge belongs to at most one face (face_of_), so "u and v are
// adjacent" and "the face across u->v" are map look-ups. Removed faces stay
// as empty slots so face indices remain stable.

class Surface {
 public:
  explicit Surface(const Mesh& quads);

  bool add_handle(SplitMix64* rng);
  bool cut_hole(SplitMix64* rng);
  bool triangulate(SplitMix64* rng);
  void try_split(SplitMix64* rng, int min_degree);
  void try_merge(SplitMix64* rng, int max_degree);
  bool try_insert_valence_two(SplitMix64* rng, int max_degree);

  size_t face_count() const { return live_faces_; }
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<float>& positions() const { return positions_; }

 private:
  void set_face(uint32_t f, Face face);
  uint32_t add_face(Face face);
  bool adjacent(uint32_t u, uint32_t v) const;
  uint32_t face_across(uint32_t u, uint32_t v) const;  // the face using v->u
  bool touches_boundary(const Face& face) const;
  bool far_apart(const Face& a, const Face& b) const;
  void build_tube(uint32_t a, uint32_t b, uint32_t twist);
  void split_at(uint32_t f, size_t i, size_t j);
  uint32_t random_face(SplitMix64* rng) const;

  std::vector<Face> faces_;
  std::map<uint64_t, uint32_t> face_of_;  // directed edge -> face
  std::vector<int> valence_;              // undirected edges per vertex
  std::vector<bool> on_boundary_;
  std::vector<bool> raised_;  // face already got a valence-2 vertex
  std::vector<float> positions_;
  size_t live_faces_ = 0;
};

Surface::Surface(const Mesh& quads) : positions_(quads.positions) {
  valence_.assign(quads.vertex_count(), 0);
  on_boundary_.assign(quads.vertex_count(), false);
  for (size_t f = 0; f < quads.face_count(); ++f) add_face(Face(quads.corners.begin() + 4 * f, quads.corners.begin() + 4 * f + 4));
  // The sphere is closed: each undirected edge is seen once per direction.
  for (const auto& [key, face] : face_of_) ++valence_[key >> 32];
}

void Surface::set_face(uint32_t f, Face face) {
  Face& old = faces_[f];
  for (size_t i = 0; i < old.size(); ++i) face_of_.erase(half_edge_key(old[i], old[(i + 1) % old.size()]));
  live_faces_ += (old.empty() ? 1 : 0) - (face.empty() ? 1 : 0);
  old = std::move(face);
  for (size_t i = 0; i < old.size(); ++i) face_of_[half_edge_key(old[i], old[(i + 1) % old.size()])] = f;
}

uint32_t Surface::add_face(Face face) {
  faces_.emplace_back();
  raised_.push_back(false);
  set_face(static_cast<uint32_t>(faces_.size() - 1), std::move(face));
  return static_cast<uint32_t>(faces_.size() - 1);
}

bool Surface::adjacent(uint32_t u, uint32_t v) const {
  return face_of_.count(half_edge_key(u, v)) != 0 || face_of_.count(half_edge_key(v, u)) != 0;
}

uint32_t Surface::face_across(uint32_t u, uint32_t v) const {
  auto it = face_of_.find(half_edge_key(v, u));
  return it == face_of_.end() ? kNoFace : it->second;
}

bool Surface::touches_boundary(const Face& face) const {
  return std::any_of(face.begin(), face.end(), [this](uint32_t v) { return on_boundary_[v]; });
}

// No shared and no adjacent vertices: the tube's new edges are then all new,
// and the faces around each vertex of A and of B stay one fan.
bool Surface::far_apart(const Face& a, const Face& b) const {
  for (uint32_t x : a) {
    for (uint32_t y : b) {
      if (x == y || adjacent(x, y)) return false;
    }
  }
  return true;
}

uint32_t Surface::random_face(SplitMix64* rng) const { return rng->below(static_cast<uint32_t>(faces_.size())); }

// Searches every pair from random starting points, so a handle is found
// whenever one can be placed.
bool Surface::add_handle(SplitMix64* rng) {
  const uint32_t n = static_cast<uint32_t>(faces_.size());
  const uint32_t start_a = rng->below(n);
  const uint32_t start_b = rng->below(n);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t a = (start_a + i) % n;
    if (faces_[a].size() != 4 || touches_boundary(faces_[a])) continue;
    for (uint32_t j = 0; j < n; ++j) {
      const uint32_t b = (start_b + j) % n;
      if (b == a || faces_[b].size() != 4 || touches_boundary(faces_[b]) || !far_apart(faces_[a], faces_[b])) continue;
      build_tube(a, b, rng->below(4));
      return true;
    }
  }
  return false;
}

// Removing quads A = (a0..a3) and B leaves two square holes whose remaining
// neighbours use a(i+1)->a(i) and b(k+1)->b(k). Tube quad i is
// (a(i), a(i+1), b(k), b(k+1)) with k = twist - i: it uses the missing
// directions a(i)->a(i+1) and b(k)->b(k+1), and its side a(i+1)->b(k) is
// used backwards by quad i+1, so the result is closed and consistently
// oriented. V stays, E grows by 4, F by 2: V - E + F drops by 2, one handle.
void Surface::build_tube(uint32_t a, uint32_t b, uint32_t twist) {
  const Face ring_a = faces_[a];
  const Face ring_b = faces_[b];
  set_face(a, {});
  set_face(b, {});
  for (uint32_t i = 0; i < 4; ++i) {
    const uint32_t k = (twist + 4 - i) % 4;
    add_face({ring_a[i], ring_a[(i + 1) % 4], ring_b[k], ring_b[(k + 1) % 4]});
    ++valence_[ring_a[i]];
    ++valence_[ring_b[i]];
  }
}

// A face with no vertex on a boundary is surrounded by closed fans; removing
// it opens each fan once, so its cycle becomes exactly one new boundary loop
// and the surface stays connected and manifold. V - E + F drops by 1.
bool Surface::cut_hole(SplitMix64* rng) {
  const uint32_t n = static_cast<uint32_t>(faces_.size());
  const uint32_t start = rng->below(n);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t f = (start + i) % n;
    if (faces_[f].empty() || touches_boundary(faces_[f])) continue;
    for (uint32_t v : faces_[f]) on_boundary_[v] = true;
    set_face(f, {});
    return true;
  }
  return false;
}

// Replaces face f by (f[i] .. f[j]) and (f[j] .. f[i]) along the new edge
// f[i]-f[j], which the caller checked is not an edge yet. The two parts use
// it in opposite directions; V - E + F is unchanged.
void Surface::split_at(uint32_t f, size_t i, size_t j) {
  const Face face = faces_[f];
  Face first;
  Face second;
  for (size_t c = i;; c = (c + 1) % face.size()) {
    first.push_back(face[c]);
    if (c == j) break;
  }
  for (size_t c = j;; c = (c + 1) % face.size()) {
    second.push_back(face[c]);
    if (c == i) break;
  }
  set_face(f, std::move(first));
  add_face(std::move(second));
  ++valence_[face[i]];
  ++valence_[face[j]];
}

// Only used when max_degree is 3, right after the handles and holes, when
// every face is a quad.
bool Surface::triangulate(SplitMix64* rng) {
  const uint32_t n = static_cast<uint32_t>(faces_.size());
  for (uint32_t f = 0; f < n; ++f) {
    if (faces_[f].empty()) continue;
    const size_t first = rng->below(2);
    size_t start = first;
    if (adjacent(faces_[f][start], faces_[f][start + 2])) start = 1 - first;
    if (adjacent(faces_[f][start], faces_[f][start + 2])) return false;
    split_at(f, start, start + 2);
  }
  return true;
}

// Both parts keep at least min_degree corners: the first part has m + 1 of
// them, the second d - m + 1.
void Surface::try_split(SplitMix64* rng, int min_degree) {
  const uint32_t f = random_face(rng);
  const int degree = static_cast<int>(faces_[f].size());
  if (degree < 2 * min_degree - 2) return;
  const size_t i = rng->below(static_cast<uint32_t>(degree));
  const size_t m = static_cast<size_t>(min_degree - 1) + rng->below(static_cast<uint32_t>(degree + 3 - 2 * min_degree));
  const size_t j = (i + m) % static_cast<size_t>(degree);
  if (adjacent(faces_[f][i], faces_[f][j])) return;  // would be a second u-v edge
  split_at(f, i, j);
}

// Removes the interior edge u-v between faces f and g. Because f and g share
// no vertex but u and v, the merged cycle (f from v to u, then g from u to v)
// repeats no vertex, and around u and v the two faces were neighbours in one
// fan, which they remain as one face. Requiring valence >= 4 at u and v keeps
// every vertex at valence >= 3, so valence-2 vertices come only from
// try_insert_valence_two. V - E + F is unchanged; boundaries are untouched.
void Surface::try_merge(SplitMix64* rng, int max_degree) {
  const uint32_t f = random_face(rng);
  const Face& face_f = faces_[f];
  if (face_f.empty()) return;
  const size_t i = rng->below(static_cast<uint32_t>(face_f.size()));
  const uint32_t u = face_f[i];
  const uint32_t v = face_f[(i + 1) % face_f.size()];
  const uint32_t g = face_across(u, v);
  if (g == kNoFace || g == f) return;
  const Face& face_g = faces_[g];
  if (face_f.size() + face_g.size() - 2 > static_cast<size_t>(max_degree)) return;
  if (valence_[u] < 4 || valence_[v] < 4) return;
  const auto shared = std::count_if(face_f.begin(), face_f.end(),
                                    [&face_g](uint32_t x) { return std::find(face_g.begin(), face_g.end(), x) != face_g.end(); });
  if (shared != 2) return;
  Face merged;
  for (size_t c = 0; c < face_f.size(); ++c) merged.push_back(face_f[(i + 1 + c) % face_f.size()]);  // v .. u
  const size_t at_u = static_cast<size_t>(std::find(face_g.begin(), face_g.end(), u) - face_g.begin());
  for (size_t c = 1; c + 1 < face_g.size(); ++c) merged.push_back(face_g[(at_u + c) % face_g.size()]);  // after u, before v
  set_face(g, {});
  set_face(f, std::move(merged));
  --valence_[u];
  --valence_[v];
}

// Puts a new vertex w in the middle of an interior edge u-v: f becomes
// (.. u w v ..), g becomes (.. v w u ..). w's two faces form a closed fan,
// each face gains exactly one corner (never above max_degree, never twice),
// V and E grow by 1.
bool Surface::try_insert_valence_two(SplitMix64* rng, int max_degree) {
  const uint32_t f = random_face(rng);
  const Face& face_f = faces_[f];
  if (face_f.empty() || raised_[f] || face_f.size() >= static_cast<size_t>(max_degree)) return false;
  const size_t i = rng->below(static_cast<uint32_t>(face_f.size()));
  const uint32_t u = face_f[i];
  const uint32_t v = face_f[(i + 1) % face_f.size()];
  const uint32_t g = face_across(u, v);
  if (g == kNoFace || g == f || raised_[g] || faces_[g].size() >= static_cast<size_t>(max_degree)) return false;
  const uint32_t w = static_cast<uint32_t>(valence_.size());
  for (int axis = 0; axis < 3; ++axis) positions_.push_back((positions_[3 * size_t{u} + axis] + positions_[3 * size_t{v} + axis]) * 0.5f);
  valence_.push_back(2);
  on_boundary_.push_back(false);
  Face new_f = face_f;
  new_f.insert(new_f.begin() + static_cast<std::ptrdiff_t>(i) + 1, w);
  Face new_g = faces_[g];
  const auto at_v = std::find(new_g.begin(), new_g.end(), v);
  new_g.insert(at_v + 1, w);
  set_face(f, std::move(new_f));
  set_face(g, std::move(new_g));
  raised_[f] = raised_[g] = true;
  return true;
}

// ---------------------------------------------------------------------------
// Components.

int sphere_resolution(int target_faces) {
  int k = 2;
  while (k < 64 && 6 * (k + 1) * (k + 1) <= target_faces + target_faces / 4) ++k;
  return k;
}

// Random splits and merges, leaning towards splits below the target face
// count and towards merges above it, so the count stays near the target while
// degrees spread over the whole range.
void vary_degrees(Surface* surface, const Settings& s, SplitMix64* rng) {
  const size_t attempts = 2 * surface->face_count();
  for (size_t a = 0; a < attempts; ++a) {
    const bool below_target = surface->face_count() < static_cast<size_t>(s.target_faces);
    if (rng->below(3) < (below_target ? 2u : 1u)) {
      surface->try_split(rng, s.min_degree);
    } else {
      surface->try_merge(rng, s.max_degree);
    }
  }
}

void insert_valence_two_vertices(Surface* surface, const Settings& s, SplitMix64* rng) {
  const uint32_t wanted = 1 + rng->below(1 + static_cast<uint32_t>(surface->face_count() / 20));
  uint32_t inserted = 0;
  for (uint32_t a = 0; a < 16 * wanted && inserted < wanted; ++a) inserted += surface->try_insert_valence_two(rng, s.max_degree) ? 1 : 0;
}

// Empty when a handle or hole has no valid place on this sphere.
std::optional<Surface> try_build_component(const Settings& s, int resolution, SplitMix64* rng) {
  Surface surface(tools::make_quad_sphere(resolution));
  for (int h = 0; h < s.genus; ++h) {
    if (!surface.add_handle(rng)) return std::nullopt;
  }
  for (int h = 0; h < s.holes; ++h) {
    if (!surface.cut_hole(rng)) return std::nullopt;
  }
  if (s.max_degree == 3 && !surface.triangulate(rng)) return std::nullopt;
  vary_degrees(&surface, s, rng);
  if (s.valence_two) insert_valence_two_vertices(&surface, s, rng);
  return surface;
}

Surface build_component(const Settings& s, SplitMix64* rng) {
  for (int k = sphere_resolution(s.target_faces);; ++k) {
    if (auto surface = try_build_component(s, k, rng)) return std::move(*surface);
  }
}

// ---------------------------------------------------------------------------
// The whole mesh as vertex cycles, before the final shuffle.

struct Soup {
  std::vector<float> positions;
  std::vector<Face> faces;
  std::vector<uint32_t> component_start;  // first vertex of each component

  uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size() / 3); }
  uint32_t add_random_vertex(SplitMix64* rng) {
    for (int axis = 0; axis < 3; ++axis) positions.push_back(rng->coordinate());
    return vertex_count() - 1;
  }
};

// Components side by side along x (geometry is irrelevant, but it keeps
// them visually apart).
void append_component(const Surface& surface, int index, Soup* soup) {
  const uint32_t offset = soup->vertex_count();
  soup->component_start.push_back(offset);
  for (size_t i = 0; i < surface.positions().size(); ++i) {
    soup->positions.push_back(surface.positions()[i] + (i % 3 == 0 ? 3.0f * static_cast<float>(index) : 0.0f));
  }
  for (const Face& face : surface.faces()) {
    if (face.empty()) continue;
    soup->faces.push_back(face);
    for (uint32_t& v : soup->faces.back()) v += offset;
  }
}

// ---------------------------------------------------------------------------
// Non-manifold defects. Each one uses only vertices that no earlier defect
// touched, so none can undo or hide another.

class DefectMaker {
 public:
  DefectMaker(Soup* soup, SplitMix64* rng) : soup_(soup), rng_(rng), touched_(soup->vertex_count(), false) {}

  bool add(uint32_t kind) {
    switch (kind) {
      case 0: return add_book_face();
      case 1: return pinch_vertices();
      case 2: return change_face([](Face* face) { std::reverse(face->begin(), face->end()); });
      case 3: return change_face([this](Face* face) {
        Face copy = *face;  // push_back may move *face
        soup_->faces.push_back(std::move(copy));
      });
      default: return add_repeated_vertex_face();
    }
  }

 private:
  // First index from a random start for which `usable` holds, or n.
  template <class Predicate>
  uint32_t scan(uint32_t n, Predicate usable) {
    const uint32_t start = rng_->below(n);
    for (uint32_t i = 0; i < n; ++i) {
      if (usable((start + i) % n)) return (start + i) % n;
    }
    return n;
  }

  bool untouched(const Face& face) const {
    return std::none_of(face.begin(), face.end(), [this](uint32_t v) { return touched_[v]; });
  }
  void touch(const Face& face) {
    for (uint32_t v : face) touched_[v] = true;
  }
  uint32_t add_vertex() {
    touched_.push_back(true);
    return soup_->add_random_vertex(rng_);
  }

  template <class Change>
  bool change_face(Change change) {
    const uint32_t n = static_cast<uint32_t>(soup_->faces.size());
    const uint32_t f = scan(n, [this](uint32_t f) { return untouched(soup_->faces[f]); });
    if (f == n) return false;
    touch(soup_->faces[f]);
    change(&soup_->faces[f]);
    return true;
  }

  // A third face on an interior edge (one whose reverse is also used).
  bool add_book_face() {
    std::map<uint64_t, int> used;
    for (const Face& face : soup_->faces) {
      for (size_t i = 0; i < face.size(); ++i) ++used[half_edge_key(face[i], face[(i + 1) % face.size()])];
    }
    const uint32_t n = static_cast<uint32_t>(soup_->faces.size());
    const uint32_t f = scan(n, [&](uint32_t f) {
      const Face& face = soup_->faces[f];
      return untouched(face) && used.count(half_edge_key(face[1], face[0])) != 0;
    });
    if (f == n) return false;
    const Face& face = soup_->faces[f];
    const Face book = {face[1], face[0], add_vertex()};
    touch(face);
    soup_->faces.push_back(book);
    return true;
  }

  // Identifies two vertices with no common neighbour and no common face, in
  // different components when there are several: their fans then meet at
  // one vertex without sharing an edge.
  bool pinch_vertices() {
    const std::vector<std::vector<uint32_t>> neighbours = neighbour_lists();
    const uint32_t n = soup_->vertex_count();
    const bool several = soup_->component_start.size() > 1;
    auto component = [this](uint32_t v) {
      return std::upper_bound(soup_->component_start.begin(), soup_->component_start.end(), v) - soup_->component_start.begin();
    };
    auto usable = [&](uint32_t v) { return !touched_[v] && !neighbours[v].empty(); };
    const uint32_t x = scan(n, usable);
    if (x == n) return false;
    const uint32_t y = scan(n, [&](uint32_t y) {
      return y != x && usable(y) && (component(y) != component(x) || !several) && far_apart(neighbours, x, y);
    });
    if (y == n) return false;
    for (Face& face : soup_->faces) std::replace(face.begin(), face.end(), y, x);
    touched_[x] = touched_[y] = true;
    return true;
  }

  // Neighbours here include every vertex sharing a face, so "far apart"
  // also rules out a common face.
  std::vector<std::vector<uint32_t>> neighbour_lists() const {
    std::vector<std::vector<uint32_t>> lists(soup_->vertex_count());
    for (const Face& face : soup_->faces) {
      for (uint32_t a : face) lists[a].insert(lists[a].end(), face.begin(), face.end());
    }
    for (auto& list : lists) {
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return lists;
  }

  static bool far_apart(const std::vector<std::vector<uint32_t>>& neighbours, uint32_t x, uint32_t y) {
    const auto& nx = neighbours[x];
    const auto& ny = neighbours[y];
    if (std::binary_search(nx.begin(), nx.end(), y)) return false;
    return std::none_of(nx.begin(), nx.end(), [&ny](uint32_t v) { return std::binary_search(ny.begin(), ny.end(), v); });
  }

  // (a b a c): a listed twice, not in adjacent corners.
  bool add_repeated_vertex_face() {
    const uint32_t n = soup_->vertex_count();
    const uint32_t a = scan(n, [this](uint32_t v) { return !touched_[v]; });
    if (a == n) return false;
    touched_[a] = true;
    const uint32_t b = add_vertex();
    const uint32_t c = add_vertex();
    soup_->faces.push_back({a, b, a, c});
    return true;
  }

  Soup* soup_;
  SplitMix64* rng_;
  std::vector<bool> touched_;
};

int add_defects(Soup* soup, SplitMix64* rng) {
  DefectMaker maker(soup, rng);
  const int wanted = 1 + static_cast<int>(rng->below(3));
  int added = 0;
  for (int attempt = 0; attempt < 4 * wanted && added < wanted; ++attempt) added += maker.add(rng->below(5)) ? 1 : 0;
  // Nothing is touched yet, so the repeated-vertex face always fits.
  if (added == 0) added += maker.add(4) ? 1 : 0;
  return added;
}

// Drops vertices that pinching left without faces.
void remove_unused_vertices(Soup* soup) {
  std::vector<uint32_t> new_index(soup->vertex_count(), kNoFace);
  for (const Face& face : soup->faces) {
    for (uint32_t v : face) new_index[v] = 0;
  }
  std::vector<float> positions;
  for (uint32_t v = 0; v < soup->vertex_count(); ++v) {
    if (new_index[v] == kNoFace) continue;
    new_index[v] = static_cast<uint32_t>(positions.size() / 3);
    positions.insert(positions.end(), soup->positions.begin() + 3 * v, soup->positions.begin() + 3 * v + 3);
  }
  for (Face& face : soup->faces) {
    for (uint32_t& v : face) v = new_index[v];
  }
  soup->positions = std::move(positions);
}

// Random vertex order, face order and starting corners.
Mesh shuffled_mesh(const Soup& soup, SplitMix64* rng) {
  std::vector<uint32_t> order(soup.vertex_count());
  for (uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  shuffle(&order, rng);
  std::vector<uint32_t> new_index(order.size());
  Mesh mesh;
  for (uint32_t i = 0; i < order.size(); ++i) {
    new_index[order[i]] = i;
    mesh.positions.insert(mesh.positions.end(), soup.positions.begin() + 3 * order[i], soup.positions.begin() + 3 * order[i] + 3);
  }
  std::vector<uint32_t> face_order(soup.faces.size());
  for (uint32_t f = 0; f < face_order.size(); ++f) face_order[f] = f;
  shuffle(&face_order, rng);
  for (uint32_t f : face_order) {
    const Face& face = soup.faces[f];
    const size_t start = rng->below(static_cast<uint32_t>(face.size()));
    mesh.face_sizes.push_back(static_cast<uint32_t>(face.size()));
    for (size_t c = 0; c < face.size(); ++c) mesh.corners.push_back(new_index[face[(start + c) % face.size()]]);
  }
  return mesh;
}

}  // namespace

Mesh make_random_polygon_mesh(const RandomPolygonMeshOptions& options, RandomPolygonMeshInfo* info) {
  const Settings s = settings_from(options);
  SplitMix64 rng(options.seed);
  Soup soup;
  for (int c = 0; c < s.components; ++c) append_component(build_component(s, &rng), c, &soup);
  const int defects = s.non_manifold ? add_defects(&soup, &rng) : 0;
  remove_unused_vertices(&soup);
  for (int i = 0; i < s.isolated_vertices; ++i) soup.add_random_vertex(&rng);
  if (info != nullptr) {
    info->components = s.components;
    info->genus_per_component = s.genus;
    info->boundary_loops = s.components * s.holes;
    info->non_manifold_defects = defects;
  }
  return shuffled_mesh(soup, &rng);
}

}  // namespace qmc
