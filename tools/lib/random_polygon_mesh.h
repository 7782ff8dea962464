// qmc tools: a seeded random polygon-mesh generator for tests, with a
// requested topology (components, genus, boundary loops), mixed face degrees,
// valence-2 vertices and, on request, non-manifold defects.
//
// Why: the codec must handle every polygon mesh, so tests need many different
// meshes whose topology is known in advance, and the generator's output must
// not depend on the platform (only splitmix64 integer arithmetic and IEEE
// float operations; no std:: distributions, no hash-order iteration).
//
// Construction of one component (each step keeps it a connected, oriented,
// edge- and vertex-manifold surface without repeated face vertices or
// duplicate edges; the reasons are in the .cc):
//  1. A quad sphere (a cube with k x k quads per side, genus 0), k chosen so
//     the sphere has about target_faces quads.
//  2. `genus` handles: remove two quads A, B whose vertices are pairwise
//     non-adjacent and join their boundary squares by a tube of four quads,
//     oriented so the surface stays orientable. Each tube lowers V - E + F
//     by 2, i.e. adds one handle.
//  3. `holes` holes: remove a face none of whose vertices is on a boundary
//     yet; its cycle becomes exactly one new boundary loop and the fans
//     around its vertices open without splitting.
//  4. Random splits of a face by a diagonal (both parts >= min_degree, no
//     edge between the two corners yet) and random merges of two faces across
//     an interior edge (merged degree <= max_degree, the faces share no other
//     vertex, both edge ends keep valence >= 3). Neither changes V - E + F or
//     the boundary. If max_degree is 3, every quad is split into triangles.
//  5. With valence_two, a few interior edges shared by two faces of degree
//     < max_degree get a new vertex in their middle (each face raised once).
// If steps 2-4 find no valid choice (tiny sphere), the component is rebuilt
// from a finer sphere, so the requested topology is always met exactly.
//
// With non_manifold, defects are then added to the finished mesh, each on
// vertices no earlier defect touched so that every one stays detectable:
// a "book" triangle on an interior edge (three faces on one edge), two far
// apart vertices identified (a pinched vertex, joining two components when
// there are several), a reversed face, a duplicated face, or a new face
// (a b a c) listing an existing vertex a twice.
//
// Finally isolated vertices (random positions) are added, vertices and faces
// are shuffled, and every face starts at a random corner. Positions are the
// sphere's, moved apart per component: finite, but geometry is not the point.
#pragma once

#include <cstdint>

#include "qmc/mesh.h"

namespace qmc {

struct RandomPolygonMeshOptions {
  uint64_t seed = 1;
  int components = 1;  // connected surface pieces (raised to 1)
  int genus = 0;       // handles added to EACH component (tested 0..4; raised to 0)
  int holes = 0;       // boundary loops cut into EACH component (tested 0..6; raised to 0)
  // Face degrees lie in [min_degree, max_degree]. min_degree is clamped to
  // [3, 4] (faces of degree >= 6 only cannot tile a sphere without valence-2
  // vertices; 5 is possible but not by this construction) and max_degree is
  // raised to min_degree.
  int min_degree = 3, max_degree = 8;
  int target_faces = 60;     // approximate faces per component
  bool valence_two = true;   // insert some valence-2 vertices; without, every vertex has valence >= 3
  bool non_manifold = false; // then ALSO add 1..3 non-manifold defects
  int isolated_vertices = 0; // vertices no face uses
};

// What was built, so tests can assert it. In the non-manifold case the first
// three fields describe the manifold mesh before the defects.
struct RandomPolygonMeshInfo {
  int components = 0;
  int genus_per_component = 0;
  int boundary_loops = 0;  // over all components
  int non_manifold_defects = 0;
};

Mesh make_random_polygon_mesh(const RandomPolygonMeshOptions& options, RandomPolygonMeshInfo* info = nullptr);

}  // namespace qmc
