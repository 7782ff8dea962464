// Known answers for the Metro-style surface distances of mesh_distance.h.
#include "mesh_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "mesh_generators.h"

namespace {

using qmc::Mesh;
using qmc::tools::fan_triangulate;
using qmc::tools::measure_mesh_distance;
using qmc::tools::MeshDistance;
using qmc::tools::MeshDistanceOptions;
using qmc::tools::point_triangle_distance_squared;
using qmc::tools::sample_surface;
using qmc::tools::SurfaceSample;
using qmc::tools::Triangle;
using qmc::tools::TriangleBvh;
using qmc::tools::Vec3d;

constexpr double kExact = 1e-12;  // "exact up to rounding" for unit-sized meshes

MeshDistance measure(const Mesh& a, const Mesh& b, size_t samples = 200000, uint64_t seed = 1) {
  MeshDistanceOptions options;
  options.samples = samples;
  options.seed = seed;
  MeshDistance d;
  const qmc::Status s = measure_mesh_distance(a, b, options, &d);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return d;
}

// Axis-aligned cube [-h, h]^3 as six quads. With fan_top the top face (z = h)
// is instead four triangles around an extra vertex at its centre, and with
// open_top those four triangles are left out: a cube with a square hole.
Mesh box(float h, bool fan_top = false, bool open_top = false) {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.positions.insert(m.positions.end(), {i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {1, 3, 7, 5}, {3, 2, 6, 7}, {2, 0, 4, 6}, {4, 5, 7, 6}};
  for (int f = 0; f < (fan_top ? 5 : 6); ++f) {
    m.face_sizes.push_back(4);
    m.corners.insert(m.corners.end(), quads[f], quads[f] + 4);
  }
  if (fan_top) {
    m.positions.insert(m.positions.end(), {0.f, 0.f, h});
    if (!open_top) {
      const uint32_t ring[4] = {4, 5, 7, 6};
      for (int i = 0; i < 4; ++i) {
        m.face_sizes.push_back(3);
        m.corners.insert(m.corners.end(), {8u, ring[i], ring[(i + 1) % 4]});
      }
    }
  }
  return m;
}

Mesh unit_square(float z) {
  Mesh m;
  m.positions = {0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z};
  m.face_sizes = {4};
  m.corners = {0, 1, 2, 3};
  return m;
}

TEST(MeshDistance, PointTriangleVoronoiRegions) {
  const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  struct Case {
    Vec3d p, closest;
    double d2;
  } cases[] = {
      {{-1, -1, 0}, {0, 0, 0}, 2},          // vertex a
      {{2, -1, 0}, {1, 0, 0}, 2},           // vertex b
      {{-1, 2, 3}, {0, 1, 0}, 11},          // vertex c
      {{0.5, -1, 1}, {0.5, 0, 0}, 2},       // edge ab
      {{-2, 0.25, 0}, {0, 0.25, 0}, 4},     // edge ac
      {{1, 1, -2}, {0.5, 0.5, 0}, 4.5},     // edge bc
      {{0.25, 0.25, 2}, {0.25, 0.25, 0}, 4},  // interior, above
      {{0.2, 0.3, -0.5}, {0.2, 0.3, 0}, 0.25},  // interior, below
      {{0.1, 0.1, 0}, {0.1, 0.1, 0}, 0},    // on the triangle
      {{0.5, 0, 0}, {0.5, 0, 0}, 0},        // on an edge
  };
  for (const Case& c : cases) {
    Vec3d q;
    EXPECT_NEAR(point_triangle_distance_squared(c.p, t, &q), c.d2, kExact) << c.p.x << " " << c.p.y << " " << c.p.z;
    EXPECT_NEAR(q.x, c.closest.x, kExact);
    EXPECT_NEAR(q.y, c.closest.y, kExact);
    EXPECT_NEAR(q.z, c.closest.z, kExact);
  }
}

// For arbitrary triangles and points the answer must be a point of the
// triangle that no other point of the triangle beats.
TEST(MeshDistance, PointTriangleIsTheMinimumOverTheTriangle) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const Triangle t{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    const Vec3d p{2 * u(rng), 2 * u(rng), 2 * u(rng)};
    Vec3d q;
    const double d2 = point_triangle_distance_squared(p, t, &q);
    const Vec3d to_q{q.x - p.x, q.y - p.y, q.z - p.z};
    EXPECT_NEAR(d2, to_q.x * to_q.x + to_q.y * to_q.y + to_q.z * to_q.z, kExact);
    // q lies in the triangle: its barycentric weights are in [0, 1].
    const Vec3d e1{t.b.x - t.a.x, t.b.y - t.a.y, t.b.z - t.a.z}, e2{t.c.x - t.a.x, t.c.y - t.a.y, t.c.z - t.a.z},
        r{q.x - t.a.x, q.y - t.a.y, q.z - t.a.z};
    const double d11 = e1.x * e1.x + e1.y * e1.y + e1.z * e1.z, d22 = e2.x * e2.x + e2.y * e2.y + e2.z * e2.z,
                 d12 = e1.x * e2.x + e1.y * e2.y + e1.z * e2.z, r1 = r.x * e1.x + r.y * e1.y + r.z * e1.z,
                 r2 = r.x * e2.x + r.y * e2.y + r.z * e2.z, det = d11 * d22 - d12 * d12;
    const double beta = (d22 * r1 - d12 * r2) / det, gamma = (d11 * r2 - d12 * r1) / det;
    EXPECT_GE(beta, -1e-9);
    EXPECT_GE(gamma, -1e-9);
    EXPECT_LE(beta + gamma, 1 + 1e-9);
    for (int k = 0; k < 200; ++k) {
      double s = w(rng), v = w(rng);
      if (s + v > 1) s = 1 - s, v = 1 - v;
      const Vec3d x{t.a.x + s * e1.x + v * e2.x - p.x, t.a.y + s * e1.y + v * e2.y - p.y,
                    t.a.z + s * e1.z + v * e2.z - p.z};
      ASSERT_GE(x.x * x.x + x.y * x.y + x.z * x.z, d2 - 1e-12);
    }
  }
}

TEST(MeshDistance, BvhAgreesWithAScanOverAllTriangles) {
  std::vector<Triangle> tris;
  ASSERT_TRUE(fan_triangulate(qmc::tools::make_torus(30, 14), &tris, nullptr, nullptr).ok());
  const TriangleBvh bvh(tris);
  ASSERT_EQ(bvh.size(), tris.size());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  std::uniform_int_distribution<uint32_t> any(0, uint32_t(tris.size() - 1));
  for (int i = 0; i < 2000; ++i) {
    const Vec3d p{u(rng), u(rng), u(rng) * 0.5};
    double scan = std::numeric_limits<double>::infinity();
    for (const Triangle& t : tris) scan = std::min(scan, point_triangle_distance_squared(p, t));
    uint32_t nearest = UINT32_MAX;
    // Every other query gets a hint far from the answer: it must not matter.
    const double got = bvh.distance_squared(p, i % 2 ? any(rng) : UINT32_MAX, &nearest);
    EXPECT_EQ(got, scan);
    ASSERT_LT(nearest, tris.size());
    EXPECT_EQ(point_triangle_distance_squared(p, tris[nearest]), got);
  }
  EXPECT_EQ(TriangleBvh().distance_squared({0, 0, 0}), std::numeric_limits<double>::infinity());
}

TEST(MeshDistance, FanTriangulationSkipsZeroAreaTriangles) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5f, 1.5f, 0, 0, 1, 0, 2, 0, 0, 9, 9, 9};
  m.face_sizes = {5, 3, 3};
  m.corners = {0, 1, 2, 3, 4,  // pentagon: 3 triangles
               0, 1, 5,        // collinear: zero area
               2, 2, 3};       // repeated corner: zero area
  std::vector<Triangle> tris;
  size_t degenerate = 0;
  std::vector<uint32_t> vertices;
  ASSERT_TRUE(fan_triangulate(m, &tris, &degenerate, &vertices).ok());
  EXPECT_EQ(tris.size(), 3u);
  EXPECT_EQ(degenerate, 2u);
  EXPECT_EQ(vertices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));  // 6 is unreferenced
  double area = 0;
  for (const Triangle& t : tris) area += qmc::tools::triangle_area(t);
  EXPECT_NEAR(area, 1.25, kExact);

  m.corners[3] = 7;
  EXPECT_EQ(fan_triangulate(m, &tris, nullptr, nullptr).code(), qmc::ErrorCode::kInvalidArgument);
  m.corners[3] = 3;
  m.face_sizes[0] = 4;
  EXPECT_EQ(fan_triangulate(m, &tris, nullptr, nullptr).code(), qmc::ErrorCode::kInvalidArgument);
}

