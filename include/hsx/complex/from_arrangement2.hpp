// Building the complex from an exact 2D arrangement.
#pragma once

#include <hsx/complex/complex.hpp>
#include <hsx/geometry/arrangement2.hpp>
#include <hsx/geometry/scene.hpp>

namespace hsx {

/// A 2D scene's arrangement and its complex, built together so that pictures and reports can refer from
/// patches (Patch::pieces) back to arrangement edges and from junctions to vertices.
struct Arranged2 {
  Arrangement2 arrangement;
  Complex complex;
};

/// Patches are maximal chains of arrangement edges through degree-2 vertices (polygon corners and the
/// x-extreme points CGAL splits circles at), one patch per halfspace carried by the chain. Edges on the domain
/// box are dropped. Cells are the arrangement's bounded faces, in the same order.
Complex complex_from_arrangement(const Scene2& scene, const Arrangement2& arrangement);

/// validate_and_resolve must have been called on `scene`. Throws InputError for samples on junctions and for an
/// arrangement larger than `limits` (Arrangement2::build).
Arranged2 arrange(const Scene2& scene, const ArrangementLimits& limits = {});

/// `scene` arranged on `arrangement`, an arrangement of the same halfspaces and domain (built from this scene or
/// from another with other samples): Arrangement2::with_samples places the samples, then the complex is built. The
/// same result as arrange(scene) (proofs/arrangement2.md, claim 4) without a second sweep. Throws InputError for
/// samples on junctions, std::invalid_argument when the halfspace count or the domain differ.
Arranged2 arrange(const Scene2& scene, const Arrangement2& arrangement);

}  // namespace hsx
