// qmc: the polygon mesh that goes into the encoder and comes out of the decoder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace qmc {

// Section 15.1: what an attribute's values mean (informative; a decoder
// treats every kind alike, and keeps kinds it does not know).
enum class AttributeKind : uint8_t {
  kGeneric = 0,
  kTextureCoordinate = 1,  // OBJ vt, PLY u v
  kNormal = 2,             // OBJ vn, PLY nx ny nz
  kColour = 3,
};

// An attribute of the mesh's corners (spec section 15): a table of values of
// `components` binary32 each, and per corner of Mesh::corners the index of
// its value. Corners of one vertex may refer to different values (a seam
// of texture coordinates) and corners of different vertices to one value.
struct MeshAttribute {
  std::string name;  // 1..255 bytes, distinct within a mesh (e.g. "texcoord", "normal")
  AttributeKind kind = AttributeKind::kGeneric;
  uint32_t components = 0;             // 1..3
  std::vector<float> values;           // components per value
  std::vector<uint32_t> corner_values; // per corner, an index into the values

  size_t value_count() const { return components == 0 ? 0 : values.size() / components; }
};

// Labels of the faces (spec section 16): each face has one of `values`, or
// none (face_values[f] == values.size()). OBJ's objects, groups, materials
// and smoothing groups are read as the labels "object", "group",
// "material" (its `mtllib` files in references) and "smoothing".
struct FaceLabels {
  std::string name;                     // 1..255 bytes, distinct within a mesh
  std::vector<std::string> references;  // files the values refer to (OBJ mtllib)
  std::vector<std::string> values;
  std::vector<uint32_t> face_values;    // per face, an index into values or values.size()

  uint32_t none() const { return uint32_t(values.size()); }
};

// A polygon soup: positions plus faces given as vertex-index cycles.
// Face f has face_sizes[f] corners, stored consecutively in `corners`.
// Nothing here requires the mesh to be manifold, oriented or free of
// unreferenced vertices: every container of the format can carry it.
struct Mesh {
  std::vector<float> positions;      // x0 y0 z0 x1 y1 z1 ...
  std::vector<uint32_t> face_sizes;  // degree of each face, >= 3
  std::vector<uint32_t> corners;     // concatenated face cycles
  std::vector<MeshAttribute> attributes;  // section 15; empty for most meshes
  std::vector<FaceLabels> face_labels;    // section 16

  size_t vertex_count() const { return positions.size() / 3; }
  size_t face_count() const { return face_sizes.size(); }
};

}  // namespace qmc
