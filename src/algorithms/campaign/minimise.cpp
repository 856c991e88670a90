// Minimising a failing scene: see minimise.hpp.
#include <hsx/algorithms/campaign/minimise.hpp>

#include <hsx/algorithms/bsh/problem.hpp>
#include <hsx/geometry/tessellate3.hpp>

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <new>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace hsx::campaign {
namespace {

using Clock = std::chrono::steady_clock;

Integer trunc_of(const Rational& q) {
  Integer out;
  mpz_tdiv_q(out.get_mpz_t(), q.get_num().get_mpz_t(), q.get_den().get_mpz_t());
  return out;
}

/// Nearest whole number, halves away from zero.
Integer round_of(const Rational& q) {
  const Rational half(1, 2);
  return q >= 0 ? trunc_of(q + half) : Integer(-trunc_of(-q + half));
}

bool simpler(const Rational& a, const Rational& b) {
  if (a.get_den() != b.get_den()) return a.get_den() < b.get_den();
  return abs(a.get_num()) < abs(b.get_num());
}

/// A scene arranged as the campaign arranges it (2D: arrange within the limits; 3D: arrange_campaign_scene3).
Arranged2 arranged_for(const CampaignSettings& s, const Scene2& scene) { return arrange(scene, s.limits); }
Arranged3 arranged_for(const CampaignSettings& s, const Scene3& scene) { return arrange_campaign_scene3(scene, s.limits); }

template <class Scene>
struct ArrangedOf;
template <>
struct ArrangedOf<Scene2> {
  using type = Arranged2;
};
template <>
struct ArrangedOf<Scene3> {
  using type = Arranged3;
};

/// The original scene's intended shape (minimise.hpp): its complex and its flags.
struct Shape {
  Complex complex;
  std::vector<char> solid;
  bool orientation_preserving = true;  ///< the original shape is
  bool touches_box = false;            ///< some outer cell of the original is inside
};

/// A record of a reduced scene the library threw on while arranging it (check_scene's Error record).
SceneRecord error_record(const CampaignSettings& s, std::uint64_t index, const std::string& what) {
  SceneRecord r;
  r.index = index;
  r.seed = s.seed;
  r.outcome = SceneOutcome::Error;
  r.note = "the library threw: " + what;
  return r;
}

/// Everything minimise_scene needs while it runs.
template <class Scene>
struct Reducer {
  using Arranged = typename ArrangedOf<Scene>::type;
  CampaignSettings eval;  ///< the settings restricted to the target checks
  std::uint64_t index = 0;
  std::vector<std::string> target;
  bool error = false;
  MinimiseOptions options;
  Clock::time_point start = Clock::now();
  Minimised<Scene> result;
  std::optional<Shape> shape;  ///< SamplePolicy::Intended: the intended shape, carried to each reduced scene
  std::vector<int> origin;     ///< result.scene's halfspace k is the original's origin[k]

  bool out_of_budget() {
    if (options.max_steps > 0 && result.steps >= options.max_steps) return result.exhausted = true;
    if (options.time_limit > 0 &&
        std::chrono::duration<double>(Clock::now() - start).count() >= options.time_limit)
      return result.exhausted = true;
    return false;
  }

  bool fails(const SceneRecord& r) const {
    if (error) return r.outcome == SceneOutcome::Error;
    if (r.outcome != SceneOutcome::Checked) return false;
    for (const std::string& name : target) {
      const auto it = std::find_if(r.checks.begin(), r.checks.end(), [&](const CheckOutcome& c) { return c.check == name; });
      if (it == r.checks.end() || it->status != CheckStatus::Failed) return false;
    }
    return true;
  }

  /// The intended shape carried to a reduced scene's complex, when it is well defined and keeps the original's
  /// kind (orientation-preserving when the original is, no outer cell inside when the original has none);
  /// std::nullopt otherwise.
  std::optional<std::vector<char>> carried(const Complex& complex, const std::vector<int>& kept) const {
    std::optional<std::vector<char>> solid = carry_by_sign_vectors(shape->complex, shape->solid, kept, complex);
    if (!solid) return std::nullopt;
    if (!shape->touches_box)
      for (std::size_t c = 0; c < complex.cells.size(); ++c)
        if ((*solid)[c] && complex.cells[c].outer) return std::nullopt;
    if (shape->orientation_preserving && !bsh::is_orientation_preserving(bsh::Problem(complex), *solid))
      return std::nullopt;
    return solid;
  }

  /// The record of a valid reduced scene whose halfspace k is the original's `kept[k]`; std::nullopt when its
  /// intended shape is not well defined. `given`: the intended shape to use instead of carrying it (the original's).
  std::optional<SceneRecord> record_of(const Scene& candidate, const std::vector<int>& kept,
                                       const std::vector<char>* given) {
    if constexpr (std::is_same_v<Scene, Scene2>)
      if (!shape) return check_scene(eval, candidate, index);  // check_scene arranges it (a refusal: Refused)
    std::optional<Arranged> arranged;
    try {
      arranged = arranged_for(eval, candidate);
    } catch (const InputError&) {
      return std::nullopt;  // refused by the limits (or a sample the arrangement refuses): does not fail
    } catch (const std::bad_alloc&) {
      throw;  // out of memory ends the run (exit 2): it says nothing about the input
    } catch (const std::exception& e) {
      return error_record(eval, index, e.what());
    }
    std::vector<char> intended;
    if (given) {
      intended = *given;
    } else if (shape) {
      std::optional<std::vector<char>> solid = carried(arranged->complex, kept);
      if (!solid) return std::nullopt;
      intended = std::move(*solid);
    }
    return check_scene(eval, candidate, std::move(*arranged), intended, index);
  }

  /// Checks `candidate` (unresolved), whose halfspace k is the original's `kept[k]`; when it is valid and still
  /// fails, it becomes the result. False otherwise, or when the budget is spent (then nothing is checked).
  bool attempt(Scene candidate, std::vector<int> kept, const std::vector<char>* given = nullptr) {
    if (out_of_budget()) return false;
    try {
      validate_and_resolve(candidate);
    } catch (const std::bad_alloc&) {
      throw;  // out of memory ends the run (exit 2): it says nothing about the input
    } catch (const std::exception&) {
      return false;  // not a valid scene: not a step
    }
    ++result.steps;
    std::optional<SceneRecord> r = record_of(candidate, kept, given);
    if (!r || !fails(*r)) return false;
    r->scene.reset();
    r->scene3.reset();
    result.record = std::move(*r);
    result.scene = std::move(candidate);
    origin = std::move(kept);
    return true;
  }

  /// Tries removing the halfspaces `drop` (ascending indices of result.scene) with the samples on them.
  bool attempt_without(const std::vector<int>& drop) {
    Scene candidate = result.scene;
    candidate.halfspaces.clear();
    candidate.samples.clear();
    std::vector<int> kept, renumber(result.scene.halfspaces.size(), -1);
    for (std::size_t h = 0; h < result.scene.halfspaces.size(); ++h)
      if (!std::binary_search(drop.begin(), drop.end(), static_cast<int>(h))) {
        renumber[h] = static_cast<int>(candidate.halfspaces.size());
        candidate.halfspaces.push_back(result.scene.halfspaces[h]);
        kept.push_back(origin[h]);
      }
    for (const auto& sample : result.scene.samples) {
      if (renumber[static_cast<std::size_t>(sample.halfspace)] < 0) continue;
      auto t = sample;
      t.halfspace = renumber[static_cast<std::size_t>(sample.halfspace)];
      candidate.samples.push_back(t);
    }
    const std::size_t samples = result.scene.samples.size();
    if (!attempt(std::move(candidate), std::move(kept))) return false;
    result.removed_halfspaces += static_cast<int>(drop.size());
    result.removed_samples += static_cast<int>(samples - result.scene.samples.size());
    return true;
  }

  /// Sets up the target checks and the shape, and re-checks the original; false when it did not fail again.
  bool begin(const CampaignSettings& settings, const Scene& scene, const SceneRecord& record) {
    if (!record.failed()) throw std::invalid_argument("minimise_scene: the record did not fail");
    index = record.index;
    eval = settings;
    error = record.outcome == SceneOutcome::Error;
    if (error) {
      target = {"error"};
    } else {
      std::vector<std::string> catalogue;
      for (const CheckOutcome& c : record.checks)
        if (c.status == CheckStatus::Failed) {
          target.push_back(c.check);
          if (std::any_of(check_catalogue().begin(), check_catalogue().end(),
                          [&](const CheckInfo& i) { return c.check == i.name; }))
            catalogue.push_back(c.check);
        }
      // Only the target checks are computed (at least one catalogue check: an empty list means all of them).
      eval.checks = catalogue.empty() ? std::vector<std::string>{check_catalogue().front().name} : catalogue;
      std::vector<ExtraCheck> extra;
      for (const ExtraCheck& e : settings.extra)
        if (std::find(target.begin(), target.end(), e.name) != target.end()) extra.push_back(e);
      eval.extra = std::move(extra);
    }
    result.target = target;
    result.scene = scene;
    result.record = record;
    result.record.scene.reset();
    result.record.scene3.reset();
    for (std::size_t h = 0; h < scene.halfspaces.size(); ++h) origin.push_back(static_cast<int>(h));
    std::vector<char> given;
    const auto on_shape = [](const std::string& name) {
      return name == "prop61" || name == "propB1" || name == "describability" || name == "nhrep";
    };
    if (settings.sample_policy == SamplePolicy::Intended && record.outcome == SceneOutcome::Checked &&
        std::any_of(target.begin(), target.end(), on_shape)) {
      Shape s;
      try {
        s.complex = arranged_for(eval, scene).complex;
      } catch (const std::bad_alloc&) {
        throw;  // out of memory ends the run (exit 2): it says nothing about the input
      } catch (const std::exception&) {
        result.reproduced = false;  // the original no longer arranges (other limits): nothing to carry
        return false;
      }
      s.solid.assign(s.complex.cells.size(), 0);
      for (int c : record.intended) {
        if (c < 0 || static_cast<std::size_t>(c) >= s.solid.size())
          throw std::invalid_argument("minimise_scene: the record's intended cell " + std::to_string(c) +
                                      " is not a cell of the scene");
        s.solid[static_cast<std::size_t>(c)] = 1;
        s.touches_box = s.touches_box || s.complex.cells[static_cast<std::size_t>(c)].outer;
      }
      s.orientation_preserving = bsh::is_orientation_preserving(bsh::Problem(s.complex), s.solid);
      given = s.solid;
      shape = std::move(s);
    }
    // The original, under the restricted checks: it must fail again (it does unless a time limit intervened).
    if (!attempt(scene, origin, shape ? &given : nullptr)) {
      result.reproduced = false;
      result.scene = scene;
      return false;
    }
    return true;
  }

  /// Each halfspace h of result.scene that `allowed(h)`, with its samples, last to first, until a pass removes
  /// nothing.
  void remove_each_halfspace(const std::function<bool(int)>& allowed) {
    for (bool changed = true; changed && !result.exhausted;) {
      changed = false;
      for (int h = static_cast<int>(result.scene.halfspaces.size()) - 1; h >= 0 && !result.exhausted; --h)
        if (allowed(h) && attempt_without({h})) changed = true;
    }
  }

  /// Step 2: samples, last to first, until a pass removes nothing.
  void remove_samples() {
    for (bool changed = true; changed && !result.exhausted;) {
      changed = false;
      for (int k = static_cast<int>(result.scene.samples.size()) - 1; k >= 0 && !result.exhausted; --k) {
        Scene candidate = result.scene;
        candidate.samples.erase(candidate.samples.begin() + k);
        if (attempt(std::move(candidate), origin)) {
          ++result.removed_samples;
          changed = true;
        }
      }
    }
  }
};

/// The samples on halfspace `h` become `near` samples of their points (after a change of h's boundary).
void snap_samples_of(Scene2& scene, int h) {
  for (Sample2& s : scene.samples)
    if (s.halfspace == h) s.snapped = true;
}

/// The rational parameters of a halfspace, in the documented order.
std::vector<Rational*> parameters(Halfspace2& h) {
  switch (h.kind) {
    case HalfspaceKind2::Halfplane: return {&h.normal.x, &h.normal.y, &h.offset};
    case HalfspaceKind2::Disk: return {&h.center.x, &h.center.y, &h.radius};
    case HalfspaceKind2::Polygon: {
      std::vector<Rational*> out;
      for (PointQ2& v : h.vertices) {
        out.push_back(&v.x);
        out.push_back(&v.y);
      }
      return out;
    }
  }
  return {};
}

}  // namespace

std::vector<Rational> simpler_values(const Rational& q) {
  std::vector<Rational> tried;
  const auto add = [&](const Rational& c) {
    if (simpler(c, q) && std::find(tried.begin(), tried.end(), c) == tried.end()) tried.push_back(c);
  };
  add(Rational(0));
  add(Rational(trunc_of(q)));
  add(Rational(round_of(q)));
  if (q.get_den() == 1) add(Rational(trunc_of(q / 2)));
  for (Integer scale = 2; scale < q.get_den(); scale *= 2) {
    Rational c(round_of(q * scale), scale);
    c.canonicalize();
    add(c);
  }
  return tried;
}

MinimiseResult minimise_scene(const CampaignSettings& settings, const Scene2& scene, const SceneRecord& record,
                              const MinimiseOptions& options) {
  if (settings.dimension != 2) throw std::invalid_argument("minimise_scene: a 2D campaign's scene");
  Reducer<Scene2> z;
  z.options = options;
  if (!z.begin(settings, scene, record)) return z.result;

  // 1. Halfspaces, with their samples, last to first, until a pass removes nothing.
  z.remove_each_halfspace([](int) { return true; });
  // 2. Samples.
  z.remove_samples();
  // 3. Coordinates: the halfspaces' parameters, the samples' points, the domain.
  for (std::size_t h = 0; h < z.result.scene.halfspaces.size() && !z.result.exhausted; ++h) {
    const int hi = static_cast<int>(h);
    if (z.result.scene.halfspaces[h].kind == HalfspaceKind2::Halfplane) {
      const Halfspace2& p = z.result.scene.halfspaces[h];
      if (p.normal.x.get_den() == 1 && p.normal.y.get_den() == 1 && p.offset.get_den() == 1) {
        Integer g;
        mpz_gcd(g.get_mpz_t(), p.normal.x.get_num().get_mpz_t(), p.normal.y.get_num().get_mpz_t());
        mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), p.offset.get_num().get_mpz_t());
        if (g > 1) {
          Scene2 candidate = z.result.scene;
          Halfspace2& c = candidate.halfspaces[h];
          c.normal.x /= g;
          c.normal.y /= g;
          c.offset /= g;
          if (z.attempt(std::move(candidate), z.origin)) ++z.result.simplified_coordinates;
        }
      }
    }
    const std::size_t count = parameters(z.result.scene.halfspaces[h]).size();
    for (std::size_t k = 0; k < count && !z.result.exhausted; ++k) {
      const Rational value = *parameters(z.result.scene.halfspaces[h])[k];
      for (const Rational& v : simpler_values(value)) {
        Scene2 candidate = z.result.scene;
        *parameters(candidate.halfspaces[h])[k] = v;
        snap_samples_of(candidate, hi);
        if (z.attempt(std::move(candidate), z.origin)) {
          ++z.result.simplified_coordinates;
          break;
        }
        if (z.result.exhausted) break;
      }
    }
  }
  for (std::size_t k = 0; k < z.result.scene.samples.size() && !z.result.exhausted; ++k)
    for (int axis = 0; axis < 2 && !z.result.exhausted; ++axis) {
      const PointQ2& given = z.result.scene.samples[k].given;
      const Rational value = axis == 0 ? given.x : given.y;
      for (const Rational& v : simpler_values(value)) {
        Scene2 candidate = z.result.scene;
        Sample2& s = candidate.samples[k];
        (axis == 0 ? s.given.x : s.given.y) = v;
        s.snapped = true;
        if (z.attempt(std::move(candidate), z.origin)) {
          ++z.result.simplified_coordinates;
          break;
        }
        if (z.result.exhausted) break;
      }
    }
  if (z.result.scene.domain_given && !z.result.exhausted) {
    const Box2& d = z.result.scene.domain;
    const auto floor_of = [](const Rational& q) {
      Integer out;
      mpz_fdiv_q(out.get_mpz_t(), q.get_num().get_mpz_t(), q.get_den().get_mpz_t());
      return Rational(out);
    };
    const auto ceil_of = [](const Rational& q) {
      Integer out;
      mpz_cdiv_q(out.get_mpz_t(), q.get_num().get_mpz_t(), q.get_den().get_mpz_t());
      return Rational(out);
    };
    const Box2 rounded{{floor_of(d.min.x), floor_of(d.min.y)}, {ceil_of(d.max.x), ceil_of(d.max.y)}};
    if (!(rounded.min == d.min && rounded.max == d.max)) {
      Scene2 candidate = z.result.scene;
      candidate.domain = rounded;
      if (z.attempt(std::move(candidate), z.origin)) ++z.result.simplified_coordinates;
    }
  }
  return z.result;
}

