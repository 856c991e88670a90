// The BSH labelling problem on a complex (BSH paper, Sections 3 and 5).
//
// Conventions (owned here):
// - A labelling gives every cell 1 (inside the shape) or 0 (outside); outer cells are always 0.
// - The boundary b of a labelling is the set of supports (groups of coincident patches, complex/complex.hpp)
//   whose two cells have different labels; a patch is on b when its support is.
// - Orientation-preserving (Def. 3.1): a support may lie on b only with an orientation (which of its two cells
//   is labelled 1) that one of its halfspaces has. On coincident boundaries (Def. 3.1 leaves them open) hsx adds:
//   a patch of halfspace i "is on b" only where b has i's orientation, and a sampled patch may not be used
//   reversed (a sample of i says "this boundary, with i's inside"). So a halfspace given twice behaves like one,
//   two squares sharing an edge line can use it either way, and a disk and its complement both sampled on the
//   same arc keep that arc off b. Equivalently, per support: an orientation is allowed iff some halfspace has it
//   and no sampled patch has the other; as implications: "cell b inside => cell a inside" when only a-inside is
//   allowed, and equal labels when neither is.
// - A sample is covered when its patch is on b (with its halfspace's orientation). Energy (Eq. 1) is the pair
//   (missing samples, measure of b) compared lexicographically: no lambda constant. The measure counts each
//   support once.
// - Sample-connected (Def. 3.2): for every halfspace i, every connected component of b ∩ b_i (patches of i on b
//   with i's orientation, connected through shared junctions) holds a sample of i.
#pragma once

#include <hsx/complex/complex.hpp>
#include <hsx/kernel/measure.hpp>

#include <memory>
#include <string>
#include <vector>

namespace hsx::bsh {

using Labelling = std::vector<char>;  ///< per cell: 1 inside the shape, 0 outside

class Problem;

/// E(b) as the pair (|S \ b|, |b|), |b| exact.
/// An energy made by energy(problem, labelling) holds |b| as the list of b's supports (each support's measure is
/// the problem's, shared, so the energy stays valid after the problem is gone) and forms the exact sum only when
/// measure() is first called (once; safe from several threads). compare() of two such energies of one problem
/// needs no sum: it encloses the supports the two boundaries do not share (certified doubles, then their exact
/// sum only when those do not separate). In 3D, where a measure is thousands of square roots, that is the
/// difference between microseconds and a tenth of a second per energy.
struct Energy {
  long missing_samples = 0;

  Energy() = default;  ///< (0, 0)
  /// (missing_samples, measure) given explicitly.
  Energy(long missing_samples, Measure measure);
  /// |b|, exact: formed on first use for an energy made by energy(problem, labelling).
  const Measure& measure() const;

 private:
  struct Value;
  std::shared_ptr<const Value> value_;  // null: measure 0
  friend Energy energy(const Problem& problem, const Labelling& labelling);
  friend Order compare(const Energy& a, const Energy& b, const CompareOptions& options);
};
/// Lexicographic and certified: Less/Greater/Equal are proofs, Tie means the measures did not separate.
Order compare(const Energy& a, const Energy& b, const CompareOptions& options = {});

/// One support group seen by the labelling problem.
struct SupportTerm {
  int cell_a = -1, cell_b = -1;  ///< the two cells, in the first patch's inside/outside order
  bool allow_a_inside = false;   ///< may lie on b with cell_a = 1, cell_b = 0
  bool allow_b_inside = false;   ///< may lie on b with cell_b = 1, cell_a = 0
  bool allows(int inside) const { return inside == cell_a ? allow_a_inside : allow_b_inside; }
  std::vector<int> patches;
  long samples = 0;       ///< samples on all its patches
  Measure measure;        ///< counted once
};

/// Precomputed, read-only view of a complex for the BSH algorithms.
class Problem {
 public:
  explicit Problem(const Complex& complex);
  const Complex& complex() const { return complex_; }
  const std::vector<SupportTerm>& supports() const { return supports_; }
  int cell_count() const { return static_cast<int>(complex_.cells.size()); }
  int support_count() const { return static_cast<int>(supports_.size()); }
  long total_samples() const { return total_samples_; }
  /// Supports adjacent to each support (sharing a junction through any of their patches), ascending.
  const std::vector<std::vector<int>>& support_neighbours() const { return support_neighbours_; }
  /// Junctions where the paper's genericity assumption fails (Section 3.1: then an orientation-preserving
  /// boundary may be non-manifold, Prop. 5.1 may fail, and best-first is not proven complete). A junction is
  /// generic when its patches lie on exactly two boundaries (coincident patches count as one) that cross: two
  /// ends each and four distinct cells around it (a tangency has three). Junctions whose patches all separate
  /// outer cells are ignored: no boundary can use them. Ascending.
  const std::vector<int>& non_generic_junctions() const { return non_generic_junctions_; }
  /// Rigorous double enclosure [lo, hi] of each support's measure times 2^-enclosure_scale() (fast comparisons
  /// before exact ones, and the weights of the double-precision searches that the exact ones then verify). Every
  /// end is finite and at most 2^512, so sums of them times any sample count stay finite: never inf or NaN.
  const std::vector<std::pair<double, double>>& support_enclosures() const { return atoms_->enclosures; }
  /// The common scale S >= 0 of support_enclosures(): 0 unless a support's measure passes 2^512 (measures beyond
  /// the largest double, such as the lengths of a circle of radius 1e399, are within the input limits), then the
  /// smallest S that brings every enclosure to at most 2^512. Multiplying by 2^-S is exact unless it underflows,
  /// where the ends round outward, so comparisons of sums of enclosures keep their meaning (signs are
  /// scale-free); a double compared with them must be scaled likewise (scaled_enclosure).
  long enclosure_scale() const { return atoms_->scale; }
  /// Rigorous double enclosure [lo, hi] of `measure` times 2^-enclosure_scale() (finite unless `measure` is far
  /// above every support's measure together), e.g. of an energy's measure to compare with sums of
  /// support_enclosures().
  std::pair<double, double> scaled_enclosure(const Measure& measure) const;

