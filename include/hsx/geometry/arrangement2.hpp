// The exact planar arrangement of a 2D scene's boundaries inside its domain box, as plain data (no CGAL types).
//
// Conventions (owned here):
// - Built by CGAL's circle-segment traits over exact rationals (geometry/cgal_arrangement2.cpp). Circles are split
//   by CGAL into x-monotone arcs at their leftmost and rightmost points; polygon corners are vertices. Those
//   degree-2 vertices are real vertices of this structure (so Euler's relation holds), but patches (complex/)
//   run through them.
// - The domain box is part of the arrangement: its four sides are edges with `on_box == true`. The unbounded
//   face outside the box is not a face here; face index -1 means "outside the domain".
// - Faces are the bounded faces (the cells). A face is `outer` iff it shares an edge with the box.
// - Edge orientation: an edge runs from `source` to `target`; `left_face`/`right_face` are the faces on its left
//   and right when walking that way. For an arc, `ccw` tells whether that walk is counter-clockwise around the
//   circle.
// - `inside[f][i]` is face f's side of halfspace i (complement applied): 1 inside, 0 outside. Faces are open
//   sets, so the side is never "on".
#pragma once

#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/lazy_measure.hpp>

#include <memory>
#include <vector>

namespace hsx {

struct ArrVertex2 {
  OneRootPoint point;
  int degree = 0;  ///< number of incident edges
};

enum class EdgeShape2 { Segment, Arc };

struct ArrEdge2 {
  int source = -1, target = -1;   ///< vertex indices
  std::vector<int> halfspaces;    ///< halfspaces whose boundary contains this edge, ascending (coincident: >1)
  bool on_box = false;            ///< lies on the domain box
  int left_face = -1, right_face = -1;
  EdgeShape2 shape = EdgeShape2::Segment;
  PointQ2 center;                 ///< arc only: supporting circle
  Rational radius;                ///< arc only
  bool ccw = false;               ///< arc only: source -> target runs counter-clockwise
  /// segment only: the supporting line a*x + b*y + c = 0 with rational coefficients (all zero when unknown,
  /// e.g. read from a document)
  Rational line_a, line_b, line_c;
};

struct ArrFace2 {
  bool outer = false;
  std::vector<char> inside;       ///< per halfspace: 1 inside, 0 outside
  /// Boundary walks, each a cycle of (edge, forward) with the face on the left; the first is the outer
  /// boundary, the rest are holes.
  std::vector<std::vector<std::pair<int, bool>>> boundary;
};

struct PointLocation2 {
  enum Kind { Face, Edge, Vertex, Outside } kind = Outside;
  int index = -1;
};

/// How large an arrangement may grow. Time and memory grow with the cells (about 10 KB each, see docs/limits.md)
/// and with cells x halfspaces (every cell records its side of every halfspace, here and in the complex): an
/// input within the scene limits can still have an arrangement quadratic in its size. 0 disables a limit.
struct ArrangementLimits {
  long max_cells = 250000;            ///< bounded faces
  long max_side_entries = 1L << 27;   ///< cells x halfspaces
  long max_triangles = 4'000'000;     ///< 3D only: refined triangles (Arrangement3), checked before cells are found
};

/// Bench support (hsx bench --arrange), used by no algorithm: the baseline hsx's arrangement is measured
/// against. Inserts the same distinct curves Arrangement2::build hands to CGAL (the domain box's sides and every
/// halfspace boundary, coincident ones once) into a bare CGAL Arrangement_2 (the same instantiation:
/// circle-segment traits over exact rationals, each curve's index as consolidated data, an int on every DCEL
/// record (Arrangement2::build's indices, unset here); aggregated insertion, no observer) and returns its number of
/// bounded faces. Nothing else is extracted: no vertices, edges, measures,
/// interior points, sides or samples. `scene` must be validated (validate_and_resolve).
long bare_cgal_arrangement_faces(const Scene2& scene);

class Arrangement2 {
 public:
  /// Builds the arrangement of every halfspace boundary of `scene` (validated, see validate_and_resolve) with
  /// the domain box, classifies faces and places samples. Edge lengths, face areas and faces' interior points are
  /// computed on first request (edge_lengths(), face_areas(), face_interiors()).
  /// Throws InputError when a sample lies on a vertex where two boundaries meet, and when the arrangement
  /// outgrows `limits` (checked while CGAL builds it, so refusing costs about what the limit allows). A refusal
  /// from inside CGAL's sweep leaks the sweep's buffers (CGAL frees them only when a sweep completes): about
  /// 1 KB per curve, measured with valgrind; harmless for a program that then ends, worth knowing for a host that
  /// refuses many inputs.
  static Arrangement2 build(const Scene2& scene, const ArrangementLimits& limits = {});

