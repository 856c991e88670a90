// Exact areas with pi and short witness points, on scenes whose answers are known in closed form.
#include <hsx/complex/complex.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/geometry/scene.hpp>
#include <hsx/io/json_values.hpp>
#include <hsx/kernel/measure.hpp>
#include "support/random_scenes.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace hsx;
using namespace hsx::test;

namespace {

/// Sum of the measures of the cells inside at least one halfspace (the union).
Measure union_measure(const Complex& c) {
  Measure total;
  for (const Cell& cell : c.cells) {
    bool inside = false;
    for (char b : cell.inside) inside = inside || b;
    if (inside) total += cell.measure;
  }
  return total;
}

}  // namespace

TEST_CASE("two unit disks at distance 1: the union's area is 4/3*pi + 1/2*sqrt(3), exactly", "[complex][pi]") {
  const Scene2 s = make_scene(Box2{pt(-3, -3), pt(4, 3)}, {disk("A", pt(0, 0), 1), disk("B", pt(1, 0), 1)});
  const Complex c = arrange(s).complex;
  REQUIRE(c.cells.size() == 4);
  const Measure area = union_measure(c);
  REQUIRE(area.exact_string());
  CHECK(*area.exact_string() == "4/3*pi + 1/2*sqrt(3)");
  CHECK(compare(area, Measure::pi(Rational(4, 3)) + Measure::sqrt_of(Rational(3, 4))) == Order::Equal);
  const nlohmann::json j = measure_to_json(area);
  CHECK(j["exact"] == "4/3*pi + 1/2*sqrt(3)");
  CHECK(j["decimal"] == "5.05481560857082963138058101513");  // bc: 5.054815608570829631380581015125...
  CHECK_FALSE(j.contains("certified"));
  // each of the two crescents is 1/3*pi + 1/2*sqrt(3), the lens 2/3*pi - 1/2*sqrt(3): decided Equal, not Tie
  int crescents = 0;
  for (const Cell& cell : c.cells) {
    if (cell.inside[0] != cell.inside[1]) {
      ++crescents;
      CHECK(compare(cell.measure, Measure::pi(Rational(1, 3)) + Measure::sqrt_of(Rational(3, 4))) == Order::Equal);
    }
    if (cell.inside[0] && cell.inside[1])
      CHECK(*cell.measure.get().exact_string() == "2/3*pi - 1/2*sqrt(3)");
  }
  CHECK(crescents == 2);
  // the two inner arcs (angle 2pi/3 each) are congruent arcs on different circles: their lengths are Equal
  std::vector<Measure> inner;
  for (const Patch& p : c.patches)
    if (c.cells[p.inside_cell].inside[0] && c.cells[p.inside_cell].inside[1]) inner.push_back(p.measure);
  REQUIRE(inner.size() == 2);
  CHECK(compare(inner[0], inner[1]) == Order::Equal);
  CHECK(*inner[0].exact_string() == "2/3*pi");
}

TEST_CASE("witness points are short rationals strictly inside their cells", "[complex][witness]") {
  const Scene2 s = make_scene(Box2{pt(-3, -3), pt(4, 3)},
                              {disk("A", pt(0, 0), 1), disk("B", pt(1, 0), 1), halfplane("L", pt(0, 1), 1)});
  const Complex c = arrange(s).complex;
  REQUIRE(c.cells.size() > 4);
  for (const Cell& cell : c.cells) {
    REQUIRE(cell.witness.get().size() == 2);
    const PointQ2 w{cell.witness.get()[0], cell.witness.get()[1]};
    INFO("witness " << exact_string(w.x) << ", " << exact_string(w.y));
    // dyadic midpoints of enclosures had 2^62-sized denominators; the simplest rational has a small one here
    CHECK(w.x.get_den() < 100);
    CHECK(w.y.get_den() < 100);
    for (std::size_t i = 0; i < s.halfspaces.size(); ++i) {
      const int side = s.halfspaces[i].side(w);
      CHECK(side != 0);
      CHECK((side > 0) == static_cast<bool>(cell.inside[i]));
    }
  }
}

TEST_CASE("measure_to_json marks uncertified digits", "[io][decimal]") {
  // q plus a zero that is not known to be zero (two keys of one nested radical), with q = 1 + 5*10^-30 exactly
  // half-way between two 30-digit decimals: the 30 digits cannot be pinned down at the precision cap.
  const Measure d = Measure::distance(OneRootPoint(Rational(0), Rational(0)),
                                      OneRootPoint(Rational(1), OneRoot(Rational(1), Rational(1), Rational(2))));
  const Measure d2 = Measure::distance(OneRootPoint(Rational(0), Rational(0)),
                                       OneRootPoint(Rational(2), OneRoot(Rational(2), Rational(2), Rational(2))));
  const Rational q = 1 + make_rational(Integer(5), Integer("1000000000000000000000000000000"));
  const Measure m = Measure(q) + d - d2 * Rational(1, 2);
  REQUIRE_FALSE(m.decimal(30).certified);
  const nlohmann::json j = measure_to_json(m);
  CHECK(j["certified"] == false);
  CHECK(j["decimal"].get<std::string>().find('~') == std::string::npos);  // JSON keeps the digits parseable
  CHECK(m.decimal_string(30).back() == '~');
  // certified values have no such field (documents without special cases are unchanged)
  CHECK_FALSE(measure_to_json(Measure(q)).contains("certified"));
  CHECK_FALSE(measure_to_json(Measure::pi()).contains("certified"));
}
