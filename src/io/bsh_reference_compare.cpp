// Comparing the BSH authors' reference-result.grid with hsx's arrangement (conventions in
// include/hsx/io/bsh_reference.hpp).
#include <hsx/io/bsh_reference.hpp>

#include <hsx/geometry/mesh3.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <sstream>

namespace hsx {

namespace {

PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

int orient(const PointQ3& a, const PointQ3& b, const PointQ3& c, const PointQ3& d) {
  return sgn(dot3(triangle_normal(a, b, c), sub(d, a)));
}

/// A conservative double box (every exact coordinate lies inside).
struct Box {
  double lo[3], hi[3];
  bool overlaps(const Box& o) const {
    for (int i = 0; i < 3; ++i)
      if (hi[i] < o.lo[i] || o.hi[i] < lo[i]) return false;
    return true;
  }
};

Box box_of(const PointQ3* const* points, int n) {
  Box b;
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = INFINITY;
    b.hi[i] = -INFINITY;
  }
  for (int k = 0; k < n; ++k) {
    const Rational* c[3] = {&points[k]->x, &points[k]->y, &points[k]->z};
    for (int i = 0; i < 3; ++i) {
      const double d = c[i]->get_d();  // within one ulp of the exact value
      b.lo[i] = std::min(b.lo[i], std::nextafter(std::nextafter(d, -INFINITY), -INFINITY));
      b.hi[i] = std::max(b.hi[i], std::nextafter(std::nextafter(d, INFINITY), INFINITY));
    }
  }
  return b;
}

enum class Hit { None, Cross, Degenerate };

/// Segment [p, q] against triangle (a, b, c), exactly: Cross through its interior, Degenerate when an end point
/// is on its plane or the segment meets an edge or a vertex.
Hit segment_hits(const PointQ3& p, const PointQ3& q, const PointQ3& a, const PointQ3& b, const PointQ3& c) {
  const int op = orient(a, b, c, p), oq = orient(a, b, c, q);
  if (op != 0 && op == oq) return Hit::None;
  const int s1 = orient(p, q, a, b), s2 = orient(p, q, b, c), s3 = orient(p, q, c, a);
  const bool pos = s1 >= 0 && s2 >= 0 && s3 >= 0, neg = s1 <= 0 && s2 <= 0 && s3 <= 0;
  if (!pos && !neg) return Hit::None;
  if (op == 0 || oq == 0 || s1 == 0 || s2 == 0 || s3 == 0) return Hit::Degenerate;
  return Hit::Cross;
}

/// Their mesh with double boxes and per-block faces.
class Mesh {
 public:
  explicit Mesh(const BshReference& r) : r_(r) {
    boxes_.reserve(r.faces.size());
    for (const auto& f : r.faces) {
      const PointQ3* v[3] = {&r.vertices[f[0]], &r.vertices[f[1]], &r.vertices[f[2]]};
      boxes_.push_back(box_of(v, 3));
    }
    block_faces_.resize(r.block_patches.size());
    for (std::size_t b = 0; b < r.block_patches.size(); ++b)
      for (int p : r.block_patches[b])
        for (int f : r.patch_faces[p])
          if (!r.zero_area[f]) block_faces_[b].push_back(f);
  }

  const std::vector<int>& block_faces(int b) const { return block_faces_[b]; }
  const PointQ3& vertex(int face, int i) const { return r_.vertices[r_.faces[face][i]]; }

  Hit hits(const PointQ3& p, const PointQ3& q, const Box& pq, int face) const {
    if (!boxes_[face].overlaps(pq)) return Hit::None;
    return segment_hits(p, q, vertex(face, 0), vertex(face, 1), vertex(face, 2));
  }

  /// Crossings of [p, q] with `faces` mod 2; nullopt when a crossing is degenerate.
  std::optional<int> parity(const PointQ3& p, const PointQ3& q, const std::vector<int>& faces) const {
    const PointQ3* ends[2] = {&p, &q};
    const Box pq = box_of(ends, 2);
    int count = 0;
    for (int f : faces) {
      const Hit h = hits(p, q, pq, f);
      if (h == Hit::Degenerate) return std::nullopt;
      if (h == Hit::Cross) ++count;
    }
    return count % 2;
  }