// Two triangles of areas 1 and 3 share the samples 1:3, and inside a
// triangle each of the four half-size corner and middle triangles (a quarter
// of the area each) gets a quarter of them.
TEST(MeshDistance, SamplingIsAreaUniform) {
  const std::vector<Triangle> tris = {{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {3, 0, 1}, {0, 2, 1}}};
  for (size_t n : {size_t(100000), size_t(99999), size_t(7)}) {
    const std::vector<SurfaceSample> s = sample_surface(tris, n, 3);
    ASSERT_EQ(s.size(), n);
    size_t first = 0;
    for (const SurfaceSample& x : s) first += x.triangle == 0;
    EXPECT_LE(std::fabs(double(first) - double(n) / 4), 1.0) << n;
  }
  const std::vector<SurfaceSample> s = sample_surface(tris, 400000, 5);
  size_t corner[2][3] = {}, middle[2] = {};
  for (const SurfaceSample& x : s) {
    const Triangle& t = tris[x.triangle];
    ASSERT_DOUBLE_EQ(x.point.z, t.a.z);
    // Right triangles with legs along x and y: barycentric weights by hand.
    const double wb = x.point.x / t.b.x, wc = x.point.y / t.c.y, wa = 1 - wb - wc;
    ASSERT_GE(wa, -1e-12);
    ASSERT_GE(wb, -1e-12);
    ASSERT_GE(wc, -1e-12);
    if (wa > 0.5)
      ++corner[x.triangle][0];
    else if (wb > 0.5)
      ++corner[x.triangle][1];
    else if (wc > 0.5)
      ++corner[x.triangle][2];
    else
      ++middle[x.triangle];
  }
  for (int t = 0; t < 2; ++t) {
    const double n = t == 0 ? 100000 : 300000;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(double(corner[t][c]) / n, 0.25, 0.006) << t << " " << c;
    EXPECT_NEAR(double(middle[t]) / n, 0.25, 0.006) << t;
  }
  EXPECT_TRUE(sample_surface(tris, 0, 1).empty());
}

