// A campaign's random 3D scenes: see scene3.hpp.
#include <hsx/algorithms/campaign/scene3.hpp>
#include <hsx/geometry/scene_builders.hpp>

#include <hsx/algorithms/bsh/sample_scene.hpp>
#include <hsx/algorithms/bsh/samples.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/kernel/random.hpp>

#include <stdexcept>

namespace hsx::campaign {
namespace {

Rational half(Random& rng, long a, long b) { return Rational(rng.in(a, b)) / Rational(2); }

/// The axis (0, 1, 2) of an axis-aligned plane normal, or -1.
int axis_of(const PointQ3& n) {
  const bool x = n.x != 0, y = n.y != 0, z = n.z != 0;
  if (x + y + z != 1) return -1;
  return x ? 0 : y ? 1 : 2;
}

Rational& coordinate(PointQ3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
const Rational& component(const PointQ3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

/// The box faces of the scene (step 3): plane halfspaces whose name holds a '.', axis-aligned.
std::vector<int> box_faces(const Scene3& scene) {
  std::vector<int> out;
  for (std::size_t k = 0; k < scene.halfspaces.size(); ++k) {
    const Halfspace3& h = scene.halfspaces[k];
    if (h.kind == HalfspaceKind3::Plane && h.name.find('.') != std::string::npos && axis_of(h.normal) >= 0)
      out.push_back(static_cast<int>(k));
  }
  return out;
}

/// The d-th of the 13 directions with entries in {-1, 0, 1}, first non-zero entry 1, lexicographic.
PointQ3 direction(long d) {
  long count = 0;
  for (int x = 0; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        const bool leading = x == 1 || (x == 0 && (y == 1 || (y == 0 && z == 1)));
        if (leading && count++ == d) return {Rational(x), Rational(y), Rational(z)};
      }
  throw std::logic_error("campaign scene3: direction out of range");
}

/// Appends one pattern's halfspaces (step 3).
void apply(Degeneracy3 kind, const std::string& name, Random& rng, const std::vector<int>& faces,
           const Arrangement3& arrangement, Scene3& scene) {
  switch (kind) {
    case Degeneracy3::PlaneOnBoxFace: {
      const Halfspace3 f = scene.halfspaces[static_cast<std::size_t>(rng.pick(faces))];
      scene.halfspaces.push_back(plane(name, f.normal, f.offset, rng.one_in(2)));
      return;
    }
    case Degeneracy3::CoincidentFaces: {
      const Halfspace3 f = scene.halfspaces[static_cast<std::size_t>(rng.pick(faces))];
      const int a = axis_of(f.normal);
      const bool positive = component(f.normal, a) > 0;
      const Rational c = positive ? f.offset : -f.offset, length = half(rng, 2, 8);
      PointQ3 lo, hi;
      coordinate(lo, a) = positive ? c : c - length;
      coordinate(hi, a) = positive ? c + length : c;
      for (int other = 0; other < 3; ++other) {
        if (other == a) continue;
        coordinate(lo, other) = half(rng, -8, 8);
        coordinate(hi, other) = coordinate(lo, other) + half(rng, 2, 8);
      }
      const Rational one(1), zero(0);
      scene.halfspaces.push_back(plane(name + ".xmin", {-one, zero, zero}, -lo.x));
      scene.halfspaces.push_back(plane(name + ".xmax", {one, zero, zero}, hi.x));
      scene.halfspaces.push_back(plane(name + ".ymin", {zero, -one, zero}, -lo.y));
      scene.halfspaces.push_back(plane(name + ".ymax", {zero, one, zero}, hi.y));
      scene.halfspaces.push_back(plane(name + ".zmin", {zero, zero, -one}, -lo.z));
      scene.halfspaces.push_back(plane(name + ".zmax", {zero, zero, one}, hi.z));
      return;
    }
    case Degeneracy3::ConcurrentPlanes: {
      const PointQ3 v = rng.pick(arrangement.vertices());
      const PointQ3 d = direction(rng.in(0, 12));
      scene.halfspaces.push_back(plane(name, d, d.x * v.x + d.y * v.y + d.z * v.z));
      return;
    }
  }
}

/// Step 5's patches.
std::vector<int> sample_patches(const Scene3Settings& settings, Samples3 policy, const Complex& complex,
                                const std::vector<char>& intended, Random& rng) {
  if (policy == Samples3::Intended) return bsh::initial_samples(complex, intended);
  std::vector<int> left, out;
  for (std::size_t p = 0; p < complex.patches.size(); ++p) left.push_back(static_cast<int>(p));
  if (settings.max_samples == 0 || left.empty()) return out;
  const long n = rng.in(1, settings.max_samples);
  for (long k = 0; k < n && !left.empty(); ++k) {
    const std::size_t i = rng.index(left.size());
    out.push_back(left[i]);
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
  }
  return out;
}

}  // namespace

const char* to_string(Degeneracy3 d) {
  switch (d) {
    case Degeneracy3::PlaneOnBoxFace: return "PlaneOnBoxFace";
    case Degeneracy3::CoincidentFaces: return "CoincidentFaces";
    case Degeneracy3::ConcurrentPlanes: return "ConcurrentPlanes";
  }
  return "?";
}

std::optional<Degeneracy3> degeneracy3_from_string(const std::string& s) {
  for (int k = 0; k < kDegeneracy3Count; ++k)
    if (s == to_string(static_cast<Degeneracy3>(k))) return static_cast<Degeneracy3>(k);
  return std::nullopt;
}

Arranged3 arrange_campaign_scene3(const Scene3& scene, const ArrangementLimits& limits) {
  Arrangement3Options options;
  options.volumes = false;
  options.threads = 1;
  return arrange(scene, limits, options);
}

void validate(const Scene3Settings& s) {
  if (s.solid.min_primitives < 1 || s.solid.max_primitives < s.solid.min_primitives ||
      s.solid.max_primitives > csg::kMaxRandomPrimitives3)
    throw std::invalid_argument("primitives: need 1 <= A <= B <= " + std::to_string(csg::kMaxRandomPrimitives3));
  if (s.solid.segments < 6 || s.solid.segments > 64) throw std::invalid_argument("segments: in [6, 64]");
  if (s.solid.max_draws < 1) throw std::invalid_argument("max draws: at least 1");
  if (s.min_degeneracies < 0 || s.max_degeneracies < s.min_degeneracies)
    throw std::invalid_argument("degeneracies: need 0 <= A <= B");
  for (int w : s.degeneracy_weight)
    if (w < 0) throw std::invalid_argument("degeneracy weights: >= 0");
  if (s.max_samples < 0) throw std::invalid_argument("samples: >= 0");
}

CampaignScene3 random_campaign_scene3(const Scene3Settings& settings, Samples3 policy, std::uint64_t seed,
                                      std::uint64_t index, const ArrangementLimits& limits, int* generated) {
  validate(settings);
  csg::RandomSolid3 r = csg::random_solid3(settings.solid, seed, index, limits, generated);
  const auto made = [&](const Scene3& scene) {
    if (generated) *generated = static_cast<int>(scene.halfspaces.size());
  };
  made(r.scene);
  const bool bounded = r.status == csg::SolidStatus::Bounded;
  Random rng(item_seed(item_seed(seed, index), 1));
  CampaignScene3 out;
  out.scene = std::move(r.scene);
  const std::vector<int> faces = box_faces(out.scene);
  std::vector<Degeneracy3> pool;
  std::vector<int> weights;
  for (int k = 0; k < kDegeneracy3Count; ++k) {
    const auto d = static_cast<Degeneracy3>(k);
    if (settings.degeneracy_weight[static_cast<std::size_t>(k)] <= 0) continue;
    if (d != Degeneracy3::ConcurrentPlanes && faces.empty()) continue;
    if (d == Degeneracy3::ConcurrentPlanes && r.arranged.arrangement.vertices().empty()) continue;
    pool.push_back(d);
    weights.push_back(settings.degeneracy_weight[static_cast<std::size_t>(k)]);
  }
  if (!pool.empty() && settings.max_degeneracies > 0) {
    const long count = rng.in(settings.min_degeneracies, settings.max_degeneracies);
    for (long j = 0; j < count; ++j) {
      const Degeneracy3 d = pool[rng.weighted(weights)];
      apply(d, "d" + std::to_string(j), rng, faces, r.arranged.arrangement, out.scene);
      out.degeneracies.push_back(to_string(d));
    }
  }
  made(out.scene);
  if (out.degeneracies.empty()) {
    out.arranged = std::move(r.arranged);
  } else {
    out.scene.domain_given = false;
    validate_and_resolve(out.scene);
    out.arranged = arrange_campaign_scene3(out.scene, limits);
  }
  const auto intended = [&](const Complex& complex) {
    return bounded ? csg::evaluate(*r.expression, complex) : std::vector<char>(complex.cells.size(), 0);
  };
  out.intended = intended(out.arranged.complex);
  const std::vector<int> patches = sample_patches(settings, policy, out.arranged.complex, out.intended, rng);
  if (!patches.empty()) {
    Scene3 sampled = bsh::scene_with_samples(out.scene, out.arranged, patches, out.scene.description);
    validate_and_resolve(sampled);
    out.scene = std::move(sampled);
    out.arranged = arrange_campaign_scene3(out.scene, limits);
    out.intended = intended(out.arranged.complex);
  }
  return out;
}

}  // namespace hsx::campaign