  /// This arrangement with the samples of `scene` placed instead of its own: the same faces, edges and vertices
  /// (shared, not copied), sample_edges() for `scene`. `scene` must have the halfspaces and domain this was
  /// built from (samples do not change the arrangement); its halfspace count and domain are checked
  /// (std::invalid_argument). Throws InputError for a misplaced sample, as build() does.
  Arrangement2 with_samples(const Scene2& scene) const;

  const Box2& domain() const { return domain_; }
  int halfspace_count() const { return halfspace_count_; }
  const std::vector<ArrVertex2>& vertices() const { return pieces_->vertices; }
  const std::vector<ArrEdge2>& edges() const { return pieces_->edges; }
  const std::vector<ArrFace2>& faces() const { return pieces_->faces; }
  /// Exact edge lengths, entry e for edges()[e] (geometry/planar_measures.hpp: edge_length), each computed on its
  /// first read and kept; thread-safe. The cache keeps the geometry it needs alive: it may outlive this object.
  const std::shared_ptr<const MeasureCache>& edge_lengths() const { return edge_lengths_; }
  /// Exact face areas, entry f for faces()[f] (planar_measures.hpp: enclosed_area), as edge_lengths().
  const std::shared_ptr<const MeasureCache>& face_areas() const { return face_areas_; }
  /// An exact rational point strictly inside each face, entry f for faces()[f]: on a vertical line through a
  /// rational x between two vertices of a non-vertical boundary edge of f, a rational y between that edge and the
  /// next boundary above or below it, both short rationals (few digits). Each computed on its first
  /// read and kept, as edge_lengths(); the same points whenever and by whichever thread they are read.
  const std::shared_ptr<const LazyCache<PointQ2>>& face_interiors() const { return face_interiors_; }
  /// For each scene sample, the edge that holds it (an edge carrying the sample's halfspace). A sample on a
  /// degree-2 vertex inside one curve run (a polygon corner, a circle's x-extreme point) is given one of the two
  /// edges.
  const std::vector<int>& sample_edges() const { return sample_edges_; }
  /// Number of connected components of the edge graph (for Euler's relation V - E + F = 1 + C, F counting the
  /// unbounded face).
  int connected_components() const;

  /// Exact point location of a rational point.
  PointLocation2 locate(const PointQ2& p) const;
  /// The same answer as locate(p), found faster when p lies on the boundary of halfspace `halfspace` (an index
  /// into the scene's halfspaces; std::invalid_argument when out of range): only the edges carrying it and their
  /// ends are tested, and locate(p) is asked when p is on none of them.
  PointLocation2 locate_on_boundary(const PointQ2& p, int halfspace) const;
  /// The edges that end at vertex `vertex` (an index into vertices(); std::invalid_argument when out of range), in
  /// increasing order, an edge twice when both its ends are there.
  std::vector<int> incident_edges(int vertex) const;
  /// The edge that holds a point of halfspace `halfspace`'s boundary (an index into the scene's halfspaces;
  /// std::invalid_argument when out of range) located at `where` (locate() or locate_on_boundary()'s answer for
  /// it), as sample_edges() gives it: `where`'s edge when that edge carries the halfspace and is not on the domain
  /// box; at a degree-2 vertex whose two edges carry the same halfspaces, `halfspace` among them (a point inside
  /// one curve run: a polygon corner, a circle's x-extreme point), the lower-indexed of the two; else -1 (the point
  /// is not inside a patch of the halfspace's boundary). std::invalid_argument when `where` names no edge or vertex
  /// of this arrangement.
  int holding_edge(const PointLocation2& where, int halfspace) const;

 private:
  struct Impl;
  /// For each sample of `scene`, the edge that holds it (build's step 7; see sample_edges()).
  std::vector<int> place_samples(const Scene2& scene) const;
  std::shared_ptr<const Impl> impl_;
  /// The plain data, shared with the measure caches (which must not hold the arrangement itself).
  struct Pieces {
    std::vector<ArrVertex2> vertices;
    std::vector<ArrEdge2> edges;
    std::vector<ArrFace2> faces;
  };
  Box2 domain_;
  int halfspace_count_ = 0;
  std::shared_ptr<const Pieces> pieces_ = std::make_shared<const Pieces>();
  std::shared_ptr<const MeasureCache> edge_lengths_ = std::make_shared<const MeasureCache>(0, nullptr);
  std::shared_ptr<const MeasureCache> face_areas_ = std::make_shared<const MeasureCache>(0, nullptr);
  std::shared_ptr<const LazyCache<PointQ2>> face_interiors_ = std::make_shared<const LazyCache<PointQ2>>(0, nullptr);
  std::vector<int> sample_edges_;
};

}  // namespace hsx
