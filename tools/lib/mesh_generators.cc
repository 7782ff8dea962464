// qmc tools: synthetic meshes. See mesh_generators.h for the determinism
// rules every function here follows.
#include "mesh_generators.h"

#include "splitmix64.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <unordered_map>
#include <utility>
#include <vector>

#include "subdivision.h"

namespace qmc::tools {
namespace {

using qmc::Mesh;

void add_vertex(Mesh* mesh, float x, float y, float z) {
  mesh->positions.push_back(x);
  mesh->positions.push_back(y);
  mesh->positions.push_back(z);
}

void add_face(Mesh* mesh, std::initializer_list<uint32_t> corners) {
  mesh->face_sizes.push_back(static_cast<uint32_t>(corners.size()));
  mesh->corners.insert(mesh->corners.end(), corners.begin(), corners.end());
}

// ---------------------------------------------------------------------------
// Sine and cosine from integer arithmetic. libm's sin/cos differ in the last
// bit between platforms, and the compiler may fuse float multiply-adds
// differently, so angles are evaluated in Q30 fixed point, where every
// operation is exact and identical everywhere.

constexpr int64_t kOne = int64_t{1} << 30;
constexpr int64_t kHalfPi = 1686629713;  // round(pi/2 * 2^30)

int64_t mul_q30(int64_t a, int64_t b) { return (a * b) >> 30; }  // a, b in [0, 2^31)

// Taylor series in Horner form for 0 <= x <= pi/4 (Q30 radians); the first
// omitted terms are below 2^-32.
void sin_cos_q30(int64_t x, int64_t* sine, int64_t* cosine) {
  const int64_t x2 = mul_q30(x, x);
  int64_t t = kOne - x2 / 110;
  for (int64_t divisor : {72, 42, 20, 6}) t = kOne - mul_q30(x2, t) / divisor;
  *sine = mul_q30(x, t);
  t = kOne - x2 / 132;
  for (int64_t divisor : {90, 56, 30, 12, 2}) t = kOne - mul_q30(x2, t) / divisor;
  *cosine = t;
}

struct UnitVector {
  float c, s;
};

// cos and sin of 2*pi*k/n, exact at multiples of a quarter turn.
UnitVector unit_circle(uint64_t k, uint64_t n) {
  const uint64_t turns = ((k % n) << 32) / n;  // Q32 fraction of a full turn
  const uint64_t quadrant = turns >> 30;
  int64_t within = static_cast<int64_t>(turns & (kOne - 1));  // Q30 fraction of a quarter turn
  const bool mirrored = within > kOne / 2;  // use sin(pi/2 - x) = cos(x) to stay below pi/4
  if (mirrored) within = kOne - within;
  int64_t s = 0;
  int64_t c = 0;
  sin_cos_q30(mul_q30(within, kHalfPi), &s, &c);
  if (mirrored) std::swap(s, c);
  int64_t rotated_c = c;
  int64_t rotated_s = s;
  if (quadrant == 1) {
    rotated_c = -s;
    rotated_s = c;
  } else if (quadrant == 2) {
    rotated_c = -c;
    rotated_s = -s;
  } else if (quadrant == 3) {
    rotated_c = s;
    rotated_s = -c;
  }
  // int64 -> float rounds the same everywhere; scaling by 2^-30 is exact.
  const float scale = 1.0f / static_cast<float>(kOne);
  return {static_cast<float>(rotated_c) * scale, static_cast<float>(rotated_s) * scale};
}

// a*b + c*d rounded to float. Products of two floats are exact in double, so
// whether the compiler fuses them into an FMA cannot change the result. (A
// lone float product needs no such care: nothing is there to fuse it with.)
float sum_of_products(float a, float b, float c, float d) {
  return static_cast<float>(static_cast<double>(a) * b + static_cast<double>(c) * d);
}

// ---------------------------------------------------------------------------
// Exact arithmetic in Z[phi], phi the golden ratio (phi^2 = phi + 1): the
// icosahedron's coordinates, and the sums and dot products built from them,
// are a + b*phi with small integers a, b. Topology and squared lengths are
// decided exactly; only the final normalisation rounds, and it evaluates
// b*phi by repeated addition so no product exists that a compiler could
// fuse into a multiply-add.

struct Golden {
  int64_t a = 0, b = 0;  // a + b*phi