TEST(MeshDistance, IdenticalMeshesAreZeroApart) {
  qmc::tools::RandomSoupOptions soup;
  soup.vertices = 300;
  soup.faces = 400;
  for (const Mesh& m : {qmc::tools::make_torus(24, 12), qmc::tools::make_random_soup(9, soup), box(0.5f)}) {
    const MeshDistance d = measure(m, m, 50000);
    EXPECT_EQ(d.a_to_b.max, 0);
    EXPECT_EQ(d.b_to_a.max, 0);
    EXPECT_EQ(d.hausdorff, 0);
    EXPECT_EQ(d.l2, 0);
    EXPECT_EQ(d.mean, 0);
    EXPECT_TRUE(std::isinf(d.psnr_db) && d.psnr_db > 0);
    EXPECT_GT(d.bbox_diagonal, 0);
  }
}

// Every point of either square projects inside the other one, so every
// sample, vertex or not, is exactly d away.
TEST(MeshDistance, SquareTranslatedAlongItsNormal) {
  for (float z : {0.25f, 0.1f, 3.0f}) {
    const double d = z;
    const MeshDistance r = measure(unit_square(0), unit_square(z), 20000);
    EXPECT_NEAR(r.hausdorff, d, kExact);
    EXPECT_NEAR(r.l2, d, kExact);
    EXPECT_NEAR(r.mean, d, kExact);
    for (const auto* o : {&r.a_to_b, &r.b_to_a}) {
      EXPECT_NEAR(o->max, d, kExact);
      EXPECT_NEAR(o->mean, d, kExact);
      EXPECT_NEAR(o->rms, d, kExact);
      EXPECT_EQ(o->area_samples, 20000u);
      EXPECT_EQ(o->vertex_samples, 4u);
    }
    EXPECT_NEAR(r.bbox_diagonal, std::sqrt(2.0), kExact);
    EXPECT_NEAR(r.relative(r.hausdorff), d / std::sqrt(2.0), kExact);
    EXPECT_NEAR(r.psnr_db, 20 * std::log10(std::sqrt(2.0) / d), 1e-9);
    EXPECT_NEAR(r.a.area, 1, kExact);
  }
}

