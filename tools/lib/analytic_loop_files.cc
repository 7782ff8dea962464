// Progressive files aiming at analytic surfaces (see the header).
#include "analytic_loop_files.h"

#include <algorithm>
#include <cmath>

#include "encoder/encoder_internal.h"
#include "mesh_generators.h"

namespace qmc::tools {
namespace {

// Applies `place` to each edge point of the predicted level.
LevelTargets per_point(void (*place)(const double* q, double* t, const double* params), std::vector<double> params) {
  return [place, params](int, const LoopMesh& fine, const std::vector<double>& normals, uint32_t coarse_vertices,
                         std::vector<double>* targets) {
    targets->resize(normals.size());
    for (size_t e = 0; e < normals.size() / 3; ++e)
      place(&fine.positions[3 * (coarse_vertices + e)], &(*targets)[3 * e], params.data());
  };
}

void on_sphere(const double* q, double* t, const double*) {
  const double r = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
  for (int k = 0; k < 3; ++k) t[k] = r > 0 ? q[k] / r : q[k];
}

void on_torus(const double* q, double* t, const double* radii) {
  const double rho = std::hypot(q[0], q[1]);
  const double cx = rho > 0 ? radii[0] * q[0] / rho : radii[0], cy = rho > 0 ? radii[0] * q[1] / rho : 0;
  const double dx = q[0] - cx, dy = q[1] - cy, dz = q[2];
  const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double s = d > 0 ? radii[1] / d : 0;
  t[0] = cx + dx * s, t[1] = cy + dy * s, t[2] = dz * s;
}

void on_height_field(const double* q, double* t, const double*) {
  t[0] = q[0], t[1] = q[1], t[2] = 0.3 * std::sin(2 * q[0]) * std::cos(3 * q[1]);
}

}  // namespace

Mesh loop_octahedron() {
  Mesh m = make_octahedron();
  const double w = 3.0 / (8.0 * loop_beta(4));
  for (float& x : m.positions) x = float(x * (w + 4) / w);
  return m;
}

LevelTargets unit_sphere_targets() { return per_point(on_sphere, {}); }
LevelTargets torus_targets(double R, double r) { return per_point(on_torus, {R, r}); }
LevelTargets height_field_targets() { return per_point(on_height_field, {}); }

LevelCorrector sphere_corrections(int every, double step, std::vector<int> levels, bool list_unmoved) {
  return [=](int j, const LoopMesh& level, LevelCode* code) {
    code->correction_step = step;
    code->corrections.clear();
    if (std::find(levels.begin(), levels.end(), j) == levels.end()) return Status::Ok();
    for (uint32_t v = 0; v < level.vertex_count(); v += uint32_t(every)) {
      const double* p = &level.positions[3 * size_t(v)];
      double target[3];
      on_sphere(p, target, nullptr);
      VertexCorrection c;
      c.vertex = v;
      for (int a = 0; a < 3; ++a)
        c.offset[a] = int32_t(std::clamp(std::nearbyint((target[a] - p[a]) / step),
                                         double(-kMaxCorrectionOffset), double(kMaxCorrectionOffset)));
      if (list_unmoved || c.offset[0] != 0 || c.offset[1] != 0 || c.offset[2] != 0) code->corrections.push_back(c);
    }
    return Status::Ok();
  };
}

Status make_loop_file(const Mesh& base, int levels, const LevelTargets& targets, int bits, std::vector<uint8_t>* out,
                      EncodeStats* stats, PositionMethod base_positions, int displacement_code,
                      bool context_coded_faces, const LevelJudge* judge, const LevelCorrector* corrector) {
  EncodeOptions options;
  options.position_bits = bits;
  options.position_grid = PositionGrid::kPerAxis;  // LEVL's arithmetic starts from section 6.1's grid
  options.position_method = base_positions;
  options.candidate_choice = CandidateChoice::kNearest;  // the choice when valid_posn1_loop_base was made
  options.graded_class_start = false;                    // and its POSN method, 1 (14.4.1 and 14.6 came later)
  options.geometry_order = false;
  options.displacement_code = displacement_code;
  options.connectivity = ConnectivityChoice::kPolygon;
  options.polygon_context_coding = context_coded_faces;
  EncodeStats local;
  EncodeStats& st = stats ? *stats : local;
  FileConnectivity conn;
  if (Status s = choose_connectivity(base, options, &conn, &st); !s.ok()) return s;
  std::vector<double> positions;
  positions.reserve(base.positions.size());
  for (uint32_t v : conn.file_vertex)
    for (int k = 0; k < 3; ++k) positions.push_back(base.positions[3 * size_t(v) + k]);
  return write_loop_file(conn, positions, levels, options, targets, judge, corrector, out, &st);
}

}  // namespace qmc::tools
