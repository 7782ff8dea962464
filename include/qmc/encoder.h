// qmc encoder: polygon mesh in, .qmc bytes out.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "qmc/format.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Which connectivity coding to use (section 5.1).
enum class ConnectivityChoice : uint8_t {
  kAuto,     // the quad coder where the mesh is in its scope, else the polygon coder
  kIndexed,  // always the indexed coding
  kQuad,     // the quad coder or an error naming why it cannot be used
  kPolygon,  // always the polygon coder (section 5.4)
};

// Section 13: how to make a geometry image (seeds 000 and 002).
enum class GimSampling : uint8_t {
  kRegular,    // n x n samples evenly spaced on the parametrization
  kAdaptive,   // seed 000 section 3.1: vertex-density equalization
  kHausdorff,  // section 3.1, then the Hausdorff-driven adjustment of 3.2-3.3
};

struct GeometryImageOptions {
  // > 0: write a geometry image (section 13) instead of CONN/POSN. For a
  // sampled image the size is size x size pixels; for a topology-preserving
  // one it is the largest width or height the generator may use.
  uint32_t size = 0;
  GimSampling sampling = GimSampling::kRegular;
  // Seed 002: every input vertex on its own pixel, the input's triangles in
  // GFAC; lossless with float samples, within rounding with 16-bit ones.
  bool topology_preserving = false;
  bool float_samples = false;        // binary32 planes (format 1) instead of 16-bit
  bool quads = false;                // grid face mode 0 (quads) instead of 1 (triangles)
  bool store_blank_pixels = false;   // code the samples of blank pixels (flag bit 1)
  bool normal_planes = false;        // add unit-normal planes (kinds 3, 4, 5)
  // Seed 000 section 4: a region of interest (the text format of
  // src/geometry/gim_roi.h: vertex / face lists or a box); empty: none.
  std::string roi;
  uint32_t hausdorff_iterations = 2000;  // bound of seed 000's algorithm 1
};

// Section 14.1: the grid the positions are rounded to.
enum class PositionGrid : uint8_t {
  kUniform,  // one step for all axes: the largest side / (2^bits - 1), as Draco and meshoptimizer
  kPerAxis,  // each axis over its own range in 2^bits - 1 steps (section 6.1)
};

// How POSN codes the grid points (sections 6 and 14).
enum class PositionMethod : uint8_t {
  kAuto,       // the smaller of the methods that can carry the grid
  kDeltas,     // method 0: deltas in file order (section 6); per-axis grid only
  kPredicted,  // method 1: predicted from the decoded mesh, range coded (section 14)
};

// Section 14.5: how the encoder picks each vertex's candidates.
enum class CandidateChoice : uint8_t {
  kFewestBits,  // the mask and residuals cheapest under the coder's current probabilities
  kNearest,     // the prediction nearest to the vertex (L1): faster, about 1.5 % larger
};

// EncodeOptions::start_faces at most: each start is a whole encode.
constexpr uint32_t kMaxStartFaces = 256;