  Golden operator+(Golden o) const { return {a + o.a, b + o.b}; }
  Golden operator-(Golden o) const { return {a - o.a, b - o.b}; }
  Golden operator*(Golden o) const { return {a * o.a + b * o.b, a * o.b + b * o.a + b * o.b}; }
  bool operator==(Golden o) const { return a == o.a && b == o.b; }

  double value() const {
    constexpr double kPhi = 1.6180339887498948482;
    double multiple = 0;
    for (int64_t i = 0; i < (b < 0 ? -b : b); ++i) multiple += kPhi;
    return (b < 0 ? -multiple : multiple) + static_cast<double>(a);
  }
};

struct GoldenVector {
  Golden c[3];

  GoldenVector operator+(const GoldenVector& o) const { return {{c[0] + o.c[0], c[1] + o.c[1], c[2] + o.c[2]}}; }
  GoldenVector operator-(const GoldenVector& o) const { return {{c[0] - o.c[0], c[1] - o.c[1], c[2] - o.c[2]}}; }
  Golden dot(const GoldenVector& o) const { return c[0] * o.c[0] + c[1] * o.c[1] + c[2] * o.c[2]; }
  GoldenVector cross(const GoldenVector& o) const {
    return {{c[1] * o.c[2] - c[2] * o.c[1], c[2] * o.c[0] - c[0] * o.c[2], c[0] * o.c[1] - c[1] * o.c[0]}};
  }
};

void add_unit_vertex(Mesh* mesh, const GoldenVector& direction) {
  const double length = std::sqrt(direction.dot(direction).value());
  for (const Golden& coordinate : direction.c) mesh->positions.push_back(static_cast<float>(coordinate.value() / length));
}

// x / |x| for a float vector; x*x is exact in double, so fusing it into the
// following addition changes nothing.
void project_to_unit_sphere(Mesh* mesh) {
  for (size_t v = 0; v < mesh->vertex_count(); ++v) {
    float* p = &mesh->positions[3 * v];
    const double x = p[0], y = p[1], z = p[2];
    const double length = std::sqrt(x * x + y * y + z * z);
    if (length == 0) continue;
    for (int axis = 0; axis < 3; ++axis) p[axis] = static_cast<float>(static_cast<double>(p[axis]) / length);
  }
}

template <class T>
void shuffle(std::vector<T>* items, SplitMix64* rng) {
  for (size_t i = items->size(); i > 1; --i) std::swap((*items)[i - 1], (*items)[rng->below(static_cast<uint32_t>(i))]);
}

// Picks the corners of one soup face. Vertices not yet used by any face are
// handed out first (spread evenly over the remaining faces) so that only the
// designated unreferenced vertices stay unused.
class SoupCornerPicker {
 public:
  SoupCornerPicker(std::vector<uint32_t> pool, uint32_t vertex_count)
      : pool_(std::move(pool)), used_(vertex_count, false), unused_(pool_.size()) {}

  void pick(uint32_t distinct, uint64_t faces_left, SplitMix64* rng, std::vector<uint32_t>* face) {
    face->clear();
    uint64_t fresh = std::min<uint64_t>(distinct, (unused_ + faces_left - 1) / faces_left);
    for (uint64_t i = 0; i < fresh; ++i) {
      while (used_[pool_[next_fresh_]]) ++next_fresh_;
      face->push_back(use(pool_[next_fresh_]));
    }
    while (face->size() < distinct) {
      uint32_t vertex = pool_[rng->below(static_cast<uint32_t>(pool_.size()))];
      bool repeat = std::find(face->begin(), face->end(), vertex) != face->end();
      if (repeat && face->size() < pool_.size()) continue;  // repeats only when the pool is exhausted
      face->push_back(use(vertex));
    }
    shuffle(face, rng);
  }

 private:
  uint32_t use(uint32_t vertex) {
    if (!used_[vertex]) {
      used_[vertex] = true;
      --unused_;
    }
    return vertex;
  }

