// Reading helpers shared by the hsx-complex/1 reader's sections (complex_json.cpp: the document and its 2D
// geometry; complex_json3.cpp: the 3D geometry section). Private to io.
#pragma once

#include <hsx/geometry/arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/kernel/measure.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hsx::complex_json_detail {

/// Work allowed for one document. The kernel merges square-root terms with a cost up to quadratic in their number,
/// so each sum built from n pieces (a patch of n edges or triangles, a face walk of n steps, a closed form of n
/// terms) costs n^2. Hsx's own largest legitimate documents (5000-vertex polygons) use a fraction of this.
constexpr std::uint64_t kWorkBudget = std::uint64_t(1) << 27;
/// Dense per-cell side vectors and the per-patch checks cost cells x halfspaces and patches x halfspaces.
const std::uint64_t kMaxTableEntries = static_cast<std::uint64_t>(ArrangementLimits{}.max_side_entries);

class Budget {
 public:
  /// Spends n^2 units for a sum of n pieces; fails at `where` when the document's total exceeds kWorkBudget.
  void spend(std::uint64_t n, const JsonField& where) {
    const std::uint64_t cost = n > (std::uint64_t(1) << 31) ? kWorkBudget + 1 : n * n;
    used_ += cost;
    if (used_ > kWorkBudget) {
      where.fail("the document is too large to check: its sums of terms exceed the work limit (" +
                 std::to_string(kWorkBudget) + " term pairs)");
    }
  }

 private:
  std::uint64_t used_ = 0;
};

/// Halfspace name -> index; an unknown name fails at the field.
class Names {
 public:
  explicit Names(const std::vector<std::string>& names) {
    for (std::size_t i = 0; i < names.size(); ++i) index_.emplace(names[i], static_cast<int>(i));
  }
  int operator()(const JsonField& f) const {
    const std::string name = f.string();
    auto it = index_.find(name);
    if (it == index_.end()) f.fail("unknown halfspace " + describe_json(nlohmann::json(name)));
    return it->second;
  }

 private:
  std::map<std::string, int> index_;
};

nlohmann::json measure_json(const Measure& m);
/// A length, area or volume read without geometry: it must be positive (a proven sign <= 0 is refused).
Measure positive_measure_from_fields(const JsonField& f, Budget& budget, const std::string& what);
/// Checks given measure fields (exact and/or decimal) against a value recomputed from the geometry.
void check_measure(const JsonField& f, const Measure& recomputed, const std::string& what, Budget& budget);
/// An index in [0, count): "WHAT V is out of range (there are COUNT WHATs)" otherwise.
int read_index(const JsonField& f, std::size_t count, const std::string& what);
/// An element's optional "id" must be its position.
void check_id(const JsonField& element, std::size_t position);
/// Indices in range, returned sorted; a duplicate fails.
std::vector<int> read_index_set(const JsonField& f, std::size_t count, const std::string& what);
/// A halfspace name quoted for messages.
std::string name_of(const std::vector<std::string>& names, int h);

}  // namespace hsx::complex_json_detail