struct EncodeOptions {
  int position_bits = kDefaultPositionBits;  // 1..30, section 6.1
  // The grid of a plain file. A progressive file's base always takes
  // section 6.1's per-axis grid of position_bits (step and max error are
  // refused there); a geometry image has grids of its own (section 13).
  PositionGrid position_grid = PositionGrid::kUniform;
  // > 0: this step (model units) on every axis instead of bits and grid.
  double position_step = 0;
  // > 0: the largest uniform step that keeps every vertex within this
  // Euclidean distance of its input (binary32 rounding included); instead
  // of bits, grid and step.
  double max_position_error = 0;
  // > 1: POSN method 14 (format 1.19, spec 14.15), the surface lattice of
  // this factor k (2 .. 16): each vertex keeps the grid's step along the
  // axis nearest its surface's normal and moves in steps of k along the
  // other two, so that it stays near the input's surface (within a step of
  // it, nearly) but up to k steps from its input position along it.
  // Smaller positions at the same distance between surfaces on dense
  // meshes (scans); vertices no longer on the nearest grid point. Kept only
  // where its POSN is smaller than the grid's (PositionStats says). 1: off.
  int surface_lattice = 1;
  PositionMethod position_method = PositionMethod::kAuto;
  CandidateChoice candidate_choice = CandidateChoice::kFewestBits;
  ConnectivityChoice connectivity = ConnectivityChoice::kAuto;
  // Quad coder only: force a coding (0..4, section 5.3.5); -1 picks the
  // smallest. A forced coding that cannot express the mesh is an error.
  int quad_coding = -1;
  // Polygon coder only: force a coding (0..5, 7 or 8, section 5.4.4); -1 picks the smallest.
  int polygon_coding = -1;
  // Whether the smallest may be coding 7 (format 1.6, 5.4.10); false keeps
  // a file readable by 1.5 decoders.
  bool polygon_context_coding = true;
  // Whether it may be coding 8 too (format 1.18, 5.4.10: quads coded in
  // contexts of the gate's neighbours as well; the whole CONN 8-35 % smaller
  // on the corpus's quad meshes that take it); false keeps a file readable
  // by 1.17 decoders.
  bool polygon_quad_contexts = true;
  // Polygon coder only: the whole file is coded from this many first faces
  // per component (5.4.2 leaves the first face to the encoder; it moves
  // every label, the geometry order of 14.6 and so the positions and
  // attributes) and the smallest kept, ties to the usual start. The time is
  // that many encodes, for a file 0 - 4 % smaller (the corpus at 12 bits,
  // 64 starts: 1.1 % on average, 3.6 - 4.2 % on halftunnel and
  // spot_control_mesh; docs/results/start_faces.md). 1: the usual start
  // only (the first virtual face, else the lowest face). Single-rate files
  // only.
  uint32_t start_faces = 1;
  // Polygon coder only: vertices no face uses take the last labels along a
  // Z-order curve, so that each is predicted from a near one (5.4.9); false
  // keeps them in input order, as the encoder did before.
  bool unused_vertices_along_curve = true;
  // Predicted positions of meshes under 1,000 vertices as POSN method 3
  // (format 1.7, spec 14.4.1): the class probabilities start graded, 6-11 %
  // smaller there; false writes method 1, which 1.5 and 1.6 decoders read.
  bool graded_class_start = true;
  // Predicted positions in the geometry order, POSN method 4 (format 1.8,
  // spec 14.6): a vertex closing two faces first, so that most have several
  // parallelograms; 4-20 % smaller on the corpus's triangle meshes (16 % on
  // face and beetle). false writes method 1 or 3, which 1.5-1.7 decoders read.
  bool geometry_order = true;
  // With geometry_order: a quad's prediction also carries the twist of the
  // quads beside it, POSN method 5 (format 1.9, spec 14.7), written where a
  // pass of predictions says it beats method 4 (finely meshed quad surfaces:
  // 3-14 % of their positions on the corpus). false keeps method 4, which
  // 1.8 decoders read.
  bool quad_twist = true;
  // With geometry_order: the decisions that select a vertex's candidates
  // take a context from how far apart the candidates are, POSN methods 6
  // and 7 (format 1.10, spec 14.8), written for meshes of 10,000 vertices
  // or more (spec 14.5: face.obj's positions 6.4 % smaller at 12 bits,
  // beetle's 4.8 %). false keeps methods 4 and 5, which 1.9 decoders read.
  bool mask_contexts = true;
  // With geometry_order: a triangle's parallelogram also carries the twist
  // of the parallelograms beside it, in the share the vertices before it
  // say pays, POSN method 8 (format 1.11, spec 14.9), written where a pass
  // of predictions says it beats methods 4 - 7 (regular triangulations:
  // camelhead's positions 9-15 % smaller). false keeps methods 4 - 7, which
  // 1.10 decoders read.
  bool triangle_twist = true;
  // With geometry_order: where reflecting the vertices across a plane
  // halfway across the grid puts 1/8 of them or more onto others exactly (a
  // mesh modelled with a mirror), a vertex whose mirror image was decoded
  // before it may be predicted by it, POSN method 9 (format 1.12, spec
  // 14.10). false keeps methods 4 - 8, which 1.11 decoders read.
  bool mirror_symmetry = true;
  // With mirror_symmetry: image vertices also a step beside the mirror
  // image along its axis, where the halves of a mirrored mesh round apart
  // once quantized, POSN method 10 (format 1.13, spec 14.11): face's
  // positions 6 % smaller at 14 bits, camelhead's 6 % at 14 and 16 bits
  // (where no plane maps 1/8 of the vertices exactly, one that maps them
  // within that step is taken). false keeps method 9, which 1.12 decoders read.
  bool near_mirror = true;
  // With geometry_order: each parallelogram's reflection of the vertex
  // across the edge pulled back towards the edge's middle by a weight the
  // encoder picks, POSN method 11 (format 1.15, spec 14.12), written where
  // the first vertices code smaller with it (irregular triangulations: cow's
  // positions 4.6 % smaller at 12 bits, lilium's 3.4 %). false keeps methods
  // 4 - 10, which 1.14 decoders read.
  bool shear = true;
  // With geometry_order: a vertex that no rule of 14.3.1 predicts (on a
  // boundary of quads, where no face lies across) predicted by an edge at
  // its decoded neighbours continued to it, POSN method 12 (format 1.16,
  // spec 14.13), written where the rule gives some vertex a candidate
  // (halftunnel's positions 2 - 3 % smaller, suzanne's 2 - 3 %). false keeps
  // methods 4 - 11, which 1.15 decoders read.
  bool edge_extrapolation = true;
  // With edge_extrapolation, from 1,000 vertices on: the class decisions of
  // each axis coded with the mean of the shared probability and one of that
  // axis's own, POSN method 13 (format 1.17, spec 14.14; the scans of more
  // than 10,000 vertices 1 - 2.5 % smaller, the regular torus 7 - 8.5 %).
  // false keeps methods 4 - 12, which 1.16 decoders read.
  bool axis_class_probabilities = true;
  // Attribute values on a grid may take aTTR coding 4 (spec 15.9, 14.6's
  // order over the attribute mesh) where it is smaller than coding 0: 2-7 %
  // of the corpus's texture coordinates. Decoders of the revisions before
  // it skip such an attribute; false keeps coding 0.
  bool attribute_geometry_order = true;
  // Attribute values on a grid may take aTTR coding 5 or 6 (spec 15.10:
  // codings 0 and 4 with 14.4.1's start of the class probabilities) where
  // that is smaller: 10-15 % of the texture coordinates of the corpus's
  // control meshes; from 1,000 values on only the winning coding's graded
  // start is tried (spot's texture coordinates: 0.4 %). Decoders of the
  // revisions before it skip such an attribute; false keeps codings 0 and 4.
  bool attribute_graded_start = true;
  // A per-corner attribute may take aTTR mapping 3 (spec 15.11: a decision a
  // vertex where its corners share one value, a seam vertex's corners
  // predicted from the faces next to them) where it is smaller than 15.3's
  // mapping 1: about half the mapping bytes of the corpus's texture
  // coordinates. Decoders of the revisions before it skip such an attribute;
  // false keeps mapping 1.
  bool attribute_predicted_mapping = true;
  // Values of two components on a grid (texture coordinates) may take aTTR
  // coding 7 (spec 15.12: each corner predicted where the shape of its face
  // in space puts it, relative to the values of its two neighbours) where
  // that is smaller: boat's texture coordinates 16 % smaller, cathead's 29 %.
  // Decoders of the revisions before it skip such an attribute; false keeps
  // codings 0 and 4 - 6.
  bool attribute_guided = true;
  // Unit normals may take aTTR coding 8 (spec 15.13: coding 3 with each face
  // weighted by its angle at the vertex, as many tools compute vertex
  // normals, instead of its area) where that is smaller: human_neutral's
  // normals ~15 % smaller. Decoders of the revisions before it skip such an
  // attribute; false keeps coding 3.
  bool angle_weighted_normals = true;
  // Values on a grid may take aTTR coding 9 (spec 15.14: a value whose
  // vertex has a mirror twin across a plane of the positions predicted by
  // the twin's value, flipped where the values around the two say so)
  // where that is smaller: the texture coordinates of meshes modelled with
  // a mirror. The plane is POSN method 9's, else one found as for it.
  // Decoders of the revisions before it skip such an attribute; false keeps
  // codings 0 and 4 - 7.
  bool attribute_twins = true;
  std::vector<std::string> texts;            // written as teXt chunks ("key=value")
  // Write an oRDR chunk (section 4.5) so that the decoder restores the
  // input's order of vertices, faces and corners exactly; nothing is
  // written when the coder order already is the input's order.
  bool keep_order = false;
  // Section 12: > 0 (1..8) writes a progressive file with this many Loop
  // levels, made by seed 003's pipeline (simplify, fit, subdivide, displace,
  // inverse Loop). Lossy by nature: the output is a semi-regular remesh of
  // the input surface, not its vertices. The input must be a triangle mesh;
  // where it is not manifold or not consistently oriented it is cut open
  // first, its surface unchanged (LoopEncodeStats says what was cut);
  // position_bits applies to the base.
  int progressive_levels = 0;
  // The LEVL displacement code: -1 the smaller of 0 (the seed's 1/9-bit
  // code, section 12.7) and 2 (range coded in contexts, 12.7.1); or 0 or 2.
  int displacement_code = -1;
  // Section 12.10: the finest level's displacement step is the least-error
  // step times this (1..64), the level below it times its square root.
  // Larger values trade accuracy for bytes: 4 made camelhead's 2-level file
  // 25 % smaller for 9 % more L2 error (docs/results/seed003.md).
  double finest_step_scale = 1;
  // Section 12.7.2: where the finest level strays farther than this from the
  // input surface, or leaves input points farther than this from itself
  // (sampled both ways), its vertices are moved back and the moves coded as
  // LEVL code 4's corrections (format 1.14). Relative to the input's
  // bounding-box diagonal; 0: no corrections. LoopEncodeStats says how far
  // the fit got.
  double max_deviation = 0;
  GeometryImageOptions gim;
  // Section 15: the attributes of mesh.attributes, each quantized on the
  // uniform grid of its bounding box with these bits (1..30) by kind, or
  // kept as exact binary32. A progressive file or a geometry image cannot
  // carry attributes: encode() refuses a mesh that has any.
  int texcoord_bits = 12;  // step 1/4095 of the range: 1/4 texel of a 1024-texel texture
  int normal_bits = 10;    // unit normals: octahedral, B bits (15.7), about 0.1 degree
  int colour_bits = 10;
  int generic_bits = 12;
  bool exact_attributes = false;
  // Unit normals take section 15.7's octahedral coding; false keeps them on
  // 15.4's grid of three components (as the first aTTR vectors were made).
  bool octahedral_normals = true;
  // Called during long operations (the progressive pipeline, the starts of
  // start_faces) with a stage name and the fraction done, 0..1; may be empty.
  std::function<void(const char* stage, double fraction)> progress;
};

