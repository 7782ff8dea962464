// qmc tools: the software rasterizer and the plane pictures.
//
// Rasterization: each fan triangle is scanned over its pixel bounding box;
// a pixel centre inside the triangle (edges included) takes the
// barycentric interpolation of the vertices' "nearness" (minus the depth
// for orthographic views, 1/z for perspective, which is linear in screen
// space) and wins the pixel if it is strictly nearer than what is there, so
// on ties the face drawn first stays. The wireframe darkens pixels closer to
// a polygon edge than the line half-width, measured in the triangle itself,
// so hidden edges stay hidden.
#include "mesh_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "image_io.h"

namespace qmc::tools {
namespace {

using qmc::ErrorCode;
using qmc::Mesh;
using qmc::Status;

constexpr double kPi = 3.14159265358979323846;
constexpr uint8_t kBackground = 255;
constexpr double kSurfaceGrey = 0.85;  // albedo of the surface, 0..1
constexpr double kAmbient = 0.2;       // share of the light that ignores orientation
constexpr double kWireDarkening = 0.3;

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(const Vec3& a) { return std::sqrt(dot(a, a)); }

Vec3 vertex(const Mesh& mesh, uint32_t v) {
  return {mesh.positions[3 * size_t{v}], mesh.positions[3 * size_t{v} + 1], mesh.positions[3 * size_t{v} + 2]};
}

Status validate_mesh(const Mesh& mesh) {
  if (mesh.positions.size() % 3 != 0) return invalid("render: position count is not a multiple of 3");
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!std::isfinite(mesh.positions[i])) return invalid("render: vertex " + std::to_string(i / 3) + " is not finite");
  }
  size_t total = 0;
  for (size_t f = 0; f < mesh.face_sizes.size(); ++f) {
    if (mesh.face_sizes[f] < 3) return invalid("render: face " + std::to_string(f) + " has fewer than 3 corners");
    total += mesh.face_sizes[f];
  }
  if (total != mesh.corners.size()) return invalid("render: face sizes do not add up to the corner count");
  for (size_t c = 0; c < mesh.corners.size(); ++c) {
    if (mesh.corners[c] >= mesh.vertex_count()) {
      return invalid("render: corner " + std::to_string(c) + " names vertex " + std::to_string(mesh.corners[c]) +
                     " of " + std::to_string(mesh.vertex_count()));
    }
  }
  return Status::Ok();
}

// ---------------------------------------------------------------------------
// Camera

struct Camera {
  Vec3 centre, right, up, forward;  // forward: from the camera into the scene
  bool perspective = false;
  double pixels_per_unit = 1;  // orthographic scale, or the focal length in pixels
  double distance = 0;         // perspective: camera to centre
  double cx = 0, cy = 0;       // image centre in pixel coordinates
};

struct ScreenVertex {
  double x = 0, y = 0, nearness = 0;
};

Camera make_camera(const Mesh& mesh, const RenderOptions& options) {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3 p = vertex(mesh, static_cast<uint32_t>(v));
    if (v == 0) lo = hi = p;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  double radius = 0.5 * length(hi - lo);
  if (!(radius > 0)) radius = 1;

  const double yaw = options.yaw_degrees * kPi / 180, pitch = options.pitch_degrees * kPi / 180;
  Camera camera;
  camera.centre = {0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)};
  camera.forward = {-std::cos(pitch) * std::sin(yaw), -std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
  camera.right = {std::cos(yaw), 0, -std::sin(yaw)};  // horizontal, so "up" stays up at any pitch
  camera.up = cross(camera.right, camera.forward);
  camera.perspective = options.perspective;
  camera.cx = 0.5 * options.width;
  camera.cy = 0.5 * options.height;
  const double half = 0.5 * options.fill * std::min(options.width, options.height);
  if (camera.perspective) {
    const double half_angle = std::clamp(options.field_of_view_degrees, 1.0, 170.0) * kPi / 360;
    camera.distance = radius / std::sin(half_angle);
    camera.pixels_per_unit = half / std::tan(half_angle);
  } else {
    camera.pixels_per_unit = half / radius;
  }
  return camera;
}

