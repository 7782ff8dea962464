// qmc-meshgen: writes one of the project's generated meshes to a file, e.g.
// the demo mesh data/demo/torus.obj (`qmc-meshgen torus 48 24 data/demo/torus.obj`),
// or the thesis's quad meshes: `qmc-meshgen sphere-series 5 sphere61440.obj`,
// `qmc-meshgen catmull-clark ../shared/corpus/tri/cow.obj cow17412.obj`.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "mesh_generators.h"
#include "mesh_io.h"
#include "subdivision.h"

namespace {

const char kUsage[] =
    "usage: qmc-meshgen KIND [PARAMS] OUT.{obj,off,ply}\n"
    "  tetrahedron | cube | sphere N | torus MAJOR MINOR | grid NX NY | prism N | soup SEED\n"
    "  triangle-torus MAJOR MINOR  the torus with each quad cut into two triangles\n"
    "  polygon N | book N | star N   one N-gon; N triangles on one edge; N triangles on one vertex\n"
    "  deltoidal                the 60-quad sphere (deltoidal hexecontahedron)\n"
    "  sphere-series LEVELS     it after LEVELS Catmull-Clark steps, on the unit sphere (0..10)\n"
    "  terraces N STEPS         an N x N grid of triangles in STEPS flat rings with cliffs between\n"
    "  jittered-sphere LEVELS SEED  sphere-series LEVELS in triangles, each vertex moved along the\n"
    "                           sphere by up to 0.3 of an edge: an irregular triangulation\n"
    "  catmull-clark IN         IN (a mesh file) after one Catmull-Clark step\n";

int param(int argc, char** argv, int i) {
  if (i >= argc - 1) {
    std::fputs(kUsage, stderr);
    std::exit(2);
  }
  const int v = std::atoi(argv[i]);
  if (v <= 0) {
    std::fprintf(stderr, "qmc-meshgen: '%s' is not a positive number\n", argv[i]);
    std::exit(2);
  }
  return v;
}

// Like param, but 0 is allowed (sphere-series 0 is the unrefined sphere).
int levels_param(int argc, char** argv, int i) {
  if (i >= argc - 1) {
    std::fputs(kUsage, stderr);
    std::exit(2);
  }
  char* end = nullptr;
  const long v = std::strtol(argv[i], &end, 10);
  if (end == argv[i] || *end != '\0' || v < 0 || v > 10) {
    std::fprintf(stderr, "qmc-meshgen: '%s' is not a level count from 0 to 10\n", argv[i]);
    std::exit(2);
  }
  return static_cast<int>(v);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace qmc::tools;
  if (argc < 3) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const std::string kind = argv[1];
  qmc::Mesh mesh;
  if (kind == "tetrahedron") mesh = make_tetrahedron();
  else if (kind == "cube") mesh = make_cube();
  else if (kind == "sphere") mesh = make_quad_sphere(param(argc, argv, 2));
  else if (kind == "torus") mesh = make_torus(param(argc, argv, 2), param(argc, argv, 3));
  else if (kind == "triangle-torus") mesh = triangulated(make_torus(param(argc, argv, 2), param(argc, argv, 3)));
  else if (kind == "grid") mesh = make_grid(param(argc, argv, 2), param(argc, argv, 3));
  else if (kind == "prism") mesh = make_prism(param(argc, argv, 2));
  else if (kind == "polygon") mesh = make_polygon(uint32_t(param(argc, argv, 2)));
  else if (kind == "book") mesh = make_book(uint32_t(param(argc, argv, 2)));
  else if (kind == "star") mesh = make_vertex_star(uint32_t(param(argc, argv, 2)));
  else if (kind == "soup") mesh = make_random_soup(uint64_t(param(argc, argv, 2)), RandomSoupOptions{});
  else if (kind == "deltoidal") mesh = make_deltoidal_hexecontahedron();
  else if (kind == "sphere-series") mesh = make_refined_sphere(levels_param(argc, argv, 2));
  else if (kind == "jittered-sphere")
    mesh = make_jittered_sphere(levels_param(argc, argv, 2), 0.3f, uint64_t(param(argc, argv, 3)));
  else if (kind == "terraces") mesh = make_terraces(uint32_t(param(argc, argv, 2)), uint32_t(param(argc, argv, 3)), 9);
  else if (kind == "catmull-clark") {
    if (argc != 4) {
      std::fputs(kUsage, stderr);
      return 2;
    }
    qmc::Mesh input;
    std::vector<std::string> warnings;
    if (qmc::Status s = read_mesh(argv[2], &input, &warnings); !s.ok()) {
      std::fprintf(stderr, "qmc-meshgen: %s\n", s.to_string().c_str());
      return 3;
    }
    for (const std::string& w : warnings) std::fprintf(stderr, "qmc-meshgen: %s: %s\n", argv[2], w.c_str());
    if (qmc::Status s = catmull_clark(input, &mesh); !s.ok()) {
      std::fprintf(stderr, "qmc-meshgen: %s: %s\n", argv[2], s.to_string().c_str());
      return 3;
    }
  } else {
    std::fputs(kUsage, stderr);
    return 2;
  }
  if (qmc::Status s = write_mesh(argv[argc - 1], mesh); !s.ok()) {
    std::fprintf(stderr, "qmc-meshgen: %s\n", s.to_string().c_str());
    return 3;
  }
  std::printf("%s: %zu vertices, %zu faces\n", argv[argc - 1], mesh.vertex_count(), mesh.face_count());
  return 0;
}
