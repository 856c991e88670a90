// The BSH authors' config.json: see bsh_config.hpp.
#include <hsx/io/bsh_config.hpp>
#include <hsx/geometry/scene_builders.hpp>

#include <hsx/geometry/tessellate3.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/scene_json.hpp>

#include "kernel/printable.hpp"
#include "io/surface_triangles.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>

namespace hsx {

namespace {

using json = nlohmann::json;

PointQ3 point3(const JsonField& f) {
  if (f.size() != 3) f.fail("expected [x, y, z], got " + std::to_string(f.size()) + " numbers");
  return PointQ3{f.at(std::size_t{0}).rational(), f.at(std::size_t{1}).rational(), f.at(std::size_t{2}).rational()};
}

Rational positive(const JsonField& f) {
  Rational q = f.rational();
  if (sgn(q) <= 0) f.fail("must be positive, got " + describe_json(f.json()));
  return q;
}

/// Their grid file: the domain box and their h, the diagonal of one grid cell, |(bbox_max - bbox_min) / resolution|
/// in double precision.
struct Grid {
  Box3 box;
  double h = 0;
};

Grid read_grid(const std::string& path) {
  const json doc = read_exact_json_file(path);
  try {
    JsonField root(doc, "");
    root.expect_object();
    Grid grid;
    Box3& box = grid.box;
    box = Box3{point3(root.at("bbox_min")), point3(root.at("bbox_max"))};
    if (!(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z))
      root.fail("bbox_min must be below bbox_max in every coordinate");
    JsonField res = root.at("resolution");
    if (res.size() != 3) res.fail("expected [nx, ny, nz], got " + std::to_string(res.size()) + " numbers");
    const Rational side[3] = {box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z};
    double sum = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      JsonField r = res.at(i);
      const std::int64_t cells = r.integer();
      if (cells < 1 || cells > 1'000'000) r.fail("must be between 1 and 1000000, got " + std::to_string(cells));
      const double d = side[i].get_d() / static_cast<double>(cells);
      sum += d * d;
    }
    grid.h = std::sqrt(sum);
    if (!std::isfinite(grid.h) || grid.h <= 0)
      root.fail("the grid cell's diagonal (their h, in double precision) is " +
                std::string(grid.h > 0 ? "infinite" : "zero") +
                ": bbox_min and bbox_max are out of the range of doubles, in which the authors' program works");
    return grid;
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

/// The most bytes a samples file may have, and the most samples all of a config's files may give together (as
/// many as an hsx scene may have: SceneReadLimits::max_samples).
constexpr std::size_t kMaxSamplesFileBytes = std::size_t(64) << 20;
constexpr std::size_t kMaxSamples = SceneReadLimits{}.max_samples;

/// A samples file: the token 3, then x y z triples, exact, into `out`; more than `room` points is an InputError
/// (the files' samples together may not pass kMaxSamples).
void read_samples_file(const std::string& path, std::size_t room, std::vector<PointQ3>* out) {
  std::istringstream in(read_file(path, kMaxSamplesFileBytes));
  std::vector<Rational> pending;
  std::string line;
  long line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      if (!header) {
        if (w != "3")
          throw InputError(path + ":" + std::to_string(line_no) + ": the first token must be 3, got \"" + printable(w) +
                           "\"");
        header = true;
        continue;
      }
      std::string why;
      auto q = parse_rational(w, &why);
      if (!q) throw InputError(path + ":" + std::to_string(line_no) + ": coordinate \"" + printable(w) + "\": " + why);
      pending.push_back(std::move(*q));
      if (pending.size() == 3) {
        if (out->size() == room)
          throw InputError(path + ":" + std::to_string(line_no) + ": more than " + std::to_string(kMaxSamples) +
                           " samples in the config's samples files (the limit of a scene)");
        out->push_back(PointQ3{pending[0], pending[1], pending[2]});
        pending.clear();
      }
    }
  }
  if (!header) throw InputError(path + ": empty samples file (expected 3, then x y z triples)");
  if (!pending.empty()) throw InputError(path + ":" + std::to_string(line_no) + ": the last point has fewer than 3 coordinates");
}

/// Their tessellation of a circle of radius `radius` (a torus: also `minor`; a sphere: its latitude bands).
Tessellation3 bsh_tessellation(double h, const Rational& radius, const Rational* minor = nullptr, bool sphere = false) {
  Tessellation3 t;
  t.frame = Tessellation3::Frame::Bsh;
  t.segments = bsh_segments(h, radius.get_d());
  if (minor) t.minor_segments = bsh_segments(h, minor->get_d());
  if (sphere) t.bands = bsh_sphere_bands(h, radius.get_d());
  return t;
}

Halfspace3 read_entry(const JsonField& f, const Box3& domain, double h) {
  f.expect_object();
  const std::string type = f.at("type").string();
  Halfspace3 hs;
  Primitive3& p = hs.primitive;
  if (type == "plane") {
    f.check_keys({"type", "name", "samples", "color", "point", "normal"}, "a plane");
    const PointQ3 normal = point3(f.at("normal"));
    if (sgn(normal.x) == 0 && sgn(normal.y) == 0 && sgn(normal.z) == 0) f.at("normal").fail("must not be zero");
    hs = plane_through("", normal, point3(f.at("point")));  // named below, as every type
  } else if (type == "sphere") {
    f.check_keys({"type", "name", "samples", "color", "is_flipped", "center", "radius"}, "a sphere");
    hs.kind = HalfspaceKind3::Sphere;
    p.center = point3(f.at("center"));
    p.radius = positive(f.at("radius"));
    p.tessellation = bsh_tessellation(h, p.radius, nullptr, true);
  } else if (type == "cylinder") {
    f.check_keys({"type", "name", "samples", "color", "is_flipped", "axis_point1", "axis_point2", "radius"},
                 "a cylinder");
    hs.kind = HalfspaceKind3::Cylinder;
    p.point1 = point3(f.at("axis_point1"));
    p.point2 = point3(f.at("axis_point2"));
    if (p.point1 == p.point2) f.at("axis_point2").fail("the axis has zero length (equal to axis_point1)");
    p.radius = positive(f.at("radius"));
    p.infinite = true;
    p.tessellation = bsh_tessellation(h, p.radius);
  } else if (type == "torus") {
    f.check_keys({"type", "name", "samples", "color", "is_flipped", "center", "axis_vector", "major_radius",
                  "minor_radius"}, "a torus");
    hs.kind = HalfspaceKind3::Torus;
    p.center = point3(f.at("center"));
    p.axis = point3(f.at("axis_vector"));
    if (sgn(p.axis.x) == 0 && sgn(p.axis.y) == 0 && sgn(p.axis.z) == 0) f.at("axis_vector").fail("must not be zero");
    p.major_radius = positive(f.at("major_radius"));
    p.minor_radius = positive(f.at("minor_radius"));
    if (p.minor_radius >= p.major_radius)
      f.at("minor_radius").fail("must be below major_radius (otherwise the torus intersects itself)");
    p.tessellation = bsh_tessellation(h, p.major_radius, &p.minor_radius);
  } else if (type == "cone") {
    f.check_keys({"type", "name", "samples", "color", "is_flipped", "apex", "axis_vector", "apex_angle"}, "a cone");
    hs.kind = HalfspaceKind3::Cone;
    p.point1 = point3(f.at("apex"));
    const PointQ3 axis = point3(f.at("axis_vector"));
    if (sgn(axis.x) == 0 && sgn(axis.y) == 0 && sgn(axis.z) == 0) f.at("axis_vector").fail("must not be zero");
    const double angle = f.at("apex_angle").rational().get_d();
    if (!(angle > 0 && angle < M_PI / 2))
      f.at("apex_angle").fail("must be between 0 and pi/2 (the half angle of one nappe; above pi/2 the authors' "
                              "mesh lies on the other nappe than their function)");
    // Their mesh (Mesh_BSH::generate_cone), in doubles, read exactly: the ring at 1.001 times the distance from the
    // apex to the farthest box corner, about the axis.
    const double w[3] = {axis.x.get_d(), axis.y.get_d(), axis.z.get_d()};
    const double norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double apex[3] = {p.point1.x.get_d(), p.point1.y.get_d(), p.point1.z.get_d()};
    double far = 0;
    for (int c = 0; c < 8; ++c) {
      const double corner[3] = {(c & 1 ? domain.max : domain.min).x.get_d(), (c & 2 ? domain.max : domain.min).y.get_d(),
                                (c & 4 ? domain.max : domain.min).z.get_d()};
      double d2 = 0;
      for (int i = 0; i < 3; ++i) d2 += (corner[i] - apex[i]) * (corner[i] - apex[i]);
      far = std::max(far, std::sqrt(d2));
    }
    far *= 1.001;
    const double end[4] = {apex[0] + far * std::cos(angle) * w[0] / norm, apex[1] + far * std::cos(angle) * w[1] / norm,
                           apex[2] + far * std::cos(angle) * w[2] / norm, far * std::sin(angle)};
    for (double d : end)
      if (!std::isfinite(d))
        f.fail("the authors' cone mesh, computed in double precision, overflows: the apex, the axis_vector and the "
               "grid's box must be within the range of doubles");
    p.point2 = PointQ3{Rational(end[0]), Rational(end[1]), Rational(end[2])};
    p.radius = Rational(end[3]);
    p.infinite = true;
    p.tessellation.frame = Tessellation3::Frame::Bsh;
    const double box = std::sqrt(Rational((domain.max.x - domain.min.x) * (domain.max.x - domain.min.x) +
                                          (domain.max.y - domain.min.y) * (domain.max.y - domain.min.y) +
                                          (domain.max.z - domain.min.z) * (domain.max.z - domain.min.z)).get_d());
    p.tessellation.segments = bsh_segments(h, box * std::sin(angle));
  } else if (type == "quadric" || type == "rbf") {
    f.at("type").fail("type \"" + type + "\" is not supported: hsx arranges planes and tessellated primitives only");
  } else {
    f.at("type").fail("unknown type " + describe_json(f.at("type").json()) +
                      " (expected plane, sphere, cylinder, cone or torus)");
  }
  hs.name = f.at("name").name();
  if (auto flipped = f.get("is_flipped")) hs.complement = flipped->boolean();
  if (hs.kind != HalfspaceKind3::Plane) {
    try {
      hs.surface = tessellate(hs, domain);
      hs.origin = tessellation_summary(hs) + " (the BSH authors' rule)";
    } catch (const InputError& e) {
      f.fail(e.what());
    }
  }
  return hs;
}

}  // namespace

