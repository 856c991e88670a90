// The exact arrangement of a 3D scene's boundaries inside its domain box, as plain data (no CGAL types).
//
// Conventions (owned here):
// - Built from the input triangles (every surface's triangles, every plane clipped to the domain box as a convex
//   polygon, the box's six faces) by exact refinement in geometry/cgal_arrangement3.cpp: every intersection is
//   computed from ORIGINAL input triangles (never from refined ones), so coordinates stay small; the result is a
//   set of triangles that meet only along whole edges and at vertices. All vertices are exact rational points.
// - Coplanar input triangles are triangulated together, once per exact supporting plane: an output triangle is
//   emitted once, carrying every halfspace whose boundary contains it (`halfspaces`, ascending) and, for each, the
//   side its inside lies on (`front_inside`). The domain box's faces are triangles with `on_box` set; a box face
//   on a boundary carries that boundary's halfspaces too.
// - Orientation: a triangle's front is the side (v1 - v0) x (v2 - v0) points to. `front_cell` and `back_cell` are
//   the cells on either side; -1 is outside the domain.
// - Cells are the connected open regions of the domain minus all triangles. A cell is `outer` iff one of its
//   boundary triangles is on the box. `inside[c][i]` is cell c's side of halfspace i (complement applied).
// - Edges: every segment where refined triangles meet, with its triangles sorted radially (exact orientation
//   determinants; ArrEdge3 says which way round). Edges are ordered by (a, b).
// - Floating shells (triangles connected across edges, none on the box: a surface no other boundary crosses, also
//   when it touches another shell or the box only at a vertex) are joined to the cell around them by an exact ray
//   from the centroid of one of their triangles: the open segment from the ray's last crossing of the shell to its
//   next crossing of another one lies in that cell. Rays that cross either of these two at an edge or vertex, or
//   two triangles at once, or run inside a triangle's plane are replaced by others.
// - Cell ids: in order of the lowest triangle side (2 * triangle + (front ? 0 : 1)) bounding them.
#pragma once

#include <hsx/geometry/arrangement2.hpp>  // ArrangementLimits
#include <hsx/geometry/scene3.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hsx {

struct ArrTriangle3 {
  std::array<int, 3> vertices{};  ///< indices into Arrangement3::vertices(); front = (v1-v0)x(v2-v0)
  std::vector<int> halfspaces;    ///< halfspaces whose boundary contains this triangle, ascending (coincident: >1)
  std::vector<char> front_inside; ///< per entry of `halfspaces`: 1 if that halfspace's inside is on the front side
  bool on_box = false;            ///< lies on a face of the domain box
  int front_cell = -1, back_cell = -1;
  Rational area2;                 ///< |(v1-v0)x(v2-v0)|^2: the triangle's area is sqrt(area2)/2
};

struct ArrEdge3 {
  int a = -1, b = -1;             ///< vertex ids, a < b
  std::vector<int> triangles;     ///< triangles containing the edge, in radial order around it: right-handed
                                  ///< about the direction a -> b (counter-clockwise seen from b looking at a),
                                  ///< starting anywhere
};

struct ArrCell3 {
  bool outer = false;
  PointQ3 interior;               ///< an exact rational point strictly inside the cell (half way from the centroid
                                  ///< of its largest boundary triangle to the first triangle along its normal)
  std::vector<char> inside;       ///< per halfspace: 1 inside, 0 outside
  std::optional<Rational> volume; ///< exact; unset when Arrangement3Options::volumes is false
};

struct PointLocation3 {
  enum Kind { Cell, Triangle, Edge, Vertex, Outside } kind = Outside;
  int index = -1;
};

/// Wall-clock seconds of Arrangement3::build's phases, in the order they run (for `hsx bench --3d --phases`).
struct Arrangement3Timings {
  std::vector<std::pair<std::string, double>> phases;  ///< (phase name, seconds); a repeated name adds up
  /// Adds `seconds` to the phase called `name` (appended when new).
  void add(const std::string& name, double seconds);
};

struct Arrangement3Options {
  bool volumes = true;  ///< compute every cell's exact volume
  Arrangement3Timings* timings = nullptr;  ///< when set, build adds each phase's time to it (not printed anywhere)
  int threads = 0;      ///< worker threads for the per-triangle work; 0: hardware concurrency. The result does not
                        ///< depend on it (same triangles, same order).
};

class Arrangement3 {
 public:
  /// Builds the arrangement of every boundary of `scene` (validated, see validate_and_resolve(Scene3&)) with the
  /// domain box, finds cells and their sides, and places samples. Throws InputError when a surface intersects
  /// itself (naming the halfspace and two of its triangles), when a sample lies on an edge where boundaries meet,
  /// and when the arrangement outgrows `limits`.
  static Arrangement3 build(const Scene3& scene, const ArrangementLimits& limits = {},
                            const Arrangement3Options& options = {});

  const Box3& domain() const { return domain_; }
  int halfspace_count() const { return halfspace_count_; }
  const std::vector<PointQ3>& vertices() const { return vertices_; }
  const std::vector<ArrTriangle3>& triangles() const { return triangles_; }
  const std::vector<ArrEdge3>& edges() const { return edges_; }
  const std::vector<ArrCell3>& cells() const { return cells_; }
  /// For each scene sample, a triangle that holds it and carries the sample's halfspace.
  const std::vector<int>& sample_triangles() const { return sample_triangles_; }

  /// Exact point location of a rational point `p`: the cell, triangle (interior), edge or vertex holding it (the
  /// lowest-numbered triangle when several hold it), Outside beyond the domain box. Exact ray shooting: the
  /// triangles a ray meets come from an AABB tree over the triangles with exact ray-box and ray-triangle
  /// predicates, so a query costs O(log triangles + the triangles on the ray), of which only those whose interval
  /// crossing bound can come first are decided in rationals. The tree and the triangles' planes are built on the
  /// first call (figure19_b, 24k triangles: about 0.5 s, then about 0.1 ms a point).
  PointLocation3 locate(const PointQ3& p) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
  Box3 domain_;
  int halfspace_count_ = 0;
  std::vector<PointQ3> vertices_;
  std::vector<ArrTriangle3> triangles_;
  std::vector<ArrEdge3> edges_;
  std::vector<ArrCell3> cells_;
  std::vector<int> sample_triangles_;
};

}  // namespace hsx
