// Bytes -> small scene -> exact arrangement -> the BSH extraction pipeline: the graph cut, beam search (K = 1 and
// K = 2), best-first with a state limit, and the brute-force oracle where it needs few labellings. The scene limits
// (8 halfspaces, 16 samples, 12 polygon vertices) keep one execution fast. Bad input must end in InputError, and
// brute force past its labelling limit in its documented std::runtime_error; anything else is a finding. Checked:
// every returned labelling is orientation-preserving with the energy reported, search results are
// sample-connected, the graph cut is not beaten by any search, and a proven optimum equals the oracle's.
#include "fuzz_support.hpp"

#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/scene_json.hpp>

#include <optional>
#include <stdexcept>

namespace {

constexpr const char* kTarget = "fuzz_extract";
constexpr long kOracleLabellings = 4096;

using hsx::Order;
using hsx::bsh::Method;

// The invariants every method's result must keep.
void check_result(const hsx::bsh::Problem& problem, const hsx::bsh::ExtractResult& r, const char* method) {
  const std::string name(method);
  std::string why;
  if (!hsx::bsh::is_orientation_preserving(problem, r.labelling, &why))
    hsx::fuzz::finding(kTarget, name + ": not orientation-preserving: " + why);
  const Order o = hsx::bsh::compare(hsx::bsh::energy(problem, r.labelling), r.energy);
  if (o == Order::Less || o == Order::Greater) hsx::fuzz::finding(kTarget, name + ": reported energy is not its own");
  if (r.method != Method::GraphCut &&
      (!r.sample_connected || !hsx::bsh::sample_connectivity(problem, r.labelling).sample_connected()))
    hsx::fuzz::finding(kTarget, name + ": not sample-connected");
}

hsx::bsh::ExtractResult run(const hsx::bsh::Problem& problem, Method method, int beam_width = 1) {
  hsx::bsh::ExtractOptions options;
  options.method = method;
  options.beam_width = beam_width;
  options.max_states = 200;
  options.max_ties = 4;
  options.certify_limit = kOracleLabellings;
  hsx::bsh::ExtractResult r = hsx::bsh::extract(problem, options);
  check_result(problem, r, hsx::bsh::to_string(method));
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 8192) return -1;
  hsx::SceneReadLimits limits;
  limits.numbers.max_chars = 24;
  limits.numbers.max_exponent = 6;
  limits.max_halfspaces = 8;
  limits.max_samples = 16;
  limits.max_polygon_vertices = 12;
  hsx::Arranged2 arranged;
  try {
    arranged = hsx::arrange(hsx::read_scene_text(hsx::fuzz::as_text(data, size), limits));
  } catch (const hsx::InputError&) {
    return 0;
  }
  const hsx::bsh::Problem problem(arranged.complex);
  const hsx::bsh::ExtractResult cut = run(problem, Method::GraphCut);
  const hsx::bsh::ExtractResult beam = run(problem, Method::Beam);
  const hsx::bsh::ExtractResult beam2 = run(problem, Method::Beam, 2);
  const hsx::bsh::ExtractResult best = run(problem, Method::BestFirst);
  // The graph cut is optimal without sample-connectedness (when its cuts were certified): no search may beat it.
  for (const auto* r : {&beam, &beam2, &best})
    if (cut.optimal && cut.stats.uncertified_cuts == 0 && hsx::bsh::compare(r->energy, cut.energy) == Order::Less)
      hsx::fuzz::finding(kTarget, std::string(hsx::bsh::to_string(r->method)) + " beats the graph cut");
  std::optional<hsx::bsh::BruteForceResult> oracle;
  try {
    oracle = hsx::bsh::brute_force(problem, true, kOracleLabellings);
  } catch (const std::runtime_error&) {
    return 0;  // more labellings than the oracle may enumerate: documented refusal
  }
  for (const auto* r : {&beam, &beam2, &best})
    if (oracle->certified && hsx::bsh::compare(r->energy, oracle->energy) == Order::Less)
      hsx::fuzz::finding(kTarget, std::string(hsx::bsh::to_string(r->method)) + " beats the oracle");
  if (best.optimal && oracle->certified && hsx::bsh::compare(best.energy, oracle->energy) == Order::Greater)
    hsx::fuzz::finding(kTarget, "best-first proven optimal but the oracle found less");
  return 0;
}