// A = [-1/2, 1/2]^3, B = A scaled by s about the centre, h = (s - 1) / 2.
// A -> B: a point x of A is inside B, so its distance to B's surface is
// min_i (s/2 - |x_i|) = s/2 - max_i |x_i| = s/2 - 1/2 = h for every point of
// A's surface: max = mean = rms = h, the face-to-face distance.
// B -> A: a point y of B is outside A, at distance
// sqrt(sum_i max(|y_i| - 1/2, 0)^2), largest at B's corners: sqrt(3) h, which
// is the symmetric Hausdorff distance (a vertex sample, so exact). On B's face
// y_3 = s/2, with |y_1|, |y_2| uniform on [0, s/2],
// E[max(|y_1| - 1/2, 0)^2] = (2/s) int_0^h t^2 dt = 2 h^3 / (3 s), so
// rms_BA^2 = h^2 + 4 h^3 / (3 s).
TEST(MeshDistance, CubeAgainstScaledCube) {
  for (float s : {2.0f, 1.5f, 1.1f}) {
    const double h = (double(s) - 1) / 2;
    const MeshDistance r = measure(box(0.5f), box(s / 2), 200000);
    EXPECT_NEAR(r.a_to_b.max, h, kExact);
    EXPECT_NEAR(r.a_to_b.mean, h, kExact);
    EXPECT_NEAR(r.a_to_b.rms, h, kExact);
    EXPECT_NEAR(r.b_to_a.max, std::sqrt(3.0) * h, kExact);
    EXPECT_NEAR(r.hausdorff, std::sqrt(3.0) * h, kExact);
    const double rms_ba = std::sqrt(h * h + 4 * h * h * h / (3 * s));
    EXPECT_NEAR(r.b_to_a.rms, rms_ba, 2e-3 * rms_ba);
    EXPECT_NEAR(r.l2, std::max(h, rms_ba), 2e-3 * rms_ba);
    // The mean has no short closed form: integrate over one face of B (all
    // six are alike) with a fine midpoint rule instead.
    const int n = 1500;
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double y1 = s * ((i + 0.5) / n - 0.5), y2 = s * ((j + 0.5) / n - 0.5);
        const double e1 = std::max(std::fabs(y1) - 0.5, 0.0), e2 = std::max(std::fabs(y2) - 0.5, 0.0);
        sum += std::sqrt(h * h + e1 * e1 + e2 * e2);
      }
    const double mean_ba = sum / (double(n) * n);
    EXPECT_NEAR(r.b_to_a.mean, mean_ba, 2e-3 * mean_ba);
    EXPECT_NEAR(r.mean, std::max(h, mean_ba), 2e-3 * mean_ba);
    EXPECT_NEAR(r.bbox_diagonal, std::sqrt(3.0), kExact);
    EXPECT_NEAR(r.psnr_db, 20 * std::log10(std::sqrt(3.0) / std::max(h, rms_ba)), 0.02);
  }
}

// A: the closed cube [-1/2, 1/2]^3 whose top face is four triangles around its
// centre vertex; B: the same without those four triangles (a square hole).
// B lies on A, so B -> A is 0. A point (x, y, 1/2) of the missing top face is
// min(1/2 - |x|, 1/2 - |y|) from B (the top edges of the side faces), largest
// at the centre: Hausdorff = 1/2, attained at a vertex sample of A. With u, v
// uniform on [0, 1/2], E[min(u, v)] = 1/6 and E[min(u, v)^2] = 1/24; the top
// face is 1/6 of A's area, so A -> B has mean 1/36 and rms sqrt(1/144) = 1/12.
TEST(MeshDistance, MeshWithAHoleAgainstTheClosedOne) {
  const Mesh closed = box(0.5f, true), holed = box(0.5f, true, true);
  const MeshDistance r = measure(closed, holed, 300000);
  EXPECT_NEAR(r.a_to_b.max, 0.5, kExact);
  EXPECT_NEAR(r.hausdorff, 0.5, kExact);
  EXPECT_EQ(r.b_to_a.max, 0);
  EXPECT_EQ(r.b_to_a.rms, 0);
  // 50000 samples fall on the top face: the standard errors are about 0.3%.
  EXPECT_NEAR(r.a_to_b.mean, 1.0 / 36, 0.01 / 36);
  EXPECT_NEAR(r.a_to_b.rms, 1.0 / 12, 0.01 / 12);
  EXPECT_NEAR(r.l2, 1.0 / 12, 0.01 / 12);
  EXPECT_NEAR(r.a.area, 6, kExact);
  EXPECT_NEAR(r.b.area, 5, kExact);
  EXPECT_EQ(r.b.referenced_vertices, 8u);  // the centre vertex is used by no face of B
  // Reversed roles: the hole is then on the A side of the report.
  const MeshDistance back = measure(holed, closed, 300000);
  EXPECT_NEAR(back.b_to_a.max, 0.5, kExact);
  EXPECT_EQ(back.a_to_b.max, 0);
}

