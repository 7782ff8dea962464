// Seed 000 §3.1: the initial adaptive sampling of the geometry image by
// vertex density equalization. Along each axis of the parameter rectangle the
// sample lines start as a floor(n/2) uniform partition; the strip (x-partition
// set, resp. y-partition set) holding the most parametrized vertices is then
// halved, again and again, until there are n - 1 strips, i.e. n lines. Pixel
// column i is sampled at u = column_u[i] and row j at v = row_v[j]
// (sample_geometry_image in gim_sampling.h takes exactly these).
#pragma once

#include <cstdint>
#include <vector>

namespace qmc {

// Sample lines for an n_columns x n_rows image over [0, u_max] x [0, v_max]
// (pixel units: u_max = W - 1, v_max = H - 1). `uv` holds u0 v0 u1 v1 ... of
// the parametrized vertices (DiskParametrization::uv).
//
// Output: strictly increasing lines, first 0, last u_max (resp. v_max); an
// axis of one line gets {0}. A vertex on the line between two strips counts
// in the strip to its right (the last strip is closed). Ties between equally
// full strips go to the wider one, then to the one nearer 0, so the result
// depends on the input only. A strip narrower than 1/16 of the uniform line
// spacing (u_max / (n - 1)) is never split: halving it again would only put
// two sample lines on top of each other (a vertex cluster at one u cannot be
// separated by lines); the next fullest strip is split instead. The widest
// strip is always at least the uniform spacing wide, so there is always a
// strip to split and exactly n - 1 - floor(n/2) splits are made.
void vertex_density_equalization(const std::vector<double>& uv, uint32_t n_columns, uint32_t n_rows, double u_max,
                                 double v_max, std::vector<double>* column_u, std::vector<double>* row_v);

// One axis of the above: `coordinates` are the vertices' u (or v) values.
std::vector<double> equalized_lines(std::vector<double> coordinates, uint32_t n, double extent);

}  // namespace qmc
