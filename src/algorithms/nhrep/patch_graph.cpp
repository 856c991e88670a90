#include <hsx/algorithms/nhrep/patch_graph.hpp>

#include "algorithms/flow_graph.hpp"
#include "geometry/components.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/edmonds_karp_max_flow.hpp>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <stdexcept>
#include <utility>

namespace hsx::nhrep {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

bool is_convexish(FeatureType t) { return t == FeatureType::Convex || t == FeatureType::Hybrid; }
bool is_concaveish(FeatureType t) { return t == FeatureType::Concave || t == FeatureType::Hybrid; }

/// Connected components of `pieces` (ascending; member[p] flags them) across non-feature links whose both ends
/// satisfy `same(a, b)` (a symmetric test), each sorted; components ordered by their lowest piece.
template <class Same>
std::vector<std::vector<int>> components(const BoundarySurface& surface, const std::vector<int>& pieces,
                                         const std::vector<char>& member, Same same) {
  std::vector<std::pair<int, int>> edges;
  for (int p : pieces)
    for (int l : surface.pieces[at(p)].links) {
      const int q = surface.across(l, p);
      if (p < q && !surface.links[at(l)].feature && member[at(q)] && same(p, q)) edges.emplace_back(p, q);
    }
  return induced_components(pieces, edges);
}

}  // namespace

std::vector<int> PatchGraph::live_patches() const {
  std::vector<int> live;
  for (std::size_t p = 0; p < patches.size(); ++p)
    if (patches[p].alive) live.push_back(static_cast<int>(p));
  return live;
}

std::vector<std::vector<int>> PatchGraph::incident_curves() const {
  std::vector<std::vector<int>> incident(patches.size());
  for (std::size_t c = 0; c < curves.size(); ++c) {
    incident[at(curves[c].patch_a)].push_back(static_cast<int>(c));
    incident[at(curves[c].patch_b)].push_back(static_cast<int>(c));
  }
  return incident;
}

bool PatchGraph::has_convex(int patch) const {
  return std::any_of(curves.begin(), curves.end(), [&](const Curve& c) {
    return (c.patch_a == patch || c.patch_b == patch) && is_convexish(c.type);
  });
}

bool PatchGraph::has_concave(int patch) const {
  return std::any_of(curves.begin(), curves.end(), [&](const Curve& c) {
    return (c.patch_a == patch || c.patch_b == patch) && is_concaveish(c.type);
  });
}

int PatchGraph::both_kinds_count() const {
  std::vector<char> convex(patches.size(), 0), concave(patches.size(), 0);
  for (const Curve& c : curves)
    for (int p : {c.patch_a, c.patch_b}) {
      convex[at(p)] |= is_convexish(c.type);
      concave[at(p)] |= is_concaveish(c.type);
    }
  int count = 0;
  for (std::size_t p = 0; p < patches.size(); ++p) count += patches[p].alive && convex[p] && concave[p];
  return count;
}

int PatchGraph::original_of(int patch) const {
  while (patches[at(patch)].parent >= 0) patch = patches[at(patch)].parent;
  return patch;
}