  /// True when [p, q] meets no face of the mesh but `face`, through its interior.
  bool crosses_only(const PointQ3& p, const PointQ3& q, int face) const {
    const PointQ3* ends[2] = {&p, &q};
    const Box pq = box_of(ends, 2);
    for (int f = 0; f < static_cast<int>(r_.faces.size()); ++f) {
      if (r_.zero_area[f]) continue;
      const Hit h = hits(p, q, pq, f);
      if (h != (f == face ? Hit::Cross : Hit::None)) return false;
    }
    return true;
  }

  /// Whether block b's faces close up (every edge used an even number of times).
  bool closed(int b) const {
    std::map<std::pair<int, int>, int> uses;
    for (int f : block_faces_[b])
      for (int i = 0; i < 3; ++i) {
        const int u = r_.faces[f][i], v = r_.faces[f][(i + 1) % 3];
        ++uses[{std::min(u, v), std::max(u, v)}];
      }
    return std::all_of(uses.begin(), uses.end(), [](const auto& e) { return e.second % 2 == 0; });
  }

  /// A point far outside every vertex (attempt k gives another one): above the vertices' greatest coordinates,
  /// found exactly (their doubles may overflow) and rounded up to integers.
  PointQ3 far_point(int k) const {
    if (!far_base_) {
      mpz_class top[3];
      for (std::size_t v = 0; v < r_.vertices.size(); ++v)
        for (int i = 0; i < 3; ++i) {
          const Rational& c = i == 0 ? r_.vertices[v].x : (i == 1 ? r_.vertices[v].y : r_.vertices[v].z);
          mpz_class up;
          mpz_cdiv_q(up.get_mpz_t(), c.get_num_mpz_t(), c.get_den_mpz_t());
          if (v == 0 || top[i] < up) top[i] = up;
        }
      far_base_ = PointQ3{Rational(top[0] + 1), Rational(top[1] + 2), Rational(top[2] + 3)};
    }
    return {far_base_->x + Rational(k + 1, 7), far_base_->y + Rational(k + 2, 11), far_base_->z + Rational(k + 3, 13)};
  }

  /// Faces of patch p worth trying, the fattest first (largest double altitude), at most `n`.
  std::vector<int> candidate_faces(int p, std::size_t n) const {
    std::vector<std::pair<double, int>> scored;
    for (int f : r_.patch_faces[p])
      if (!r_.zero_area[f]) scored.push_back({-altitude(f), f});
    std::sort(scored.begin(), scored.end());
    std::vector<int> out;
    for (std::size_t i = 0; i < scored.size() && i < n; ++i) out.push_back(scored[i].second);
    return out;
  }

  double altitude(int f) const {
    double len2[3], n2 = 0;
    const PointQ3 n = triangle_normal(vertex(f, 0), vertex(f, 1), vertex(f, 2));
    n2 = n.x.get_d() * n.x.get_d() + n.y.get_d() * n.y.get_d() + n.z.get_d() * n.z.get_d();
    for (int i = 0; i < 3; ++i) {
      const PointQ3 e = sub(vertex(f, (i + 1) % 3), vertex(f, i));
      len2[i] = e.x.get_d() * e.x.get_d() + e.y.get_d() * e.y.get_d() + e.z.get_d() * e.z.get_d();
    }
    const double longest = std::sqrt(std::max({len2[0], len2[1], len2[2]}));
    return longest > 0 ? std::sqrt(n2) / longest : 0;
  }

