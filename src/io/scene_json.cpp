// Scene files: see scene_json.hpp and docs/scene-format.md.
#include <hsx/io/scene_json.hpp>

#include <unordered_map>
#include <utility>

namespace hsx {

namespace {

using json = nlohmann::json;

std::string quote_name(const std::string& s) { return describe_json(json(s)); }

Halfspace2 read_halfspace(const JsonField& f, const SceneReadLimits& limits) {
  f.expect_object();
  Halfspace2 h;
  JsonField kind = f.at("kind");
  const std::string k = kind.string();
  // The allowed fields depend on the kind: check them before reading anything else, so that a misspelt field is
  // reported as unknown rather than as missing.
  if (k == "halfplane") {
    f.check_keys({"name", "kind", "complement", "normal", "offset"}, "a halfplane");
  } else if (k == "disk") {
    f.check_keys({"name", "kind", "complement", "center", "radius"}, "a disk");
  } else if (k == "polygon") {
    f.check_keys({"name", "kind", "complement", "vertices"}, "a polygon");
  }
  if (k == "halfplane" || k == "disk" || k == "polygon") {
    h.name = f.at("name").name();
  }
  if (k == "halfplane") {
    h.kind = HalfspaceKind2::Halfplane;
    h.normal = f.at("normal").point2(limits.numbers);
    h.offset = f.at("offset").rational(limits.numbers);
    if (h.normal.x == 0 && h.normal.y == 0) f.at("normal").fail("the normal must not be zero");
  } else if (k == "disk") {
    h.kind = HalfspaceKind2::Disk;
    h.center = f.at("center").point2(limits.numbers);
    JsonField radius = f.at("radius");
    h.radius = radius.rational(limits.numbers);
    if (h.radius <= 0) radius.fail("the radius must be positive, got " + describe_json(radius.json()));
  } else if (k == "polygon") {
    h.kind = HalfspaceKind2::Polygon;
    JsonField vertices = f.at("vertices");
    const std::size_t n = vertices.size();
    if (n > limits.max_polygon_vertices) {
      vertices.fail("too many vertices (" + std::to_string(n) + "; the limit is " +
                    std::to_string(limits.max_polygon_vertices) + ")");
    }
    h.vertices.reserve(n);
    for (std::size_t i = 0; i < n; ++i) h.vertices.push_back(vertices.at(i).point2(limits.numbers));
  } else if (k == "plane" || k == "mesh" || k == "sphere" || k == "cylinder" || k == "cone" || k == "torus" ||
             k == "box") {
    kind.fail("kind " + quote_name(k) + " is a 3D kind; a 2D scene has halfplane, disk or polygon");
  } else {
    kind.fail("unknown kind " + quote_name(k) + " (expected halfplane, disk or polygon)");
  }
  if (auto c = f.get("complement")) h.complement = c->boolean();
  return h;
}

Box2 read_domain(const JsonField& f, const SceneReadLimits& limits) {
  f.check_keys({"min", "max"});
  Box2 box;
  box.min = f.at("min").point2(limits.numbers);
  box.max = f.at("max").point2(limits.numbers);
  if (!(box.min.x < box.max.x && box.min.y < box.max.y)) f.fail("min must be below max in both coordinates");
  return box;
}

}  // namespace

int scene_dimension(const json& doc) {
  JsonField root(doc, "");
  root.expect_object();
  if (!root.has("format")) root.fail("missing field \"format\" (expected \"" + std::string(kSceneFormat) + "\")");
  JsonField format = root.at("format");
  if (!format.json().is_string() || format.json().get<std::string>() != kSceneFormat) {
    format.fail("expected \"" + std::string(kSceneFormat) + "\", got " + describe_json(format.json()));
  }
  JsonField dimension = root.at("dimension");
  if (!dimension.json().is_number_integer() ||
      (dimension.json().get<std::int64_t>() != 2 && dimension.json().get<std::int64_t>() != 3)) {
    dimension.fail("expected 2 or 3, got " + describe_json(dimension.json()));
  }
  return static_cast<int>(dimension.json().get<std::int64_t>());
}

Scene2 read_scene2(const json& doc, const SceneReadLimits& limits) {
  JsonField root(doc, "");
  if (scene_dimension(doc) == 3) root.at("dimension").fail("3D scenes are not supported yet");
  root.check_keys({"format", "dimension", "domain", "halfspaces", "samples", "description"});

  Scene2 scene;
  if (auto d = root.get("description")) scene.description = d->string();
  if (auto d = root.get("domain")) {
    scene.domain = read_domain(*d, limits);
    scene.domain_given = true;
  }

  JsonField halfspaces = root.at("halfspaces");
  const std::size_t n = halfspaces.size();
  if (n == 0) halfspaces.fail("the scene has no halfspace (at least one is needed)");
  if (n > limits.max_halfspaces) {
    halfspaces.fail("too many halfspaces (" + std::to_string(n) + "; the limit is " +
                    std::to_string(limits.max_halfspaces) + ")");
  }
  std::unordered_map<std::string, std::size_t> index;
  scene.halfspaces.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    JsonField f = halfspaces.at(i);
    Halfspace2 h = read_halfspace(f, limits);
    auto [it, fresh] = index.emplace(h.name, i);
    if (!fresh) {
      f.at("name").fail("duplicate name " + quote_name(h.name) + " (also halfspaces[" + std::to_string(it->second) +
                        "])");
    }
    scene.halfspaces.push_back(std::move(h));
  }

