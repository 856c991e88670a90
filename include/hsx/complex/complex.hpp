// The complex: a dimension-free combinatorial arrangement. Every algorithm (bsh, csg, nhrep) works on this and
// nothing else, so it can be built from geometry (from_arrangement2.hpp), read from JSON (io/complex_json.hpp),
// or written by hand in a test.
//
// Conventions (owned here):
// - Cells are the open d-dimensional regions of the arrangement inside the domain. `inside[i]` is the cell's
//   side of halfspace i (1 inside, 0 outside). Outer cells touch the domain's boundary and are always outside
//   any shape.
// - A patch is a maximal connected piece of ONE halfspace's boundary that no other boundary crosses. It
//   separates two cells: `inside_cell` lies inside its halfspace, `outside_cell` outside.
// - Coincident boundaries (a halfspace given twice, a half-plane containing a polygon edge, a disk and its
//   complement) give one patch per halfspace over the same point set; such patches form a `support` group. They
//   separate the same two cells, and those cells differ in exactly the group's halfspaces. A measure of a set of
//   patches counts each support once (see measure_of).
//   In 3D: every arrangement triangle carries each halfspace whose boundary contains it (a plane given twice in
//   either orientation, a box face on a plane, two meshes sharing a face); a patch region is a maximal set of
//   triangles carrying the same halfspaces, joined across edges that hold exactly those two triangles
//   (complex/from_arrangement3.hpp); each region gives one patch per halfspace it carries, all in one support group.
// - Patch pieces lying on the domain's boundary are not patches (both of their sides cannot be cells).
// - Junctions are where patches meet: vertices in 2D, edges in 3D (chains of arrangement edges). Two patches are adjacent iff they share a
//   junction; a closed patch with no junction (a lone circle) has no neighbours.
// - Samples sit on patches of their own halfspace.
// - Local structure for the manifold check (Section 3.1; both empty when not known, e.g. a complex read from JSON):
//   Junction::sheets lists, once per side, the patch sheets meeting along the junction (3D: one entry per patch
//   triangle along one edge of the chain, naming the lowest patch of its support group; a patch on both sides of
//   a junction, around a slit, appears twice). Corners are the points where junctions end or patches touch
//   (3D: arrangement vertices; 2D: none, a 2D junction is a point and its sheets are its patch ends): each lists
//   its spokes (one per junction end at the corner: a junction running through it gives two) and its wedges (one
//   per fan of one patch's triangles around the corner, from spoke to spoke, or a whole disc).
#pragma once

#include <hsx/kernel/lazy_measure.hpp>
#include <hsx/kernel/rational.hpp>

#include <string>
#include <vector>

namespace hsx {

struct Cell {
  bool outer = false;
  /// An exact interior point, `dimension` coordinates (empty when not known, e.g. read from JSON without one);
  /// computed on first read (2D arrangements). Read it with witness.get().
  Lazy<std::vector<Rational>> witness;
  std::vector<char> inside;       ///< per halfspace: 1 inside, 0 outside
  LazyMeasure measure;            ///< area (2D) or volume (3D); computed on first read (2D arrangements)
};

struct Patch {
  int halfspace = -1;
  int inside_cell = -1, outside_cell = -1;
  LazyMeasure measure;            ///< length (2D) or area (3D); computed on first read (2D arrangements)
  std::vector<int> samples;       ///< indices into Complex::samples, ascending
  int support = -1;               ///< index into Complex::supports
  std::vector<int> junctions;     ///< junctions this patch ends at (2D: its two end vertices; none when closed)
  std::vector<int> pieces;        ///< geometry pieces in order (2D: arrangement edges); empty when not known
};

struct Junction {
  std::vector<int> patches;       ///< patches that end here, ascending
  int piece = -1;                 ///< geometry piece (2D: arrangement vertex), -1 when not known
  /// Patch sheets along the junction, one per side (see the conventions; 3D only, empty when not known). Every
  /// edge of the chain has the same sheets (the builder splits chains where they change).
  std::vector<int> sheets;
};

/// A point where junctions end or patches touch (3D: an arrangement vertex; see the conventions).
struct Corner {
  /// One fan of a patch's triangles around the corner: between spokes `from` and `to` (indices into `spokes`;
  /// equal around a slit), or a whole disc around the corner when both are -1.
  struct Wedge {
    int patch = -1;               ///< the lowest patch of the fan's support group
    int from = -1, to = -1;
  };
  int piece = -1;                 ///< geometry piece (3D: arrangement vertex)
  std::vector<int> spokes;        ///< the junction of each spoke
  std::vector<Wedge> wedges;
};

struct SampleSite {
  int halfspace = -1;
  int patch = -1;
};

struct Complex {
  int dimension = 2;
  std::vector<std::string> halfspace_names;
  std::vector<Cell> cells;
  std::vector<Patch> patches;
  std::vector<std::vector<int>> supports;  ///< groups of coincident patches; every patch in exactly one group
  std::vector<Junction> junctions;
  std::vector<SampleSite> samples;
  /// Corners whose link the junctions' sheets do not settle (3D, see complex/from_arrangement3.hpp; empty in 2D
  /// and when not known).
  std::vector<Corner> corners;

  int halfspace_count() const { return static_cast<int>(halfspace_names.size()); }
  int outer_cell_count() const;
  /// Patches sharing a junction with p (p excluded), ascending, for every patch.
  std::vector<std::vector<int>> patch_neighbours() const;
  /// Patches bounding each cell, ascending.
  std::vector<std::vector<int>> cell_patches() const;
  /// The measure of a set of patches as a point set: each support group counted once.
  Measure measure_of(const std::vector<int>& patches) const;
};

/// Every structural invariant of a complex, checked exactly. Returns human-readable violations (empty: valid):
/// indices in range, each patch's cells distinct and on the right sides of its halfspace, the two cells of a
/// patch differ exactly in the halfspaces of its support group, support groups share cells, junction lists and
/// patch junction lists agree, junction sheets name listed patches, corners' spokes and wedges are in range,
/// samples sit on patches of their own halfspace.
std::vector<std::string> check_complex(const Complex& complex);

}  // namespace hsx
