// Rate control of progressive files; see progressive_rate.h.
#include "progressive_rate.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace qmc::tools {
namespace {

// One coded candidate and, once measured, its decoded mesh and distance.
struct Candidate {
  RatePoint point;
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  DecodedFile decoded;
  MeshDistance distance;
};

Status code_candidate(const ProgressiveEncoder& encoder, EncodeOptions options, int bits, double scale,
                      Candidate* c) {
  options.position_bits = bits;
  options.finest_step_scale = scale;
  c->point = RatePoint{};
  c->point.levels = options.progressive_levels;
  c->point.position_bits = bits;
  c->point.step_scale = scale;
  if (Status s = encoder.code(options, &c->bytes, &c->stats); !s.ok()) return s;
  c->point.bytes = c->bytes.size();
  return Status::Ok();
}

Status measure(const Mesh& mesh, size_t samples, Candidate* c) {
  if (Status s = decode_and_measure(mesh, c->bytes, samples, &c->decoded, &c->distance); !s.ok()) return s;
  c->point.relative_l2 = c->distance.relative(c->distance.l2);
  c->point.relative_hausdorff = c->distance.relative(c->distance.hausdorff);
  return Status::Ok();
}

// The search state: every point tried, and the best candidate so far.
class Search {
 public:
  Search(const Mesh& mesh, const RateTarget& target, size_t samples, RateChoice* out)
      : mesh_(mesh), target_(target), samples_(samples), out_(out) {}

  bool meets(const Candidate& c) const {
    if (target_.max_bytes > 0) return c.point.bytes <= target_.max_bytes;
    if (target_.max_relative_hausdorff > 0) return c.point.relative_hausdorff <= target_.max_relative_hausdorff;
    return c.point.relative_l2 <= target_.max_relative_l2;
  }
  // Whether `c` can still win: a smaller file (error target) or one that fits (size target).
  bool worth_measuring(const Candidate& c) const {
    return target_.max_bytes > 0 ? c.point.bytes <= target_.max_bytes : c.point.bytes < best_bytes_;
  }
  Status measure_and_keep(Candidate* c) {
    if (Status s = measure(mesh_, samples_, c); !s.ok()) return s;
    out_->tried.push_back(c->point);
    if (meets(*c) && better(*c)) keep(c);
    return Status::Ok();
  }
  void skip(const Candidate& c) { out_->tried.push_back(c.point); }
  void fail(int levels, const Status& s) {
    RatePoint p;
    p.levels = levels;
    p.failure = s.message();
    out_->tried.push_back(p);
  }

 private:
  bool better(const Candidate& c) const {
    if (out_->chosen < 0) return true;
    return target_.max_bytes > 0 ? c.point.relative_l2 < best_error_ : c.point.bytes < best_bytes_;
  }
  void keep(Candidate* c) {
    out_->chosen = int(out_->tried.size()) - 1;
    best_bytes_ = c->point.bytes;
    best_error_ = c->point.relative_l2;
    out_->bytes = std::move(c->bytes);
    out_->stats = std::move(c->stats);
    out_->decoded = std::move(c->decoded);
    out_->distance = c->distance;
  }