  /// Points on either side of face f: centroid +- step along the normal, the step about altitude / 2^shift.
  std::array<PointQ3, 2> pair_at(int f, int shift) const {
    const PointQ3 &a = vertex(f, 0), &b = vertex(f, 1), &c = vertex(f, 2);
    const PointQ3 centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
    const PointQ3 n = triangle_normal(a, b, c);
    Rational inf = abs(n.x);
    inf = std::max({inf, Rational(abs(n.y)), Rational(abs(n.z))});
    const int e = static_cast<int>(std::floor(std::log2(std::max(altitude(f), 1e-300)))) - shift;
    Rational step = 1;
    if (e >= 0) step = Rational(Integer(1) << e);
    else step = Rational(Integer(1), Integer(1) << -e);
    const Rational t = step / inf;
    return {PointQ3{centroid.x + t * n.x, centroid.y + t * n.y, centroid.z + t * n.z},
            PointQ3{centroid.x - t * n.x, centroid.y - t * n.y, centroid.z - t * n.z}};
  }

 private:
  const BshReference& r_;
  std::vector<Box> boxes_;
  std::vector<std::vector<int>> block_faces_;
  mutable std::optional<PointQ3> far_base_;
};

constexpr std::size_t kFacesTried = 6;
constexpr int kShifts[] = {4, 10, 16};

/// A point off the mesh next to a face of patch p (in one of p's blocks), or nullopt.
std::optional<PointQ3> point_near(const Mesh& mesh, int p) {
  for (int f : mesh.candidate_faces(p, 2))
    for (int shift : kShifts) {
      const auto pair = mesh.pair_at(f, shift);
      if (mesh.crosses_only(pair[0], pair[1], f)) return pair[0];
    }
  return std::nullopt;
}

/// Whether p is enclosed by block b's closed faces (odd crossings to a far point); nullopt when degenerate.
std::optional<bool> enclosed(const Mesh& mesh, int b, const PointQ3& p) {
  for (int k = 0; k < 3; ++k)
    if (const auto odd = mesh.parity(p, mesh.far_point(k), mesh.block_faces(b))) return *odd == 1;
  return std::nullopt;
}

/// Whether closed block b is the region outside its faces (it reaches their box): then every other patch lies
/// inside its faces; a bounded block has every other patch outside. When b's patches are all there is (a lone
/// shell, two blocks with the same faces), the lower-numbered block is taken as the outer one (their code lists
/// the outside first); nullopt when undecided.
std::optional<bool> outer_block(const Mesh& mesh, const BshReference& r, int b) {
  const auto& own = r.block_patches[b];
  for (int p = 0; p < static_cast<int>(r.patch_faces.size()); ++p) {
    if (std::find(own.begin(), own.end(), p) != own.end()) continue;
    const auto q = point_near(mesh, p);
    if (!q) continue;
    if (const auto in = enclosed(mesh, b, *q)) return *in;
  }
  const auto& pb = r.patch_blocks[own.front()];
  return b == std::min(pb[0], pb[1]);
}

/// A point proven inside closed block b: one of a pair at a face of its patches, by parity to a far point.
std::optional<PointQ3> seed_point(const Mesh& mesh, const BshReference& r, int b) {
  const auto outer = outer_block(mesh, r, b);
  if (!outer) return std::nullopt;
  for (int p : r.block_patches[b])
    for (int f : mesh.candidate_faces(p, 2))
      for (int shift : kShifts) {
        const auto pair = mesh.pair_at(f, shift);
        if (!mesh.crosses_only(pair[0], pair[1], f)) continue;
        if (const auto in = enclosed(mesh, b, pair[0])) return *in != *outer ? pair[0] : pair[1];
      }
  return std::nullopt;
}

/// A point proven inside the block across patch p from block a (holding proven point `in_a`).
std::optional<PointQ3> point_across(const Mesh& mesh, int a, const PointQ3& in_a, int p) {
  for (int f : mesh.candidate_faces(p, kFacesTried))
    for (int shift : kShifts) {
      const auto pair = mesh.pair_at(f, shift);
      if (!mesh.crosses_only(pair[0], pair[1], f)) continue;
      for (int i = 0; i < 2; ++i) {
        const auto odd = mesh.parity(in_a, pair[i], mesh.block_faces(a));
        if (odd) return (*odd == 0) == (i == 0) ? pair[1] : pair[0];  // pair[i] in a iff even
      }
    }
  return std::nullopt;
}

/// The point half way from face f's centroid, along its normal towards block b (holding proven point `in_b`), to
/// the first face of b met; its depth (the distance to that face, approximate) comes with it. nullopt when a test
/// is degenerate or nothing is met.
std::optional<std::pair<double, PointQ3>> deep_point(const Mesh& mesh, int b, const PointQ3& in_b, int f) {
  const auto pair = mesh.pair_at(f, kShifts[0]);
  const auto odd = mesh.parity(in_b, pair[0], mesh.block_faces(b));
  if (!odd) return std::nullopt;
  const PointQ3 &a = mesh.vertex(f, 0), &v1 = mesh.vertex(f, 1), &v2 = mesh.vertex(f, 2);
  const PointQ3 c{(a.x + v1.x + v2.x) / 3, (a.y + v1.y + v2.y) / 3, (a.z + v1.z + v2.z) / 3};
  const PointQ3 towards = *odd == 0 ? pair[0] : pair[1];
  const PointQ3 d = sub(towards, c);
  // Far enough to leave every face of b: the extent of its vertices' boxes, over |d|_inf.
  Rational reach = 0;
  for (int g : mesh.block_faces(b))
    for (int i = 0; i < 3; ++i) {
      const PointQ3 e = sub(mesh.vertex(g, i), c);
      reach = std::max({reach, Rational(abs(e.x)), Rational(abs(e.y)), Rational(abs(e.z))});
    }
  Rational dinf = std::max({Rational(abs(d.x)), Rational(abs(d.y)), Rational(abs(d.z))});
  const Rational scale = 2 * reach / dinf + 1;
  const PointQ3 end{c.x + scale * d.x, c.y + scale * d.y, c.z + scale * d.z};
  const PointQ3* ends[2] = {&towards, &end};
  const Box box = box_of(ends, 2);
  std::optional<Rational> first;  // parameter along d
  for (int g : mesh.block_faces(b)) {
    if (g == f) continue;
    const Hit h = mesh.hits(towards, end, box, g);
    if (h == Hit::None) continue;
    if (h == Hit::Degenerate) return std::nullopt;
    const PointQ3 n = triangle_normal(mesh.vertex(g, 0), mesh.vertex(g, 1), mesh.vertex(g, 2));
    const Rational t = dot3(n, sub(mesh.vertex(g, 0), c)) / dot3(n, d);
    if (!first || t < *first) first = t;
  }
  if (!first) return std::nullopt;
  const Rational half = *first / 2;
  PointQ3 m{c.x + half * d.x, c.y + half * d.y, c.z + half * d.z};
  const auto check = mesh.parity(in_b, m, mesh.block_faces(b));
  if (!check || *check != 0) return std::nullopt;
  const double depth = half.get_d() * std::sqrt(dot3(d, d).get_d());
  return std::make_pair(depth, std::move(m));
}

/// The deepest of deep_point over the fattest face of each of b's patches (up to kDeepPatches, the largest
/// first); `in_b` when none passes.
constexpr std::size_t kDeepPatches = 8;
PointQ3 deepen(const Mesh& mesh, const BshReference& r, int b, const PointQ3& in_b) {
  std::vector<std::pair<double, int>> faces;
  for (int p : r.block_patches[b]) {
    const auto candidates = mesh.candidate_faces(p, 1);
    if (candidates.empty()) continue;
    const int f = candidates.front();
    faces.push_back({-mesh.altitude(f) * static_cast<double>(r.patch_faces[p].size()), f});
  }
  std::sort(faces.begin(), faces.end());
  std::optional<std::pair<double, PointQ3>> best;
  for (std::size_t i = 0; i < faces.size() && i < kDeepPatches; ++i) {
    auto m = deep_point(mesh, b, in_b, faces[i].second);
    if (m && (!best || m->first > best->first)) best = std::move(m);
  }
  return best ? best->second : in_b;
}

std::vector<std::optional<PointQ3>> block_points(const BshReference& r) {
  const Mesh mesh(r);
  const int n = static_cast<int>(r.block_patches.size());
  std::vector<std::optional<PointQ3>> points(n);
  for (int s = 0; s < n; ++s) {
    if (points[s] || r.block_patches[s].empty() || !mesh.closed(s)) continue;
    points[s] = seed_point(mesh, r, s);
    if (!points[s]) continue;
    std::deque<int> queue{s};
    while (!queue.empty()) {
      const int a = queue.front();
      queue.pop_front();
      for (int p : r.block_patches[a]) {
        const int b = r.patch_blocks[p][0] == a ? r.patch_blocks[p][1] : r.patch_blocks[p][0];
        if (points[b]) continue;
        points[b] = point_across(mesh, a, *points[a], p);
        if (points[b]) queue.push_back(b);
      }
    }
  }
  for (int b = 0; b < n; ++b)
    if (points[b]) points[b] = deepen(mesh, r, b, *points[b]);
  return points;
}

Measure face_area(const BshReference& r, int f) {
  const auto& v = r.faces[f];
  const PointQ3 n = triangle_normal(r.vertices[v[0]], r.vertices[v[1]], r.vertices[v[2]]);
  return Measure::sqrt_of(dot3(n, n)) * Rational(1, 2);
}

BshAreaFigure figure(Measure m) {
  BshAreaFigure out;
  out.decimal = m.decimal_string(9);
  out.exact = std::move(m);
  return out;
}

void compare_areas(const BshReference& r, BshReferenceComparison& c) {
  std::map<std::array<int, 2>, int> pair_count;
  for (const auto& pb : r.patch_blocks) ++pair_count[pb];
  Measure area, charged;
  for (std::size_t p = 0; p < r.patch_faces.size(); ++p) {
    const auto& pb = r.patch_blocks[p];
    if ((r.block_labels[pb[0]] == 0) == (r.block_labels[pb[1]] == 0)) continue;
    ++c.their_boundary_patches;
    Measure patch;
    for (int f : r.patch_faces[p]) patch += face_area(r, f);
    charged += patch * Rational(pair_count[pb]);
    area += patch;
  }
  for (const auto& [pair, k] : pair_count) {
    if (k < 2) continue;
    c.multi_patch_pairs.push_back({pair[0], pair[1], k});
    if ((r.block_labels[pair[0]] == 0) != (r.block_labels[pair[1]] == 0)) ++c.charged_multi_patch_pairs;
  }
  c.their_area = figure(area);
  c.their_charged = figure(charged);
}

/// Our boundary area under a labelling of our cells (1 = inside).
Measure our_boundary_area(const Complex& complex, const std::vector<char>& inside) {
  std::vector<int> boundary;
  for (std::size_t p = 0; p < complex.patches.size(); ++p) {
    const auto& patch = complex.patches[p];
    const bool in = patch.inside_cell >= 0 && inside[patch.inside_cell];
    const bool out = patch.outside_cell >= 0 && inside[patch.outside_cell];
    if (in != out) boundary.push_back(static_cast<int>(p));
  }
  return complex.measure_of(boundary);
}

void map_blocks(const BshReference& r, const Arranged3& arranged, BshReferenceComparison& c) {
  const auto points = block_points(r);
  const int cells = static_cast<int>(arranged.complex.cells.size());
  std::vector<std::vector<int>> blocks_of_cell(cells);
  c.mapped_labels.assign(cells, -1);
  for (std::size_t b = 0; b < points.size(); ++b) {
    BshBlockMapping m;
    m.point = points[b];
    m.label = r.block_labels[b];
    if (!m.point) {
      ++c.blocks_without_point;
    } else {
      const PointLocation3 at = arranged.arrangement.locate(*m.point);
      if (at.kind == PointLocation3::Cell) {
        m.cell = at.index;
        blocks_of_cell[at.index].push_back(static_cast<int>(b));
        int& label = c.mapped_labels[at.index];
        const int solid = m.label == 0 ? 1 : 0;
        label = label == -1 ? solid : (label == solid ? label : -2);
      } else {
        ++c.blocks_on_our_boundary;
      }
    }
    c.blocks.push_back(m);
  }
  for (int cell = 0; cell < cells; ++cell) {
    if (blocks_of_cell[cell].size() > 1) {
      std::vector<int> row{cell};
      row.insert(row.end(), blocks_of_cell[cell].begin(), blocks_of_cell[cell].end());
      c.shared_cells.push_back(row);
    }
    if (c.mapped_labels[cell] == -1) ++c.unmapped_cells;
    if (c.mapped_labels[cell] == -2) ++c.conflicting_cells;
  }
}

int our_multi_patch_pairs(const Complex& complex) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& p : complex.patches)
    ++count[{std::min(p.inside_cell, p.outside_cell), std::max(p.inside_cell, p.outside_cell)}];
  return static_cast<int>(std::count_if(count.begin(), count.end(), [](const auto& e) { return e.second > 1; }));
}

}  // namespace