  std::vector<uint32_t> pool_;  // vertices faces may use, in random order
  std::vector<bool> used_;
  uint64_t unused_;
  size_t next_fresh_ = 0;
};

}  // namespace

Mesh make_octahedron() {
  Mesh mesh;
  const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& a : axes) add_vertex(&mesh, a[0], a[1], a[2]);
  // Around +z then -z, counter-clockwise seen from outside.
  const uint32_t ring[4] = {0, 2, 1, 3};
  for (int i = 0; i < 4; ++i) {
    add_face(&mesh, {4, ring[i], ring[(i + 1) % 4]});
    add_face(&mesh, {5, ring[(i + 1) % 4], ring[i]});
  }
  return mesh;
}

Mesh triangulated(const Mesh& mesh, size_t* polygons_split) {
  Mesh out;
  out.positions = mesh.positions;
  size_t split = 0, first = 0;
  for (uint32_t d : mesh.face_sizes) {
    split += d > 3;
    for (uint32_t k = 1; k + 1 < d; ++k) add_face(&out, {mesh.corners[first], mesh.corners[first + k], mesh.corners[first + k + 1]});
    first += d;
  }
  if (polygons_split) *polygons_split = split;
  return out;
}

Mesh make_tetrahedron() {
  Mesh mesh;
  add_vertex(&mesh, 1, 1, 1);
  add_vertex(&mesh, 1, -1, -1);
  add_vertex(&mesh, -1, 1, -1);
  add_vertex(&mesh, -1, -1, 1);
  add_face(&mesh, {0, 1, 2});
  add_face(&mesh, {0, 3, 1});
  add_face(&mesh, {0, 2, 3});
  add_face(&mesh, {1, 3, 2});
  return mesh;
}

Mesh make_cube() {
  Mesh mesh;
  // Vertex i has x, y, z = bits 0, 1, 2 of i.
  for (int i = 0; i < 8; ++i) add_vertex(&mesh, (i & 1) ? 1.f : -1.f, (i & 2) ? 1.f : -1.f, (i & 4) ? 1.f : -1.f);
  add_face(&mesh, {0, 4, 6, 2});  // -x
  add_face(&mesh, {1, 3, 7, 5});  // +x
  add_face(&mesh, {0, 1, 5, 4});  // -y
  add_face(&mesh, {2, 6, 7, 3});  // +y
  add_face(&mesh, {0, 2, 3, 1});  // -z
  add_face(&mesh, {4, 5, 7, 6});  // +z
  return mesh;
}

