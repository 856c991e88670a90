// Bytes -> hsx-result/1 document (read_result_labelling) on a fixed small arrangement, then what the CLI does with a
// solid read from a result file: describability, the BHC tree and NH-Rep's tree of the solid. Bad input must end in
// InputError (an empty solid or one touching the domain's boundary is refused by the NH-Rep builder as such);
// anything else is a finding. Checked on every accepted solid: describability agrees with BHC, and a BHC tree
// evaluates to the solid on every cell.
// Documents are read both as they are and, without a complex_id, with the right one filled in (see below).
// The same bytes go through read_labelling_text (io/labelling.hpp: every format `hsx grade` accepts) too: a
// labelling it accepts has one label per cell, and its grade never finds a valid labelling below the optimum.
#include "fuzz_support.hpp"

#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/hsx.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/labelling.hpp>
#include <hsx/io/result_json.hpp>
#include <hsx/io/scene_json.hpp>

namespace {

constexpr const char* kTarget = "fuzz_result_json";

// Two disks, a half-plane and a triangle (data/scenes/lens.json without its samples): 4 halfspaces, a dozen cells.
constexpr const char* kScene = R"({"format": "hsx-scene/1", "dimension": 2, "domain": {"min": [-4, -4], "max": [6, 5]},
  "halfspaces": [{"name": "A", "kind": "disk", "center": [0, 0], "radius": 2},
                 {"name": "B", "kind": "disk", "center": [2, 0], "radius": 2},
                 {"name": "C", "kind": "halfplane", "normal": [0, 1], "offset": 1.5},
                 {"name": "T", "kind": "polygon", "vertices": [[1, -3], [4, -1], [-1, -1]], "complement": true}],
  "samples": []})";

const hsx::Scene2& scene() {
  static const hsx::Scene2 s = hsx::read_scene_text(kScene);
  return s;
}

const hsx::Arranged2& arranged() {
  static const hsx::Arranged2 a = hsx::arrange(scene());
  return a;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  const hsx::Complex& complex = arranged().complex;
  try {
    const hsx::ReadLabelling read = hsx::read_labelling_text(std::string(hsx::fuzz::as_text(data, size)), "fuzz", complex);
    if (read.cells.size() != complex.cells.size()) hsx::fuzz::finding(kTarget, "read_labelling: wrong size");
    const hsx::bsh::Grade g = hsx::grade_labelling(complex, read.cells);
    if (g.orientation_preserving && g.sample_connected && g.versus_optimum == hsx::Order::Less)
      hsx::fuzz::finding(kTarget, "grade: a valid labelling below the proven optimum");
  } catch (const hsx::InputError&) {
  }
  std::vector<char> solid;
  try {
    nlohmann::json document = hsx::parse_exact_json(hsx::fuzz::as_text(data, size));
    // Results carry their input's identity. On odd sizes the document is read as it is (the identity check is
    // fuzzed); on even sizes a document without "complex_id" gets the right one, so the cells are fuzzed too.
    static const std::string identity = hsx::complex_identity(complex);
    if (size % 2 == 0 && document.is_object() && !document.contains("complex_id")) document["complex_id"] = identity;
    solid = hsx::read_result_labelling(document, complex);
  } catch (const hsx::InputError&) {
    return 0;
  }
  if (solid.size() != complex.cells.size()) hsx::fuzz::finding(kTarget, "labelling of the wrong size");
  const hsx::csg::Describability d = hsx::csg::describability(complex, solid);
  const hsx::csg::BhcResult tree = hsx::csg::bhc(complex, solid);
  if (tree.describable != d.describable) hsx::fuzz::finding(kTarget, "BHC and describability disagree");
  if (tree.describable && (!tree.tree || !tree.verified || hsx::csg::evaluate(*tree.tree, complex) != solid))
    hsx::fuzz::finding(kTarget, "a BHC tree that does not give the solid back");
  try {
    const hsx::nhrep::BuildResult nh = hsx::nhrep_tree(arranged(), solid);
    const auto violations = hsx::nhrep::check_tree(nh);
    if (!violations.empty()) hsx::fuzz::finding(kTarget, "NH-Rep tree check: " + violations.front());
  } catch (const hsx::InputError&) {
    // an empty solid, or one reaching the domain's boundary
  }
  return 0;
}
