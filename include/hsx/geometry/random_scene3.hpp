// Random 3D scenes of planes, for `hsx bench`'s 3D entry and the property tests of the 3D arrangement.
// Reproducible on every machine from (seed, index) (kernel/random.hpp: only Random's exactly specified draws).
//
// The procedure (rng = Random(item_seed(seed, index)), B = settings.coordinate_bound, d = settings.denominator,
// m = settings.max_coefficient): the domain is the box [-B, B]^3 (domain_given = true); then, for k = 0, 1, ...,
// planes - 1, plane "P<k>": normal (a, b, c) = (in(-m, m), in(-m, m), in(-m, m)) (x drawn first), drawn again
// while it is zero; a point p = (in(-(B-1)d, (B-1)d), ...) / d strictly inside the box; the halfspace
// { x : n . x <= n . p }, complemented when rng.one_in(4) (drawn last). Small coefficients make coincident and
// concurrent planes likely for many planes; large ones make general position likely.
#pragma once

#include <hsx/geometry/scene3.hpp>

#include <cstdint>

namespace hsx {

struct RandomPlanesSettings {
  int planes = 10;           ///< number of planes, >= 1
  int max_coefficient = 5;   ///< |normal coordinates| <= this, >= 1
  int coordinate_bound = 4;  ///< the domain is [-B, B]^3, B >= 2
  int denominator = 2;       ///< the planes' points are multiples of 1/denominator, >= 1
};

/// Scene `index` of stream `seed` by the procedure above. Not validated (planes need nothing beyond a non-zero
/// normal, which the procedure guarantees). Throws std::invalid_argument for settings out of range.
Scene3 random_plane_scene3(const RandomPlanesSettings& settings, std::uint64_t seed, std::uint64_t index);

}  // namespace hsx
