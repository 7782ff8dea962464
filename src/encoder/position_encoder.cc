// Positions of spec/qmc-format.md sections 6 and 14. The seed (001 §2.6)
// maps the range onto 0..2^n; we use 0..2^n-1 so that every value fits in
// n bits.
#include "encoder/position_encoder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/exact_arith.h"
#include "common/geometry_order.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "common/mirror_prediction.h"
#include "common/position_coding.h"
#include "common/range_coder.h"
#include "common/surface_lattice.h"
#include "common/vertex_prediction.h"
#include "encoder/occupied_blocks.h"
#include "encoder/residual_costs.h"

namespace qmc {
namespace {

constexpr uint8_t kPredictedSelector = 0x81, kGradedSelector = 0x83;  // methods 1 and 3 (section 14.1)
constexpr uint8_t kGeometryOrderSelector = 0x84;                         // method 4 (14.1, 14.6)
constexpr uint8_t kQuadTwistSelector = 0x85;                             // method 5 (14.1, 14.7)
constexpr uint8_t kMaskContextSelectors[2] = {0x86, 0x87};               // methods 6 and 7 (14.1, 14.8)
constexpr uint8_t kFeaturesSelector = 0x88;                              // method 8 (14.1, 14.9)
constexpr uint8_t kMirrorSelector = 0x89;                                // method 9 (14.1, 14.10)
constexpr uint8_t kNearMirrorSelector = 0x8A;                            // method 10 (14.1, 14.11)
constexpr uint8_t kShearSelector = 0x8B;                                 // method 11 (14.1, 14.12)
constexpr uint8_t kExtrapolationSelector = 0x8C;                         // method 12 (14.1, 14.13)
constexpr uint8_t kAxisClassSelector = 0x8D;                             // method 13 (14.1, 14.14)
constexpr uint8_t kLatticeSelector = 0x8E;                               // method 14 (14.1, 14.15)
constexpr uint32_t kMaxTop = (uint32_t(1) << 30) - 1;

void bounding_box(const std::vector<float>& positions, QuantizedPositions* out) {
  const size_t n = positions.size() / 3;
  for (int a = 0; a < 3; ++a) {
    out->min[a] = n ? positions[a] : 0.f;
    out->max[a] = out->min[a];
  }
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      out->min[a] = std::min(out->min[a], positions[3 * i + a]);
      out->max[a] = std::max(out->max[a], positions[3 * i + a]);
    }
}

// Rounds every coordinate to the grid of out's min (origin) and step.
void round_to_grid(const std::vector<float>& positions, QuantizedPositions* out) {
  out->q.resize(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const int a = int(i % 3);
    const double v = out->step[a] > 0 ? std::nearbyint((double(positions[i]) - out->min[a]) / out->step[a]) : 0.0;
    out->q[i] = uint32_t(std::clamp(v, 0.0, double(out->top[a])));
  }
  int bits = 0;
  for (int a = 0; a < 3; ++a) {
    out->max[a] = float(double(out->min[a]) + mul(double(out->top[a]), out->step[a]));
    bits = std::max(bits, bit_length(out->top[a]));
  }
  if (!out->per_axis_bits) out->bits = bits;
}

std::string shortest(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// One step on every axis: the tops follow from the box.
Status uniform_grid(double step, const char* what, QuantizedPositions* out) {
  for (int a = 0; a < 3; ++a) {
    const double side = double(out->max[a]) - double(out->min[a]);
    const double top = step > 0 ? std::nearbyint(side / step) : 0.0;
    if (!(top <= kMaxTop))
      return Status(ErrorCode::kInvalidArgument, std::string(what) + " needs " + shortest(top) + " steps on axis " +
                                                     std::to_string(a) + "; the format allows 2^30 - 1 (section 14.1)");
    out->step[a] = step;
    out->top[a] = uint32_t(top);
  }
  return Status::Ok();
}

// The largest step whose rounding (half the cell's diagonal) plus the
// binary32 rounding of the output (half an ulp per axis) stays within e.
double step_for_error(const QuantizedPositions& box, double e) {
  double ulp_sq = 0;
  for (int a = 0; a < 3; ++a) {
    const float far = std::max(std::fabs(box.min[a]), std::fabs(box.max[a]));
    const double half_ulp = 0.5 * (double(std::nextafter(far, INFINITY)) - double(far));
    ulp_sq += half_ulp * half_ulp;
  }
  const double room = e - std::sqrt(ulp_sq);
  return room > 0 ? 2 * room / std::sqrt(3.0) : 0;
}

}  // namespace

QuantizedPositions quantize_positions(const std::vector<float>& positions, int bits) {
  QuantizedPositions out;
  out.bits = bits;
  out.per_axis_bits = true;
  bounding_box(positions, &out);
  const double top = double((uint64_t(1) << bits) - 1);
  for (int a = 0; a < 3; ++a) {
    out.step[a] = (double(out.max[a]) - double(out.min[a])) / top;
    out.top[a] = uint32_t(top);
  }
  // Section 6.1 rounds (x - min) / range x top, which is not always the
  // same as (x - min) / step.
  out.q.resize(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const int a = int(i % 3);
    const double range = double(out.max[a]) - double(out.min[a]);
    const double v = range > 0 ? std::nearbyint((double(positions[i]) - out.min[a]) / range * top) : 0.0;
    out.q[i] = uint32_t(std::clamp(v, 0.0, top));
  }
  return out;
}

Status quantize_positions(const std::vector<float>& positions, const EncodeOptions& options,
                          QuantizedPositions* out) {
  if (options.position_step <= 0 && options.max_position_error <= 0 &&
      options.position_grid == PositionGrid::kPerAxis) {
    *out = quantize_positions(positions, options.position_bits);
    return Status::Ok();
  }
  *out = QuantizedPositions{};
  bounding_box(positions, out);
  Status s;
  if (options.max_position_error > 0) {
    const double step = step_for_error(*out, options.max_position_error);
    if (step <= 0)
      return Status(ErrorCode::kInvalidArgument, "max error " + std::to_string(options.max_position_error) +
                                                     " is below binary32's own rounding of these coordinates");
    s = uniform_grid(step, "the max error", out);
  } else if (options.position_step > 0) {
    s = uniform_grid(options.position_step, "the step", out);
  } else {
    double side = 0;
    for (int a = 0; a < 3; ++a) side = std::max(side, double(out->max[a]) - double(out->min[a]));
    s = uniform_grid(side / double((uint64_t(1) << options.position_bits) - 1), "the bits", out);
  }
  if (!s.ok()) return s;
  round_to_grid(positions, out);
  return Status::Ok();
}

Status set_surface_lattice(const Mesh& mesh, int k, QuantizedPositions* positions) {
  if (k < kLatticeLeastFactor || k > kLatticeLargestFactor)
    return Status(ErrorCode::kInvalidArgument, "the surface lattice's factor " + std::to_string(k) +
                                                   " is outside 2..16 (spec 14.15)");
  for (int a = 0; a < 3; ++a)
    if (positions->top[a] >= kLatticeTopBound)
      return Status(ErrorCode::kInvalidArgument,
                    "the surface lattice (spec 14.15) needs a grid of at most 2^24 points per axis; axis " +
                        std::to_string(a) + " has " + std::to_string(uint64_t(positions->top[a]) + 1));
  const size_t n = positions->q.size() / 3;
  positions->lattice = k;
  positions->x.resize(3 * n);
  for (size_t i = 0; i < 3 * n; ++i) {
    const int a = int(i % 3);
    const double step = positions->step[a] > 0 ? positions->step[a] : 1.0;
    positions->x[i] = (double(mesh.positions[i]) - double(positions->min[a])) / step;
  }
  // Area-weighted normals in grid steps (on a per-axis grid the surface's
  // normal in grid steps is not its normal in model units), polygons fanned
  // from their first corner.
  std::vector<double>& normal = positions->normal;
  normal.assign(3 * n, 0.0);
  const std::vector<double>& p = positions->x;
  size_t corner = 0;
  for (const uint32_t degree : mesh.face_sizes) {
    const uint32_t* c = &mesh.corners[corner];
    for (uint32_t j = 1; j + 1 < degree; ++j) {
      double e[3], f[3];
      for (int a = 0; a < 3; ++a) {
        e[a] = p[3 * size_t(c[j]) + a] - p[3 * size_t(c[0]) + a];
        f[a] = p[3 * size_t(c[j + 1]) + a] - p[3 * size_t(c[0]) + a];
      }
      const double cross[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
      for (const uint32_t v : {c[0], c[j], c[j + 1]})
        for (int a = 0; a < 3; ++a) normal[3 * size_t(v) + a] += cross[a];
    }
    corner += degree;
  }
  for (size_t v = 0; v < n; ++v) {
    double* m = &normal[3 * v];
    const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (int a = 0; a < 3; ++a) m[a] = length > 0 ? m[a] / length : 0.0;
  }
  return Status::Ok();
}

std::vector<uint8_t> encode_positions(const QuantizedPositions& positions) {
  const size_t n = positions.q.size() / 3;
  std::vector<uint8_t> payload;
  put_varint(&payload, n);
  put_u8(&payload, uint8_t(positions.bits));
  for (int a = 0; a < 3; ++a) put_f32le(&payload, positions.min[a]);
  for (int a = 0; a < 3; ++a) put_f32le(&payload, positions.max[a]);
  if (n == 0) return payload;

  // Deltas from the previous vertex in file order, the first from zero.
  std::vector<int32_t> delta(positions.q.size());
  std::vector<std::vector<uint64_t>> freq(3, std::vector<uint64_t>(positions.bits + 1, 0));
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const int64_t prev = i ? int64_t(positions.q[3 * (i - 1) + a]) : 0;
      const int32_t d = int32_t(int64_t(positions.q[3 * i + a]) - prev);
      delta[3 * i + a] = d;
      ++freq[a][magnitude_class(uint32_t(d < 0 ? -d : d))];
    }
  BitWriter bits;
  std::vector<HuffmanEncoder> codes;
  for (int a = 0; a < 3; ++a) {
    const std::vector<uint8_t> lengths = huffman_code_lengths(freq[a]);
    write_code_lengths(&bits, lengths);
    codes.emplace_back(lengths);
  }
  for (size_t i = 0; i < 3 * n; ++i) {
    const int32_t d = delta[i];
    const int c = magnitude_class(uint32_t(d < 0 ? -d : d));
    codes[i % 3].write(&bits, uint32_t(c));
    write_signed_extra(&bits, d, c);
  }
  const std::vector<uint8_t> stream = bits.finish();
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

namespace {

// The range encoder, also adding up each decision's information content
// (CostMeter's, before the decision adapts the probability) for
// PositionStats.
class MeteredRangeEncoder {
 public:
  int code(int bit, uint16_t* prob) {
    meter.code(bit, prob);
    return rc.code(bit, prob);
  }
  int code_direct(int bit) {
    meter.code_direct(bit);
    return rc.code_direct(bit);
  }
  int code_fixed(int bit, uint32_t prob) {
    meter.code_fixed(bit, prob);
    return rc.code_fixed(bit, prob);
  }
  void adapt(uint16_t* prob, int bit) { rc.adapt(prob, bit); }
  RangeEncoder rc;
  CostMeter meter;
};

// The subset of the candidates (14.3.3) chosen as 14.5 says: the mask and
// residuals cheapest under the current probabilities, or the prediction
// nearest to the vertex (L1); ties go to the lower mask. Leaves *p
// selected with that mask (select_candidates).
//
// The mask of all candidates, the one most often cheapest, is costed first
// and the others after it in ascending order: a mask stops being costed once
// it cannot win (costs only add up), and a good first bound stops most of
// them after an axis or two. The choice is the same as in ascending order.
// all_selected: p already holds the selection of every candidate (the
// mirror candidate's reference, 14.10), which is not made again. bits, if
// given, gets the chosen mask's and residuals' bits when they were costed
// (fewest bits, two or more candidates), else NAN.
unsigned best_candidates(const uint32_t* q, const uint32_t* top, PositionResidualModel* model, CandidateChoice choice,
                         int context, VertexPrediction* p, bool all_selected = false, double* bits = nullptr) {
  if (bits) *bits = NAN;
  if (p->candidates < 2) {
    const unsigned only = p->candidates == 1 ? 1u : 0u;
    if (!all_selected) select_candidates(p, only, top);
    return only;
  }
  const unsigned all = (1u << p->candidates) - 1;
  unsigned best = all;
  double best_cost = INFINITY;
  int64_t best_value[3] = {0, 0, 0}, best_mean[3] = {0, 0, 0}, best_twist[3] = {0, 0, 0};
  PredictionKind best_kind = PredictionKind::kPrevious;
  const bool fewest_bits = choice == CandidateChoice::kFewestBits;
  ResidualCosts residual_costs(*model);
  for (unsigned k = 0; k < all; ++k) {
    const unsigned mask = k == 0 ? all : k;
    // Against a higher mask (only `all` is costed before a lower one) a tie wins.
    const auto wins = [&](double cost) { return cost < best_cost || (cost == best_cost && mask < best); };
    if (mask != all || !all_selected) select_candidates(p, mask, top);
    CostMeter meter;
    double distance = 0;
    const auto cost = [&] { return fewest_bits ? meter.bits : distance; };
    if (fewest_bits) code_candidate_mask(&meter, model, p->candidates, mask, context);
    uint32_t magnitude[3] = {0, 0, 0};
    for (int a = 0; a < 3 && wins(cost()); ++a) {
      const int64_t r = int64_t(q[a]) - p->value[a];
      magnitude[a] = uint32_t(r < 0 ? -r : r);
      distance += magnitude[a];
      if (fewest_bits) meter.bits += residual_costs.axis(*p, magnitude, a, r < 0);
    }
    if (wins(cost())) {
      best_cost = cost();
      best = mask;
      std::copy(p->value, p->value + 3, best_value);
      std::copy(p->mean, p->mean + 3, best_mean);
      std::copy(p->twist_mean, p->twist_mean + 3, best_twist);
      best_kind = p->kind;
    }
  }
  std::copy(best_value, best_value + 3, p->value);
  std::copy(best_mean, best_mean + 3, p->mean);
  std::copy(best_twist, best_twist + 3, p->twist_mean);
  p->kind = best_kind;
  if (bits && fewest_bits) *bits = best_cost;
  return best;
}

// 14.4's residuals of the vertex q (3 integers) predicted by p, coded by
// coder (an encoder, or a CostMeter to price them); their activity.
// With 14.15's lattice (divisor: the steps per axis, q on the lattice, so
// every residual a multiple of its step) axis a's residual is coded in
// steps of divisor[a]; the activity stays in grid steps.
template <class Coder>
uint32_t code_residuals(Coder* coder, PositionResidualModel* model, const VertexPrediction& p, const uint32_t* q,
                        const int* divisor = nullptr) {
  uint32_t magnitude[3] = {0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    const int64_t r = int64_t(q[a]) - p.value[a];
    magnitude[a] = uint32_t(r < 0 ? -r : r);
    const int step = divisor ? divisor[a] : 1;
    const uint32_t coded = step == 1 ? magnitude[a] : magnitude[a] / uint32_t(step);
    code_position_residual(coder, model, p, magnitude, a, SignedResidual{coded, r < 0}, step);
  }
  return magnitude[0] + magnitude[1] + magnitude[2];
}

// 14.15 (informative part): the lattice point for a vertex at x (grid
// units) with unit normal n, predicted at P, its fine axis `fine`. Across
// the fine axis every multiple of k from P within k steps of x and inside
// the grid is tried; along it, the grid point that takes back what those
// moved along n (at most k - 1/2 steps). Of these, the one whose move is
// smallest along n, then across the surface (weight kAcross), then whose
// residuals are shortest (weight kShorter): on stanford-bunny at 12 bits
// with k = 4 the weights 0.02 and 0.05 gave the smallest positions whose
// distance to the input's surface (L2) is the grid's.
constexpr double kAcross = 0.02, kShorter = 0.05;

void place_on_lattice(const double* x, const double* n, const int64_t P[3], const uint32_t top[3], int k, int fine,
                      uint32_t* q) {
  const int across[2] = {fine == 0 ? 1 : 0, fine == 2 ? 1 : 2};
  int64_t first[2], last[2];
  for (int j = 0; j < 2; ++j) {
    const int a = across[j];
    first[j] = int64_t(std::ceil((x[a] - double(k) - double(P[a])) / k));
    last[j] = int64_t(std::floor((x[a] + double(k) - double(P[a])) / k));
  }
  double best = std::numeric_limits<double>::infinity();
  int64_t point[3] = {P[0], P[1], P[2]};  // P is on the grid: the fallback
  for (int64_t m0 = first[0]; m0 <= last[0]; ++m0)
    for (int64_t m1 = first[1]; m1 <= last[1]; ++m1) {
      int64_t c[3];
      c[across[0]] = P[across[0]] + k * m0;
      c[across[1]] = P[across[1]] + k * m1;
      if (c[across[0]] < 0 || c[across[0]] > int64_t(top[across[0]]) || c[across[1]] < 0 ||
          c[across[1]] > int64_t(top[across[1]]))
        continue;
      const double moved = (double(c[across[0]]) - x[across[0]]) * n[across[0]] +
                           (double(c[across[1]]) - x[across[1]]) * n[across[1]];
      const double limit = double(k) - 0.5;
      const double back = std::fabs(n[fine]) > 1e-9 ? std::clamp(moved / n[fine], -limit, limit) : 0.0;
      c[fine] = std::clamp<int64_t>(std::llround(x[fine] - back), 0, int64_t(top[fine]));
      double e[3], along = 0, length = 0, shorter = 0;
      for (int a = 0; a < 3; ++a) {
        e[a] = double(c[a]) - x[a];
        along += e[a] * n[a];
        length += e[a] * e[a];
        shorter += std::log2(1.0 + std::fabs(double(c[a] - P[a])) / (a == fine ? 1 : k));
      }
      const double cost = along * along + kAcross * (length - along * along) + kShorter * shorter;
      if (cost < best) best = cost, std::copy(c, c + 3, point);
    }
  for (int a = 0; a < 3; ++a) q[a] = uint32_t(point[a]);
}

// 14.10 for the vertex q (3 integers) with p's candidates: whether its
// mirror candidate (if it has one) is used, priced against the mask
// best_candidates chooses (p is left selected with that mask, *mask set);
// the decision is coded, and when true p predicts by the candidate.
bool code_mirror_choice(MeteredRangeEncoder* rc, PositionResidualModel* model, const MirrorSource& mirrors,
                        uint32_t v, const std::vector<uint32_t>& q, const uint32_t top[3], CandidateChoice choice,
                        VertexPrediction* p, unsigned* mask) {
  select_candidates(p, (1u << p->candidates) - 1, top);  // the reference: every candidate
  int64_t candidate[3];
  const bool has_candidate = mirrors.find(v, q.data(), *p, candidate);
  const int mirror = has_candidate ? mirror_context(candidate, p->value) : 0;
  const int context = mask_context(*model, *p);
  double plain_bits;
  *mask = best_candidates(&q[3 * size_t(v)], top, model, choice, context, p, true, &plain_bits);
  if (!has_candidate) return false;
  // best_candidates changed only what the mirror candidate replaces (value,
  // mean, kind); the bucket's inputs (activity, scale) are v's.
  VertexPrediction mirrored = *p;
  mirrored.kind = PredictionKind::kMirror;
  std::copy(candidate, candidate + 3, mirrored.value);
  CostMeter use, plain;
  use.code(1, &model->mirror[mirror]);
  code_residuals(&use, model, mirrored, &q[3 * size_t(v)]);
  plain.code(0, &model->mirror[mirror]);
  if (std::isnan(plain_bits)) {  // not costed by best_candidates: priced here
    code_candidate_mask(&plain, model, p->candidates, *mask, context);
    code_residuals(&plain, model, *p, &q[3 * size_t(v)]);
  } else {
    plain.bits += plain_bits;
  }
  const bool used = use.bits < plain.bits;
  rc->code(used, &model->mirror[mirror]);
  if (used) *p = mirrored;
  return used;
}

// 14.12: the shear is weighed on meshes of this many vertices or more (on
// the corpus it pays on none under 1,000: cathead's POSN 2 bytes smaller at
// best, for more passes than its whole encode), over the first kShearPrefix
// vertices of the order, where a weight must save kShearMargin of their
// bits (512 vertices choose as 1,024 do on the corpus at 12 and 16 bits,
// 256 miss lilium's and fertility's weights at 16). The corpus's triangle
// meshes at 12 bits, the weight written and POSN against method 10 or
// below: cow 12 (4.6 % smaller), lilium 8 (3.4 %), bunny_small 8, fertility
// 8, armadillo 16 (1.6 - 1.9 %); stanford-bunny, face, beetle and camelhead
// lose with any weight and stay as they were.
constexpr uint32_t kShearFrom = 1000, kShearPrefix = 512;
constexpr double kShearMargin = 0.995;

// 14.2 - 14.4 over a visit built for q's vertices (its order, guide and
// twist set; 14.12's shear its own), with 14.8's mask contexts or not, with
// 14.10's mirror candidate where a plane is given, with 15.14's twin
// candidate where twins are; coded as far as asked, so that the encoder can
// code the first vertices of a visit in several ways and carry on with the
// one it keeps. Its statistics start from `stats`.
class VisitCoder {
 public:
  // With a lattice (14.15: positions whose lattice is k > 1), the vertices
  // are placed on it as they are coded, in a copy of q.
  VisitCoder(const std::vector<uint32_t>& q, const uint32_t top[3], PredictionVisit* visit, const PositionStats& stats,
             CandidateChoice choice, ClassStart start, bool mask_contexts, const MirrorPlane* mirror,
             const AttributeTwins* twins, int shear, bool axis_classes = false,
             const QuantizedPositions* lattice = nullptr)
      : q_(q), top_(top), visit_(visit), stats_(stats), choice_(choice), shear_(shear),
        activity_(q.size() / 3), model_(top, start, mask_contexts, axis_classes) {
    if (mirror) mirrors_.reset(images_ = new MirrorCandidates(visit->mesh(), *mirror, top));
    if (twins) mirrors_ = std::make_unique<ValueTwins>(visit->mesh(), *twins, top);
    deferred_ = mirrors_ && mirrors_->prefetches();  // as the decoder (decode_predicted_grid)
    if (lattice && lattice->lattice > 1) {
      lattice_ = lattice;
      placed_ = q;
      model_.start_lattice_classes(start);
    }
  }

  // Codes the vertices up to the limit-th of the visit (all if it has fewer).
  void code(uint32_t limit) {
    visit_->shear(shear_);
    for (const uint32_t n = std::min(uint32_t(q_.size() / 3), limit); next_ < n; ++next_) code_vertex(next_);
  }
  // The information content coded so far.
  double bits() const { return rc_.meter.bits; }
  int shear() const { return shear_; }
  // The grid points coded: q, or with a lattice where it placed them.
  const std::vector<uint32_t>& coded() const { return lattice_ ? placed_ : q_; }
  // Codes the rest; the stream, and the statistics of the whole visit.
  std::vector<uint8_t> finish(PositionStats* stats) {
    code(UINT32_MAX);
    settle_mirror_bookkeeping();
    if (images_) stats_.pairs_beside += images_->pairs_beside();
    if (stats) *stats = stats_;
    return rc_.rc.finish();
  }

 private:
  void code_vertex(uint32_t i) {
    const uint32_t v = visit_->item(i);
    const std::vector<uint32_t>& q = coded();
    visit_->predict(i, q.data(), activity_.data(), top_, &p_);
    settle_mirror_bookkeeping();
    twist_weight_.apply(&p_);
    const double before = rc_.meter.bits;
    unsigned mask = 0;
    const bool mirrored =
        mirrors_ && code_mirror_choice(&rc_, &model_, *mirrors_, v, q, top_, choice_, &p_, &mask);
    if (!mirrors_) mask = best_candidates(&q[3 * size_t(v)], top_, &model_, choice_, mask_context(model_, p_), &p_);
    if (!mirrored) code_candidate_mask(&rc_, &model_, p_.candidates, mask, mask_context(model_, p_));
    activity_[v] = lattice_ ? code_on_lattice(v, i) : code_residuals(&rc_, &model_, p_, &q[3 * size_t(v)]);
    if (!mirrored) twist_weight_.learn(p_, &q[3 * size_t(v)]);
    if (deferred_) {
      mirrors_->prefetch(v, q.data());
      pending_ = v;
    } else if (mirrors_) {
      mirrors_->decoded(v, q.data());
    }
    ++stats_.vertices_by_kind[int(p_.kind)];
    stats_.bits_by_kind[int(p_.kind)] += rc_.meter.bits - before;
    if (p_.extrapolated) ++stats_.extrapolated_vertices;
  }

  // The mirror bookkeeping of the vertex coded last, where it waited for
  // its prefetched slots (large meshes only: MirrorSource::prefetches).
  void settle_mirror_bookkeeping() {
    if (pending_ == GridPointTable::kNone) return;
    mirrors_->decoded(pending_, coded().data());
    pending_ = GridPointTable::kNone;
  }

  // 14.15: v (the i-th visited) placed on its lattice around p_ and its
  // residuals coded; without a fine axis (N = 0), v's grid point as it is.
  uint32_t code_on_lattice(uint32_t v, uint32_t i) {
    uint32_t* q = &placed_[3 * size_t(v)];
    const int fine = lattice_fine_axis(*visit_, v, i, placed_.data(), p_.value);
    if (fine < 0) return code_residuals(&rc_, &model_, p_, q);
    const int k = lattice_->lattice;
    place_on_lattice(&lattice_->x[3 * size_t(v)], &lattice_->normal[3 * size_t(v)], p_.value, top_, k, fine, q);
    const int divisor[3] = {fine == 0 ? 1 : k, fine == 1 ? 1 : k, fine == 2 ? 1 : k};
    return code_residuals(&rc_, &model_, p_, q, divisor);
  }

  const std::vector<uint32_t>& q_;
  const QuantizedPositions* lattice_ = nullptr;
  std::vector<uint32_t> placed_;  // with a lattice: the points coded so far, the input's after them
  const uint32_t* top_;
  PredictionVisit* visit_;
  PositionStats stats_;
  CandidateChoice choice_;
  int shear_;
  uint32_t next_ = 0;
  std::vector<uint32_t> activity_;
  PositionResidualModel model_;
  MeteredRangeEncoder rc_;
  VertexPrediction p_;
  TriangleTwistWeight twist_weight_;  // 14.9: no correction without the triangle twist
  std::unique_ptr<MirrorSource> mirrors_;
  MirrorCandidates* images_ = nullptr;
  bool deferred_ = false;  // large meshes: each vertex's mirror bookkeeping waits for the next prediction
  uint32_t pending_ = GridPointTable::kNone;  // the vertex whose bookkeeping waits
};

// A whole visit, coded at once (VisitCoder); stats (may be null) gain its counts.
std::vector<uint8_t> encode_visit(const std::vector<uint32_t>& q, const uint32_t top[3], PredictionVisit& visit,
                                  PositionStats* stats, CandidateChoice choice, ClassStart start,
                                  bool mask_contexts = false, const MirrorPlane* mirror = nullptr,
                                  const AttributeTwins* twins = nullptr, bool axis_classes = false,
                                  const QuantizedPositions* lattice = nullptr) {
  VisitCoder coder(q, top, &visit, stats ? *stats : PositionStats{}, choice, start, mask_contexts, mirror, twins,
                   visit.shear(), axis_classes, lattice);
  return coder.finish(stats);
}

// 14.1: where the selector is in a predicted POSN payload (after vertex_count).
size_t selector_offset(const QuantizedPositions& positions) {
  std::vector<uint8_t> count;
  put_varint(&count, positions.q.size() / 3);
  return count.size();
}

// 14.1: the payload of a predicted POSN, its header and the stream; empty
// when the vertices cost too little for 14.1's bound.
std::vector<uint8_t> predicted_payload(const QuantizedPositions& positions, ClassStart start, PredictionOrder order,
                                       bool quad_twist, bool mask_contexts, bool triangle_twist,
                                       const MirrorPlane* mirror, const std::vector<uint8_t>& stream,
                                       int shear = 0, bool extrapolate = false, bool axis_classes = false) {
  const uint32_t n = uint32_t(positions.q.size() / 3);
  if (!range_stream_justifies(n, stream.size())) return {};
  std::vector<uint8_t> payload;
  put_varint(&payload, n);
  const bool lattice = positions.lattice > 1;  // method 14, which has 12's and 13's rules (14.15)
  if (order == PredictionOrder::kGeometry && (shear > 0 || extrapolate || axis_classes || lattice)) {  // 11 - 14
    put_u8(&payload, lattice        ? kLatticeSelector
                     : axis_classes ? kAxisClassSelector
                     : extrapolate  ? kExtrapolationSelector
                                    : kShearSelector);
    put_u8(&payload, start == ClassStart::kGraded ? 1 : 0);
    put_u8(&payload, position_features(quad_twist, mask_contexts, triangle_twist));
    put_u8(&payload, uint8_t(shear));
    put_u8(&payload, !mirror ? 0 : mirror->near_images ? 2 : 1);
    if (lattice) put_u8(&payload, uint8_t(positions.lattice));
    if (mirror) {
      put_u8(&payload, uint8_t(mirror->axis));
      put_varint(&payload, mirror->sum);
    }
  } else if (order == PredictionOrder::kGeometry && (triangle_twist || mirror)) {
    put_u8(&payload, !mirror ? kFeaturesSelector : mirror->near_images ? kNearMirrorSelector : kMirrorSelector);
    put_u8(&payload, start == ClassStart::kGraded ? 1 : 0);
    put_u8(&payload, position_features(quad_twist, mask_contexts, triangle_twist));
    if (mirror) {
      put_u8(&payload, uint8_t(mirror->axis));
      put_varint(&payload, mirror->sum);
    }
  } else if (order == PredictionOrder::kGeometry) {
    if (mask_contexts)
      put_u8(&payload, kMaskContextSelectors[quad_twist ? 1 : 0]);
    else
      put_u8(&payload, quad_twist ? kQuadTwistSelector : kGeometryOrderSelector);
    put_u8(&payload, start == ClassStart::kGraded ? 1 : 0);
  } else {
    put_u8(&payload, start == ClassStart::kGraded ? kGradedSelector : kPredictedSelector);
  }
  const bool one_step = positions.step[0] == positions.step[1] && positions.step[1] == positions.step[2];
  put_u8(&payload, one_step ? 0 : 1);
  for (int a = 0; a < 3; ++a) put_f32le(&payload, positions.min[a]);
  for (int a = 0; a < (one_step ? 1 : 3); ++a) put_f64le(&payload, positions.step[a]);
  for (int a = 0; a < 3; ++a) put_varint(&payload, positions.top[a]);
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

}  // namespace

// 14.2 - 14.4 in label order or 14.6's geometry order.
std::vector<uint8_t> encode_predicted_grid(const std::vector<uint32_t>& q, const uint32_t top[3], const Mesh& faces,
                                           PositionStats* stats, CandidateChoice choice, ClassStart start,
                                           PredictionOrder order, const PositionGuide* guide, bool quad_twist,
                                           bool mask_contexts, bool triangle_twist, const AttributeTwins* twins) {
  VertexCorners corners;
  corners.build(uint32_t(q.size() / 3), faces.face_sizes, faces.corners);
  PredictionVisit visit(corners, order);
  visit.guide_by(guide);
  visit.twist_quads(quad_twist);
  visit.twist_triangles(triangle_twist);
  return encode_visit(q, top, visit, stats, choice, start, mask_contexts, nullptr, twins);
}

std::vector<uint8_t> encode_predicted_positions(const QuantizedPositions& positions, const Mesh& faces,
                                                PositionStats* stats, CandidateChoice choice, ClassStart start,
                                                PredictionOrder order, bool quad_twist, bool mask_contexts,
                                                bool triangle_twist, const MirrorPlane* mirror, int shear,
                                                bool extrapolate, bool axis_classes) {
  mask_contexts = mask_contexts && order == PredictionOrder::kGeometry;
  triangle_twist = triangle_twist && order == PredictionOrder::kGeometry;
  if (order != PredictionOrder::kGeometry) mirror = nullptr, shear = 0, extrapolate = false, axis_classes = false;
  const QuantizedPositions* lattice = order == PredictionOrder::kGeometry && positions.lattice > 1 ? &positions : nullptr;
  if (lattice) axis_classes = true;      // method 14 has 14.14's tables (14.15)
  if (axis_classes) extrapolate = true;  // method 13 has 14.13's rule (14.14)
  VertexCorners corners;
  corners.build(uint32_t(positions.q.size() / 3), faces.face_sizes, faces.corners);
  PredictionVisit visit(corners, order);
  visit.twist_quads(quad_twist);
  visit.twist_triangles(triangle_twist);
  visit.shear(shear);
  visit.extrapolate_edges(extrapolate);
  return predicted_payload(
      positions, start, order, quad_twist, mask_contexts, triangle_twist, mirror,
      encode_visit(positions.q, positions.top.data(), visit, stats, choice, start, mask_contexts, mirror, nullptr,
                   axis_classes, lattice),
      shear, extrapolate, axis_classes);
}

// find_mirror_plane's screen: every plane tried on about kMirrorScreen
// vertices, those that map 1/16 of them onto vertices on about
// kMirrorSample, the best of those on all (1/8 needed, 1/16 below
// kGradedStartBelow vertices), then with method 10 from kGradedStartBelow
// vertices on counting the points within a step too. A mesh without a plane
// costs a table of its points, one of (a sample of) its columns per axis,
// and 18 x kMirrorScreen look-ups, 27 times as many more in that pass.
constexpr uint32_t kMirrorScreen = 128, kMirrorSample = 1024, kMirroredShareDivisor = 8;

namespace {

// The sum q[axis] + q'[axis] most pairs of vertices make that are equal on
// the other two axes (each vertex paired with the first one there): a
// plane away from the middle of the bounding box, where a part on one side
// of it sticks out further than its image (penguin_control_mesh's wings).
// Above kPairedColumns vertices, only the columns (points of the other two
// axes) of one hash class in n / kPairedColumns are looked at: a pair shares
// its column, so the sample keeps whole pairs. False if no two vertices pair.
constexpr uint32_t kPairedColumns = 4096;

bool most_paired_sum(const QuantizedPositions& positions, int axis, uint32_t* sum) {
  const uint32_t n = uint32_t(positions.q.size() / 3);
  const uint32_t classes = std::max<uint32_t>(1, n / kPairedColumns);
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  std::vector<uint32_t> sampled;
  for (uint32_t v = 0; v < n; ++v) {
    const uint32_t* q = &positions.q[3 * size_t(v)];
    if ((uint32_t(q[u] * 0x9E3779B1u ^ q[w] * 0x85EBCA77u) >> 16) % classes == 0) sampled.push_back(v);
  }
  GridPointTable columns(uint32_t(sampled.size()));
  std::vector<uint32_t> sums;
  for (const uint32_t v : sampled) {
    const uint32_t* q = &positions.q[3 * size_t(v)];
    uint32_t column[3] = {q[0], q[1], q[2]};
    column[axis] = 0;
    const uint32_t first = columns.insert(column, v);
    if (first != GridPointTable::kNone) sums.push_back(positions.q[3 * size_t(first) + size_t(axis)] + q[axis]);
  }
  if (sums.empty()) return false;
  std::sort(sums.begin(), sums.end());
  size_t best = 0;
  for (size_t i = 0, run = 0; i < sums.size(); i += run) {
    run = size_t(std::upper_bound(sums.begin() + i, sums.end(), sums[i]) - (sums.begin() + i));
    if (run > best) {
      best = run;
      *sum = sums[i];
    }
  }
  return true;
}

// The planes find_mirror_plane screens on one axis: sums top - 2 .. top + 2
// (a plane through the middle of the bounding box, rounded either way) and
// the sum most pairs of vertices make.
std::vector<uint32_t> candidate_sums(const QuantizedPositions& positions, int axis) {
  const int64_t top = positions.top[size_t(axis)];
  std::vector<uint32_t> sums;
  for (int64_t sum = std::max<int64_t>(0, top - 2); sum <= top + 2; ++sum) sums.push_back(uint32_t(sum));
  uint32_t paired = 0;
  if (most_paired_sum(positions, axis, &paired) && std::find(sums.begin(), sums.end(), paired) == sums.end())
    sums.push_back(paired);
  return sums;
}

}  // namespace

bool find_mirror_plane(const QuantizedPositions& positions, MirrorPlane* plane, bool near) {
  const uint32_t n = uint32_t(positions.q.size() / 3);
  if (n < 16) return false;
  VertexPointTable points(n);
  for (uint32_t v = 0; v < n; ++v) points.insert(positions.q.data(), v);
  // The second pass: a vertex within a step of the image on every axis
  // counts too (the halves of a scanned mesh, quantized, are often a step
  // apart on any axis; method 10's twins then are the ones a step beside the
  // image along the axis, 14.11).
  bool near_hits = false;
  std::unique_ptr<OccupiedBlocks> occupied;
  // Of every stride-th vertex, how many have a vertex at their image (in
  // the second pass, near it), counting no further than `enough`.
  const auto count_images = [&](MirrorPlane candidate, uint32_t stride, uint32_t enough, auto found) {
    uint32_t count = 0;
    for (uint32_t v = 0; v < n && count < enough; v += stride) {
      uint32_t image[3];
      std::copy(&positions.q[3 * size_t(v)], &positions.q[3 * size_t(v)] + 3, image);
      const int64_t m = int64_t(candidate.sum) - int64_t(image[candidate.axis]);
      if (m < 0 || m > int64_t(positions.top[size_t(candidate.axis)])) continue;
      image[candidate.axis] = uint32_t(m);
      count += found(image);
    }
    return count;
  };
  const auto hits = [&](MirrorPlane candidate, uint32_t stride,
                        uint32_t enough = std::numeric_limits<uint32_t>::max()) {
    if (near_hits)
      return count_images(candidate, stride, enough, [&](const uint32_t* image) { return occupied->near(image); });
    return count_images(candidate, stride, enough,
                        [&](const uint32_t* image) { return points.find(positions.q.data(), image) != VertexPointTable::kNone; });
  };
  const uint32_t sample_stride = std::max<uint32_t>(1, n / kMirrorSample);
  // Under kGradedStartBelow vertices the encoder codes the positions without
  // the plane too where it has few twins, so a plane of fewer is tried.
  const uint32_t divisor = n < kGradedStartBelow ? 2 * kMirroredShareDivisor : kMirroredShareDivisor;
  // The second pass (method 10) from kGradedStartBelow vertices on: it
  // finds the planes of scanned halves (camelhead at 16 bits), which small
  // meshes, modelled, rarely have, and costs up to 8 look-ups (of blocks) a
  // vertex screened. It screens a quarter as many vertices.
  std::vector<uint32_t> sums[3];
  for (int axis = 0; axis < 3; ++axis) sums[axis] = candidate_sums(positions, axis);
  for (int pass = 0; pass < (near && n >= kGradedStartBelow ? 2 : 1); ++pass) {
    near_hits = pass == 1;
    if (near_hits) occupied = std::make_unique<OccupiedBlocks>(positions.q);
    const uint32_t screen_stride = std::max<uint32_t>(1, n / (near_hits ? kMirrorScreen / 4 : kMirrorScreen));
    const uint32_t screened = (n + screen_stride - 1) / screen_stride;
    uint32_t best = 0;
    for (int axis = 0; axis < 3; ++axis) {
      for (const uint32_t sum : sums[axis]) {
        const MirrorPlane candidate{axis, sum};
        if (hits(candidate, screen_stride) * 16 < screened) continue;
        const uint32_t count = hits(candidate, sample_stride);
        if (count > best) {
          best = count;
          *plane = candidate;
        }
      }
    }
    plane->near_images = near;
    if (best > 0 && hits(*plane, 1, n / divisor) >= n / divisor) return true;
  }
  return false;
}

namespace {

// Whether some face is a quad, which POSN method 5's twist (14.7) needs.
bool has_quads(const Mesh& faces) {
  return std::find(faces.face_sizes.begin(), faces.face_sizes.end(), 4u) != faces.face_sizes.end();
}

// Whether some face is a triangle, which method 8's twist of triangles (14.9) needs.
bool has_triangles(const Mesh& faces) {
  return std::find(faces.face_sizes.begin(), faces.face_sizes.end(), 3u) != faces.face_sizes.end();
}

// Whether 14.7's twist brings the predictions nearer to the vertices, told
// without coding them: per vertex the mean of all its candidates with the
// twist and without, summed over the axes as log2(1 + |residual|), a
// stand-in for bits. A prediction pass costs a fraction of coding one.
// `visit` is in the geometry order; it is left with the twist on.
bool twist_pays(const QuantizedPositions& positions, PredictionVisit* visit) {
  const uint32_t n = uint32_t(positions.q.size() / 3);
  visit->twist_quads();
  const std::vector<uint32_t> activity(n, 0);  // contexts only: no candidate depends on it
  const uint32_t* top = positions.top.data();
  const auto cost = [&](VertexPrediction* p, const uint32_t* q) {
    select_candidates(p, (1u << p->candidates) - 1, top);
    double bits = 0;
    for (int a = 0; a < 3; ++a) bits += std::log2(1.0 + std::fabs(double(int64_t(q[a]) - p->value[a])));
    return bits;
  };
  double plain_cost = 0, twist_cost = 0;
  VertexPrediction twist;
  for (uint32_t i = 0; i < n; ++i) {
    visit->predict(i, positions.q.data(), activity.data(), top, &twist);
    if (twist.twisted == 0) continue;  // the same prediction either way
    VertexPrediction plain = twist;
    for (int k = 0; k < plain.candidates; ++k)
      if (plain.twisted >> k & 1)
        for (int a = 0; a < 3; ++a) plain.candidate[k][a] -= plain.twist_term[k][a];
    const uint32_t* q = &positions.q[3 * size_t(visit->item(i))];
    twist_cost += cost(&twist, q);
    plain_cost += cost(&plain, q);
  }
  return twist_cost < plain_cost;
}

// 14.5: the triangle twist must save this share of triangle_twist_pays's
// stand-in for bits. Near 1 the stand-in misjudges: on the corpus it said
// 0.998-1.02 wherever coding with the twist changed POSN by less than 0.2 %
// either way, 0.991-0.993 on armadillo and human_neutral at 12 bits, which
// it makes 0.3-0.8 % smaller, and 0.86 on face at 12 bits, which it makes
// 0.16 % larger (0.75 at 16 bits: 2.2 % smaller).
constexpr double kTriangleTwistMargin = 0.995;
// The pass runs on meshes of this many vertices or more (a prediction pass
// costs a small mesh 10-25 % of its encode, and on the corpus the twist pays
// on none under 1,000 vertices: cathead's POSN takes 1 byte more with it),
// and looks at every eighth vertex only.
constexpr uint32_t kTriangleTwistFrom = 1000, kTriangleTwistStride = 8;

// log2(1 + m) for the small m most residuals are, without a call to log2.
const std::array<double, 256> kLog2Table = [] {
  std::array<double, 256> table{};
  for (size_t m = 0; m < table.size(); ++m) table[m] = std::log2(1.0 + double(m));
  return table;
}();

// Whether 14.9's triangle twist brings the predictions nearer to the
// vertices, told without coding them: over the vertices with a twisted
// candidate, log2(1 + |residual|) summed over the axes for the subset of
// candidates (all of them, or one alone) that minimises it, with the
// correction and without, the weight learning from the former as the
// decoder's would; never under kTriangleTwistFrom vertices. `visit` is
// left with the triangle twist on.
bool triangle_twist_pays(const QuantizedPositions& positions, PredictionVisit* visit) {
  const uint32_t n = uint32_t(positions.q.size() / 3);
  if (n < kTriangleTwistFrom) return false;
  visit->twist_triangles();
  const std::vector<uint32_t> activity(n, 0);  // no candidate depends on it
  const uint32_t* top = positions.top.data();
  double plain_cost = 0, twist_cost = 0;
  TriangleTwistWeight weight;
  VertexPrediction p;
  // The encoder knows every vertex, so any of them can be predicted alone:
  // every kTriangleTwistStride-th vertex tells as well.
  for (uint32_t i = 0; i < n; i += kTriangleTwistStride) {
    visit->predict(i, positions.q.data(), activity.data(), top, &p);
    if (p.triangle_twisted == 0) continue;
    weight.apply(&p);
    const uint32_t* q = &positions.q[3 * size_t(visit->item(i))];
    // Per variant, the mask nearest in log2(1 + |r|) (14.5 picks the cheapest one)
    // among all candidates and each alone.
    const auto log_cost = [&](const int64_t* value) {
      double bits = 0;
      for (int a = 0; a < 3; ++a) {
        const int64_t r = int64_t(q[a]) - value[a];
        const uint64_t m = uint64_t(r < 0 ? -r : r);
        bits += m < kLog2Table.size() ? kLog2Table[m] : std::log2(1.0 + double(m));
      }
      return bits;
    };
    double best_twist = INFINITY, best_plain = INFINITY;
    unsigned best_mask = 1;
    // All candidates, then each alone: the masks 14.5 picks most often.
    const unsigned all = (1u << p.candidates) - 1;
    for (unsigned k = 0; k <= unsigned(p.candidates); ++k) {
      const unsigned mask = k == 0 ? all : 1u << (k - 1);
      if (k == 1 && p.candidates == 1) break;
      select_candidates(&p, mask, top);
      int64_t plain[3];
      for (int a = 0; a < 3; ++a) plain[a] = std::clamp<int64_t>(p.mean[a], 0, top[a]);
      const double t = log_cost(p.value), u = log_cost(plain);
      if (t < best_twist) best_twist = t, best_mask = mask;
      best_plain = std::min(best_plain, u);
    }
    twist_cost += best_twist;
    plain_cost += best_plain;
    select_candidates(&p, best_mask, top);
    weight.learn(p, q);
  }
  return twist_cost < kTriangleTwistMargin * plain_cost;
}


// The weight k of 14.12's shear for which bits(k), the cost of coding some
// vertices with it, is smallest of 8, 12 and 16, or 0 if 8 does not save
// kShearMargin of `none`, their cost without it: 12 is tried if 8 saves, 16
// if 12 saves more (smaller weights never coded the corpus smallest).
template <class Bits>
int shear_weight(double none, Bits bits) {
  const double half = bits(8);
  if (!(half < kShearMargin * none)) return 0;
  const double three_quarters = bits(12);
  if (!(three_quarters < half)) return 8;
  return bits(16) < three_quarters ? 16 : 12;
}

// 14.12: the stream of the visit with the weight *k of the shear that
// codes its first kShearPrefix vertices smallest (0: none, or not weighed):
// each weight shear_weight tries is coded that far, and the coder of the
// best carries on to the end. stats gain the visit's counts.
std::vector<uint8_t> code_weighing_shear(const QuantizedPositions& positions, PredictionVisit* visit, bool weigh,
                                         PositionStats* stats, CandidateChoice choice, ClassStart start,
                                         bool contexts, const MirrorPlane* plane, bool axis_classes, int* k) {
  std::vector<VisitCoder> coders;
  coders.reserve(4);  // at most 0, 8, 12 and 16
  const auto coded_head = [&](int weight) {
    coders.emplace_back(positions.q, positions.top.data(), visit, *stats, choice, start, contexts, plane, nullptr,
                        weight, axis_classes, &positions);
    coders.back().code(kShearPrefix);
    return coders.back().bits();
  };
  *k = weigh ? shear_weight(coded_head(0), coded_head) : 0;
  if (!weigh) coders.emplace_back(positions.q, positions.top.data(), visit, *stats, choice, start, contexts, plane,
                                  nullptr, 0, axis_classes, &positions);
  return std::find_if(coders.begin(), coders.end(), [&](const VisitCoder& c) { return c.shear() == *k; })
      ->finish(stats);
}

}  // namespace

// The predicted payload of `order` (with 14.7's twist where twist_pays:
// method 5), with 14.8's mask contexts (methods 6 and 7) where mask_contexts
// allows it and the mesh has kMaskContextsFrom vertices or more; and under
// kGradedStartBelow vertices (where coding twice costs little) the smaller
// of it and the label order's: method 4's gain is then a few bytes either
// way (fish_control_mesh at 14 bits: 516 against 514).
std::vector<uint8_t> encode_predicted_choice(const QuantizedPositions& positions, const Mesh& faces,
                                             CandidateChoice choice, ClassStart start, PredictionOrder order,
                                             bool quad_twist, bool mask_contexts, bool triangle_twist,
                                             bool mirror, bool near_mirror, bool shear, PositionStats* stats,
                                             bool edge_extrapolation, bool axis_class_probabilities) {
  const PositionStats before = *stats;  // the coder adds its counts to stats
  // The corners, and 14.6's order, built once for every payload tried.
  VertexCorners corners;
  corners.build(uint32_t(positions.q.size() / 3), faces.face_sizes, faces.corners);
  PredictionVisit visit(corners, order);
  // 14.13: the rule adds candidates only where 14.3.1 has none, so a visit
  // in which it adds none codes what it would without it, and is written
  // with the method before (used() below).
  const bool lattice = order == PredictionOrder::kGeometry && positions.lattice > 1;  // method 14 (14.15)
  visit.extrapolate_edges(edge_extrapolation || lattice);
  const auto used = [&](const PositionStats& s) {
    return lattice || s.extrapolated_vertices > before.extrapolated_vertices;
  };
  const bool twisted = order == PredictionOrder::kGeometry && quad_twist && has_quads(faces) &&
                       twist_pays(positions, &visit);
  visit.twist_quads(twisted);
  const bool triangles_twisted = order == PredictionOrder::kGeometry && triangle_twist && has_triangles(faces) &&
                                 triangle_twist_pays(positions, &visit);
  visit.twist_triangles(triangles_twisted);
  const uint32_t* top = positions.top.data();
  const bool contexts =
      mask_contexts && order == PredictionOrder::kGeometry && positions.q.size() / 3 >= kMaskContextsFrom;
  MirrorPlane plane;
  const bool mirrored =
      order == PredictionOrder::kGeometry && mirror && find_mirror_plane(positions, &plane, near_mirror);
  const MirrorPlane* const planed = mirrored ? &plane : nullptr;
  const bool weigh_shear =
      shear && order == PredictionOrder::kGeometry && positions.q.size() / 3 >= kShearFrom && has_triangles(faces);
  // 14.14: from kAxisClassesFrom vertices, with the rule of 14.13 (method 13
  // has it), class probabilities per axis too; a rule, no second pass.
  const bool axis = lattice || (axis_class_probabilities && edge_extrapolation &&
                                order == PredictionOrder::kGeometry && positions.q.size() / 3 >= kAxisClassesFrom);
  int k = 0;
  const std::vector<uint8_t> stream =
      code_weighing_shear(positions, &visit, weigh_shear, stats, choice, start, contexts, planed, axis, &k);
  std::vector<uint8_t> best = predicted_payload(positions, start, order, twisted, contexts, triangles_twisted, planed,
                                                stream, k, used(*stats), axis);
  visit.shear(k);  // the payloads below (none from kShearFrom vertices on) as this one
  int method = twisted ? 5 : order == PredictionOrder::kGeometry ? 4 : start == ClassStart::kGraded ? 3 : 1;
  if (contexts) method += 2;
  if (triangles_twisted) method = 8;
  const int method_without_mirror = method;
  if (mirrored) method = plane.near_images ? 10 : 9;
  if (method == 10 && stats->pairs_beside == before.pairs_beside && !best.empty()) {
    // No vertex paired beside its image: every decision is method 9's, and
    // only the selector differs (14.11); a file 1.12 decoders read. (With
    // the shear, method 11's plane byte, 14.12.)
    if (k == 0 && !used(*stats) && !axis)
      best[selector_offset(positions)] = kMirrorSelector;
    else  // methods 11 and 12 (14.12, 14.13)
      best[selector_offset(positions) + 4] = 1;  // the plane byte, after selector, start, features and shear
    method = 9;
  } else if (method == 10 && positions.q.size() / 3 < kGradedStartBelow) {
    // Under 1,000 vertices method 9's payload too, the smaller kept (9 on a
    // tie): a near image vertex may be a worse twin than none
    // (fish_control_mesh at 12 bits: 364 bytes with method 9, 366 with 10).
    PositionStats exact_stats = before;
    MirrorPlane exact = plane;
    exact.near_images = false;
    const std::vector<uint8_t> exact_stream =
        encode_visit(positions.q, top, visit, &exact_stats, choice, start, contexts, &exact, nullptr, axis, &positions);
    std::vector<uint8_t> exact_payload = predicted_payload(positions, start, order, twisted, contexts,
                                                           triangles_twisted, &exact, exact_stream, k, used(exact_stats),
                                                           axis);
    if (!exact_payload.empty() && exact_payload.size() <= best.size()) {
      best = std::move(exact_payload);
      *stats = exact_stats;
      method = 9;
    }
  }
  const uint32_t twins = stats->vertices_by_kind[int(PredictionKind::kMirror)] -
                         before.vertices_by_kind[int(PredictionKind::kMirror)];
  if (mirrored && positions.q.size() / 3 < kGradedStartBelow && twins < positions.q.size() / 3 / 8) {
    // A small mesh with few twins may pay more for its mirror decisions than
    // they save (cylinder_ngon_caps: 4 - 10 bytes): methods 4 - 8 too, the
    // smaller kept.
    PositionStats plain_stats = before;
    const std::vector<uint8_t> plain_stream =
        encode_visit(positions.q, top, visit, &plain_stats, choice, start, contexts, nullptr, nullptr, axis, &positions);
    std::vector<uint8_t> plain = predicted_payload(positions, start, order, twisted, contexts, triangles_twisted,
                                                   nullptr, plain_stream, k, used(plain_stats), axis);
    if (!plain.empty() && plain.size() <= best.size()) {
      best = std::move(plain);
      *stats = plain_stats;
      method = method_without_mirror;
    }
  }
  // Under 1,000 vertices the label order's payload too, unless method 9's or 10's
  // twins pay (the label order has none: on the corpus it never won then).
  if (order == PredictionOrder::kGeometry && positions.q.size() / 3 < kGradedStartBelow && method < 9 && !lattice) {
    PositionStats label_stats = before;
    PredictionVisit labels_visit(corners, PredictionOrder::kLabels);
    std::vector<uint8_t> labels =
        predicted_payload(positions, start, PredictionOrder::kLabels, false, false, false, nullptr,
                          encode_visit(positions.q, top, labels_visit, &label_stats, choice, start));
    if (!labels.empty() && labels.size() <= best.size()) {
      best = std::move(labels);
      *stats = label_stats;
      method = start == ClassStart::kGraded ? 3 : 1;
    }
  }
  if (method == 9 || method == 10) stats->mirror = method - 8;
  if (k > 0 && method >= 4) {  // methods 4 - 10 with the shear (14.12)
    stats->shear = k;
    method = 11;
  }
  if (used(*stats) && method >= 4) {  // methods 4 - 11 with the edge extrapolation (14.13)
    stats->shear = k;
    method = 12;
  }
  if (axis && method >= 4) {  // methods 4 - 12 with the class probabilities per axis (14.14)
    stats->shear = k;
    stats->axis_classes = true;
    method = 13;
  }
  if (lattice && method >= 4) {  // method 13 on the surface lattice (14.15)
    stats->lattice = positions.lattice;
    method = 14;
  }
  stats->method = method;
  stats->features = method >= 4 ? position_features(twisted, contexts, triangles_twisted) : 0;
  stats->graded_start = start == ClassStart::kGraded;
  return best;
}

std::vector<uint8_t> encode_positions(const QuantizedPositions& positions, const Mesh& faces, PositionMethod method,
                                      CandidateChoice choice, ClassStart start, PredictionOrder order,
                                      bool quad_twist, bool mask_contexts, bool triangle_twist, bool mirror,
                                      bool near_mirror, bool shear, PositionStats* stats, bool edge_extrapolation,
                                      bool axis_class_probabilities) {
  *stats = PositionStats{};
  stats->step = positions.step;
  stats->top = positions.top;
  // 14.15: a vertex on a lattice of factor k lies within k steps per axis.
  const double within = positions.lattice > 1 ? double(positions.lattice) : 0.5;
  stats->error_bound = within * std::sqrt(positions.step[0] * positions.step[0] +
                                          positions.step[1] * positions.step[1] + positions.step[2] * positions.step[2]);
  std::vector<uint8_t> deltas;
  if (positions.per_axis_bits && method != PositionMethod::kPredicted) deltas = encode_positions(positions);
  if (method == PositionMethod::kDeltas) return deltas;
  if (positions.q.size() / 3 >= kGradedStartBelow) start = ClassStart::kFlat;
  PositionStats predicted_stats = *stats;
  std::vector<uint8_t> predicted =
      encode_predicted_choice(positions, faces, choice, start, order, quad_twist, mask_contexts, triangle_twist,
                              mirror, near_mirror, shear, &predicted_stats, edge_extrapolation,
                              axis_class_probabilities);
  if (predicted.empty()) {
    // Only vertices that all coincide cost so little (section 14.1); on
    // one point method 0's per-axis grid gives the same positions.
    QuantizedPositions point;
    point.bits = 1;
    point.per_axis_bits = true;
    point.min = point.max = positions.min;
    point.top = {1, 1, 1};
    point.q.assign(positions.q.size(), 0);
    *stats = PositionStats{};
    return encode_positions(point);
  }
  if (!deltas.empty() && deltas.size() <= predicted.size()) return deltas;
  *stats = predicted_stats;
  return predicted;
}

}  // namespace qmc