struct ChunkStats {
  uint32_t type = 0;
  uint64_t bytes = 0;  // whole chunk: 12 bytes of framing plus the payload
};

struct QuadCoderStats {
  bool closed = false;                   // a quad was cut open (closed mesh)
  uint8_t coding = 0;                    // chosen coding, spec 5.3.5
  std::array<int64_t, 5> coding_bits{};  // symbol-stream bits per coding; -1 = not applicable
  uint32_t claim_violations = 0;         // Q5/Q10/Q12/Q13 followed by Q1-Q5
  std::array<uint32_t, 14> type_counts{};  // index 1..13
};

struct PolygonCoderStats {
  uint8_t coding = 0;                    // chosen coding, spec 5.4.4
  std::array<int64_t, kPolygonCodingCount> coding_bits{};  // face-symbol bits per coding; -1 = not applicable
  uint32_t components = 0, holes = 0, handles = 0, identifications = 0, loose_faces = 0;
  uint32_t non_quad_faces = 0;
  uint64_t record_bits = 0;              // bits of the records of 5.4.7 and 5.4.8
  // With EncodeOptions::start_faces > 1: the starts coded, the one kept
  // (0: the usual start) and the file from the usual start.
  uint32_t start_trials = 1, start_kept = 0;
  uint64_t usual_start_bytes = 0;
};