Mesh make_quad_sphere(int n) {
  const int64_t size = std::max(n, 1);
  Mesh mesh;
  // Vertices are lattice points of the subdivided cube surface, welded by
  // lattice position and numbered in order of first use.
  std::unordered_map<int64_t, uint32_t> index_of;
  auto vertex = [&](int64_t lattice[3]) {
    int64_t key = (lattice[0] * (size + 1) + lattice[1]) * (size + 1) + lattice[2];
    auto [it, inserted] = index_of.try_emplace(key, static_cast<uint32_t>(mesh.vertex_count()));
    if (inserted) {
      // Centered integer coordinates; sqrt and division are correctly
      // rounded, so the projection is the same everywhere.
      int64_t c[3] = {2 * lattice[0] - size, 2 * lattice[1] - size, 2 * lattice[2] - size};
      double length = std::sqrt(static_cast<double>(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
      for (int64_t value : c) mesh.positions.push_back(static_cast<float>(static_cast<double>(value) / length));
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    // (u, v) along axes b, c with e_b x e_c = e_axis: counter-clockwise seen
    // from +axis, so the + side keeps the order and the - side reverses it.
    const int b = (axis + 1) % 3;
    const int c = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int64_t v = 0; v < size; ++v) {
        for (int64_t u = 0; u < size; ++u) {
          uint32_t quad[4];
          const int64_t du[4] = {0, 1, 1, 0};
          const int64_t dv[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            int64_t lattice[3];
            lattice[axis] = side == 0 ? 0 : size;
            lattice[b] = u + du[k];
            lattice[c] = v + dv[k];
            quad[k] = vertex(lattice);
          }
          if (side == 1) {
            add_face(&mesh, {quad[0], quad[1], quad[2], quad[3]});
          } else {
            add_face(&mesh, {quad[0], quad[3], quad[2], quad[1]});
          }
        }
      }
    }
  }
  return mesh;
}

Mesh make_torus(int major, int minor, float R, float r) {
  const uint32_t around = static_cast<uint32_t>(std::max(major, 3));
  const uint32_t tube = static_cast<uint32_t>(std::max(minor, 3));
  Mesh mesh;
  for (uint32_t i = 0; i < around; ++i) {
    const UnitVector u = unit_circle(i, around);
    for (uint32_t j = 0; j < tube; ++j) {
      const UnitVector v = unit_circle(j, tube);
      const float ring = sum_of_products(R, 1.f, r, v.c);  // distance from the z axis
      add_vertex(&mesh, ring * u.c, ring * u.s, r * v.s);
    }
  }
  for (uint32_t i = 0; i < around; ++i) {
    const uint32_t next_i = (i + 1) % around;
    for (uint32_t j = 0; j < tube; ++j) {
      const uint32_t next_j = (j + 1) % tube;
      add_face(&mesh, {i * tube + j, next_i * tube + j, next_i * tube + next_j, i * tube + next_j});
    }
  }
  return mesh;
}

Mesh make_terraces(uint32_t n, uint32_t steps, uint64_t seed) {
  n = std::max<uint32_t>(n, 1);
  steps = std::max<uint32_t>(steps, 1);
  Mesh mesh;
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) {
      const int64_t di = 2 * int64_t{i} - n, dj = 2 * int64_t{j} - n;
      const int64_t level = (di * di + dj * dj) * steps / (2 * int64_t{n} * n);
      add_vertex(&mesh, float(i) / float(n), float(j) / float(n), float(level) / float(4 * steps));
    }
  SplitMix64 random(seed);
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if (random.next() % 2) {
        add_face(&mesh, {a, b, d});
        add_face(&mesh, {a, d, c});
      } else {
        add_face(&mesh, {a, b, c});
        add_face(&mesh, {b, d, c});
      }
    }
  return mesh;
}

Mesh make_grid(int nx, int ny) {
  const uint32_t cols = static_cast<uint32_t>(std::max(nx, 1));
  const uint32_t rows = static_cast<uint32_t>(std::max(ny, 1));
  Mesh mesh;
  for (uint32_t j = 0; j <= rows; ++j) {
    for (uint32_t i = 0; i <= cols; ++i) {
      // x = (2i - cols) / cols; bump = (1 - x^2) in [0, 1], likewise for y,
      // each one correctly rounded division of exact integers.
      const int64_t sx = 2 * int64_t{i} - cols;
      const int64_t sy = 2 * int64_t{j} - rows;
      const float x = static_cast<float>(static_cast<double>(sx) / cols);
      const float y = static_cast<float>(static_cast<double>(sy) / rows);
      const float bump_x = static_cast<float>(static_cast<double>(int64_t{cols} * cols - sx * sx) / (double(cols) * cols));
      const float bump_y = static_cast<float>(static_cast<double>(int64_t{rows} * rows - sy * sy) / (double(rows) * rows));
      const float z = bump_x * bump_y * 0.125f;  // the last factor is a power of two: exact
      add_vertex(&mesh, x, y, z);
    }
  }
  const uint32_t stride = cols + 1;
  for (uint32_t j = 0; j < rows; ++j) {
    for (uint32_t i = 0; i < cols; ++i) {
      const uint32_t corner = j * stride + i;
      add_face(&mesh, {corner, corner + 1, corner + 1 + stride, corner + stride});
    }
  }
  return mesh;
}

Mesh make_bent_grid(int nx, int ny) {
  Mesh m = make_grid(nx, ny);
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    const float x = m.positions[i], y = m.positions[i + 1];
    m.positions[i] = x + 0.125f * x * x;
    m.positions[i + 1] = y + 0.0625f * x * y;
  }
  return m;
}

