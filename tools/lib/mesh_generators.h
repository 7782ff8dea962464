// qmc tools: synthetic meshes for tests, fuzzing seeds and benchmarks.
//
// Every generator is deterministic and platform-independent: positions come
// from integer arithmetic or from IEEE operations whose results do not depend
// on the compiler (correctly rounded +, *, /, sqrt on values where fused
// multiply-add cannot change the outcome), and the random soup uses its own
// integer RNG rather than std:: distributions, whose output varies between
// standard libraries. The same call gives the same bits everywhere.
#pragma once

#include <cstdint>

#include "qmc/mesh.h"

namespace qmc::tools {

// Regular octahedron with vertices +-x, +-y, +-z on the unit sphere: 6
// vertices of valence 4, 8 triangles, outward.
qmc::Mesh make_octahedron();

// Each face of degree d > 3 split into the d - 2 triangles of the fan from
// its first corner (c0 ck ck+1); triangles are kept, vertices untouched.
// *polygons_split (if not null) gets the number of faces that were split.
qmc::Mesh triangulated(const qmc::Mesh& mesh, size_t* polygons_split = nullptr);

// Regular tetrahedron inscribed in the cube [-1,1]^3; 4 triangles, outward.
qmc::Mesh make_tetrahedron();

// Cube [-1,1]^3: 8 vertices, 6 quads, outward orientation.
qmc::Mesh make_cube();

// Cube subdivided n x n per side, projected to the unit sphere: all quads,
// closed, genus 0, 6n^2+2 vertices (shared vertices welded), 6n^2 faces,
// outward. n < 1 is treated as 1.
qmc::Mesh make_quad_sphere(int n);

// Torus around the z axis: `major` x `minor` vertices and quads, genus 1,
// outward. major and minor below 3 are treated as 3.
qmc::Mesh make_torus(int major, int minor, float R = 1.f, float r = 0.35f);

// Open nx x ny quad grid over [-1,1]^2 (one boundary loop), z a small smooth
// bump, faces counter-clockwise seen from +z. Sizes below 1 are treated as 1.
qmc::Mesh make_grid(int nx, int ny);

// make_grid bent in the plane (x + x^2 / 8, y + x y / 16), so that no plane
// mirrors it: its boundary takes POSN method 12's edge extrapolation (14.13).
qmc::Mesh make_bent_grid(int nx, int ny);

// Circular terraces: an n x n grid over [0,1]^2 (n >= 1) of triangles, each
// cell split along a diagonal the seed picks, at height level / (4 steps)
// with level = floor(steps r^2 / (2 n^2)), r^2 = (2i - n)^2 + (2j - n)^2:
// flat rings with a cliff between two. Integer arithmetic and exact
// divisions only, so every platform builds the same mesh.
qmc::Mesh make_terraces(uint32_t n, uint32_t steps, uint64_t seed);

// Deltoidal hexecontahedron with its vertices on the unit sphere: the thesis's
// "60-quad sphere". 62 vertices -- the 12 icosahedron vertices (valence 5),
// then the 20 icosahedron face centres (the dodecahedron's vertices, valence
// 3), then the 30 icosahedron edge midpoints (valence 4), each direction
// normalised -- and 60 kites, closed, genus 0, outward. It is numbered like
// one Catmull-Clark step of the icosahedron (see subdivision.h): for each
// icosahedron face, one kite per corner, (vertex, edge, centre, edge). On the
// sphere the kites are slightly non-planar.
qmc::Mesh make_deltoidal_hexecontahedron();

// The deltoidal hexecontahedron after `levels` Catmull-Clark steps, every
// vertex projected back to the unit sphere after each step: 60 * 4^levels
// quads, 60 * 4^levels + 2 vertices (levels 5: 61440 quads; levels 7:
// 983040). levels is clamped to [0, 10].
qmc::Mesh make_refined_sphere(int levels);

// make_refined_sphere(levels) cut into triangles, each vertex then moved by
// up to `jitter` times the mean edge length along each axis and put back on
// the unit sphere: an irregular triangulation, where a parallelogram's
// reflection overshoots along its edge (POSN method 11, spec 14.12).
qmc::Mesh make_jittered_sphere(int levels, float jitter, uint64_t seed);

// n-sided prism: n quads around, two n-gon caps; 2n vertices, outward.
// n < 3 is treated as 3.
qmc::Mesh make_prism(int n);

// Degenerate shapes for complexity tests (issue #12 item 6):
// one face of `corners` corners (at least 3) around the unit circle in z = 0;
// a "book": `pages` triangles (0, 1, k + 2) all on the one edge 0-1, page k's
// tip on the unit circle; a "star": `triangles` triangles that share vertex 0
// and nothing else.
qmc::Mesh make_polygon(uint32_t corners);
qmc::Mesh make_book(uint32_t pages);
qmc::Mesh make_vertex_star(uint32_t triangles);

// The mesh made mirror-symmetric across x = 0, as a modeller's mirror leaves
// it: vertices within `near` of the plane moved onto it, every other one with
// x < 0 moved to the image of the vertex with x > 0 nearest to its own image
// (spec 14.10's twins). Quadratic in the vertices: for test meshes.
qmc::Mesh make_mirrored_across_x(qmc::Mesh mesh, float near = 0.01f);

// Splits quad `quad` of `mesh` along its diagonal corner 0 - corner 2 into
// two quads that share two edges, around a new vertex of valence 2 at the
// diagonal's midpoint (appended last): (c0, c1, c2, v) in place and
// (c0, v, c2, c3) appended. Seed 001's §4.1 claim fails next to it.
qmc::Mesh split_quad_with_doublet(qmc::Mesh mesh, size_t quad);

struct RandomSoupOptions {
  uint32_t vertices = 100;  // total vertex count
  uint32_t faces = 150;
  uint32_t min_degree = 3, max_degree = 8;  // corners per face (min raised to 3, max to min)
  uint32_t unreferenced = 5;                // vertices no face uses (capped so faces have a vertex)
  bool repeated_corners = true;             // some faces list a vertex twice
};

// Arbitrary polygon soup: positions on a 2^-23 grid in [-1,1)^3 (some
// duplicated), faces of random degree whose corners are random vertices.
// Exactly `unreferenced` vertices are unused whenever the faces have enough
// corners to use all the others. With repeated_corners, face 0 and about a
// fifth of the others contain one vertex twice; without, every face's corners
// are distinct (as long as enough vertices exist). options.vertices == 0 gives
// an empty mesh.
qmc::Mesh make_random_soup(uint64_t seed, const RandomSoupOptions& options);

// `mesh` with vertices renumbered, faces shuffled and each face starting at
// another corner: the same mesh in an input order no coder keeps.
qmc::Mesh make_scrambled(const qmc::Mesh& mesh, uint64_t seed);

}  // namespace qmc::tools