// Section 12: what the progressive encoder did (seed 003 tables 2 and 3).
struct LoopLevelStats {
  uint32_t vertices = 0, faces = 0;  // of the level
  uint32_t edge_points = 0, zeros = 0, clamped = 0;
  double step = 0;
  uint64_t bytes = 0;                // the LEVL chunk (level 0: CONN + POSN)
  uint8_t code = 0;                  // level >= 1: the displacement code (12.7: 0; 12.7.1: 2; 12.7.2: 4)
  uint32_t corrected_vertices = 0;   // code 4: vertices the corrections move
  // level >= 1: whose targets the displacements aim at (spec 12.10's closed
  // loop): 0 the encoder's own; where those would leave the level no nearer
  // the input than the level below, the alternative taken: 1 points whose
  // line misses the input stay where subdivision put them, 2 the same with
  // five times the reach, 3 the closest points, 4 no displacement.
  uint8_t targets = 0;
};
struct LoopEncodeStats {
  uint32_t input_vertices = 0, input_faces = 0, unreferenced_vertices_dropped = 0;
  uint32_t target_base_faces = 0;
  // The input made manifold (spec 12.10), its surface unchanged: faces of no
  // area and second copies of a face left out, edges of three or more faces
  // (or run the same way by two) cut open, and a vertex whose faces form
  // several fans split into one vertex per fan.
  uint32_t faces_without_area_dropped = 0, duplicate_faces_dropped = 0, edges_cut = 0, vertices_added = 0;
  std::vector<LoopLevelStats> levels;  // [0] = base mesh
  // Finest level, the encoder's own targets (spec 12.10): lines along N that
  // hit the input within the reach, and those that missed it.
  uint32_t ray_hits = 0, ray_misses = 0;
  // With max_deviation: the finest level's largest distance to the input and
  // the input's to it, over the fit's samples (deviation_fit.h: points of
  // each surface as dense as the level's edges), relative to the diagonal,
  // before and after the corrections.
  double deviation_before = 0, deviation_after = 0;
  double seconds_simplify = 0, seconds_fit = 0, seconds_remesh = 0, seconds_code = 0, seconds_deviation = 0;
};

