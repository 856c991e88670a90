// Bytes -> one CSGNet program (io/csgnet.hpp) -> scene + expression; small programs are then arranged and the
// solid evaluated on the cells, its describability and BHC tree computed. Bad input must end in InputError;
// anything else is a finding. Checked on every accepted program: the scene is valid, the expression only names its
// halfspaces, and (when arranged) the complex is consistent and BHC gives the solid back. A CSGNet solid is a
// Boolean combination of its halfspaces, so it is always describable.
#include "fuzz_support.hpp"

#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/csg/describability.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/csgnet.hpp>

namespace {

constexpr const char* kTarget = "fuzz_csgnet";
// Arranging is the costly part: only programs with this few halfspaces are arranged (three squares, say).
constexpr std::size_t kMaxArrangedHalfspaces = 12;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 2048) return -1;
  hsx::CsgnetProgram program;
  try {
    program = hsx::read_csgnet(hsx::fuzz::as_text(data, size), "fuzz");
  } catch (const hsx::InputError&) {
    return 0;
  }
  if (!program.expression) hsx::fuzz::finding(kTarget, "accepted without an expression");
  const auto expression_stats = hsx::csg::stats(*program.expression);
  if (expression_stats.distinct_halfspaces > static_cast<int>(program.scene.halfspaces.size()))
    hsx::fuzz::finding(kTarget, "the expression uses more halfspaces than the scene has");
  if (program.scene.halfspaces.size() > kMaxArrangedHalfspaces) return 0;
  hsx::Arranged2 arranged;
  try {
    arranged = hsx::arrange(program.scene);
  } catch (const hsx::InputError&) {
    return 0;  // e.g. a limit of the arrangement
  }
  const auto problems = hsx::check_complex(arranged.complex);
  if (!problems.empty()) hsx::fuzz::finding(kTarget, "inconsistent complex: " + problems.front());
  const std::vector<char> solid = hsx::csg::evaluate(*program.expression, arranged.complex);
  if (!hsx::csg::describability(arranged.complex, solid).describable)
    hsx::fuzz::finding(kTarget, "a CSGNet solid that its own halfspaces do not describe");
  const hsx::csg::BhcResult tree = hsx::csg::bhc(arranged.complex, solid);
  if (!tree.describable || !tree.verified || hsx::csg::evaluate(*tree.tree, arranged.complex) != solid)
    hsx::fuzz::finding(kTarget, "BHC did not give the CSGNet solid back");
  return 0;
}
