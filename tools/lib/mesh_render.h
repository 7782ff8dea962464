// qmc tools: pictures for the geometry-image results -- a small z-buffered
// software rasterizer for meshes, and colour-mapped pictures of image planes.
//
// The results pages need the same picture from every run (so a changed
// picture means a changed mesh), without a GPU or a windowing system. The
// rasterizer is deliberately simple: polygon faces split into fans, flat
// Lambert shading under a headlight plus ambient, a light grey surface on a
// white background, and an optional wireframe of the polygon edges (not the
// fan diagonals), which shows the quad grid of a geometry-image remesh. All
// arithmetic is in double with a fixed drawing order, so the same mesh and
// options give the same bytes on every run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc::tools {

// 8-bit RGB pixels, rows top to bottom: pixel (x, y) is rgb[3 * (y * width + x)] ...
struct RgbImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgb;
};

struct RenderOptions {
  uint32_t width = 512, height = 512;
  // The camera looks at the centre of the bounding box from the direction
  // (cos p sin y, sin p, cos p cos y) for yaw y and pitch p, +Y up: yaw 0,
  // pitch 0 looks from +Z towards -Z; positive pitch looks from above.
  double yaw_degrees = 30.0;
  double pitch_degrees = 20.0;
  // Orthographic by default; perspective with this field of view, the camera
  // just far enough away for the bounding sphere (below) to fill that angle.
  bool perspective = false;
  double field_of_view_degrees = 30.0;
  // The bounding sphere -- centred on the bounding box, through its corners,
  // so any view direction fits -- spans this share of the smaller image side.
  double fill = 0.9;
  // Darken the polygon edges: lines about 2 * wire_half_width_pixels wide.
  bool wireframe = false;
  double wire_half_width_pixels = 0.6;
};

// Renders into *image. Faces are drawn two-sided (back faces lit like front
// faces, so open meshes look right). A mesh whose face list is inconsistent
// (corner count, index out of range) or that has non-finite positions gives
// kInvalidArgument; a mesh without faces gives a blank white picture.
qmc::Status render_mesh(const qmc::Mesh& mesh, const RenderOptions& options, RgbImage* image);

// render_mesh, saved as an 8-bit RGB PNG.
qmc::Status render_mesh_png(const qmc::Mesh& mesh, const RenderOptions& options, const std::string& path);

// A plane (values[y * width + x]) colour-mapped from its minimum (dark
// blue-violet) to its maximum (yellow). Pixels whose mask byte is 0 (mask may
// be null: all pixels used) or whose value is not finite are black and do not
// take part in the minimum and maximum; a constant plane maps to the middle
// colour. Sizes that disagree give kInvalidArgument.
qmc::Status false_colour_plane(const std::vector<double>& values, uint32_t width, uint32_t height,
                               const std::vector<uint8_t>* mask, RgbImage* image);
qmc::Status render_false_colour_plane(const std::vector<double>& values, uint32_t width, uint32_t height,
                                      const std::vector<uint8_t>* mask, const std::string& path);

// The classic geometry-image picture: X, Y, Z each normalised to its own
// min..max over the used pixels and shown as R, G, B. Blank pixels (mask 0,
// or any coordinate not finite) are black.
qmc::Status rgb_geometry_image(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& z, uint32_t width, uint32_t height,
                               const std::vector<uint8_t>* mask, RgbImage* image);
qmc::Status render_rgb_geometry_image(const std::vector<double>& x, const std::vector<double>& y,
                                      const std::vector<double>& z, uint32_t width, uint32_t height,
                                      const std::vector<uint8_t>* mask, const std::string& path);

}  // namespace qmc::tools
