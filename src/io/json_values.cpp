#include <hsx/io/json_values.hpp>

namespace hsx {

nlohmann::json measure_to_json(const Measure& m) {
  nlohmann::json j;
  const Measure::Decimal decimal = m.decimal(30);
  j["decimal"] = decimal.digits;
  if (!decimal.certified) j["certified"] = false;  // digits not pinned down at the precision cap
  if (auto exact = m.exact_string())
    j["exact"] = *exact;
  else
    j["exact"] = nullptr;
  return j;
}

nlohmann::json point_to_json(const OneRootPoint& p) {
  return nlohmann::json::array({p.x.exact_string(), p.y.exact_string()});
}

nlohmann::json point_to_json(const PointQ2& p) {
  return nlohmann::json::array({exact_string(p.x), exact_string(p.y)});
}

nlohmann::json box_to_json(const Box2& box) {
  return {{"min", point_to_json(box.min)}, {"max", point_to_json(box.max)}};
}

}  // namespace hsx
