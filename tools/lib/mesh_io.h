// qmc tools: reading and writing meshes in common interchange formats.
//
// These readers are deliberately our own: qmc must carry any polygon soup
// exactly (repeated corners, non-manifold edges, pinched and unreferenced
// vertices, all in file order), and general-purpose mesh libraries reject or
// repair such faces while loading.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc::tools {

// Reads by extension (case-insensitive): .obj .off .ply .stl. OBJ texture
// coordinates and normals with their per-corner indices (f v/vt/vn) become
// the attributes "texcoord" and "normal" (spec section 15), OBJ o/g/usemtl/s
// and mtllib the face labels "object", "group", "material", "smoothing"
// (section 16); PLY vertex nx ny nz, red green blue, alpha and u v (s t,
// texture_u texture_v) and face texcoord lists become attributes too.
// Anything in the file that a qmc::Mesh does not carry (colours, groups,
// materials, attributes on only some corners, 'l'/'p' elements, extra PLY elements or properties, STL
// vertex merging) is reported in *warnings as one short counted sentence per
// kind; `warnings` may be null. Unreadable files give ErrorCode::kIo,
// malformed content ErrorCode::kInvalidArgument with a message naming the
// file, the line (text formats) or byte offset (binary formats) and the
// problem. On failure *mesh and *warnings are left unchanged.
qmc::Status read_mesh(const std::string& path, qmc::Mesh* mesh, std::vector<std::string>* warnings);

// As read_mesh, for data already in memory; `format` is "obj", "off", "ply"
// or "stl" (case-insensitive).
qmc::Status read_mesh_from_memory(std::string_view text_or_bytes, std::string_view format,
                                  qmc::Mesh* mesh, std::vector<std::string>* warnings);

// How write_mesh writes: PLY as ASCII (default) or binary_little_endian
// (boat's decoded mesh with texture coordinates: 1.4 MB instead of 3.7 MB;
// floats bit for bit either way).
struct MeshWriteOptions {
  bool binary_ply = false;
};

// Writes .obj .off .ply (ASCII, or PLY binary as `options` say) by extension,
// faces exactly as stored. Floats are printed like "%.9g" (locale-independent),
// so they read back bit-exact.
// OBJ writes the first texture-coordinate and normal attributes as vt / vn
// with per-corner indices and the face labels as statements; PLY the
// attributes it reads, in the same form (colours above 1 as uchar). A mesh that violates the qmc::Mesh invariants,
// or has an attribute the format cannot hold, gives kInvalidArgument.
qmc::Status write_mesh(const std::string& path, const qmc::Mesh& mesh, const MeshWriteOptions& options = {});

// The format read_mesh and write_mesh take `path` to be in: its extension,
// lower case ("obj" for "a/B.OBJ"), empty without one.
std::string mesh_format_of(const std::string& path);

// What write_mesh would refuse to put in a file of `format` ("obj", "off",
// "ply"; case-insensitive; none for any other format, which write_mesh
// refuses as a whole): the attributes, then the face labels, of `mesh`
// that the format cannot hold, in the mesh's order, each with the message
// write_mesh gives for it. Leaving them all out makes the mesh writable (as
// far as its attributes and labels go).
struct UnwritablePart {
  std::string name;    // the attribute's or the face labels' name
  std::string reason;  // why, as write_mesh says it
};
std::vector<UnwritablePart> unwritable_parts(const qmc::Mesh& mesh, std::string_view format);

// As write_mesh, into *text; `format` is "obj", "off" or "ply".
qmc::Status write_mesh_to_memory(const qmc::Mesh& mesh, std::string_view format, std::string* text,
                                 const MeshWriteOptions& options = {});

}  // namespace qmc::tools