TEST(MeshDistance, DeterministicForAFixedSeed) {
  const Mesh coarse = qmc::tools::make_torus(24, 12), fine = qmc::tools::make_torus(48, 24);
  const MeshDistance x = measure(coarse, fine, 30000, 42), y = measure(coarse, fine, 30000, 42);
  EXPECT_EQ(x.a_to_b.max, y.a_to_b.max);
  EXPECT_EQ(x.a_to_b.mean, y.a_to_b.mean);
  EXPECT_EQ(x.a_to_b.rms, y.a_to_b.rms);
  EXPECT_EQ(x.b_to_a.max, y.b_to_a.max);
  EXPECT_EQ(x.b_to_a.mean, y.b_to_a.mean);
  EXPECT_EQ(x.b_to_a.rms, y.b_to_a.rms);
  EXPECT_EQ(x.psnr_db, y.psnr_db);
  EXPECT_GT(x.hausdorff, 0);
  // Another seed samples other points but estimates the same integrals.
  const MeshDistance z = measure(coarse, fine, 30000, 43);
  EXPECT_NE(x.a_to_b.rms, z.a_to_b.rms);
  EXPECT_NEAR(x.l2, z.l2, 0.02 * x.l2);
  EXPECT_NEAR(x.mean, z.mean, 0.02 * x.mean);

  std::vector<Triangle> tris;
  ASSERT_TRUE(fan_triangulate(coarse, &tris, nullptr, nullptr).ok());
  const std::vector<SurfaceSample> p = sample_surface(tris, 1000, 9), q = sample_surface(tris, 1000, 9);
  ASSERT_EQ(p.size(), q.size());
  for (size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p[i].point.x, q[i].point.x);
    EXPECT_EQ(p[i].point.y, q[i].point.y);
    EXPECT_EQ(p[i].point.z, q[i].point.z);
    EXPECT_EQ(p[i].triangle, q[i].triangle);
  }
}

TEST(MeshDistance, ProgressReachesTheTotal) {
  MeshDistanceOptions options;
  options.samples = 40000;
  size_t last_done = 0, last_total = 0, calls = 0;
  options.progress = [&](size_t done, size_t total) {
    EXPECT_GE(done, last_done);
    last_done = done, last_total = total, ++calls;
  };
  MeshDistance d;
  const Mesh m = qmc::tools::make_torus(24, 12);
  ASSERT_TRUE(measure_mesh_distance(m, m, options, &d).ok());
  EXPECT_GT(calls, 1u);
  EXPECT_EQ(last_done, last_total);
  EXPECT_EQ(last_total, 2 * (40000 + m.vertex_count()));
}

TEST(MeshDistance, MeshWithoutAreaIsRejected) {
  Mesh flat;
  flat.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0};
  flat.face_sizes = {3};
  flat.corners = {0, 1, 2};
  MeshDistance d;
  const qmc::Status s = measure_mesh_distance(box(0.5f), flat, MeshDistanceOptions(), &d);
  EXPECT_EQ(s.code(), qmc::ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("mesh B"), std::string::npos) << s.message();
  EXPECT_EQ(measure_mesh_distance(Mesh(), box(0.5f), MeshDistanceOptions(), &d).code(),
            qmc::ErrorCode::kInvalidArgument);
}

}  // namespace
