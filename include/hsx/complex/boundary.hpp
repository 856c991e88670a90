// A solid's boundary cut into pieces: the input of NH-Rep's patch graphs (algorithms/nhrep). Dimension-free, so
// the patch graph, Algorithm 1 and patch decomposition are written once for curves and for meshes, and can be
// tested on hand-built boundaries.
//
// Conventions (owned here):
// - 2D: a piece is an arrangement edge on the solid's boundary (or a part of one, see split_piece); a link is a
//   point where two consecutive boundary pieces meet (an arrangement vertex). 3D: a piece is a mesh triangle and
//   a link is a mesh edge.
// - Every link joins exactly two distinct pieces (the boundary is a closed manifold). Pieces joined by a
//   non-feature link lie on the same patch; a feature link is a piece of a feature curve.
// - A feature link's `type` is the exact type of its feature points, measured by the solid's interior angle
//   there: Convex (< 180 degrees), Concave (> 180 degrees), Smooth (= 180 degrees, or, in 3D, a dihedral
//   deviation from flat below the sharpness angle). A single link is never Hybrid; curves are (see nhrep).
// - `corners` of a link are its end points where it can continue into another link of the same feature curve
//   (3D: the mesh edge's two vertex ids; 2D: none, a 2D feature curve is a single point).
// - `region` / `hole` (optional) say which connected part of the solid a piece bounds and whether it bounds a
//   hole or cavity of it; every piece of one boundary component has the same values. Section 5.2's tree
//   initialisation ignores them; nhrep's `nest_holes` option uses them.
// - `origin` ties a piece back to geometry (2D: arrangement edge index; 3D: triangle index). A piece made by
//   split_piece keeps its parent's origin and records the one original link it kept in `kept_link`.
#pragma once

#include <string>
#include <vector>

namespace hsx {

enum class FeatureType : char { Smooth = 0, Convex = 1, Concave = 2, Hybrid = 3 };

/// "smooth", "convex", "concave", "hybrid".
const char* feature_type_name(FeatureType type);

/// The type of a curve made of parts of types a and b (Guo et al., Section 3): smooth adds nothing, convex with
/// concave (or anything with hybrid) is hybrid.
FeatureType combine_feature_types(FeatureType a, FeatureType b);

struct BoundaryLink {
  int piece_a = -1, piece_b = -1;
  bool feature = false;
  FeatureType type = FeatureType::Smooth;  ///< meaningful for feature links only
  int corner_a = -1, corner_b = -1;        ///< ids into BoundarySurface corners, -1 when none
  int origin = -1;                         ///< geometry element (2D arrangement vertex), -1 when none
};

struct BoundaryPiece {
  std::vector<int> links;         ///< every link of this piece (2D: its two ends; 3D: its three edges)
  int origin = -1;                ///< geometry element (2D arrangement edge, 3D triangle)
  int carrier = -1;               ///< 2D: the halfspace whose boundary carries the piece; -1 when not known
  bool carrier_complemented = false;  ///< 2D: the solid lies outside `carrier` along this piece
  int split_of = -1;              ///< the piece this one was split from (-1: an original piece)
  int kept_link = -1;             ///< for a split piece: the parent's link it kept
  bool retired = false;           ///< replaced by split_piece; has no links and belongs to no patch
  /// Nesting, when known: the connected part of the solid the piece bounds (-1: not known), and whether the
  /// outside across the piece is bounded (a hole in 2D, a cavity in 3D) rather than reaching infinity.
  int region = -1;
  bool hole = false;
};

struct BoundarySurface {
  int dimension = 2;
  std::vector<BoundaryPiece> pieces;
  std::vector<BoundaryLink> links;
  int corner_count = 0;

  /// The piece across `link` from `piece`.
  int across(int link, int piece) const {
    const BoundaryLink& l = links[static_cast<std::size_t>(link)];
    return l.piece_a == piece ? l.piece_b : l.piece_a;
  }
};

/// Structural invariants: indices in range, each link joins two distinct pieces that both list it, no piece lists
/// a link twice, single links are not Hybrid, corners in range. Returns violations (empty: valid).
std::vector<std::string> check_boundary(const BoundarySurface& surface);

/// NH-Rep's face-splitting: replaces `piece` by one new piece per link of it, each keeping one of those links,
/// pairwise joined by new non-feature links (2D: an edge split at an interior point into two halves; 3D: a
/// triangle split at its centroid into three). The old piece is left in place with no links (so indices stay
/// valid), marked `retired`. Returns the new pieces, in the order of the old piece's links.
std::vector<int> split_piece(BoundarySurface& surface, int piece);

}  // namespace hsx