bool is_bsh_config(const json& doc) { return doc.is_object() && doc.contains("input") && !doc.contains("format"); }

Scene3 read_bsh_config(const json& doc, const std::string& directory, const std::string& config_name,
                       const BshReadOptions& options, std::vector<std::string>* files_read) {
  if (!(options.h_scale > 0) || !std::isfinite(options.h_scale))
    throw InputError("BSH config: h_scale must be a positive number");
  const std::filesystem::path dir(directory);
  const auto opened = [&](std::string path) {
    if (files_read) files_read->push_back(path);
    return path;
  };
  Scene3 scene;
  const Grid grid = read_grid(opened((dir / "grid_64.json").string()));
  scene.domain = grid.box;
  scene.domain_given = true;
  const double h = grid.h * options.h_scale;
  std::vector<std::string> sample_files;
  try {
    JsonField root(doc, "");
    root.expect_object();
    JsonField input = root.at("input");
    const std::size_t n = input.size();
    if (n == 0) input.fail("no halfspace (at least one is needed)");
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < n; ++i) {
      JsonField f = input.at(i);
      Halfspace3 hs = read_entry(f, scene.domain, h);
      triangles += hs.surface.triangles.size();
      check_surface_triangles(triangles, options.max_surface_triangles, f);
      if (scene.find_halfspace(hs.name) >= 0) f.at("name").fail("duplicate name " + describe_json(json(hs.name)));
      sample_files.push_back(f.has("samples") ? f.at("samples").string() : std::string());
      scene.halfspaces.push_back(std::move(hs));
    }
  } catch (const InputError& e) {
    throw InputError(config_name + ": " + e.what());
  }
  scene.description = "BSH authors' scene " + std::filesystem::path(config_name).filename().string() + " (h = " +
                      std::to_string(h) + ")";
  std::vector<PointQ3> points;
  for (std::size_t i = 0; i < sample_files.size(); ++i) {
    if (sample_files[i].empty()) continue;
    points.clear();
    read_samples_file(opened((dir / sample_files[i]).string()), kMaxSamples - scene.samples.size(), &points);
    for (PointQ3& p : points) {
      Sample3 s;
      s.halfspace = static_cast<int>(i);
      s.snapped = true;
      s.given = std::move(p);
      scene.samples.push_back(std::move(s));
    }
  }
  try {
    validate_and_resolve(scene);
  } catch (const InputError& e) {
    throw InputError(config_name + ": " + e.what());
  }
  return scene;
}

Scene3 read_bsh_config_file(const std::string& path, const BshReadOptions& options) {
  const json doc = read_exact_json_file(path);
  if (!is_bsh_config(doc)) throw InputError(path + ": not the BSH authors' config (a JSON object with \"input\")");
  return read_bsh_config(doc, std::filesystem::path(path).parent_path().string(), path, options);
}

Scene3 read_scene3_input_file(const std::string& path, const SceneReadLimits& limits) {
  const json doc = read_exact_json_file(path, limits.json);
  if (is_bsh_config(doc)) return read_bsh_config(doc, std::filesystem::path(path).parent_path().string(), path);
  try {
    return read_scene3(doc, std::filesystem::path(path).parent_path().string(), limits);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace hsx
