// The geometric content of an hsx scene, independent of its file format (io/ reads and writes files).
//
// Conventions (owned here):
// - A halfspace is a closed region; its `inside` is the set the formulas below give, swapped by `complement`.
//     halfplane: { x : normal . x <= offset }  (normal is the outward normal, need not be unit)
//     disk:      { x : |x - center| <= radius }, radius > 0
//     polygon:   the closed region bounded by a simple polygon (either vertex order)
// - The domain is an axis-aligned box that contains every bounded boundary and every sample. It is not a
//   halfspace: half-plane boundaries are clipped to it, and cells that share a boundary edge with it are outer.
// - Samples: `at` must lie exactly on the boundary of its halfspace; `near` is snapped to the nearest point of
//   that boundary (a one-root point for a circle).
#pragma once

#include <hsx/kernel/one_root.hpp>
#include <hsx/kernel/rational.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsx {

/// An error in the user's input; `what()` names the offending field, halfspace, sample or line. Exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Box2 {
  PointQ2 min, max;  ///< min.x < max.x and min.y < max.y
  bool contains(const PointQ2& p) const {
    return min.x <= p.x && p.x <= max.x && min.y <= p.y && p.y <= max.y;
  }
};

enum class HalfspaceKind2 { Halfplane, Disk, Polygon };
const char* to_string(HalfspaceKind2 kind);

struct Halfspace2 {
  std::string name;
  HalfspaceKind2 kind = HalfspaceKind2::Halfplane;
  bool complement = false;
  // halfplane
  PointQ2 normal;
  Rational offset;
  // disk
  PointQ2 center;
  Rational radius;
  // polygon, in the order given (orientation is not normalised; see is_counterclockwise)
  std::vector<PointQ2> vertices;

  /// Exact side test of a rational point: +1 strictly inside, 0 on the boundary, -1 strictly outside
  /// (complement already applied).
  int side(const PointQ2& p) const;
};

struct Sample2 {
  int halfspace = -1;            ///< index into Scene2::halfspaces
  PointQ2 given;                 ///< the point as written in the file
  bool snapped = false;          ///< true for `near`: `location` is the nearest boundary point to `given`
  OneRootPoint location;         ///< exact position on the boundary (== given for `at`)
};

struct Scene2 {
  std::string description;
  Box2 domain;
  bool domain_given = false;  ///< false: `domain` was chosen by hsx (see choose_domain)
  std::vector<Halfspace2> halfspaces;
  std::vector<Sample2> samples;

  int find_halfspace(const std::string& name) const;  ///< index or -1
};

/// Signed area of a polygon (positive when counter-clockwise), exact.
Rational signed_area(const std::vector<PointQ2>& polygon);

/// Check everything about a scene that needs geometry but not the arrangement, and resolve samples.
/// - polygons: >= 3 vertices, no repeated vertex, not all collinear, simple (no two edges meet except
///   consecutive edges at their shared vertex) - exact;
/// - radius > 0, halfplane normal non-zero;
/// - every `at` sample exactly on its boundary (error names the sample and its distance, as a decimal);
///   every `near` sample snapped to the nearest boundary point (exact one-root point);
/// - without a given domain, chooses one (choose_domain); with one, checks it contains every disk, polygon and
///   sample;
/// - at least one halfspace.
/// Throws InputError naming the offending halfspace or sample ("halfspaces[2] (name \"C\"): ...",
/// "samples[4]: ...").
void validate_and_resolve(Scene2& scene);

/// A box strictly containing every disk, polygon vertex, sample, and every intersection point of two
/// half-plane lines or of a line with a bounded boundary's box, with margin; deterministic.
Box2 choose_domain(const Scene2& scene);

}  // namespace hsx
