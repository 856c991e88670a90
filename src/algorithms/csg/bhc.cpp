#include <hsx/algorithms/csg/bhc.hpp>

#include "geometry/components.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace hsx::csg {
namespace {

/// The halfspace psi = {cells with inside[i] == side}, as an expression.
ExprPtr side_expr(int i, bool side) { return side ? leaf(i) : complement(leaf(i)); }

class Builder {
 public:
  Builder(const Complex& complex, const std::vector<char>& solid, const BhcOptions& options, BhcResult& result)
      : c_(complex), solid_(solid), options_(options), result_(result) {}

  /// An expression equal to the solid on every cell of `region`, using halfspaces flagged in `available`.
  /// Returns nullptr when the solid is not describable (result_.witness is set).
  ExprPtr build(std::vector<int> region, std::vector<char> available) {
    // The chain of factored halfspaces, applied from the outside in once the innermost region is built.
    struct Factor {
      ExprPtr psi;
      bool unite;  // true: psi | rest (psi inside the solid); false: psi & rest (psi = complement side)
    };
    std::vector<Factor> chain;
    ExprPtr core;
    for (;;) {
      const int in = static_cast<int>(std::count_if(region.begin(), region.end(), [&](int k) { return solid_[k]; }));
      if (in == 0) { core = empty(); break; }
      if (in == static_cast<int>(region.size())) { core = full(); break; }

      // Dominating halfspaces of the solid, then of its complement (paper: Fig. 1 line 4, Fig. 3).
      std::vector<std::pair<int, bool>> dominating_solid, dominating_complement;
      for (int i = 0; i < c_.halfspace_count(); ++i) {
        if (!available[i]) continue;
        for (bool side : {true, false}) {
          bool any = false, rest = false, all_in = true, all_out = true;
          for (int k : region) {
            if (c_.cells[k].inside[i] == side) {
              any = true;
              (solid_[k] ? all_out : all_in) = false;
            } else {
              rest = true;
            }
          }
          if (!any || !rest) continue;
          if (all_in) dominating_solid.emplace_back(i, side);
          else if (all_out) dominating_complement.emplace_back(i, side);
        }
      }
      bool factored_any = false;
      auto factor = [&](int i, bool side, bool of_solid) {
        // Still useful on the shrunken region? (Order does not invalidate domination: psi ∩ R' ⊆ psi ∩ R.)
        std::vector<int> in_psi, out_psi;
        for (int k : region) (c_.cells[k].inside[i] == side ? in_psi : out_psi).push_back(k);
        if (in_psi.empty() || out_psi.empty() || !available[i]) return;
        if (of_solid) {
          chain.push_back({side_expr(i, side), true});    // solid ∩ R = psi ∪ (solid ∩ R \ psi)
          region = out_psi;
        } else {
          chain.push_back({side_expr(i, !side), false});  // solid ∩ R = ¬psi ∩ (solid ∩ R \ psi)
          region = out_psi;
        }
        available[i] = 0;
        ++result_.factored;
        factored_any = true;
      };
      for (auto [i, side] : dominating_solid) factor(i, side, true);
      for (auto [i, side] : dominating_complement) factor(i, side, false);
      if (factored_any) continue;

      // Partition (Fig. 5).
      const int part = choose_partition(region, available);
      if (part < 0) {
        // Every available halfspace is constant on R, and so is every halfspace used on the way here: all cells
        // of R share one sign vector, with cells both in and out.
        MixedTerm& w = result_.witness;
        w.signs = c_.cells[region.front()].inside;
        for (int k : region) (solid_[k] ? w.inside_cells : w.outside_cells).push_back(k);
        return nullptr;
      }
      ++result_.partitions;
      std::vector<int> inside, outside;
      for (int k : region) (c_.cells[k].inside[part] ? inside : outside).push_back(k);
      std::vector<char> rest = available;
      rest[part] = 0;
      ExprPtr a = build(inside, rest);
      if (!a) return nullptr;
      ExprPtr b = build(outside, rest);
      if (!b) return nullptr;
      core = unite({intersect({leaf(part), a}), intersect({complement(leaf(part)), b})});
      break;
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
      core = it->unite ? unite({it->psi, core}) : intersect({it->psi, core});
    return core;
  }

 private:
  /// Among available halfspaces that split R, the one splitting the fewest faces of the solid's boundary inside
  /// R; then planar first; then the lowest index. -1 if none splits R.
  int choose_partition(const std::vector<int>& region, const std::vector<char>& available) const {
    std::vector<char> in_region(c_.cells.size(), 0);
    for (int k : region) in_region[k] = 1;
    // Faces: boundary patches of the solid with both cells in R, grouped per halfspace through junctions.
    std::vector<int> face_patches;
    for (int p = 0; p < static_cast<int>(c_.patches.size()); ++p) {
      const Patch& patch = c_.patches[p];
      if (in_region[patch.inside_cell] && in_region[patch.outside_cell] &&
          solid_[patch.inside_cell] != solid_[patch.outside_cell])
        face_patches.push_back(p);
    }
    DisjointSets faces(c_.patches.size());
    std::vector<char> on_face(c_.patches.size(), 0);
    for (int p : face_patches) on_face[p] = 1;
    for (const Junction& j : c_.junctions)
      for (int p : j.patches)
        for (int q : j.patches)
          if (p < q && on_face[p] && on_face[q] && c_.patches[p].halfspace == c_.patches[q].halfspace)
            faces.union_set(p, q);
    std::tuple<int, int, int> best{0, 0, 0};
    int best_index = -1;
    for (int i = 0; i < c_.halfspace_count(); ++i) {
      if (!available[i]) continue;
      bool side_in = false, side_out = false;
      for (int k : region) (c_.cells[k].inside[i] ? side_in : side_out) = true;
      if (!side_in || !side_out) continue;
      // A face is split when its patches lie on both sides of psi_i (a patch on psi_i's own boundary is on it).
      std::vector<int> seen_side(c_.patches.size(), -1);
      std::vector<char> split(c_.patches.size(), 0);
      int faces_split = 0;
      for (int p : face_patches) {
        const Patch& patch = c_.patches[p];
        const Cell& a = c_.cells[patch.inside_cell];
        const Cell& b = c_.cells[patch.outside_cell];
        if (a.inside[i] != b.inside[i]) continue;  // on psi_i's boundary
        const int root = faces.find_set(p);
        if (seen_side[root] < 0) seen_side[root] = a.inside[i];
        else if (seen_side[root] != a.inside[i] && !split[root]) {
          split[root] = 1;
          ++faces_split;
        }
      }
      const int not_planar = options_.planar.empty() || !options_.planar[i] ? 1 : 0;
      const std::tuple<int, int, int> key{faces_split, not_planar, i};
      if (best_index < 0 || key < best) {
        best = key;
        best_index = i;
      }
    }
    return best_index;
  }

  const Complex& c_;
  const std::vector<char>& solid_;
  const BhcOptions& options_;
  BhcResult& result_;
};

}  // namespace

BhcResult bhc(const Complex& complex, const std::vector<char>& solid, const BhcOptions& options) {
  BhcResult result;
  std::vector<int> all(complex.cells.size());
  std::iota(all.begin(), all.end(), 0);
  Builder builder(complex, solid, options, result);
  result.tree = builder.build(all, std::vector<char>(complex.halfspace_count(), 1));
  result.describable = result.tree != nullptr;
  if (result.describable) {
    result.verified = evaluate(*result.tree, complex) == solid;
    result.stats = stats(*result.tree);
  }
  return result;
}

}  // namespace hsx::csg