void rebuild_curves(PatchGraph& graph) {
  const BoundarySurface& surface = graph.surface;
  // A curve continues through a corner only where exactly two feature links meet (elsewhere it is a feature
  // corner, an end point).
  std::vector<int> corner_degree(at(surface.corner_count), 0);
  std::vector<int> feature_links;
  for (std::size_t l = 0; l < surface.links.size(); ++l) {
    const BoundaryLink& link = surface.links[l];
    if (!link.feature) continue;
    if (graph.piece_patch[at(link.piece_a)] < 0 || graph.piece_patch[at(link.piece_b)] < 0) continue;
    feature_links.push_back(static_cast<int>(l));
    for (int c : {link.corner_a, link.corner_b})
      if (c >= 0) ++corner_degree[at(c)];
  }
  auto patch_pair = [&](int l) {
    const BoundaryLink& link = surface.links[at(l)];
    const int a = graph.piece_patch[at(link.piece_a)], b = graph.piece_patch[at(link.piece_b)];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  DisjointSets curve_of(surface.links.size());  // feature links joined through degree-2 corners into curves
  std::map<std::pair<std::pair<int, int>, int>, int> at_corner;  // (patch pair, corner) -> a link seen there
  for (int l : feature_links) {
    const BoundaryLink& link = surface.links[at(l)];
    for (int c : {link.corner_a, link.corner_b}) {
      if (c < 0 || corner_degree[at(c)] != 2) continue;
      auto [it, fresh] = at_corner.emplace(std::make_pair(patch_pair(l), c), l);
      if (!fresh) curve_of.union_set(l, it->second);
    }
  }
  std::map<int, Curve> by_root;
  std::map<int, std::array<int, 3>> votes;  // per curve: smooth, convex, concave links
  for (int l : feature_links) {
    const int root = curve_of.find_set(l);
    ++votes[root][static_cast<std::size_t>(surface.links[at(l)].type)];
    auto [it, fresh] = by_root.emplace(root, Curve{});
    Curve& curve = it->second;
    const auto [a, b] = patch_pair(l);
    if (fresh) {
      curve.patch_a = a;
      curve.patch_b = b;
      curve.type = surface.links[at(l)].type;
    } else {
      curve.type = combine_feature_types(curve.type, surface.links[at(l)].type);
    }
    curve.links.push_back(l);  // feature_links is ascending, so each curve's links are too
  }
  if (graph.rule == CurveRule::Majority)
    for (auto& [root, curve] : by_root) {
      const auto& v = votes[root];
      const int sharp = std::max(v[1], v[2]);
      if (v[1] == v[2] && v[1] >= v[0] && v[1] > 0) curve.type = FeatureType::Hybrid;
      else if (sharp >= v[0]) curve.type = v[1] > v[2] ? FeatureType::Convex : FeatureType::Concave;
      else curve.type = FeatureType::Smooth;
    }
  graph.curves.clear();
  graph.internal_curves.clear();
  for (auto& [root, curve] : by_root) (curve.patch_a == curve.patch_b ? graph.internal_curves : graph.curves).push_back(curve);
  auto order = [](const Curve& x, const Curve& y) {
    return std::tie(x.patch_a, x.patch_b, x.links.front()) < std::tie(y.patch_a, y.patch_b, y.links.front());
  };
  std::sort(graph.curves.begin(), graph.curves.end(), order);
  std::sort(graph.internal_curves.begin(), graph.internal_curves.end(), order);
}

PatchGraph build_patch_graph(BoundarySurface surface, CurveRule rule) {
  const std::vector<std::string> problems = check_boundary(surface);
  if (!problems.empty()) throw std::invalid_argument("invalid boundary: " + problems.front());
  PatchGraph graph;
  graph.rule = rule;
  graph.surface = std::move(surface);
  const BoundarySurface& s = graph.surface;
  graph.piece_patch.assign(s.pieces.size(), -1);
  std::vector<int> live;
  std::vector<char> member(s.pieces.size(), 0);
  for (std::size_t p = 0; p < s.pieces.size(); ++p)
    if (!s.pieces[p].retired) {
      live.push_back(static_cast<int>(p));
      member[p] = 1;
    }
  for (auto& component : components(s, live, member, [](int, int) { return true; })) {
    const int id = static_cast<int>(graph.patches.size());
    for (int p : component) graph.piece_patch[at(p)] = id;
    graph.patches.push_back(PatchInfo{std::move(component), -1, true});
  }
  rebuild_curves(graph);
  return graph;
}

namespace {

using Traits = FlowTraits;
using FlowGraph = hsx::FlowGraph<long>;

/// Per piece of the patch: bit 1 if it lies on a convex feature link to another patch, bit 2 on a concave one.
int terminal_kinds(const PatchGraph& graph, int patch, int piece, const std::vector<char>* scope) {
  int kinds = 0;
  for (int l : graph.surface.pieces[at(piece)].links) {
    const BoundaryLink& link = graph.surface.links[at(l)];
    const int other = graph.piece_patch[at(graph.surface.across(l, piece))];
    if (!link.feature || other == patch || (scope && !(*scope)[at(other)])) continue;
    if (link.type == FeatureType::Convex) kinds |= 1;
    if (link.type == FeatureType::Concave) kinds |= 2;
  }
  return kinds;
}

/// Minimum cut of the patch's dual graph: returns per local piece 1 when on the convex (source) side. The side is
/// the set reachable from the source in the residual graph, so the labelling is deterministic.
std::vector<char> convex_side(const PatchGraph& graph, int patch, const std::vector<int>& pieces,
                              const std::vector<int>& kinds) {
  const int n = static_cast<int>(pieces.size());
  std::map<int, int> local;
  for (int i = 0; i < n; ++i) local[pieces[at(i)]] = i;
  FlowGraph g(static_cast<std::size_t>(n + 2));
  const int s = n, t = n + 1;
  auto capacity = boost::get(boost::edge_capacity, g);
  auto residual = boost::get(boost::edge_residual_capacity, g);
  auto reverse = boost::get(boost::edge_reverse, g);
  auto arc = [&](int from, int to, long cap, long back_cap) {
    auto e = boost::add_edge(static_cast<std::size_t>(from), static_cast<std::size_t>(to), g).first;
    auto r = boost::add_edge(static_cast<std::size_t>(to), static_cast<std::size_t>(from), g).first;
    capacity[e] = cap;
    capacity[r] = back_cap;
    reverse[e] = r;
    reverse[r] = e;
  };
  const long infinite = static_cast<long>(graph.surface.links.size()) + 1;  // exceeds any finite cut
  for (int i = 0; i < n; ++i) {
    const int p = pieces[at(i)];
    if (kinds[at(i)] & 1) arc(s, i, infinite, 0);
    if (kinds[at(i)] & 2) arc(i, t, infinite, 0);
    for (int l : graph.surface.pieces[at(p)].links) {
      if (graph.surface.links[at(l)].feature) continue;
      const int q = graph.surface.across(l, p);
      if (graph.piece_patch[at(q)] != patch || q < p) continue;  // each undirected link once
      arc(i, local.at(q), 1, 1);
    }
  }
  std::vector<boost::default_color_type> color(static_cast<std::size_t>(n + 2));
  std::vector<Traits::edge_descriptor> pred(static_cast<std::size_t>(n + 2));
  const long flow = boost::edmonds_karp_max_flow(
      g, static_cast<std::size_t>(s), static_cast<std::size_t>(t), capacity, residual, reverse,
      boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, g)),
      boost::make_iterator_property_map(pred.begin(), boost::get(boost::vertex_index, g)));
  if (flow >= infinite) throw std::logic_error("patch decomposition: a piece is on both convex and concave links");
  std::vector<char> reached(static_cast<std::size_t>(n + 2), 0);
  std::deque<int> queue{s};
  reached[at(s)] = 1;
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (auto [it, end] = boost::out_edges(static_cast<std::size_t>(v), g); it != end; ++it) {
      const int w = static_cast<int>(boost::target(*it, g));
      if (residual[*it] > 0 && !reached[at(w)]) {
        reached[at(w)] = 1;
        queue.push_back(w);
      }
    }
  }
  return std::vector<char>(reached.begin(), reached.begin() + n);
}

}  // namespace