  const Mesh& mesh_;
  const RateTarget& target_;
  size_t samples_;
  RateChoice* out_;
  uint64_t best_bytes_ = std::numeric_limits<uint64_t>::max();
  double best_error_ = std::numeric_limits<double>::infinity();
};

// Measures `c` if it can still beat the best; true in *go_larger when only a
// larger scale can do better (it meets the error, or is no smaller than the
// best).
Status consider(Candidate* c, Search* search, bool* go_larger) {
  *go_larger = true;
  if (!search->worth_measuring(*c)) {
    search->skip(*c);
    return Status::Ok();
  }
  if (Status st = search->measure_and_keep(c); !st.ok()) return st;
  *go_larger = search->meets(*c);
  return Status::Ok();
}

Status try_candidate(const ProgressiveEncoder& encoder, const EncodeOptions& options, int bits, double scale,
                     Search* search, bool* go_larger) {
  Candidate c;
  if (Status st = code_candidate(encoder, options, bits, scale, &c); !st.ok()) return st;
  return consider(&c, search, go_larger);
}

// `refinements` steps of a bisection of the step scale between `passed`
// (within the target) and `missed` (not), each at their geometric mean;
// try_scale(scale, &within) codes a candidate and says which side it is on.
template <class TryScale>
Status refine_scale(double passed, double missed, int refinements, TryScale try_scale) {
  for (int step = 0; step < refinements && missed != passed; ++step) {
    const double scale = std::sqrt(passed * missed);
    bool within = false;
    if (Status st = try_scale(scale, &within); !st.ok()) return st;
    (within ? passed : missed) = scale;
  }
  return Status::Ok();
}

// Error target, one K. Its cheapest file first (fewest bits, largest
// scale): no smaller than the best, and K cannot win. Then its most
// accurate (most bits, smallest scale) decides whether K can reach the
// error at all. Then per bits the largest scale first (the cheapest file of
// those bits: when it meets the error or is no smaller than the best, the
// other scales cannot win), else a binary search for the largest scale that
// meets it (the error grows with the scale, the bytes fall).
Status search_error(const ProgressiveEncoder& encoder, const EncodeOptions& options, const RateSearch& s,
                    Search* search) {
  Candidate cheapest, top;
  if (Status st = code_candidate(encoder, options, s.position_bits.front(), s.step_scales.back(), &cheapest); !st.ok())
    return st;
  if (!search->worth_measuring(cheapest)) {
    search->skip(cheapest);
    return Status::Ok();
  }
  if (Status st = code_candidate(encoder, options, s.position_bits.back(), s.step_scales.front(), &top); !st.ok())
    return st;
  if (Status st = search->measure_and_keep(&top); !st.ok()) return st;
  if (!search->meets(top)) return Status::Ok();
  const int largest = int(s.step_scales.size()) - 1;
  for (int bits : s.position_bits) {
    bool go_larger = false;
    const Status first = bits == s.position_bits.front()
                             ? consider(&cheapest, search, &go_larger)
                             : try_candidate(encoder, options, bits, s.step_scales.back(), search, &go_larger);
    if (!first.ok()) return first;
    if (go_larger) continue;
    int lo = 0, hi = largest - 1;
    while (lo <= hi) {
      const int mid = (lo + hi + 1) / 2;
      if (Status st = try_candidate(encoder, options, bits, s.step_scales[size_t(mid)], search, &go_larger); !st.ok())
        return st;
      if (go_larger) lo = mid + 1; else hi = mid - 1;
    }
    // Between the last scale that did not miss (hi) and the first that did
    // (lo), the search goes on in halves of the ratio (geometric means).
    if (hi < 0) continue;
    if (Status st = refine_scale(s.step_scales[size_t(hi)], s.step_scales[size_t(lo)], s.refinements,
                                 [&](double scale, bool* within) {
                                   return try_candidate(encoder, options, bits, scale, search, within);
                                 });
        !st.ok())
      return st;
  }
  return Status::Ok();
}

// Size target, one K: per bits a binary search for the smallest scale whose
// file fits (the bytes fall as the scale grows), continued `refinements`
// times between that scale and the grid's next smaller one, then that file
// measured.
Status search_size(const ProgressiveEncoder& encoder, const EncodeOptions& options, const RateSearch& s,
                   Search* search) {
  for (int bits : s.position_bits) {
    int lo = 0, hi = int(s.step_scales.size()) - 1;
    Candidate fitting;
    bool found = false;
    // Keeps `c` as the best fitting file of these bits if it fits.
    const auto fits = [&](Candidate* c) {
      if (!search->worth_measuring(*c)) {
        search->skip(*c);
        return false;
      }
      if (found) search->skip(fitting);
      fitting = std::move(*c);
      found = true;
      return true;
    };
    while (lo <= hi) {
      const int mid = (lo + hi) / 2;
      Candidate c;
      if (Status st = code_candidate(encoder, options, bits, s.step_scales[size_t(mid)], &c); !st.ok()) return st;
      if (fits(&c)) hi = mid - 1; else lo = mid + 1;
    }
    if (!found) continue;
    if (lo > 0)
      if (Status st = refine_scale(s.step_scales[size_t(lo)], s.step_scales[size_t(lo - 1)], s.refinements,
                                   [&](double scale, bool* within) {
                                     Candidate c;
                                     const Status coded = code_candidate(encoder, options, bits, scale, &c);
                                     *within = coded.ok() && fits(&c);
                                     return coded;
                                   });
          !st.ok())
        return st;
    if (Status st = search->measure_and_keep(&fitting); !st.ok()) return st;
  }
  return Status::Ok();
}

RateSearch filled(RateSearch s, const EncodeOptions& options) {
  if (s.levels.empty()) s.levels = {options.progressive_levels};
  if (s.position_bits.empty()) s.position_bits = {options.position_bits};
  if (s.step_scales.empty()) s.step_scales = {options.finest_step_scale};
  std::sort(s.position_bits.begin(), s.position_bits.end());
  std::sort(s.step_scales.begin(), s.step_scales.end());
  return s;
}

}  // namespace

