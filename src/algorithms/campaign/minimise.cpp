// Minimising a failing scene: see minimise.hpp.
#include <hsx/algorithms/campaign/minimise.hpp>

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>

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

/// Everything minimise_scene needs while it runs.
struct Reducer {
  CampaignSettings eval;  ///< the settings restricted to the target checks
  std::uint64_t index = 0;
  std::vector<std::string> target;
  bool error = false;
  MinimiseOptions options;
  Clock::time_point start = Clock::now();
  MinimiseResult result;

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

  /// Checks `candidate` (unresolved); when it is valid and still fails, it becomes the result. False otherwise, or
  /// when the budget is spent (then nothing is checked).
  bool attempt(Scene2 candidate) {
    if (out_of_budget()) return false;
    try {
      validate_and_resolve(candidate);
    } catch (const std::exception&) {
      return false;  // not a valid scene: not a step
    }
    ++result.steps;
    SceneRecord r = check_scene(eval, candidate, index);
    if (!fails(r)) return false;
    r.scene.reset();
    result.record = std::move(r);
    result.scene = std::move(candidate);
    return true;
  }
};

/// `scene` without halfspace `h` and the samples on it (the other samples' indices shifted).
Scene2 without_halfspace(const Scene2& scene, int h) {
  Scene2 out = scene;
  out.halfspaces.erase(out.halfspaces.begin() + h);
  out.samples.clear();
  for (const Sample2& s : scene.samples) {
    if (s.halfspace == h) continue;
    Sample2 t = s;
    if (t.halfspace > h) --t.halfspace;
    out.samples.push_back(t);
  }
  return out;
}

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
  if (!record.failed()) throw std::invalid_argument("minimise_scene: the record did not fail");
  Reducer z;
  z.index = record.index;
  z.options = options;
  z.eval = settings;
  z.error = record.outcome == SceneOutcome::Error;
  if (z.error) {
    z.target = {"error"};
  } else {
    std::vector<std::string> catalogue;
    for (const CheckOutcome& c : record.checks)
      if (c.status == CheckStatus::Failed) {
        z.target.push_back(c.check);
        if (std::any_of(check_catalogue().begin(), check_catalogue().end(),
                        [&](const CheckInfo& i) { return c.check == i.name; }))
          catalogue.push_back(c.check);
      }
    // Only the target checks are computed (at least one catalogue check: an empty list means all of them).
    z.eval.checks = catalogue.empty() ? std::vector<std::string>{check_catalogue().front().name} : catalogue;
    std::vector<ExtraCheck> extra;
    for (const ExtraCheck& e : settings.extra)
      if (std::find(z.target.begin(), z.target.end(), e.name) != z.target.end()) extra.push_back(e);
    z.eval.extra = std::move(extra);
  }
  z.result.target = z.target;
  z.result.scene = scene;
  z.result.record = record;
  z.result.record.scene.reset();
  // The original, under the restricted checks: it must fail again (it does unless a time limit intervened).
  if (!z.attempt(scene)) {
    z.result.reproduced = false;
    z.result.scene = scene;
    return z.result;
  }

  // 1. Halfspaces, with their samples, last to first, until a pass removes nothing.
  for (bool changed = true; changed && !z.result.exhausted;) {
    changed = false;
    for (int h = static_cast<int>(z.result.scene.halfspaces.size()) - 1; h >= 0 && !z.result.exhausted; --h) {
      const std::size_t samples = z.result.scene.samples.size();
      if (z.attempt(without_halfspace(z.result.scene, h))) {
        ++z.result.removed_halfspaces;
        z.result.removed_samples += static_cast<int>(samples - z.result.scene.samples.size());
        changed = true;
      }
    }
  }
  // 2. Samples, last to first, until a pass removes nothing.
  for (bool changed = true; changed && !z.result.exhausted;) {
    changed = false;
    for (int k = static_cast<int>(z.result.scene.samples.size()) - 1; k >= 0 && !z.result.exhausted; --k) {
      Scene2 candidate = z.result.scene;
      candidate.samples.erase(candidate.samples.begin() + k);
      if (z.attempt(std::move(candidate))) {
        ++z.result.removed_samples;
        changed = true;
      }
    }
  }
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
          if (z.attempt(std::move(candidate))) ++z.result.simplified_coordinates;
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
        if (z.attempt(std::move(candidate))) {
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
        if (z.attempt(std::move(candidate))) {
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
      if (z.attempt(std::move(candidate))) ++z.result.simplified_coordinates;
    }
  }
  return z.result;
}

}  // namespace hsx::campaign