namespace {

/// A halfspace's group (minimise.hpp, 3D step 1): its name up to the first '.'.
std::string group_of(const Halfspace3& h) { return h.name.substr(0, h.name.find('.')); }

/// The groups of `scene`'s halfspaces in the order of their first halfspace, each its halfspaces ascending.
std::vector<std::vector<int>> halfspace_groups(const Scene3& scene) {
  std::vector<std::vector<int>> groups;
  std::map<std::string, std::size_t> at;
  for (std::size_t h = 0; h < scene.halfspaces.size(); ++h) {
    const auto [it, fresh] = at.emplace(group_of(scene.halfspaces[h]), groups.size());
    if (fresh) groups.emplace_back();
    groups[it->second].push_back(static_cast<int>(h));
  }
  return groups;
}

bool tessellated_by_segments(const Halfspace3& h) {
  return (h.kind == HalfspaceKind3::Sphere || h.kind == HalfspaceKind3::Cylinder || h.kind == HalfspaceKind3::Cone ||
          h.kind == HalfspaceKind3::Torus) &&
         h.primitive.tessellation.mode == Tessellation3::Mode::Segments;
}

}  // namespace

std::vector<int> lower_segments(int segments) {
  std::vector<int> out;
  for (long p = 1; p < segments; p *= 2)
    for (long v : {p * 3, p * 4})
      if (v < segments && (out.empty() || v > out.back())) out.push_back(static_cast<int>(v));
  return out;
}

