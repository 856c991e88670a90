// The 3D part of hsx-scene/1: see scene_json.hpp and docs/scene-format.md.
#include <hsx/geometry/tessellate3.hpp>
#include <hsx/io/scene_json.hpp>
#include "io/surface_triangles.hpp"

#include <cstdint>
#include <filesystem>
#include <unordered_map>
#include <utility>

namespace hsx {

namespace {

using json = nlohmann::json;

std::string quote_name(const std::string& s) { return describe_json(json(s)); }

PointQ3 point3(const JsonField& f, const NumberLimits& limits) {
  if (f.size() != 3) f.fail("expected [x, y, z], got " + std::to_string(f.size()) + " numbers");
  return PointQ3{f.at(std::size_t{0}).rational(limits), f.at(std::size_t{1}).rational(limits),
                 f.at(std::size_t{2}).rational(limits)};
}

Rational positive(const JsonField& f, const NumberLimits& limits) {
  Rational q = f.rational(limits);
  if (sgn(q) <= 0) f.fail("must be positive, got " + describe_json(f.json()));
  return q;
}

Tessellation3 read_tessellation(const JsonField& f, HalfspaceKind3 kind) {
  Tessellation3 t;
  f.expect_object();
  const bool torus = kind == HalfspaceKind3::Torus;
  if (torus) f.check_keys({"segments", "minor_segments", "edge_length", "frame"}, "a tessellation");
  else if (kind == HalfspaceKind3::Sphere) f.check_keys({"segments", "edge_length", "bands", "frame"}, "a tessellation");
  else f.check_keys({"segments", "edge_length", "frame"}, "a tessellation");
  if (auto frame = f.get("frame")) {
    const std::string style = frame->string();
    if (style == "bsh") t.frame = Tessellation3::Frame::Bsh;
    else if (style != "smallest-axis")
      frame->fail("expected \"smallest-axis\" or \"bsh\", got " + describe_json(frame->json()));
  }
  if (auto bands = f.get("bands")) {
    const std::int64_t m = bands->integer();
    if (m < 2 || m > kMaxSegments)
      bands->fail("must be between 2 and " + std::to_string(kMaxSegments) + ", got " + std::to_string(m));
    t.bands = static_cast<int>(m);
  }
  auto segments = f.get("segments");
  auto length = f.get("edge_length");
  if (segments && length) f.fail("give \"segments\" or \"edge_length\", not both");
  if (!segments && !length) f.fail("missing field \"segments\" or \"edge_length\"");
  auto bounded = [](const JsonField& g) {
    const std::int64_t n = g.integer();
    if (n < 3 || n > kMaxSegments)
      g.fail("must be between 3 and " + std::to_string(kMaxSegments) + ", got " + std::to_string(n));
    return static_cast<int>(n);
  };
  if (segments) {
    t.segments = bounded(*segments);
    if (auto minor = f.get("minor_segments")) t.minor_segments = bounded(*minor);
  } else {
    if (f.has("minor_segments")) f.at("minor_segments").fail("goes with \"segments\", not \"edge_length\"");
    t.mode = Tessellation3::Mode::EdgeLength;
    t.edge_length = positive(*length, {});
  }
  return t;
}

struct KindFields {
  const char* name;
  HalfspaceKind3 kind;
  std::initializer_list<std::string_view> keys;
};

const KindFields kKinds[] = {
    {"plane", HalfspaceKind3::Plane, {"name", "kind", "complement", "normal", "offset"}},
    {"mesh", HalfspaceKind3::Mesh, {"name", "kind", "complement", "file"}},
    {"box", HalfspaceKind3::Box, {"name", "kind", "complement", "min", "max"}},
    {"sphere", HalfspaceKind3::Sphere, {"name", "kind", "complement", "center", "radius", "tessellation"}},
    {"cylinder", HalfspaceKind3::Cylinder,
     {"name", "kind", "complement", "axis_point1", "axis_point2", "radius", "infinite", "tessellation"}},
    {"cone", HalfspaceKind3::Cone,
     {"name", "kind", "complement", "apex", "base_center", "radius", "infinite", "tessellation"}},
    {"torus", HalfspaceKind3::Torus,
     {"name", "kind", "complement", "center", "axis", "major_radius", "minor_radius", "tessellation"}},
};

void read_primitive(const JsonField& f, Halfspace3& h, const NumberLimits& n) {
  Primitive3& p = h.primitive;
  switch (h.kind) {
    case HalfspaceKind3::Box:
      p.min = point3(f.at("min"), n);
      p.max = point3(f.at("max"), n);
      if (!(p.min.x < p.max.x && p.min.y < p.max.y && p.min.z < p.max.z))
        f.at("max").fail("must be above min in every coordinate");
      break;
    case HalfspaceKind3::Sphere:
      p.center = point3(f.at("center"), n);
      p.radius = positive(f.at("radius"), n);
      break;
    case HalfspaceKind3::Cylinder:
    case HalfspaceKind3::Cone: {
      const bool cyl = h.kind == HalfspaceKind3::Cylinder;
      p.point1 = point3(f.at(cyl ? "axis_point1" : "apex"), n);
      p.point2 = point3(f.at(cyl ? "axis_point2" : "base_center"), n);
      if (p.point1 == p.point2)
        f.at(cyl ? "axis_point2" : "base_center")
            .fail(std::string("the axis has zero length (equal to ") + (cyl ? "axis_point1" : "apex") + ")");
      p.radius = positive(f.at("radius"), n);
      if (auto inf = f.get("infinite")) p.infinite = inf->boolean();
      break;
    }
    case HalfspaceKind3::Torus:
      p.center = point3(f.at("center"), n);
      p.axis = point3(f.at("axis"), n);
      if (sgn(p.axis.x) == 0 && sgn(p.axis.y) == 0 && sgn(p.axis.z) == 0) f.at("axis").fail("must not be zero");
      p.major_radius = positive(f.at("major_radius"), n);
      p.minor_radius = positive(f.at("minor_radius"), n);
      if (p.minor_radius >= p.major_radius)
        f.at("minor_radius").fail("must be below major_radius (otherwise the torus intersects itself)");
      break;
    default: break;
  }
  if (auto t = f.get("tessellation")) p.tessellation = read_tessellation(*t, h.kind);
}

Halfspace3 read_halfspace3(const JsonField& f, const std::optional<Box3>& domain, const std::string& base,
                           const SceneReadLimits& limits) {
  f.expect_object();
  Halfspace3 h;
  JsonField kind = f.at("kind");
  const std::string k = kind.string();
  const KindFields* entry = nullptr;
  for (const KindFields& e : kKinds)
    if (k == e.name) entry = &e;
  if (!entry) {
    if (k == "halfplane" || k == "disk" || k == "polygon")
      kind.fail("kind " + quote_name(k) + " is a 2D kind; a 3D scene has plane, mesh, box, sphere, cylinder, cone or torus");
    kind.fail("unknown kind " + quote_name(k) + " (expected plane, mesh, box, sphere, cylinder, cone or torus)");
  }
  f.check_keys(entry->keys, std::string("a ") + entry->name);
  h.kind = entry->kind;
  h.name = f.at("name").name();
  if (auto c = f.get("complement")) h.complement = c->boolean();
  const NumberLimits& n = limits.numbers;
  if (h.kind == HalfspaceKind3::Plane) {
    h.normal = point3(f.at("normal"), n);
    if (sgn(h.normal.x) == 0 && sgn(h.normal.y) == 0 && sgn(h.normal.z) == 0) f.at("normal").fail("must not be zero");
    h.offset = f.at("offset").rational(n);
    return h;
  }
  if (h.kind == HalfspaceKind3::Mesh) {
    JsonField file = f.at("file");
    h.primitive.file = file.string();
    if (h.primitive.file.empty()) file.fail("the file name must not be empty");
    const std::filesystem::path path = std::filesystem::path(base) / h.primitive.file;
    try {
      ObjMesh mesh = read_mesh_file(path.string(), limits.meshes);
      // build_mesh3 here too, so that a bad mesh is reported with the file's lines.
      // validate_and_resolve checks it again and reverses an inward mesh with a note.
      build_mesh3(mesh);
      h.surface.vertices = std::move(mesh.vertices);
      h.surface.triangles = std::move(mesh.faces);
    } catch (const InputError& e) {
      file.fail(e.what());
    }
    h.origin = path.string();
    return h;
  }
  read_primitive(f, h, n);
  if (h.primitive.infinite && !domain)
    f.at("infinite").fail(std::string("an infinite ") + to_string(h.kind) + " is clipped by the domain: give \"domain\"");
  try {
    const int segments = largest_circle_segments(h);
    if (segments > limits.max_segments)
      f.fail("tessellation: " + std::to_string(segments) + " segments per circle; the limit is " +
             std::to_string(limits.max_segments));
    h.surface = tessellate(h, domain ? *domain : Box3{});
    h.origin = tessellation_summary(h);
  } catch (const InputError& e) {
    f.fail(e.what());
  }
  return h;
}

Box3 read_domain3(const JsonField& f, const NumberLimits& n) {
  f.check_keys({"min", "max"});
  Box3 box{point3(f.at("min"), n), point3(f.at("max"), n)};
  if (!(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z))
    f.fail("min must be below max in every coordinate");
  return box;
}

json point_json(const PointQ3& p) {
  return json::array({rational_to_json(p.x), rational_to_json(p.y), rational_to_json(p.z)});
}

json tessellation_json(const Tessellation3& t, bool torus) {
  json j = json::object();
  if (t.mode == Tessellation3::Mode::EdgeLength) {
    j["edge_length"] = rational_to_json(t.edge_length);
  } else {
    j["segments"] = t.segments;
    if (torus && t.minor_segments != 0) j["minor_segments"] = t.minor_segments;
  }
  if (t.bands != 0) j["bands"] = t.bands;
  if (t.frame == Tessellation3::Frame::Bsh) j["frame"] = "bsh";
  return j;
}

json halfspace_json(const Halfspace3& h) {
  json j = json::object();
  j["name"] = h.name;
  j["kind"] = to_string(h.kind);
  const Primitive3& p = h.primitive;
  switch (h.kind) {
    case HalfspaceKind3::Plane:
      j["normal"] = point_json(h.normal);
      j["offset"] = rational_to_json(h.offset);
      break;
    case HalfspaceKind3::Mesh: j["file"] = p.file; break;
    case HalfspaceKind3::Box:
      j["min"] = point_json(p.min);
      j["max"] = point_json(p.max);
      break;
    case HalfspaceKind3::Sphere:
      j["center"] = point_json(p.center);
      j["radius"] = rational_to_json(p.radius);
      break;
    case HalfspaceKind3::Cylinder:
      j["axis_point1"] = point_json(p.point1);
      j["axis_point2"] = point_json(p.point2);
      j["radius"] = rational_to_json(p.radius);
      if (p.infinite) j["infinite"] = true;
      break;
    case HalfspaceKind3::Cone:
      j["apex"] = point_json(p.point1);
      j["base_center"] = point_json(p.point2);
      j["radius"] = rational_to_json(p.radius);
      if (p.infinite) j["infinite"] = true;
      break;
    case HalfspaceKind3::Torus:
      j["center"] = point_json(p.center);
      j["axis"] = point_json(p.axis);
      j["major_radius"] = rational_to_json(p.major_radius);
      j["minor_radius"] = rational_to_json(p.minor_radius);
      break;
  }
  if (h.kind != HalfspaceKind3::Plane && h.kind != HalfspaceKind3::Mesh && h.kind != HalfspaceKind3::Box)
    j["tessellation"] = tessellation_json(p.tessellation, h.kind == HalfspaceKind3::Torus);
  if (h.complement) j["complement"] = true;
  return j;
}

}  // namespace

Scene3 read_scene3(const json& doc, const std::string& base_directory, const SceneReadLimits& limits) {
  JsonField root(doc, "");
  if (scene_dimension(doc) != 3) root.at("dimension").fail("expected 3, got 2 (a 2D scene)");
  root.check_keys({"format", "dimension", "domain", "halfspaces", "samples", "description"});
  Scene3 scene;
  if (auto d = root.get("description")) scene.description = d->string();
  std::optional<Box3> domain;
  if (auto d = root.get("domain")) {
    domain = read_domain3(*d, limits.numbers);
    scene.domain = *domain;
    scene.domain_given = true;
  }
  JsonField halfspaces = root.at("halfspaces");
  const std::size_t n = halfspaces.size();
  if (n == 0) halfspaces.fail("the scene has no halfspace (at least one is needed)");
  if (n > limits.max_halfspaces)
    halfspaces.fail("too many halfspaces (" + std::to_string(n) + "; the limit is " +
                    std::to_string(limits.max_halfspaces) + ")");
  std::unordered_map<std::string, std::size_t> index;
  std::size_t triangles = 0;
  for (std::size_t i = 0; i < n; ++i) {
    JsonField f = halfspaces.at(i);
    Halfspace3 h = read_halfspace3(f, domain, base_directory, limits);
    triangles += h.surface.triangles.size();
    check_surface_triangles(triangles, limits.max_surface_triangles, f);
    auto [it, fresh] = index.emplace(h.name, i);
    if (!fresh)
      f.at("name").fail("duplicate name " + quote_name(h.name) + " (also halfspaces[" + std::to_string(it->second) + "])");
    scene.halfspaces.push_back(std::move(h));
  }
  if (auto samples = root.get("samples")) {
    const std::size_t m = samples->size();
    if (m > limits.max_samples)
      samples->fail("too many samples (" + std::to_string(m) + "; the limit is " + std::to_string(limits.max_samples) + ")");
    for (std::size_t j = 0; j < m; ++j) {
      JsonField f = samples->at(j);
      f.check_keys({"on", "at", "near"});
      JsonField on = f.at("on");
      const std::string name = on.string();
      auto it = index.find(name);
      if (it == index.end()) on.fail("unknown halfspace " + quote_name(name));
      auto at = f.get("at");
      auto near = f.get("near");
      if (at && near) f.fail("give exactly one of \"at\" and \"near\", not both");
      if (!at && !near) f.fail("missing field \"at\" or \"near\"");
      Sample3 s;
      s.halfspace = static_cast<int>(it->second);
      s.snapped = near.has_value();
      s.given = point3(at ? *at : *near, limits.numbers);
      scene.samples.push_back(std::move(s));
    }
  }
  validate_and_resolve(scene);
  return scene;
}

Scene3 read_scene3_text(std::string_view text, const std::string& base_directory, const SceneReadLimits& limits) {
  return read_scene3(parse_exact_json(text, limits.json), base_directory, limits);
}

Scene3 read_scene3_file(const std::string& path, const SceneReadLimits& limits) {
  json doc = read_exact_json_file(path, limits.json);
  try {
    return read_scene3(doc, std::filesystem::path(path).parent_path().string(), limits);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

json write_scene3(const Scene3& scene) {
  json doc = json::object();
  doc["format"] = kSceneFormat;
  doc["dimension"] = 3;
  if (!scene.description.empty()) doc["description"] = scene.description;
  if (scene.domain_given) doc["domain"] = {{"min", point_json(scene.domain.min)}, {"max", point_json(scene.domain.max)}};
  json hs = json::array();
  for (const Halfspace3& h : scene.halfspaces) hs.push_back(halfspace_json(h));
  doc["halfspaces"] = std::move(hs);
  if (!scene.samples.empty()) {
    json ss = json::array();
    for (const Sample3& s : scene.samples)
      ss.push_back({{"on", scene.halfspaces.at(static_cast<std::size_t>(s.halfspace)).name},
                    {s.snapped ? "near" : "at", point_json(s.given)}});
    doc["samples"] = std::move(ss);
  }
  return doc;
}

}  // namespace hsx