ScreenVertex project(const Camera& camera, const Vec3& p) {
  const Vec3 v = p - camera.centre;
  const double across = dot(v, camera.right), upward = dot(v, camera.up), depth = dot(v, camera.forward);
  if (!camera.perspective) {
    return {camera.cx + across * camera.pixels_per_unit, camera.cy - upward * camera.pixels_per_unit, -depth};
  }
  const double z = camera.distance + depth;  // at least distance - radius > 0
  return {camera.cx + camera.pixels_per_unit * across / z, camera.cy - camera.pixels_per_unit * upward / z, 1 / z};
}

// ---------------------------------------------------------------------------
// Rasterization

struct Raster {
  uint32_t width = 0, height = 0;
  std::vector<double> nearness;  // per pixel; larger is nearer
  RgbImage* image = nullptr;
  double wire_half_width = 0;
};

struct FanTriangle {
  ScreenVertex v[3];
  bool wire_edge[3] = {false, false, false};  // edge k is the one opposite vertex k
  uint8_t shade = 0, wire_shade = 0;
};

// Twice the signed area of (a, b, p).
double edge_function(const ScreenVertex& a, const ScreenVertex& b, double px, double py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

uint32_t clamp_pixel(double coordinate, uint32_t size) {
  if (coordinate < 0) return 0;
  if (coordinate > size - 1) return size - 1;
  return static_cast<uint32_t>(coordinate);
}

void draw_triangle(const FanTriangle& t, Raster* raster) {
  const ScreenVertex& a = t.v[0];
  const ScreenVertex& b = t.v[1];
  const ScreenVertex& c = t.v[2];
  const double area = edge_function(a, b, c.x, c.y);
  if (std::fabs(area) < 1e-12) return;
  const double min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  const double min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  if (max_x < 0 || max_y < 0 || min_x > raster->width || min_y > raster->height) return;
  const double edge_length[3] = {std::hypot(c.x - b.x, c.y - b.y), std::hypot(a.x - c.x, a.y - c.y),
                                 std::hypot(b.x - a.x, b.y - a.y)};
  const uint32_t x0 = clamp_pixel(std::floor(min_x), raster->width), x1 = clamp_pixel(max_x, raster->width);
  const uint32_t y0 = clamp_pixel(std::floor(min_y), raster->height), y1 = clamp_pixel(max_y, raster->height);
  for (uint32_t y = y0; y <= y1; ++y) {
    const double py = y + 0.5;
    for (uint32_t x = x0; x <= x1; ++x) {
      const double px = x + 0.5;
      const double w[3] = {edge_function(b, c, px, py), edge_function(c, a, px, py), edge_function(a, b, px, py)};
      const double bary[3] = {w[0] / area, w[1] / area, w[2] / area};
      if (bary[0] < 0 || bary[1] < 0 || bary[2] < 0) continue;
      const double nearness = bary[0] * a.nearness + bary[1] * b.nearness + bary[2] * c.nearness;
      const size_t pixel = size_t{y} * raster->width + x;
      if (!(nearness > raster->nearness[pixel])) continue;
      raster->nearness[pixel] = nearness;
      uint8_t shade = t.shade;
      for (int k = 0; k < 3; ++k) {
        if (t.wire_edge[k] && std::fabs(w[k]) < raster->wire_half_width * edge_length[k]) shade = t.wire_shade;
      }
      std::fill_n(raster->image->rgb.begin() + 3 * pixel, 3, shade);
    }
  }
}

// Flat Lambert under a headlight: Newell's normal of the polygon against the
// viewing direction, two-sided.
uint8_t face_shade(const Mesh& mesh, size_t first, uint32_t size, const Camera& camera) {
  Vec3 normal;
  for (uint32_t i = 0; i < size; ++i) {
    const Vec3 p = vertex(mesh, mesh.corners[first + i]);
    const Vec3 q = vertex(mesh, mesh.corners[first + (i + 1) % size]);
    normal.x += (p.y - q.y) * (p.z + q.z);
    normal.y += (p.z - q.z) * (p.x + q.x);
    normal.z += (p.x - q.x) * (p.y + q.y);
  }
  const double norm = length(normal);
  const double lambert = norm > 0 ? std::fabs(dot(normal, camera.forward)) / norm : 0;
  const double intensity = kSurfaceGrey * (kAmbient + (1 - kAmbient) * std::min(lambert, 1.0));
  return static_cast<uint8_t>(std::lround(255 * intensity));
}

void draw_face(const Mesh& mesh, size_t first, uint32_t size, const Camera& camera, bool wireframe,
               Raster* raster) {
  FanTriangle t;
  t.shade = face_shade(mesh, first, size, camera);
  t.wire_shade = static_cast<uint8_t>(std::lround(t.shade * kWireDarkening));
  t.v[0] = project(camera, vertex(mesh, mesh.corners[first]));
  for (uint32_t i = 1; i + 1 < size; ++i) {
    t.v[1] = project(camera, vertex(mesh, mesh.corners[first + i]));
    t.v[2] = project(camera, vertex(mesh, mesh.corners[first + i + 1]));
    t.wire_edge[0] = wireframe;                            // c_i c_i+1: always a polygon edge
    t.wire_edge[1] = wireframe && i + 2 == size;           // c_i+1 c_0: the polygon's closing edge
    t.wire_edge[2] = wireframe && i == 1;                  // c_0 c_1: the polygon's first edge
    draw_triangle(t, raster);
  }
}

// ---------------------------------------------------------------------------
// Plane pictures

Status check_plane(const char* what, size_t count, uint32_t width, uint32_t height) {
  if (width == 0 || height == 0 || uint64_t{width} * height > kMaxImagePixels) {
    return invalid(std::string(what) + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                   " is empty or over 2^26 pixels");
  }
  if (count != uint64_t{width} * height) {
    return invalid(std::string(what) + ": " + std::to_string(count) + " values for a " + std::to_string(width) +
                   "x" + std::to_string(height) + " plane");
  }
  return Status::Ok();
}

bool pixel_used(const std::vector<uint8_t>* mask, size_t i) { return mask == nullptr || (*mask)[i] != 0; }

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // 0..1; a constant (or empty) range maps to 0.5.
  double normalised(double v) const { return hi > lo ? (v - lo) / (hi - lo) : 0.5; }
};

