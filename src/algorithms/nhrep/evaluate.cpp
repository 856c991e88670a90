#include <hsx/algorithms/nhrep/evaluate.hpp>

#include <hsx/algorithms/csg/describability.hpp>

#include <algorithm>
#include <stdexcept>

namespace hsx::nhrep {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

bool node_value(const Tree& tree, int node, const std::vector<NaturalHalfspace>& leaf_halfspace,
                const std::vector<char>& inside, int depth) {
  if (depth > static_cast<int>(tree.nodes.size())) throw std::invalid_argument("the tree has a cycle");
  const TreeNode& n = tree.nodes.at(at(node));
  const bool is_max = n.op == Op::Max;  // max = intersection: all must hold; min = union: one must hold
  auto leaf = [&](int patch) {
    const NaturalHalfspace& h = leaf_halfspace.at(at(patch));
    if (h.halfspace < 0) return false;
    return (inside.at(at(h.halfspace)) != 0) != h.complemented;
  };
  for (int p : n.leaves)
    if (leaf(p) != is_max) return !is_max;
  for (int c : n.children)
    if (node_value(tree, c, leaf_halfspace, inside, depth + 1) != is_max) return !is_max;
  return is_max;
}

}  // namespace

const char* verdict_name(Verdict verdict) {
  switch (verdict) {
    case Verdict::TreeCorrect: return "tree correct";
    case Verdict::DescribableButFails: return "describable but the tree fails";
    case Verdict::NotDescribable: return "not describable by its patches' halfspaces";
  }
  return "?";
}

const char* verdict_key(Verdict verdict) {
  switch (verdict) {
    case Verdict::TreeCorrect: return "correct";
    case Verdict::DescribableButFails: return "describable-fails";
    case Verdict::NotDescribable: return "not-describable";
  }
  return "?";
}

std::vector<NaturalHalfspace> natural_halfspaces(const PatchGraph& graph, int halfspace_count,
                                                 std::vector<std::string>* violations) {
  std::vector<NaturalHalfspace> out(graph.patches.size());
  for (std::size_t p = 0; p < graph.patches.size(); ++p) {
    const PatchInfo& patch = graph.patches[p];
    if (!patch.alive) continue;
    const std::string name = "patch " + std::to_string(p);
    bool first = true, ok = true;
    NaturalHalfspace h;
    for (int piece : patch.pieces) {
      const BoundaryPiece& bp = graph.surface.pieces.at(at(piece));
      if (bp.carrier < 0 || bp.carrier >= halfspace_count) {
        if (violations)
          violations->push_back(name + ": piece " + std::to_string(piece) + " has no halfspace carrier (" +
                                std::to_string(bp.carrier) + ")");
        ok = false;
        break;
      }
      if (first) {
        h = NaturalHalfspace{bp.carrier, bp.carrier_complemented};
        first = false;
      } else if (bp.carrier != h.halfspace || bp.carrier_complemented != h.complemented) {
        if (violations)
          violations->push_back(name + ": its pieces lie on different carriers (" + std::to_string(h.halfspace) +
                                " and " + std::to_string(bp.carrier) + ")");
        ok = false;
        break;
      }
    }
    if (first) {
      if (violations) violations->push_back(name + ": a live patch without pieces");
      ok = false;
    }
    if (ok) out[p] = h;
  }
  return out;
}

bool tree_value(const Tree& tree, const std::vector<NaturalHalfspace>& leaf_halfspace, const std::vector<char>& inside) {
  if (tree.root < 0 || tree.root >= static_cast<int>(tree.nodes.size()))
    throw std::invalid_argument("the tree has no root");
  return node_value(tree, tree.root, leaf_halfspace, inside, 0);
}