BshReferenceComparison compare_bsh_reference(const BshReference& reference, const Arranged3& arranged,
                                             const std::vector<char>& ours) {
  const Complex& complex = arranged.complex;
  if (!ours.empty() && ours.size() != complex.cells.size())
    throw InputError("our labelling has " + std::to_string(ours.size()) + " cells, the complex " +
                     std::to_string(complex.cells.size()));
  BshReferenceComparison c;
  c.their_patches = static_cast<int>(reference.patch_faces.size());
  c.their_blocks = static_cast<int>(reference.block_patches.size());
  c.their_empty_blocks = static_cast<int>(std::count_if(reference.block_patches.begin(), reference.block_patches.end(),
                                                       [](const auto& b) { return b.empty(); }));
  c.their_zero_area_faces = static_cast<int>(std::count(reference.zero_area.begin(), reference.zero_area.end(), 1));
  c.their_solid_blocks =
      static_cast<int>(std::count(reference.block_labels.begin(), reference.block_labels.end(), 0));
  c.our_patches = static_cast<int>(complex.patches.size());
  c.our_cells = static_cast<int>(complex.cells.size());
  c.our_multi_patch_pairs = our_multi_patch_pairs(complex);
  compare_areas(reference, c);
  map_blocks(reference, arranged, c);
  if (c.unmapped_cells == 0 && c.conflicting_cells == 0) {
    std::vector<char> mapped(c.mapped_labels.begin(), c.mapped_labels.end());
    c.our_area_mapped = figure(our_boundary_area(complex, mapped));
  }
  if (!ours.empty()) {
    int agree = 0, differ = 0;
    for (std::size_t cell = 0; cell < ours.size(); ++cell) {
      if (c.mapped_labels[cell] < 0) continue;
      (c.mapped_labels[cell] == (ours[cell] ? 1 : 0) ? agree : differ) += 1;
    }
    c.agreeing_cells = agree;
    c.differing_cells = differ;
    c.our_area = figure(our_boundary_area(complex, ours));
  }
  return c;
}