// Dark blue-violet through teal and green to yellow: perceptually ordered,
// readable in grey, and never black (black marks blank pixels).
void colour_map(double t, uint8_t* rgb) {
  static const double kAnchors[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  const double s = std::clamp(t, 0.0, 1.0) * 4;
  const int i = std::min(static_cast<int>(s), 3);
  const double f = s - i;
  for (int k = 0; k < 3; ++k) {
    rgb[k] = static_cast<uint8_t>(std::lround(kAnchors[i][k] + f * (kAnchors[i + 1][k] - kAnchors[i][k])));
  }
}

uint8_t to_byte(double t) { return static_cast<uint8_t>(std::lround(255 * std::clamp(t, 0.0, 1.0))); }

Status save(const Status& made, const RgbImage& image, const std::string& path) {
  if (!made.ok()) return Status(made.code(), path + ": " + made.message());
  return write_png_rgb8(path, image.width, image.height, image.rgb);
}

}  // namespace

Status render_mesh(const Mesh& mesh, const RenderOptions& options, RgbImage* image) {
  Status status = validate_mesh(mesh);
  if (!status.ok()) return status;
  if (options.width == 0 || options.height == 0 || uint64_t{options.width} * options.height > kMaxImagePixels) {
    return invalid("render: image size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                   " is empty or over 2^26 pixels");
  }
  if (!std::isfinite(options.yaw_degrees) || !std::isfinite(options.pitch_degrees) ||
      !std::isfinite(options.field_of_view_degrees) || !(options.fill > 0 && options.fill <= 16)) {
    return invalid("render: yaw, pitch and field of view must be finite and fill in (0, 16]");
  }
  RgbImage result;
  result.width = options.width;
  result.height = options.height;
  result.rgb.assign(size_t{options.width} * options.height * 3, kBackground);
  Raster raster;
  raster.width = options.width;
  raster.height = options.height;
  raster.nearness.assign(size_t{options.width} * options.height, -std::numeric_limits<double>::infinity());
  raster.image = &result;
  raster.wire_half_width = options.wire_half_width_pixels;

  const Camera camera = make_camera(mesh, options);
  size_t first = 0;
  for (uint32_t size : mesh.face_sizes) {
    draw_face(mesh, first, size, camera, options.wireframe, &raster);
    first += size;
  }
  *image = std::move(result);
  return Status::Ok();
}

Status render_mesh_png(const Mesh& mesh, const RenderOptions& options, const std::string& path) {
  RgbImage image;
  return save(render_mesh(mesh, options, &image), image, path);
}

Status false_colour_plane(const std::vector<double>& values, uint32_t width, uint32_t height,
                          const std::vector<uint8_t>* mask, RgbImage* image) {
  Status status = check_plane("false-colour plane", values.size(), width, height);
  if (status.ok() && mask != nullptr) status = check_plane("false-colour mask", mask->size(), width, height);
  if (!status.ok()) return status;
  Range range;
  for (size_t i = 0; i < values.size(); ++i) {
    if (pixel_used(mask, i) && std::isfinite(values[i])) range.add(values[i]);
  }
  RgbImage result;
  result.width = width;
  result.height = height;
  result.rgb.assign(values.size() * 3, 0);
  for (size_t i = 0; i < values.size(); ++i) {
    if (pixel_used(mask, i) && std::isfinite(values[i])) colour_map(range.normalised(values[i]), &result.rgb[3 * i]);
  }
  *image = std::move(result);
  return Status::Ok();
}

Status render_false_colour_plane(const std::vector<double>& values, uint32_t width, uint32_t height,
                                 const std::vector<uint8_t>* mask, const std::string& path) {
  RgbImage image;
  return save(false_colour_plane(values, width, height, mask, &image), image, path);
}

Status rgb_geometry_image(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                          uint32_t width, uint32_t height, const std::vector<uint8_t>* mask, RgbImage* image) {
  Status status = check_plane("geometry image X", x.size(), width, height);
  if (status.ok()) status = check_plane("geometry image Y", y.size(), width, height);
  if (status.ok()) status = check_plane("geometry image Z", z.size(), width, height);
  if (status.ok() && mask != nullptr) status = check_plane("geometry image mask", mask->size(), width, height);
  if (!status.ok()) return status;
  const size_t count = x.size();
  auto used = [&](size_t i) {
    return pixel_used(mask, i) && std::isfinite(x[i]) && std::isfinite(y[i]) && std::isfinite(z[i]);
  };
  Range rx, ry, rz;
  for (size_t i = 0; i < count; ++i) {
    if (!used(i)) continue;
    rx.add(x[i]);
    ry.add(y[i]);
    rz.add(z[i]);
  }
  RgbImage result;
  result.width = width;
  result.height = height;
  result.rgb.assign(count * 3, 0);
  for (size_t i = 0; i < count; ++i) {
    if (!used(i)) continue;
    result.rgb[3 * i] = to_byte(rx.normalised(x[i]));
    result.rgb[3 * i + 1] = to_byte(ry.normalised(y[i]));
    result.rgb[3 * i + 2] = to_byte(rz.normalised(z[i]));
  }
  *image = std::move(result);
  return Status::Ok();
}

Status render_rgb_geometry_image(const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<double>& z, uint32_t width, uint32_t height,
                                 const std::vector<uint8_t>* mask, const std::string& path) {
  RgbImage image;
  return save(rgb_geometry_image(x, y, z, width, height, mask, &image), image, path);
}

}  // namespace qmc::tools
