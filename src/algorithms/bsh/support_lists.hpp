// Internal to the BSH algorithms: walking two ascending lists of supports (boundaries of one problem) at once.
#pragma once

#include <cstddef>
#include <vector>

namespace hsx::bsh {

/// Calls f(g, +1) for each support g only in `a` and f(g, -1) for each only in `b` (both ascending), in ascending
/// order of g. compare() adds the measures of a boundary difference in this order; brute force's screen repeats
/// that sum and must add in the same order to take the same decision.
template <class F>
void for_each_difference(const std::vector<int>& a, const std::vector<int>& b, F f) {
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i] < b[j])) {
      f(a[i++], 1);
    } else if (i == a.size() || b[j] < a[i]) {
      f(b[j++], -1);
    } else {
      ++i;
      ++j;
    }
  }
}

}  // namespace hsx::bsh
