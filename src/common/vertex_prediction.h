// Prediction of a vertex's quantized position from the vertices decoded
// before it (spec/qmc-format.md section 14.3), shared by the encoder and
// the decoder so the two cannot drift apart.
//
// Vertices are visited in label order, the order in which the connectivity
// decoder first meets them, so a vertex u is decoded before v when u < v;
// or in the geometry order of 14.6, rank(u) < rank(v). The rules, all in
// integers:
//  - across an edge of a triangle, the parallelogram a + b - c (Touma and
//    Gotsman, "Triangle mesh compression", 1998), every one available being
//    averaged (multi-parallelogram);
//  - within a polygon of degree k >= 4, the three vertices preceding (or
//    following) v along the face: p3 + c_k (p1 - p2), exact on a regular
//    k-gon and the parallelogram for k = 4 (Isenburg and Alliez, "Compressing
//    polygon mesh geometry with parallelogram prediction", 2002; Isenburg,
//    Ivrissimtzis, Gumhold and Seidel, "Geometry prediction for high degree
//    polygons", 2005);
//  - across an edge (p1, p2) of a polygon whose neighbour across it is a
//    polygon too, the extrapolation 2 p1 - y of the strip (y: p1's other
//    neighbour in that polygon);
//  - otherwise the mean of the decoded neighbours along face edges, else
//    the previous vertex.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace qmc {

// A table of T that build() fills completely, so it is not zeroed first
// (that would be one more pass over a few megabytes for nothing).
template <class T>
class FilledTable {
 public:
  void allocate(size_t n) { data_.reset(new T[n]); }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  const T* data() const { return data_.get(); }

 private:
  std::unique_ptr<T[]> data_;
};

// Section 14.2: the faces of CONN (degree >= 3 each, corners concatenated)
// with, per vertex, the corners at which it appears, in face order, and
// its face-edge neighbours by neighbour.
class VertexCorners {
 public:
  // Labels must be < vertex_count. Allocates (the API boundary catches
  // allocation failure, spec 8.1 bounds the sizes).
  void build(uint32_t vertex_count, const std::vector<uint32_t>& face_sizes, const std::vector<uint32_t>& corners);

  uint32_t vertex_count() const { return uint32_t(first_.size() - 1); }
  uint32_t corner_count() const { return first_.back(); }
  uint32_t face_count() const { return triangles_only_ ? corner_count() / 3 : uint32_t(face_start_.size() - 1); }
  // The corners of face f are face_begin(f) .. face_end(f) - 1; vertex(k) is corner k's.
  uint32_t face_begin(uint32_t f) const { return triangles_only_ ? 3 * f : face_start_[f]; }
  uint32_t face_end(uint32_t f) const { return triangles_only_ ? 3 * f + 3 : face_start_[f + 1]; }
  uint32_t vertex(uint32_t corner) const { return corners_[corner]; }
  const uint32_t* begin(uint32_t v) const { return corner_of_.data() + first_[v]; }
  const uint32_t* end(uint32_t v) const { return corner_of_.data() + first_[v + 1]; }
  // The vertices next to v at each of its corners, along(k, +1) and
  // along(k, -1), in the order of begin(v) .. end(v): kept beside the
  // corners because every search of 14.2 reads them, and reading them from
  // the faces costs a division or two table lookups per corner.
  struct Sides {
    uint32_t next, previous;
  };
  const Sides* sides(uint32_t v) const { return sides_.data() + first_[v]; }
  // Face of a corner, its degree, and the vertex `step` corners further
  // along the face's cycle (|step| <= 3 in spec 14.3, either sign).
  // A mesh of triangles only keeps no per-corner tables: corner k is
  // corner k mod 3 of face k / 3.
  uint32_t face(uint32_t corner) const { return triangles_only_ ? corner / 3 : face_of_[corner]; }
  uint32_t degree(uint32_t corner) const {
    return triangles_only_ ? 3 : face_start_[face_of_[corner] + 1] - face_start_[face_of_[corner]];
  }
  // The corner `step` corners further along corner's face (|step| <= 3).
  uint32_t corner_along(uint32_t corner, int step) const {
    if (triangles_only_) return corner + kTriangleStep[step + 3][corner % 3];
    for (; step > 0; --step) corner = next_[corner];
    for (; step < 0; ++step) corner = previous_[corner];
    return corner;
  }
  uint32_t along(uint32_t corner, int step) const {
    if (triangles_only_) return corners_[corner + kTriangleStep[step + 3][corner % 3]];
    for (; step > 0; --step) corner = next_[corner];
    for (; step < 0; ++step) corner = previous_[corner];
    return corners_[corner];
  }