// Section 13: what the geometry-image encoder did.
struct GimEncodeStats {
  uint32_t width = 0, height = 0;
  int genus = 0, boundary_loops = 0;
  uint32_t polygons_split = 0;       // input faces of degree > 3 fan-triangulated
  uint32_t unreferenced_vertices = 0;  // input vertices no face uses: not in the image
  uint32_t cut_nodes = 0, cut_paths = 0, seam_pairs = 0, occupied = 0;
  uint32_t hausdorff_iterations = 0;
  double hausdorff_before = -1, hausdorff_after = -1;  // seed 000 algorithm 1, absolute units
  double seconds_cut = 0, seconds_parametrize = 0, seconds_sample = 0, seconds_adjust = 0, seconds_code = 0;
  std::vector<int> plane_predictors;
  std::vector<uint64_t> plane_bytes;  // GPLN chunks
  uint64_t mask_bytes = 0, seam_bytes = 0, face_bytes = 0;
};

// Sections 6 and 14: how the positions were coded.
struct PositionStats {
  int method = 0;                  // POSN method: 0 deltas, 1 or 3 - 14 predicted
  int features = 0;                // methods 4 - 13: 14.9's features (1 quad twist, 2 mask contexts, 4 triangle twist)
  bool graded_start = false;       // methods 3 - 13: 14.4.1's start
  int shear = 0;                   // methods 11 - 13: 14.12's weight k of the shear (k / 16); 0 none
  uint32_t extrapolated_vertices = 0;  // methods 12 and 13: the vertices 14.13's rule gave candidates
  bool axis_classes = false;           // methods 13 and 14: 14.14's class probabilities per axis
  int lattice = 1;                     // method 14: 14.15's lattice factor k; 1 none
  // With EncodeOptions::surface_lattice: the POSN payloads of the lattice and
  // of the grid, the smaller kept (lattice > 1 if it was the lattice's).
  uint64_t lattice_payload_bytes = 0, grid_payload_bytes = 0;
  int mirror = 0;                  // methods 9 - 13: 1 image vertices at the image (14.10), 2 a step away too (14.11)
  std::array<double, 3> step{};    // the grid's step per axis
  std::array<uint32_t, 3> top{};   // the largest grid coordinate per axis
  double error_bound = 0;          // Euclidean bound of the rounding: |step| / 2
  // Methods 1, 3 - 13: vertices and information content (bits, -log2 of the
  // coded decisions' probabilities) by prediction kind (PredictionKind: 14.3.2,
  // and 4 the mirror candidate of 14.10).
  std::array<uint32_t, 5> vertices_by_kind{};
  std::array<double, 5> bits_by_kind{};
  // Method 10: the vertices paired with a partner beside the image (14.11),
  // not at it; with none, its payload is method 9's but for the selector.
  uint32_t pairs_beside = 0;
};

