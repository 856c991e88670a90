// Bytes -> .obj text, optionally followed by a line "#fea" and .fea text -> Mesh3 -> BoundarySurface. Bad input
// must end in InputError; anything else (crash, sanitizer report, other exception, hang) is a finding. Checked on
// every accepted mesh: the boundary's structural invariants, link types agreeing with edge shapes, and the same
// edge shapes, volume and boundary when every face is reversed (the reader must flip it back). The sharpness angle
// comes from the input's length, so exact (30, 45, 90, 135) and interval-decided angles are both explored. Every
// accepted mesh then goes through NH-Rep's Algorithm 1, whose tree must pass check_tree.
#include "fuzz_support.hpp"

#include <hsx/algorithms/nhrep/tree.hpp>
#include <hsx/complex/boundary_from_mesh.hpp>
#include <hsx/geometry/mesh3.hpp>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) { hsx::fuzz::finding("fuzz_mesh", what); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  // "#fea" is an .obj comment, so a joined seed is still a valid .obj on its own.
  const std::size_t cut = text.find("\n#fea\n");
  const std::string obj_text = cut == std::string::npos ? text : text.substr(0, cut + 1);
  const std::string fea_text = cut == std::string::npos ? std::string("0\n") : text.substr(cut + 6);
  hsx::MeshReadLimits limits;
  limits.numbers.max_chars = 40;
  limits.numbers.max_exponent = 12;
  limits.max_vertices = 200;
  limits.max_faces = 400;
  limits.max_feature_edges = 1000;
  static constexpr int kAngles[] = {0, 20, 30, 45, 60, 89, 90, 91, 135, 150, 179};
  const hsx::Rational delta(kAngles[size % (sizeof kAngles / sizeof kAngles[0])]);

  hsx::ObjMesh obj;
  hsx::Mesh3 mesh;
  try {
    std::istringstream in(obj_text);
    obj = hsx::read_obj(in, "fuzz.obj", limits);
    mesh = hsx::build_mesh3(obj);
  } catch (const hsx::InputError&) {
    return 0;
  }

  // Reversing every face must give the same solid back.
  hsx::ObjMesh reversed = obj;
  for (auto& f : reversed.faces) std::swap(f[1], f[2]);
  const hsx::Mesh3 back = hsx::build_mesh3(reversed);  // no InputError allowed: the input was valid
  if (back.flipped == mesh.flipped || back.volume != mesh.volume || back.edges.size() != mesh.edges.size())
    finding("reversed faces did not give the same mesh back");
  for (std::size_t e = 0; e < mesh.edges.size(); ++e)
    if (back.edges[e].a != mesh.edges[e].a || back.edges[e].b != mesh.edges[e].b ||
        back.edges[e].shape != mesh.edges[e].shape)
      finding("edge " + std::to_string(e) + " changed under reversal");

  hsx::FeatureEdgeList fea;
  try {
    std::istringstream in(fea_text);
    fea = hsx::read_fea(in, "fuzz.fea", limits);
  } catch (const hsx::InputError&) {
    fea = hsx::FeatureEdgeList{};
  }
  hsx::BoundarySurface surface;
  try {
    surface = hsx::boundary_from_mesh(mesh, fea, delta);
  } catch (const hsx::InputError&) {
    return 0;  // a feature edge that is not a mesh edge
  }
  const auto problems = hsx::check_boundary(surface);
  if (!problems.empty()) finding("inconsistent boundary: " + problems.front());
  if (surface.links.size() != mesh.edges.size() || surface.pieces.size() != mesh.faces.size())
    finding("boundary size differs from the mesh");
  const hsx::SharpnessAngle sharpness(delta);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const hsx::BoundaryLink& link = surface.links[e];
    const hsx::EdgeShape shape = mesh.edges[e].shape;
    if (shape == hsx::EdgeShape::Flat && link.type != hsx::FeatureType::Smooth) finding("flat edge not smooth");
    if (link.type == hsx::FeatureType::Convex && shape != hsx::EdgeShape::Convex) finding("convex type on a non-convex edge");
    if (link.type == hsx::FeatureType::Concave && shape != hsx::EdgeShape::Concave) finding("concave type on a non-concave edge");
    if ((link.type == hsx::FeatureType::Smooth) != sharpness.smooth(mesh, static_cast<int>(e))) finding("smooth mismatch");
  }
  const hsx::BoundarySurface surface_back = hsx::boundary_from_mesh(back, fea, delta);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e)
    if (surface_back.links[e].type != surface.links[e].type || surface_back.links[e].feature != surface.links[e].feature)
      finding("link " + std::to_string(e) + " changed under reversal");

  // NH-Rep's Algorithm 1 on every accepted mesh, both as the paper states it and as NH-Rep's tool runs it: it must
  // terminate with a tree that passes every structural check.
  const bool nesting_known = std::all_of(surface.pieces.begin(), surface.pieces.end(),
                                         [](const hsx::BoundaryPiece& p) { return p.region >= 0; });
  for (const int mode : {0, 1, 2}) {  // the paper, NH-Rep's tool, the paper with nested cavities
    const bool tool = mode == 1;
    if (mode == 2 && !nesting_known) continue;
    hsx::nhrep::BuildOptions options;
    options.restart_after_decomposition = options.decompose_within_subgraph = tool;
    options.nest_holes = mode == 2;
    options.max_decompositions = 1000;
    hsx::nhrep::BuildResult result;
    try {
      result = hsx::nhrep::build_tree(
          hsx::nhrep::build_patch_graph(surface, tool ? hsx::nhrep::CurveRule::Majority : hsx::nhrep::CurveRule::Paper),
          options);
    } catch (const std::runtime_error& e) {
      // The paper's algorithm provably needs fewer decompositions than patches (proofs/nhrep.md, Lemma 4.3); the
      // tool's scoped decomposition has no such bound, so hitting the guard there is a property of the tool.
      if (!tool) finding(std::string("the paper's Algorithm 1 hit its guard: ") + e.what());
      continue;
    }
    const auto violations = hsx::nhrep::check_tree(result);
    if (!violations.empty())
      finding(std::string(mode == 1 ? "tool mode: " : mode == 2 ? "nested: " : "") + "tree check: " + violations.front());
  }
  return 0;
}