  // A face-edge neighbour w of a vertex u, the corner of u it is next to,
  // and u's other neighbour at that corner (w again if both sides are w).
  struct Link {
    uint32_t neighbour, corner, other;
  };
  // Calls visit(corner, other) for the corners of u, in order, of triangles
  // (triangles = true) or of larger faces, that have w next to u, other
  // being u's neighbour at that corner that is not w (w if both are), until
  // visit returns false: the searches of spec 14.2. A vertex of few corners
  // is scanned; one of many has its links sorted by neighbour once and is
  // searched in O(log n).
  template <class Visit>
  void for_each_link(uint32_t u, uint32_t w, bool triangles, Visit visit) const {
    if (end(u) - begin(u) <= kScannedCorners) {
      // In a triangle along(k, 2) is along(k, -1); the neighbours, rarely w,
      // are tested before the degree.
      const Sides* s = sides(u);
      for (const uint32_t* k = begin(u); k != end(u); ++k, ++s)
        if ((s->next == w || s->previous == w) && (degree(*k) == 3) == triangles &&
            !visit(*k, s->next == w ? s->previous : s->next))
          return;
      return;
    }
    const std::vector<uint32_t>& first = triangles ? triangle_link_first_ : polygon_link_first_;
    const Link* all = (triangles ? triangle_links_ : polygon_links_).data();
    const Link* from = std::lower_bound(all + first[u], all + first[u + 1], w,
                                        [](const Link& link, uint32_t value) { return link.neighbour < value; });
    for (const Link* link = from; link != all + first[u + 1] && link->neighbour == w; ++link)
      if (!visit(link->corner, link->other)) return;
  }

 private:
  static constexpr int kScannedCorners = 12;  // vertices of more corners get sorted links
  // In a mesh of triangles only: [step + 3][corner mod 3], what to add to a
  // corner to go `step` corners along its triangle.
  static constexpr int8_t kTriangleStep[7][3] = {{0, 0, 0},  {1, 1, -2}, {2, -1, -1}, {0, 0, 0},
                                                 {1, 1, -2}, {2, -1, -1}, {0, 0, 0}};
  void build_faces(const std::vector<uint32_t>& face_sizes, size_t corner_count);
  void build_links(bool triangles, std::vector<uint32_t>* first, std::vector<Link>* links) const;

  std::vector<uint32_t> triangle_link_first_, polygon_link_first_;  // per vertex; one more at the end
  // Of the vertices of more than kScannedCorners corners, sorted by neighbour, then corner.
  std::vector<Link> triangle_links_, polygon_links_;
  const uint32_t* corners_ = nullptr;
  bool triangles_only_ = false;
  // Of meshes with a face of more than 3 corners only:
  FilledTable<uint32_t> next_, previous_;  // per corner, the next and previous corner of its face
  std::vector<uint32_t> face_start_;       // per face, its first corner; one more at the end
  FilledTable<uint32_t> face_of_;          // per corner
  std::vector<uint32_t> first_;            // per vertex, its first entry in corner_of_; one more at the end
  FilledTable<uint32_t> corner_of_;        // corners grouped by vertex, face order within a vertex
  FilledTable<Sides> sides_;               // per entry of corner_of_
};

// Sections 14.3.2 and 14.4: what a prediction was made from, which selects the
// residuals' context (14.4).
enum class PredictionKind : uint8_t {
  kPrevious = 0,    // no decoded neighbour: the previous vertex (or the grid's centre)
  kNeighbours = 1,  // the mean of decoded neighbours
  kSingle = 2,      // one parallelogram, polygon or strip rule
  kSeveral = 3,     // the weighted mean of two or more
  kMirror = 4,      // 14.10: the mirror candidate (POSN methods 9, 10; 15.14's twin)
};
inline constexpr int kPredictionKinds = 5;

// 14.3.1: the most candidates a vertex takes; a file selects a subset of
// them per vertex (14.3.3, 14.4).
inline constexpr int kMaxCandidates = 4;