// Section 15: how one attribute was coded.
struct AttributeStats {
  std::string name;
  bool per_corner = false;       // mapping 1 or 3 (else one value per vertex)
  bool predicted_mapping = false;  // mapping 3: predicted from the faces around each vertex (15.11)
  bool exact = false;            // coding 1 (else predicted on a grid)
  bool octahedral = false;       // coding 3 or 8: unit normals, octahedral (15.7)
  bool angle_weighted = false;   // coding 8: predicted with the faces weighted by angle (15.13)
  bool geometry_order = false;   // coding 4 or 6, or 7 with option 1: the values in 14.6's order (15.9)
  bool graded_start = false;     // coding 5 or 6, or 7 with option 2: the class probabilities start as 14.4.1
  bool guided = false;           // coding 7, or 9 with option 4: guided by the positions (15.12)
  bool twins = false;            // coding 9: twin candidates across a mirror plane (15.14)
  uint32_t value_count = 0;
  double step = 0;               // the grid's step (codings 0, 4, 5, 6); coding 3: 2 / (2^B - 1)
  uint64_t mapping_bytes = 0, value_bytes = 0;  // the mapping stream; the values (grid fields included)
  uint64_t chunk_bytes = 0;      // the whole aTTR chunk
};

struct EncodeStats {
  ConnectivityMethod method = ConnectivityMethod::kIndexed;
  PositionStats positions;
  std::string fallback_reason;  // why the quad coder was not used (kAuto), empty if it was
  std::string polygon_fallback_reason;  // why the polygon coder was not used either (never expected)
  QuadCoderStats quad;          // filled when method == kQuad
  PolygonCoderStats polygon;    // filled when method == kPolygon
  LoopEncodeStats loop;         // filled for a progressive file (progressive_levels > 0)
  GimEncodeStats gim;           // filled for a geometry image (gim.size > 0)
  std::vector<AttributeStats> attributes;  // section 15, in file order
  std::vector<ChunkStats> chunks;
  uint64_t total_bytes = 0;
  // Vertex order of the file: file_vertex[i] is the input index of the
  // vertex the decoder will output as vertex i (sections 5.2.1, 5.3.4, 5.4.6) in
  // coder order, i.e. before an oRDR chunk (keep_order) is applied.
  std::vector<uint32_t> file_vertex;
  // Face order of the file: face_source[i] is the input index of the face
  // the decoder will output as face i.
  std::vector<uint32_t> face_source;
};

// Encodes `mesh`. Fails (never silently drops anything) on input the format
// cannot carry: non-finite coordinates, faces with fewer than 3 corners,
// corner indices out of range, more than 2^32 - 1 vertices or faces.
Status encode(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
              EncodeStats* stats = nullptr);

// Section 12 with rate control: seed 003's geometry (simplification,
// fitting, remesh) for options.progressive_levels levels is computed once by
// prepare(), the slow part; code() then writes the file at any
// position_bits, finest_step_scale and displacement_code of its options (its
// progressive_levels must be the prepared one), in a fraction of the time.
// prepare() then code() with the same options gives the bytes encode() gives.
class ProgressiveEncoder {
 public:
  ProgressiveEncoder();
  ~ProgressiveEncoder();
  ProgressiveEncoder(const ProgressiveEncoder&) = delete;
  ProgressiveEncoder& operator=(const ProgressiveEncoder&) = delete;
  // The errors encode() gives for this mesh and options (progressive_levels
  // must be 1..8).
  Status prepare(const Mesh& mesh, const EncodeOptions& options);
  // Fails before prepare() succeeded, or when the options are invalid or
  // name another level count.
  Status code(const EncodeOptions& options, std::vector<uint8_t>* out, EncodeStats* stats = nullptr) const;

 private:
  struct Prepared;
  std::unique_ptr<Prepared> prepared_;
};

}  // namespace qmc
