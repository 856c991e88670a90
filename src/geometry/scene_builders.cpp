#include <hsx/geometry/scene_builders.hpp>

namespace hsx {

namespace {

/// halfplane and plane: a halfspace of kind `kind` bounded by { x : normal . x = offset }.
template <class Halfspace, class Kind, class Point>
Halfspace flat(const std::string& name, Kind kind, const Point& normal, const Rational& offset, bool complement) {
  Halfspace h;
  h.name = name;
  h.kind = kind;
  h.normal = normal;
  h.offset = offset;
  h.complement = complement;
  return h;
}

}  // namespace

Halfspace2 halfplane(const std::string& name, const PointQ2& normal, const Rational& offset, bool complement) {
  return flat<Halfspace2>(name, HalfspaceKind2::Halfplane, normal, offset, complement);
}

Halfspace2 halfplane_through(const std::string& name, const PointQ2& normal, const PointQ2& through,
                             bool complement) {
  return halfplane(name, normal, normal.x * through.x + normal.y * through.y, complement);
}

Halfspace2 disk(const std::string& name, const PointQ2& center, const Rational& radius, bool complement) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Disk;
  h.center = center;
  h.radius = radius;
  h.complement = complement;
  return h;
}

Halfspace2 polygon(const std::string& name, std::vector<PointQ2> vertices, bool complement) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Polygon;
  h.vertices = std::move(vertices);
  h.complement = complement;
  return h;
}

Halfspace3 plane(const std::string& name, const PointQ3& normal, const Rational& offset, bool complement) {
  return flat<Halfspace3>(name, HalfspaceKind3::Plane, normal, offset, complement);
}

Halfspace3 plane_through(const std::string& name, const PointQ3& normal, const PointQ3& through, bool complement) {
  return plane(name, normal, normal.x * through.x + normal.y * through.y + normal.z * through.z, complement);
}

}  // namespace hsx
