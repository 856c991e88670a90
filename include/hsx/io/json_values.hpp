// JSON spellings of exact values shared by every hsx document.
#pragma once

#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/measure.hpp>
#include <hsx/kernel/one_root.hpp>

#include <nlohmann/json.hpp>

namespace hsx {

/// {"decimal": "<30 significant digits>", "exact": "<closed form>" | null}; the closed form may contain "pi"
/// ("4/3*pi + 1/2*sqrt(3)"). When the digits could not be certified at the precision cap (Measure::decimal) the
/// object also has "certified": false (and "decimal" is the midpoint of the enclosure); otherwise no such field.
nlohmann::json measure_to_json(const Measure& m);
/// [x, y] as exact strings ("1/2", "1 + 2*sqrt(5)").
nlohmann::json point_to_json(const OneRootPoint& p);
nlohmann::json point_to_json(const PointQ2& p);
/// {"min": [x, y], "max": [x, y]}
nlohmann::json box_to_json(const Box2& box);

}  // namespace hsx
