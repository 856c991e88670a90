#include <hsx/complex/complex.hpp>

#include <algorithm>
#include <set>
#include <sstream>

namespace hsx {

int Complex::outer_cell_count() const {
  return static_cast<int>(std::count_if(cells.begin(), cells.end(), [](const Cell& c) { return c.outer; }));
}

std::vector<std::vector<int>> Complex::patch_neighbours() const {
  std::vector<std::vector<int>> out(patches.size());
  for (const Junction& j : junctions)
    for (int p : j.patches)
      for (int q : j.patches)
        if (p != q) out[p].push_back(q);
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

std::vector<std::vector<int>> Complex::cell_patches() const {
  std::vector<std::vector<int>> out(cells.size());
  for (int p = 0; p < static_cast<int>(patches.size()); ++p) {
    out[patches[p].inside_cell].push_back(p);
    out[patches[p].outside_cell].push_back(p);
  }
  return out;
}

Measure Complex::measure_of(const std::vector<int>& patch_list) const {
  std::set<int> counted_supports;
  Measure total;
  for (int p : patch_list)
    if (counted_supports.insert(patches[p].support).second) total += patches[p].measure;
  return total;
}

std::vector<std::string> check_complex(const Complex& c) {
  std::vector<std::string> problems;
  auto say = [&](const std::string& s) { problems.push_back(s); };
  const int n_cells = static_cast<int>(c.cells.size());
  const int n_patches = static_cast<int>(c.patches.size());
  const int n_half = c.halfspace_count();
  for (int k = 0; k < n_cells; ++k) {
    if (static_cast<int>(c.cells[k].inside.size()) != n_half)
      say("cell " + std::to_string(k) + ": side vector has wrong length");
    const std::vector<Rational>& witness = c.cells[k].witness.get();
    if (!witness.empty() && static_cast<int>(witness.size()) != c.dimension)
      say("cell " + std::to_string(k) + ": witness has wrong dimension");
  }
  if (!problems.empty()) return problems;
  std::vector<int> group_of(n_patches, -1);
  for (int g = 0; g < static_cast<int>(c.supports.size()); ++g)
    for (int p : c.supports[g]) {
      if (p < 0 || p >= n_patches) {
        say("support " + std::to_string(g) + ": patch index out of range");
        continue;
      }
      if (group_of[p] != -1) say("patch " + std::to_string(p) + ": in two support groups");
      group_of[p] = g;
    }
  for (int p = 0; p < n_patches; ++p) {
    const Patch& pa = c.patches[p];
    const std::string who = "patch " + std::to_string(p);
    if (pa.halfspace < 0 || pa.halfspace >= n_half) { say(who + ": halfspace out of range"); continue; }
    if (pa.inside_cell < 0 || pa.inside_cell >= n_cells || pa.outside_cell < 0 || pa.outside_cell >= n_cells) {
      say(who + ": cell index out of range");
      continue;
    }
    if (pa.inside_cell == pa.outside_cell) say(who + ": separates a cell from itself");
    if (group_of[p] != pa.support) say(who + ": support index disagrees with the support groups");
    const Cell& in = c.cells[pa.inside_cell];
    const Cell& out = c.cells[pa.outside_cell];
    if (!in.inside[pa.halfspace] || out.inside[pa.halfspace])
      say(who + ": its cells are not on the inside/outside of its halfspace");
    if (pa.support >= 0 && pa.support < static_cast<int>(c.supports.size())) {
      std::set<int> group_halfspaces;
      for (int q : c.supports[pa.support]) {
        if (q < 0 || q >= n_patches) continue;
        group_halfspaces.insert(c.patches[q].halfspace);
        const Patch& qa = c.patches[q];
        if (std::minmax(qa.inside_cell, qa.outside_cell) != std::minmax(pa.inside_cell, pa.outside_cell))
          say(who + ": coincident patch " + std::to_string(q) + " separates other cells");
      }
      for (int i = 0; i < n_half; ++i) {
        const bool differ = in.inside[i] != out.inside[i];
        if (differ != (group_halfspaces.count(i) > 0))
          say(who + ": its cells " + (differ ? "differ" : "agree") + " in halfspace " + std::to_string(i) +
              (differ ? " that does not bound them there" : " that bounds them there"));
      }
    }
    for (int s : pa.samples)
      if (s < 0 || s >= static_cast<int>(c.samples.size()) || c.samples[s].patch != p)
        say(who + ": sample list disagrees with the sample sites");
    for (int j : pa.junctions) {
      if (j < 0 || j >= static_cast<int>(c.junctions.size())) { say(who + ": junction out of range"); continue; }
      const auto& list = c.junctions[j].patches;
      if (!std::binary_search(list.begin(), list.end(), p)) say(who + ": junction does not list it");
    }
  }
  for (int j = 0; j < static_cast<int>(c.junctions.size()); ++j)
    for (int p : c.junctions[j].patches) {
      if (p < 0 || p >= n_patches) { say("junction " + std::to_string(j) + ": patch out of range"); continue; }
      const auto& ends = c.patches[p].junctions;
      if (std::find(ends.begin(), ends.end(), j) == ends.end())
        say("junction " + std::to_string(j) + ": lists patch " + std::to_string(p) + " that does not end there");
    }
  for (int j = 0; j < static_cast<int>(c.junctions.size()); ++j)
    for (int p : c.junctions[j].sheets)
      if (!std::binary_search(c.junctions[j].patches.begin(), c.junctions[j].patches.end(), p))
        say("junction " + std::to_string(j) + ": a sheet names patch " + std::to_string(p) + " that it does not list");
  for (int k = 0; k < static_cast<int>(c.corners.size()); ++k) {
    const Corner& corner = c.corners[k];
    const int spokes = static_cast<int>(corner.spokes.size());
    for (int j : corner.spokes)
      if (j < 0 || j >= static_cast<int>(c.junctions.size())) say("corner " + std::to_string(k) + ": junction out of range");
    for (const Corner::Wedge& w : corner.wedges)
      if (w.patch < 0 || w.patch >= n_patches || (w.from < 0) != (w.to < 0) || w.from >= spokes || w.to >= spokes)
        say("corner " + std::to_string(k) + ": a wedge out of range");
  }
  for (int s = 0; s < static_cast<int>(c.samples.size()); ++s) {
    const SampleSite& site = c.samples[s];
    if (site.patch < 0 || site.patch >= n_patches) { say("sample " + std::to_string(s) + ": patch out of range"); continue; }
    if (c.patches[site.patch].halfspace != site.halfspace)
      say("sample " + std::to_string(s) + ": sits on a patch of another halfspace");
    const auto& list = c.patches[site.patch].samples;
    if (!std::binary_search(list.begin(), list.end(), s)) say("sample " + std::to_string(s) + ": not listed by its patch");
  }
  return problems;
}

}  // namespace hsx