Decomposition decompose_patch(PatchGraph& graph, int patch, const std::vector<char>* scope) {
  if (patch < 0 || patch >= static_cast<int>(graph.patches.size()) || !graph.patches[at(patch)].alive)
    throw std::invalid_argument("decompose_patch: no live patch " + std::to_string(patch));
  if (!scope && (!graph.has_convex(patch) || !graph.has_concave(patch)))
    throw std::invalid_argument("decompose_patch: patch " + std::to_string(patch) +
                                " does not have both convex and concave edges");
  Decomposition result;
  result.patch = patch;
  result.whole_patch = scope == nullptr;
  result.both_kinds_before = graph.both_kinds_count();

  // Face-splitting: no piece may lie on both a convex and a concave feature link.
  std::vector<int> pieces;
  for (int p : graph.patches[at(patch)].pieces) {
    if (terminal_kinds(graph, patch, p, scope) != 3) {
      pieces.push_back(p);
      continue;
    }
    ++result.pieces_split;
    for (int part : split_piece(graph.surface, p)) {
      graph.piece_patch.resize(graph.surface.pieces.size(), -1);
      graph.piece_patch[at(part)] = patch;
      pieces.push_back(part);
    }
    graph.piece_patch[at(p)] = -1;
  }
  std::sort(pieces.begin(), pieces.end());
  std::vector<int> kinds;
  for (int p : pieces) kinds.push_back(terminal_kinds(graph, patch, p, scope));

  const std::vector<char> side = convex_side(graph, patch, pieces, kinds);
  std::vector<char> member(graph.surface.pieces.size(), 0), convex_label(graph.surface.pieces.size(), 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    member[at(pieces[i])] = 1;
    convex_label[at(pieces[i])] = side[i];
  }
  const auto parts = components(graph.surface, pieces, member,
                                [&](int a, int b) { return convex_label[at(a)] == convex_label[at(b)]; });
  graph.patches[at(patch)].alive = false;
  graph.patches[at(patch)].pieces.clear();
  for (const auto& part : parts) {
    const int id = static_cast<int>(graph.patches.size());
    for (int p : part) graph.piece_patch[at(p)] = id;
    graph.patches.push_back(PatchInfo{part, patch, true});
    result.subpatches.push_back(id);
  }
  // Links between two subpatches are smooth feature links (Section 5.2): the links the cut crossed, and any
  // feature link that had the old patch on both sides (a seam inside it) and now separates two subpatches.
  for (int p : pieces)
    for (int l : graph.surface.pieces[at(p)].links) {
      BoundaryLink& link = graph.surface.links[at(l)];
      const int a = graph.piece_patch[at(link.piece_a)], b = graph.piece_patch[at(link.piece_b)];
      if (a == b || graph.patches[at(a)].parent != patch || graph.patches[at(b)].parent != patch) continue;
      if (!link.feature) ++result.cut_links;
      link.feature = true;
      link.type = FeatureType::Smooth;
    }
  rebuild_curves(graph);
  result.both_kinds_after = graph.both_kinds_count();
  return result;
}

}  // namespace hsx::nhrep