Mesh make_prism(int n) {
  const uint32_t sides = static_cast<uint32_t>(std::max(n, 3));
  Mesh mesh;
  for (int level = 0; level < 2; ++level) {
    for (uint32_t k = 0; k < sides; ++k) {
      const UnitVector p = unit_circle(k, sides);
      add_vertex(&mesh, p.c, p.s, level == 0 ? -1.f : 1.f);
    }
  }
  for (uint32_t k = 0; k < sides; ++k) {
    const uint32_t next = (k + 1) % sides;
    add_face(&mesh, {k, next, sides + next, sides + k});
  }
  // Bottom cap clockwise seen from +z (outward is -z), top counter-clockwise.
  mesh.face_sizes.push_back(sides);
  for (uint32_t k = sides; k > 0; --k) mesh.corners.push_back(k - 1);
  mesh.face_sizes.push_back(sides);
  for (uint32_t k = 0; k < sides; ++k) mesh.corners.push_back(sides + k);
  return mesh;
}

Mesh make_polygon(uint32_t corners) {
  const uint32_t n = std::max<uint32_t>(corners, 3);
  Mesh mesh;
  for (uint32_t k = 0; k < n; ++k) {
    const UnitVector p = unit_circle(k, n);
    add_vertex(&mesh, p.c, p.s, 0.f);
  }
  mesh.face_sizes.push_back(n);
  for (uint32_t k = 0; k < n; ++k) mesh.corners.push_back(k);
  return mesh;
}

Mesh make_book(uint32_t pages) {
  const uint32_t n = std::max<uint32_t>(pages, 1);
  Mesh mesh;
  add_vertex(&mesh, 0.f, 0.f, -1.f);
  add_vertex(&mesh, 0.f, 0.f, 1.f);
  for (uint32_t k = 0; k < n; ++k) {
    const UnitVector p = unit_circle(k, n);
    add_vertex(&mesh, p.c, p.s, 0.f);
    add_face(&mesh, {0, 1, k + 2});
  }
  return mesh;
}

Mesh make_vertex_star(uint32_t triangles) {
  const uint32_t n = std::max<uint32_t>(triangles, 1);
  Mesh mesh;
  add_vertex(&mesh, 0.f, 0.f, 0.f);
  for (uint32_t k = 0; k < n; ++k) {
    const UnitVector p = unit_circle(2 * k, 2 * n), q = unit_circle(2 * k + 1, 2 * n);
    add_vertex(&mesh, p.c, p.s, 0.f);
    add_vertex(&mesh, q.c, q.s, 0.f);
    add_face(&mesh, {0, 2 * k + 1, 2 * k + 2});
  }
  return mesh;
}

Mesh make_mirrored_across_x(Mesh m, float near) {
  const size_t n = m.vertex_count();
  for (size_t v = 0; v < n; ++v)
    if (std::fabs(m.positions[3 * v]) < near) m.positions[3 * v] = 0;
  const std::vector<float> before = m.positions;
  for (size_t v = 0; v < n; ++v) {
    if (before[3 * v] >= 0) continue;
    size_t twin = v;
    float best = INFINITY;
    for (size_t w = 0; w < n; ++w) {
      if (before[3 * w] <= 0) continue;
      const float dx = before[3 * w] + before[3 * v], dy = before[3 * w + 1] - before[3 * v + 1],
                  dz = before[3 * w + 2] - before[3 * v + 2];
      if (dx * dx + dy * dy + dz * dz < best) {
        best = dx * dx + dy * dy + dz * dz;
        twin = w;
      }
    }
    m.positions[3 * v] = -before[3 * twin];
    m.positions[3 * v + 1] = before[3 * twin + 1];
    m.positions[3 * v + 2] = before[3 * twin + 2];
  }
  return m;
}