namespace {

nlohmann::json area_json(const BshAreaFigure& a) {
  const auto d = a.exact.decimal(12);
  return {{"decimal", d.digits}, {"certified", d.certified}};
}

}  // namespace

nlohmann::json bsh_reference_to_json(const BshReferenceComparison& c, const std::string& name) {
  nlohmann::json j;
  j["format"] = "hsx-bsh-reference/1";
  j["example"] = name;
  j["theirs"] = {{"patches", c.their_patches},
                 {"blocks", c.their_blocks},
                 {"solid_blocks", c.their_solid_blocks},
                 {"empty_blocks", c.their_empty_blocks},
                 {"zero_area_faces", c.their_zero_area_faces},
                 {"boundary_patches", c.their_boundary_patches},
                 {"boundary_area", area_json(c.their_area)},
                 {"graph_cut_cost", area_json(c.their_charged)},
                 {"multi_patch_pairs", c.multi_patch_pairs.size()},
                 {"multi_patch_pairs_on_boundary", c.charged_multi_patch_pairs}};
  j["ours"] = {{"patches", c.our_patches}, {"cells", c.our_cells}, {"multi_patch_pairs", c.our_multi_patch_pairs}};
  nlohmann::json blocks = nlohmann::json::array();
  for (const auto& b : c.blocks) {
    nlohmann::json e = {{"label", b.label}, {"cell", b.cell}};
    if (b.point) e["point"] = {exact_string(b.point->x), exact_string(b.point->y), exact_string(b.point->z)};
    blocks.push_back(e);
  }
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& p : c.multi_patch_pairs) pairs.push_back({p[0], p[1], p[2]});
  j["mapping"] = {{"blocks", blocks},
                  {"blocks_without_point", c.blocks_without_point},
                  {"blocks_on_our_boundary", c.blocks_on_our_boundary},
                  {"shared_cells", c.shared_cells},
                  {"cell_labels", c.mapped_labels},
                  {"unmapped_cells", c.unmapped_cells},
                  {"conflicting_cells", c.conflicting_cells}};
  j["theirs"]["multi_patch_pair_list"] = pairs;
  if (c.our_area_mapped) j["mapping"]["boundary_area"] = area_json(*c.our_area_mapped);
  if (c.agreeing_cells) {
    j["agreement"] = {{"agreeing_cells", *c.agreeing_cells},
                      {"differing_cells", *c.differing_cells},
                      {"our_boundary_area", area_json(*c.our_area)}};
  }
  return j;
}