std::optional<std::vector<char>> carry_by_sign_vectors(const Complex& original, const std::vector<char>& solid,
                                                       const std::vector<int>& origin, const Complex& reduced) {
  if (solid.size() != original.cells.size())
    throw std::invalid_argument("carry_by_sign_vectors: the solid needs one flag per original cell");
  const std::size_t n = original.halfspace_names.size();
  for (int o : origin)
    if (o < 0 || static_cast<std::size_t>(o) >= n)
      throw std::invalid_argument("carry_by_sign_vectors: an origin beyond the original's halfspaces");
  // Each restricted sign vector of the original: bit 0 set when some of its cells are outside, bit 1 inside.
  std::map<std::vector<char>, int> seen;
  for (std::size_t c = 0; c < original.cells.size(); ++c) {
    const std::vector<char>& inside = original.cells[c].inside;
    if (inside.size() != n) throw std::invalid_argument("carry_by_sign_vectors: an original cell's sign vector");
    std::vector<char> key;
    key.reserve(origin.size());
    for (int o : origin) key.push_back(inside[static_cast<std::size_t>(o)] ? 1 : 0);
    seen[key] |= solid[c] ? 2 : 1;
  }
  std::vector<char> out(reduced.cells.size(), 0);
  for (std::size_t c = 0; c < reduced.cells.size(); ++c) {
    const std::vector<char>& inside = reduced.cells[c].inside;
    if (inside.size() != origin.size())
      throw std::invalid_argument("carry_by_sign_vectors: a reduced cell's sign vector is not of origin's size");
    std::vector<char> key;
    key.reserve(inside.size());
    for (char v : inside) key.push_back(v ? 1 : 0);
    const auto it = seen.find(key);
    if (it == seen.end() || it->second == 3) return std::nullopt;  // no original cell, or cells of both values
    out[c] = it->second == 2 ? 1 : 0;
  }
  return out;
}

