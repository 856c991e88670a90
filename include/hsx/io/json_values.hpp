// JSON spellings of exact values shared by every hsx document.
#pragma once

#include <hsx/geometry/scene.hpp>
#include <hsx/kernel/measure.hpp>
#include <hsx/kernel/one_root.hpp>

#include <nlohmann/json.hpp>

namespace hsx {

/// {"decimal": "<30 significant digits>", "exact": "<closed form>" | null}
nlohmann::json measure_to_json(const Measure& m);
/// [x, y] as exact strings ("1/2", "1 + 2*sqrt(5)").
nlohmann::json point_to_json(const OneRootPoint& p);
nlohmann::json point_to_json(const PointQ2& p);
/// {"min": [x, y], "max": [x, y]}
nlohmann::json box_to_json(const Box2& box);

}  // namespace hsx