std::string bsh_reference_table(const BshReferenceComparison& c, const std::string& name) {
  std::ostringstream s;
  auto row = [&s](const std::string& what, const std::string& theirs, const std::string& ours) {
    s << "  " << what << std::string(what.size() < 34 ? 34 - what.size() : 1, ' ') << theirs
      << std::string(theirs.size() < 16 ? 16 - theirs.size() : 1, ' ') << ours << "\n";
  };
  s << name << "\n";
  row("", "theirs", "ours");
  row("patches", std::to_string(c.their_patches), std::to_string(c.our_patches));
  row("cells (blocks)", std::to_string(c.their_blocks), std::to_string(c.our_cells));
  row("  of them with no patch", std::to_string(c.their_empty_blocks), "");
  row("zero-area faces", std::to_string(c.their_zero_area_faces), "");
  row("cell pairs sharing >= 2 patches", std::to_string(c.multi_patch_pairs.size()),
      std::to_string(c.our_multi_patch_pairs));
  row("  of them on their boundary", std::to_string(c.charged_multi_patch_pairs), "");
  row("their solid: blocks / boundary patches",
      std::to_string(c.their_solid_blocks) + " / " + std::to_string(c.their_boundary_patches), "");
  row("their solid: boundary area", c.their_area.decimal,
      c.our_area_mapped ? c.our_area_mapped->decimal : std::string("(not all cells mapped)"));
  row("their graph cut's cost of it", c.their_charged.decimal, "");
  s << "  blocks mapped by interior points: " << (c.their_blocks - c.blocks_without_point - c.blocks_on_our_boundary)
    << " of " << c.their_blocks << " (no point found: " << c.blocks_without_point
    << ", on our boundary: " << c.blocks_on_our_boundary << ")\n";
  s << "  our cells: unmapped " << c.unmapped_cells << ", conflicting labels " << c.conflicting_cells
    << ", holding several of their blocks " << c.shared_cells.size() << "\n";
  for (const auto& row_cells : c.shared_cells) {
    s << "    our cell " << row_cells[0] << ": their blocks";
    for (std::size_t i = 1; i < row_cells.size(); ++i) s << " " << row_cells[i];
    s << "\n";
  }
  if (c.agreeing_cells) {
    s << "  our labelling against theirs (mapped cells): " << *c.agreeing_cells << " agree, " << *c.differing_cells
      << " differ; our boundary area " << c.our_area->decimal << "\n";
  }
  return s.str();
}

}  // namespace hsx