Status decode_and_measure(const Mesh& reference, const std::vector<uint8_t>& bytes, size_t samples,
                          DecodedFile* decoded, MeshDistance* distance) {
  if (Status s = decode(bytes.data(), bytes.size(), decoded, DecoderLimits::unlimited()); !s.ok())
    return Status(s.code(), "internal error, own output does not decode: " + s.message());
  MeshDistanceOptions options;
  options.samples = samples;
  return measure_mesh_distance(reference, decoded->mesh, options, distance);
}

int default_progressive_levels(size_t triangles) {
  int k = 1;
  while (k < 8 && (triangles >> (2 * (k + 1))) >= 1000) ++k;
  return k;
}

RateSearch default_rate_search(const Mesh& mesh) {
  RateSearch s;
  for (int k = 6; k >= 1; --k)
    if ((mesh.face_count() >> (2 * k)) >= 64) s.levels.push_back(k);
  if (s.levels.empty()) s.levels = {1};
  s.position_bits = {8, 9, 10, 11, 12, 13};
  s.step_scales = {1, 2, 4, 8, 16, 32, 64};
  s.refinements = 2;
  return s;
}

Status choose_progressive(const Mesh& mesh, const EncodeOptions& options, const RateTarget& target,
                          const RateSearch& search, const std::function<void(const std::string&)>& stage,
                          RateChoice* out) {
  *out = RateChoice{};
  const int targets = (target.max_relative_l2 > 0) + (target.max_bytes > 0) + (target.max_relative_hausdorff > 0);
  if (targets != 1 || !std::isfinite(target.max_relative_l2) || !std::isfinite(target.max_relative_hausdorff))
    return Status(ErrorCode::kInvalidArgument, "give one target: an L2 error, a Hausdorff error or a size");
  const RateSearch s = filled(search, options);
  Search state(mesh, target, s.samples, out);
  Status first_failure = Status::Ok();
  for (int levels : s.levels) {
    EncodeOptions o = options;
    o.progressive_levels = levels;
    if (stage) stage("K = " + std::to_string(levels) + ": simplify, fit, remesh");
    ProgressiveEncoder encoder;
    if (Status st = encoder.prepare(mesh, o); !st.ok()) {
      state.fail(levels, st);
      if (first_failure.ok()) first_failure = st;
      continue;
    }
    if (stage) stage("K = " + std::to_string(levels) + ": code and measure");
    const Status st = target.error_target() ? search_error(encoder, o, s, &state) : search_size(encoder, o, s, &state);
    if (!st.ok()) return st;
  }
  const bool all_failed = std::all_of(out->tried.begin(), out->tried.end(),
                                      [](const RatePoint& p) { return !p.failure.empty(); });
  if (all_failed && !first_failure.ok()) return first_failure;
  return Status::Ok();
}

}  // namespace qmc::tools