MinimiseResult3 minimise_scene(const CampaignSettings& settings, const Scene3& scene, const SceneRecord& record,
                               const MinimiseOptions& options) {
  if (settings.dimension != 3) throw std::invalid_argument("minimise_scene: a 3D campaign's scene");
  Reducer<Scene3> z;
  z.options = options;
  if (!z.begin(settings, scene, record)) return z.result;

  // 1. Primitives (groups), last to first, until a pass removes nothing; then single halfspaces of groups.
  for (bool changed = true; changed && !z.result.exhausted;) {
    changed = false;
    const std::vector<std::vector<int>> groups = halfspace_groups(z.result.scene);
    for (auto g = groups.rbegin(); g != groups.rend() && !z.result.exhausted; ++g)
      if (z.result.scene.halfspaces.size() > g->size() && z.attempt_without(*g)) changed = true;
  }
  z.remove_each_halfspace([&](int h) {
    const std::string group = group_of(z.result.scene.halfspaces[static_cast<std::size_t>(h)]);
    return std::count_if(z.result.scene.halfspaces.begin(), z.result.scene.halfspaces.end(),
                         [&](const Halfspace3& x) { return group_of(x) == group; }) > 1;
  });
  // 2. Samples.
  z.remove_samples();
  // 3. Segments, one pass.
  for (std::size_t h = 0; h < z.result.scene.halfspaces.size() && !z.result.exhausted; ++h) {
    if (!tessellated_by_segments(z.result.scene.halfspaces[h])) continue;
    for (int segments : lower_segments(z.result.scene.halfspaces[h].primitive.tessellation.segments)) {
      Scene3 candidate = z.result.scene;
      Halfspace3& c = candidate.halfspaces[h];
      c.primitive.tessellation.segments = segments;
      try {
        c.surface = tessellate(c, candidate.domain);
      } catch (const InputError&) {
        continue;  // not a tessellation (e.g. a sphere's bands): not a candidate
      }
      c.origin = tessellation_summary(c);
      for (Sample3& sample : candidate.samples)
        if (sample.halfspace == static_cast<int>(h)) sample.snapped = true;
      if (z.attempt(std::move(candidate), z.origin)) {
        ++z.result.lowered_segments;
        break;
      }
      if (z.result.exhausted) break;
    }
  }
  return z.result;
}

}  // namespace hsx::campaign