  if (auto samples = root.get("samples")) {
    const std::size_t m = samples->size();
    if (m > limits.max_samples) {
      samples->fail("too many samples (" + std::to_string(m) + "; the limit is " +
                    std::to_string(limits.max_samples) + ")");
    }
    scene.samples.reserve(m);
    for (std::size_t j = 0; j < m; ++j) {
      JsonField f = samples->at(j);
      f.check_keys({"on", "at", "near"});
      JsonField on = f.at("on");
      const std::string name = on.string();
      auto it = index.find(name);
      if (it == index.end()) on.fail("unknown halfspace " + quote_name(name));
      Sample2 s;
      s.halfspace = static_cast<int>(it->second);
      auto at = f.get("at");
      auto near = f.get("near");
      if (at && near) f.fail("give exactly one of \"at\" and \"near\", not both");
      if (!at && !near) f.fail("missing field \"at\" or \"near\"");
      s.snapped = near.has_value();
      s.given = (at ? *at : *near).point2(limits.numbers);
      scene.samples.push_back(std::move(s));
    }
  }

  validate_and_resolve(scene);
  return scene;
}

Scene2 read_scene_text(std::string_view text, const SceneReadLimits& limits) {
  return read_scene2(parse_exact_json(text, limits.json), limits);
}

Scene2 read_scene_file(const std::string& path, const SceneReadLimits& limits) {
  json doc = read_exact_json_file(path, limits.json);  // errors already carry the path
  try {
    return read_scene2(doc, limits);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

json write_scene2(const Scene2& scene) {
  auto point = [](const PointQ2& p) { return json::array({rational_to_json(p.x), rational_to_json(p.y)}); };
  json doc = json::object();
  doc["format"] = kSceneFormat;
  doc["dimension"] = 2;
  if (!scene.description.empty()) doc["description"] = scene.description;
  if (scene.domain_given) doc["domain"] = {{"min", point(scene.domain.min)}, {"max", point(scene.domain.max)}};
  json hs = json::array();
  for (const Halfspace2& h : scene.halfspaces) {
    json j = json::object();
    j["name"] = h.name;
    j["kind"] = to_string(h.kind);
    switch (h.kind) {
      case HalfspaceKind2::Halfplane:
        j["normal"] = point(h.normal);
        j["offset"] = rational_to_json(h.offset);
        break;
      case HalfspaceKind2::Disk:
        j["center"] = point(h.center);
        j["radius"] = rational_to_json(h.radius);
        break;
      case HalfspaceKind2::Polygon: {
        json v = json::array();
        for (const PointQ2& p : h.vertices) v.push_back(point(p));
        j["vertices"] = std::move(v);
        break;
      }
    }
    if (h.complement) j["complement"] = true;
    hs.push_back(std::move(j));
  }
  doc["halfspaces"] = std::move(hs);
  if (!scene.samples.empty()) {
    json ss = json::array();
    for (const Sample2& s : scene.samples) {
      json j = json::object();
      j["on"] = scene.halfspaces.at(static_cast<std::size_t>(s.halfspace)).name;
      j[s.snapped ? "near" : "at"] = point(s.given);
      ss.push_back(std::move(j));
    }
    doc["samples"] = std::move(ss);
  }
  return doc;
}

}  // namespace hsx
