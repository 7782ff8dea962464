// Rate control of progressive files (spec 12.10, informative): the number of
// levels K, the base mesh's position bits and the finest level's step scale
// that give the smallest file within an error, or the most accurate file
// within a size. Every candidate is coded, decoded and measured against the
// input as `qmc compare` measures (mesh_distance.h), so the choice rests on
// the error the user will see, not on an estimate.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mesh_distance.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc::tools {

// Exactly one of the three is > 0. Errors are relative to the input's
// bounding-box diagonal, as qmc compare reports them.
struct RateTarget {
  double max_relative_l2 = 0;
  uint64_t max_bytes = 0;  // the whole file; the least L2 within it
  double max_relative_hausdorff = 0;
  bool error_target() const { return max_relative_l2 > 0 || max_relative_hausdorff > 0; }
};

// Decodes the encoder's own output `bytes` (no decoder limits) and measures
// the decoded mesh against `reference` with `samples` area samples; a file
// that does not decode is an internal error.
Status decode_and_measure(const Mesh& reference, const std::vector<uint8_t>& bytes, size_t samples,
                          DecodedFile* decoded, MeshDistance* distance);

// `qmc encode --progressive`'s K when --levels is not given: the most levels
// (up to 8) whose base keeps at least 1,000 of the mesh's triangles, at least
// 1. Smaller bases lose accuracy fast: armadillo (29,170 triangles) at K = 3
// (456 base triangles) has 3.5 times the L2 of K = 2 (docs/results/seed003.md).
int default_progressive_levels(size_t triangles);

// What the search may vary; an empty list keeps the value of the options.
// Levels are tried in the order given; bits and scales in increasing order.
struct RateSearch {
  std::vector<int> levels;           // K
  std::vector<int> position_bits;    // of the base mesh
  std::vector<double> step_scales;   // EncodeOptions::finest_step_scale
  // After the search over step_scales, this many more steps of it between
  // the two neighbouring scales where the error (error target) or the size
  // (size target) crossed the target, each at the geometric mean of the two
  // it lies between.
  int refinements = 0;
  size_t samples = MeshDistanceOptions{}.samples;  // of each error measurement
};

// The defaults: K from 6 down to 1 where the base keeps at least 64 of the
// input's triangles (deep files first: they are the small ones, and a small
// best file spares measuring larger candidates), base bits 8..13, step
// scales 1, 2, 4, ..., 64, refined twice (to within a factor 2^(1/4)).
RateSearch default_rate_search(const Mesh& mesh);

struct RatePoint {
  int levels = 0, position_bits = 0;
  double step_scale = 1;
  uint64_t bytes = 0;
  double relative_l2 = -1;  // -1: not measured (it could not beat the best so far)
  double relative_hausdorff = -1;
  std::string failure;      // why K could not be coded (e.g. the simplified base is not a manifold)
};

struct RateChoice {
  std::vector<RatePoint> tried;  // in the order tried
  int chosen = -1;               // index into tried; -1 when no candidate meets the target
  std::vector<uint8_t> bytes;    // the chosen file
  EncodeStats stats;
  DecodedFile decoded;
  MeshDistance distance;
};

// Searches `search` for `target`, starting from `options` (whose
// progressive_levels, position_bits and finest_step_scale the search sets).
// For an error target: per K, the most accurate candidate first (largest
// bits, smallest scale); a K that misses the target with it is dropped;
// then per bits a binary search for the largest scale within the error,
// continued `refinements` times between the grid's scales.
// Candidates not smaller than the best so far are not measured. For a size
// target: per K and bits, a binary search for the smallest scale whose file
// fits, continued likewise, then that file measured; the lowest error wins. A K that cannot be
// coded is listed with its reason; other errors of the encoder end the
// search. `stage` (may be empty) hears what is being done.
Status choose_progressive(const Mesh& mesh, const EncodeOptions& options, const RateTarget& target,
                          const RateSearch& search, const std::function<void(const std::string&)>& stage,
                          RateChoice* out);

}  // namespace qmc::tools