struct VertexPrediction {
  // The candidates in enumeration order, in units of 2^-16, and their weights.
  int candidates = 0;
  int64_t candidate[kMaxCandidates][3];
  int64_t weight[kMaxCandidates];
  // Without candidates (14.3.2): the mean of the decoded neighbours, else
  // the previous vertex (or the grid's centre). select_candidates works it
  // out from these only when no candidate is selected: its divisions would
  // cost every vertex tens of cycles for the few that use it.
  int64_t neighbour_sum[3];
  int64_t neighbours = 0;
  int64_t previous[3];
  uint64_t neighbour_activity = 0;  // 14.3.2: the activity A, used by 14.4
  uint64_t scale = 0;  // mean L1 length of the candidates' difference vectors
  // With 14.7's twist: the candidates that carry one (a bit each) and the
  // term added to each, so the encoder can weigh method 5 against 4 from
  // one prediction.
  unsigned twisted = 0;
  int64_t twist_term[kMaxCandidates][3];
  // With 14.9's triangle twist: the parallelogram candidates that carry a
  // twist (a bit each), the twist of each (units of 2^-16), and the weight
  // lambda (units of 1/256) TriangleTwistWeight gives them.
  unsigned triangle_twisted = 0;
  int64_t triangle_twist[kMaxCandidates][3];
  int64_t twist_weight = 0;
  // The prediction of the selected subset (select_candidates): the weighted
  // mean of 14.3.3 before the twist's correction and the clamp (mean), the
  // selected candidates' weighted mean twist (twist_mean, 2^-16 units), and
  // the prediction, clamped to 0..top[a] (value).
  PredictionKind kind = PredictionKind::kPrevious;
  bool extrapolated = false;  // 14.13: the candidates continue edges (POSN method 12)
  int64_t mean[3] = {0, 0, 0};
  int64_t twist_mean[3] = {0, 0, 0};
  int64_t value[3] = {0, 0, 0};
};

// 14.9: how much of the triangle twist a vertex's prediction takes, a weight
// fitted by least squares to the vertices decoded before it (the decoder
// learns it as the encoder did, nothing is transmitted).
class TriangleTwistWeight {
 public:
  // Before v's mask: the weight of p's twists, lambda = clamp(floor(256 N /
  // D), 0, 256) in units of 1/256 (0 < N < D where it divides).
  void apply(VertexPrediction* p) const {
    p->twist_weight = products_ <= 0 ? 0 : products_ >= squares_ ? 256 : 256 * products_ / squares_;
  }
  // After v's integers q (3) are known, p selected as coded (its mean and
  // twist_mean those of v's mask): the fit learns from them.
  void learn(const VertexPrediction& p, const uint32_t* q) {
    if (p.triangle_twisted != 0) learn_twisted(p, q);  // (else T = 0: nothing to learn)
  }

 private:
  void learn_twisted(const VertexPrediction& p, const uint32_t* q);
  int64_t products_ = 0, squares_ = 0;  // 14.9's N and D
};

// Section 15.12 (aTTR coding 7): texture coordinates guided by the
// positions. The faces predicted over are an attribute mesh; the guide gives
// the CONN vertex at each of its corners and the positions' integers (3 per
// vertex), and carries the orientation from value to value.
struct PositionGuide {
  const uint32_t* vertex_of_corner = nullptr;
  const uint32_t* positions = nullptr;
  int orientation = 1;  // 15.12's ω
};

// Finds the candidates and the fallback of vertex v from q (3 per vertex,
// labels < v decoded) and the activity of each decoded vertex, the sum of
// its residuals' magnitudes |r_x| + |r_y| + |r_z| (14.3.2; below 2^32, as
// each is at most 2^30 - 1). Selects nothing yet.
// With a guide, a corner that 15.12's guided rule applies to contributes
// that candidate alone.
void predict_vertex(const VertexCorners& mesh, uint32_t v, const uint32_t* q, const uint32_t* activity,
                    const uint32_t top[3], VertexPrediction* out, PositionGuide* guide = nullptr);

// The same in 14.6's geometry order: the vertex order[i] (rank[order[i]] = i),
// the vertices decoded before it those of rank below i, and order[i - 1]
// the previous vertex. Gives what predict_vertex gives for vertex i of the
// faces renamed by rank, without renaming them. With quad_twist, a quad's
// run carries the twist of its neighbours (POSN method 5, 14.7); with
// triangle_twist, out gets the triangle candidates' twists (14.9); with a
// shear k (1..16), the parallelogram candidates are sheared (14.12).
void predict_vertex_in_order(const VertexCorners& mesh, const uint32_t* order, const uint32_t* rank, uint32_t i,
                             const uint32_t* q, const uint32_t* activity, const uint32_t top[3],
                             VertexPrediction* out, PositionGuide* guide = nullptr, bool quad_twist = false,
                             bool triangle_twist = false, int shear = 0, bool extrapolate = false);

// 14.3.3: the prediction from the candidates whose bit is set in mask (the
// weighted mean), or the fallback if none is.
void select_candidates(VertexPrediction* p, unsigned mask, const uint32_t top[3]);

}  // namespace qmc