Evaluation evaluate_tree(const BuildResult& result, const Complex& complex, const std::vector<char>& solid) {
  if (solid.size() != complex.cells.size())
    throw std::invalid_argument("evaluate_tree: " + std::to_string(solid.size()) + " solid flags for " +
                                std::to_string(complex.cells.size()) + " cells");
  if (result.tree.root < 0 || result.tree.root >= static_cast<int>(result.tree.nodes.size()))
    throw std::invalid_argument("evaluate_tree: the tree has no root");
  Evaluation e;
  e.leaf_halfspace = natural_halfspaces(result.graph, complex.halfspace_count(), &e.violations);
  for (int p : result.tree.subtree_leaves(result.tree.root))
    if (p >= 0 && p < static_cast<int>(e.leaf_halfspace.size()) && e.leaf_halfspace[at(p)].halfspace >= 0)
      e.natural_halfspaces.push_back(e.leaf_halfspace[at(p)].halfspace);
  std::sort(e.natural_halfspaces.begin(), e.natural_halfspaces.end());
  e.natural_halfspaces.erase(std::unique(e.natural_halfspaces.begin(), e.natural_halfspaces.end()),
                             e.natural_halfspaces.end());

  // The tree on every cell.
  e.tree_value.resize(complex.cells.size());
  for (std::size_t k = 0; k < complex.cells.size(); ++k) {
    const bool value = node_value(result.tree, result.tree.root, e.leaf_halfspace, complex.cells[k].inside, 0);
    e.tree_value[k] = value ? 1 : 0;
    if (solid[k] && !value) e.wrong_inside.push_back(static_cast<int>(k));
    if (!solid[k] && value) e.wrong_outside.push_back(static_cast<int>(k));
  }
  e.correct = e.wrong_inside.empty() && e.wrong_outside.empty();

  // Canonical terms over the natural halfspaces.
  csg::Describability d = csg::describability(complex, solid, e.natural_halfspaces);
  e.terms = d.terms;
  e.mixed = std::move(d.mixed);
  e.describable = e.mixed.empty();

  if (e.correct && !e.describable)
    e.violations.push_back("the tree is correct on every cell but the solid is not describable by its natural "
                           "halfspaces (mixed term holding cells " + std::to_string(e.mixed.front().inside_cells.front()) +
                           " and " + std::to_string(e.mixed.front().outside_cells.front()) + ")");
  e.verdict = e.correct ? Verdict::TreeCorrect : (e.describable ? Verdict::DescribableButFails : Verdict::NotDescribable);
  return e;
}

CellEvaluation evaluate_on_cells(const BuildResult& result, const BuildOptions& options, const Complex& complex,
                                 const std::vector<char>& solid) {
  CellEvaluation out;
  out.evaluation = evaluate_tree(result, complex, solid);
  out.cells = complex.cells.size();
  for (int c : out.evaluation.wrong_inside) out.missed.push_back(complex.cells.at(at(c)).witness.get());
  for (int c : out.evaluation.wrong_outside) out.added.push_back(complex.cells.at(at(c)).witness.get());
  if (out.evaluation.verdict == Verdict::DescribableButFails) {
    const auto& pieces = result.graph.surface.pieces;
    const bool holes = std::any_of(pieces.begin(), pieces.end(), [](const BoundaryPiece& p) { return p.hole; });
    out.diagnosis = holes && !options.nest_holes ? Diagnosis::HolesUnited : Diagnosis::NeedsExtendedSurfaces;
  }
  return out;
}

std::vector<int> leaf_nodes(const BuildResult& r) {
  std::vector<int> node_of(r.graph.patches.size(), -1);
  for (std::size_t n = 0; n < r.tree.nodes.size(); ++n)
    for (int leaf : r.tree.nodes[n].leaves) node_of.at(at(leaf)) = static_cast<int>(n);
  return node_of;
}

std::vector<std::string> leaf_names(const PatchGraph& g, const Complex& complex) {
  std::vector<std::string> names(g.patches.size());
  const std::vector<NaturalHalfspace> natural = natural_halfspaces(g, complex.halfspace_count());
  for (int p : g.live_patches()) {
    const NaturalHalfspace& h = natural[at(p)];
    if (h.halfspace < 0) continue;  // a violated check, reported by the evaluation
    names[at(p)] = (h.complemented ? "~" : "") + complex.halfspace_names[at(h.halfspace)];
  }
  return names;
}

}  // namespace hsx::nhrep