Mesh make_deltoidal_hexecontahedron() {
  // Icosahedron: cyclic permutations of (0, +-1, +-phi); edges have squared
  // length exactly 4, non-edges more.
  std::vector<GoldenVector> ico;
  for (int rotation = 0; rotation < 3; ++rotation) {
    for (int s1 : {1, -1}) {
      for (int s2 : {1, -1}) {
        GoldenVector p;
        p.c[(rotation + 1) % 3] = {s1, 0};
        p.c[(rotation + 2) % 3] = {0, s2};
        ico.push_back(p);
      }
    }
  }
  const Golden kEdgeLength2{4, 0};
  auto adjacent = [&](size_t i, size_t j) { return (ico[i] - ico[j]).dot(ico[i] - ico[j]) == kEdgeLength2; };
  std::vector<std::vector<uint32_t>> triangles;
  for (uint32_t i = 0; i < 12; ++i) {
    for (uint32_t j = i + 1; j < 12; ++j) {
      if (!adjacent(i, j)) continue;
      for (uint32_t k = j + 1; k < 12; ++k) {
        if (!adjacent(i, k) || !adjacent(j, k)) continue;
        // Outward when the triple product is positive; it is +-(2 + 2 phi),
        // far from zero, so its rounded value has the right sign.
        const bool outward = ico[i].dot(ico[j].cross(ico[k])).value() > 0;
        triangles.push_back(outward ? std::vector<uint32_t>{i, j, k} : std::vector<uint32_t>{i, k, j});
      }
    }
  }

  Mesh mesh;
  for (const GoldenVector& p : ico) add_unit_vertex(&mesh, p);
  for (const auto& t : triangles) add_unit_vertex(&mesh, ico[t[0]] + ico[t[1]] + ico[t[2]]);
  // Edge vertices numbered by first appearance walking the triangles, as
  // Catmull-Clark numbers its edge points.
  std::vector<uint32_t> edge_index(12 * 12, 0);
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t a = t[i];
      const uint32_t b = t[(i + 1) % 3];
      if (edge_index[a * 12 + b] != 0) continue;
      edge_index[a * 12 + b] = edge_index[b * 12 + a] = static_cast<uint32_t>(mesh.vertex_count());
      add_unit_vertex(&mesh, ico[a] + ico[b]);
    }
  }
  for (uint32_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    for (int i = 0; i < 3; ++i) {
      const uint32_t v = t[i];
      const uint32_t next = t[(i + 1) % 3];
      const uint32_t prev = t[(i + 2) % 3];
      add_face(&mesh, {v, edge_index[v * 12 + next], static_cast<uint32_t>(ico.size()) + f, edge_index[prev * 12 + v]});
    }
  }
  return mesh;
}

Mesh make_refined_sphere(int levels) {
  Mesh mesh = make_deltoidal_hexecontahedron();
  for (int level = 0; level < std::clamp(levels, 0, 10); ++level) {
    Mesh finer;
    // Cannot fail: every step's input is a closed, oriented manifold.
    if (!catmull_clark(mesh, &finer).ok()) break;
    project_to_unit_sphere(&finer);
    mesh = std::move(finer);
  }
  return mesh;
}