  /// The supports' measures and enclosures, shared with the energies made from this problem.
  struct SupportAtoms {
    std::vector<Measure> measures;
    std::vector<std::pair<double, double>> enclosures;  ///< of measures[g] * 2^-scale
    long scale = 0;                                     ///< Problem::enclosure_scale
  };
  const std::shared_ptr<const SupportAtoms>& support_atoms() const { return atoms_; }

 private:
  const Complex& complex_;
  std::vector<SupportTerm> supports_;
  std::vector<std::vector<int>> support_neighbours_;
  std::shared_ptr<const SupportAtoms> atoms_;
  std::vector<int> non_generic_junctions_;
  long total_samples_ = 0;
};

/// Supports on the boundary of `labelling`, ascending.
std::vector<int> boundary_supports(const Problem& problem, const Labelling& labelling);
/// The same as flags: entry g (one per support of `problem`) is 1 when support g is on `labelling`'s boundary.
std::vector<char> boundary_support_flags(const Problem& problem, const Labelling& labelling);
/// Calls f(g) for every support g on the boundary of `labelling`, ascending: boundary_supports without making the
/// list (searches walk thousands of boundaries).
template <class F>
void for_each_boundary_support(const Problem& problem, const Labelling& labelling, F f) {
  for (int g = 0; g < problem.support_count(); ++g) {
    const SupportTerm& s = problem.supports()[g];
    if (labelling[s.cell_a] != labelling[s.cell_b]) f(g);
  }
}
/// True when every outer cell is 0 and every support on b has its inside cell labelled 1. When false and `why`
/// is given, names the first offending cell or support.
bool is_orientation_preserving(const Problem& problem, const Labelling& labelling, std::string* why = nullptr);
Energy energy(const Problem& problem, const Labelling& labelling);

/// A connected component of b ∩ b_i.
struct Component {
  int halfspace = -1;
  std::vector<int> patches;   ///< ascending
  bool has_sample = false;
};

struct SampleConnectivity {
  std::vector<Component> components;  ///< ordered by halfspace, then smallest patch
  std::vector<int> islands;           ///< indices into components without a sample of their halfspace
  bool sample_connected() const { return islands.empty(); }
};
SampleConnectivity sample_connectivity(const Problem& problem, const Labelling& labelling);
/// sample_connectivity(problem, labelling).sample_connected(), without listing the components.
bool is_sample_connected(const Problem& problem, const Labelling& labelling);

/// Removable sets of b (Section 5.2) as sets of supports: each island, and each single support on b adjacent to
/// an island (outside it). Deduplicated, in a deterministic order.
std::vector<std::vector<int>> removable_sets(const Problem& problem, const Labelling& labelling,
                                             const SampleConnectivity& connectivity);

/// Area (2D) or volume (3D) of the cells labelled 1.
Measure inside_measure(const Complex& complex, const Labelling& labelling);

}  // namespace hsx::bsh