Mesh make_jittered_sphere(int levels, float jitter, uint64_t seed) {
  Mesh sphere = triangulated(make_refined_sphere(levels));
  double length = 0;
  for (size_t k = 0; k < sphere.corners.size(); ++k) {
    const float* p = &sphere.positions[3 * size_t(sphere.corners[k])];
    const float* q = &sphere.positions[3 * size_t(sphere.corners[k % 3 == 2 ? k - 2 : k + 1])];
    length += std::sqrt(double((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                               (p[2] - q[2]) * (p[2] - q[2])));
  }
  const float amount = jitter * float(length / double(std::max<size_t>(sphere.corners.size(), 1)));
  SplitMix64 rng(seed);
  for (size_t v = 0; v < sphere.vertex_count(); ++v)
    for (int a = 0; a < 3; ++a) sphere.positions[3 * v + a] += amount * (float(rng.below(2001)) / 1000.f - 1.f);
  project_to_unit_sphere(&sphere);
  return sphere;
}

Mesh make_random_soup(uint64_t seed, const RandomSoupOptions& options) {
  SplitMix64 rng(seed);
  Mesh mesh;
  const uint32_t vertices = options.vertices;
  if (vertices == 0) return mesh;
  const uint32_t min_degree = std::max<uint32_t>(options.min_degree, 3);
  const uint32_t max_degree = std::max(options.max_degree, min_degree);

  for (uint32_t v = 0; v < vertices; ++v) {
    if (v > 0 && rng.below(16) == 0) {
      // Coincident positions on distinct vertices: a codec must keep both.
      const uint32_t twin = rng.below(v);
      for (int axis = 0; axis < 3; ++axis) mesh.positions.push_back(mesh.positions[3 * twin + axis]);
    } else {
      for (int axis = 0; axis < 3; ++axis) mesh.positions.push_back(rng.coordinate());
    }
  }
  if (options.faces == 0) return mesh;

  // A random permutation: the first `unreferenced` entries are never used,
  // the rest are the pool faces draw from.
  std::vector<uint32_t> order(vertices);
  for (uint32_t v = 0; v < vertices; ++v) order[v] = v;
  shuffle(&order, &rng);
  const uint32_t unreferenced = std::min(options.unreferenced, vertices - 1);
  SoupCornerPicker picker(std::vector<uint32_t>(order.begin() + unreferenced, order.end()), vertices);

  std::vector<uint32_t> face;
  for (uint32_t f = 0; f < options.faces; ++f) {
    const uint32_t degree = min_degree + rng.below(max_degree - min_degree + 1);
    const bool repeat = options.repeated_corners && (f == 0 || rng.below(5) == 0);
    picker.pick(repeat ? degree - 1 : degree, options.faces - f, &rng, &face);
    if (repeat) {
      const uint32_t copy = face[rng.below(static_cast<uint32_t>(face.size()))];
      face.insert(face.begin() + rng.below(static_cast<uint32_t>(face.size()) + 1), copy);
    }
    mesh.face_sizes.push_back(degree);
    mesh.corners.insert(mesh.corners.end(), face.begin(), face.end());
  }
  return mesh;
}

Mesh split_quad_with_doublet(Mesh mesh, size_t quad) {
  const uint32_t a = mesh.corners[4 * quad], c = mesh.corners[4 * quad + 2], d = mesh.corners[4 * quad + 3];
  const uint32_t v = static_cast<uint32_t>(mesh.vertex_count());
  for (int k = 0; k < 3; ++k) mesh.positions.push_back(0.5f * (mesh.positions[3 * a + k] + mesh.positions[3 * c + k]));
  mesh.corners[4 * quad + 3] = v;
  mesh.face_sizes.push_back(4);
  mesh.corners.insert(mesh.corners.end(), {a, v, c, d});
  return mesh;
}

// Fisher-Yates with splitmix64 (the same on every platform) over the vertex
// labels and the faces, then a random first corner per face.
qmc::Mesh make_scrambled(const qmc::Mesh& mesh, uint64_t seed) {
  SplitMix64 rng(seed);
  const uint32_t n = uint32_t(mesh.vertex_count()), faces = uint32_t(mesh.face_count());
  std::vector<uint32_t> label(n), order(faces);
  for (uint32_t i = 0; i < n; ++i) label[i] = i;
  for (uint32_t i = n; i > 1; --i) std::swap(label[i - 1], label[rng.below(i)]);
  for (uint32_t i = 0; i < faces; ++i) order[i] = i;
  for (uint32_t i = faces; i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  std::vector<size_t> offset(faces + 1, 0);
  for (uint32_t f = 0; f < faces; ++f) offset[f + 1] = offset[f] + mesh.face_sizes[f];
  qmc::Mesh out;
  out.positions.resize(mesh.positions.size());
  for (uint32_t v = 0; v < n; ++v)
    for (int a = 0; a < 3; ++a) out.positions[3 * size_t(label[v]) + a] = mesh.positions[3 * size_t(v) + a];
  for (uint32_t f : order) {
    const uint32_t d = mesh.face_sizes[f], r = rng.below(d);
    out.face_sizes.push_back(d);
    for (uint32_t k = 0; k < d; ++k) out.corners.push_back(label[mesh.corners[offset[f] + (k + r) % d]]);
  }
  return out;
}

}  // namespace qmc::tools
