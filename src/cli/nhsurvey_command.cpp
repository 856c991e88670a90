// hsx nhsurvey: NH-Rep Boolean trees with natural halfspaces over many 2D solids (issue 5, cross-check 2).
//
// Every solid goes through the 2D pipeline: boundary_from_arrangement2 -> build_patch_graph -> build_tree ->
// check_tree -> evaluate_tree (algorithms/nhrep/evaluate.hpp), and is classified as "tree correct", "describable but
// the tree fails" (NH-Rep needs its extended surfaces, Appendix B) or "not describable by its patches' halfspaces".
//
// Sources:
// - `--random N --seed S`: N random solids from a deterministic generator (std::mt19937_64, whose output sequence
//   the C++ standard fixes, and our own integer mapping; no std distributions). Solid i uses the generator seeded
//   with splitmix64(S + i), so one solid can be reproduced alone. Even i: a random CSG expression over 2-4
//   primitives (disks, axis boxes and triangles as intersections of half-planes, lone half-planes), combined
//   pairwise at random by union, intersection and difference; odd i: a random set of inner cells of the
//   arrangement of 2-4 primitives' halfspaces (each cell in with probability 1/2). Coordinates are multiples of 1/2
//   in [-4, 4], radii in {1/2, ..., 3}. An empty or unbounded draw is redrawn (at most 50 times).
//   `--random-mode csg|cells|mixed` picks the kinds, `--random-polygons` makes boxes and triangles polygon
//   halfspaces (one patch per polygon, see evaluate.hpp) instead of half-planes.
// - `SCENE...` (files or directories of hsx-scene/1 files; other JSON files in a directory are skipped): the BSH
//   shape extracted as `hsx extract` does, by each method of `--methods` (graphcut, best-first; best-first stops
//   after `--max-states` expanded states, and then uses its best shape so far).
// - `--csgnet FILE [--from K] [--limit N]`: CSGNet programs, as `hsx corpus csgnet` reads them (malformed lines are
//   skipped and counted; a missing file is reported as skipped).
//
// Whole-plane evaluation: a cell-based check only sees sign vectors that some cell has. Each solid is therefore
// moved to the arrangement of its scene (samples dropped) in a domain that contains the scene's own domain and
// the domain hsx would choose (choose_domain: every vertex of the arrangement strictly inside), where every sign
// vector of the plane is some cell's. BSH shapes are carried over by exact point location of cell witnesses.
//
// Output: a table per source (counts and rates), then the first `--keep-count` "describable but fails" examples of
// each source; with `--keep DIR` each is written as DIR/<name>.json (the scene used, its description the note)
// and DIR/<name>.csg (the solid as {"description", "csg"}, readable by --csg): the source's own expression, or
// for BSH shapes and cell sets BHC's verified tree (falling back to the union of the solid's canonical terms over
// its natural halfspaces). The table also counts, per source, the describable-but-fails solids with a hole, and
// (for scenes with their own domain) the verdicts that change when evaluated on that domain instead.
// Exit status: 0 when every structural check holds (check_tree, the evaluation's consistency, no pipeline error),
// 3 when one fails, 2 for bad input. Output is deterministic; `--timings` adds seconds.
#include <hsx/algorithms/bsh/extract.hpp>
#include <hsx/algorithms/csg/bhc.hpp>
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/algorithms/nhrep/evaluate.hpp>
#include "cli/commands.hpp"
#include <hsx/complex/carry_solid2.hpp>
#include <hsx/complex/boundary_from_arrangement2.hpp>
#include <hsx/io/csgnet.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/files.hpp>
#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>

namespace hsx::cli {
namespace {

constexpr int kCheckFailed = 3;
constexpr int kMaxRedraws = 50;

std::size_t at(int i) { return static_cast<std::size_t>(i); }

struct SurveyOptions {
  long random = 0;
  std::uint64_t seed = 1;
  std::string random_mode = "mixed";
  bool random_polygons = false;
  std::vector<std::string> scenes;
  std::string methods = "graphcut,best-first";
  long max_states = 20000;
  std::string csgnet;
  long from = 1;
  long limit = 0;
  std::string keep_dir;
  int keep_count = 3;
  bool timings = false;
  bool verbose = false;
  bool nest_holes = false;
};

// ---- deterministic random numbers ---------------------------------------------------------------------------------

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi], by rejection (no modulo bias); portable.
  long in(long lo, long hi) {
    const std::uint64_t n = static_cast<std::uint64_t>(hi - lo) + 1;
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t x;
    do x = engine_(); while (x >= limit);
    return lo + static_cast<long>(x % n);
  }
  Rational half(long lo, long hi) { return Rational(in(lo, hi)) / 2; }

 private:
  std::mt19937_64 engine_;
};

// ---- random primitives ----------------------------------------------------------------------------------------------

Halfspace2 make_halfplane(const std::string& name, const PointQ2& normal, const PointQ2& through) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = normal;
  h.offset = normal.x * through.x + normal.y * through.y;
  return h;
}

Halfspace2 make_polygon(const std::string& name, std::vector<PointQ2> vertices) {
  Halfspace2 h;
  h.name = name;
  h.kind = HalfspaceKind2::Polygon;
  h.vertices = std::move(vertices);
  return h;
}

/// Appends a random primitive's halfspaces to `scene` and returns its expression (the intersection of them).
csg::ExprPtr random_primitive(Rng& rng, int k, bool polygons, Scene2& scene) {
  const std::string id = std::to_string(k);
  auto add = [&](Halfspace2 h) {
    scene.halfspaces.push_back(std::move(h));
    return csg::leaf(static_cast<int>(scene.halfspaces.size()) - 1);
  };
  const long kind = rng.in(0, 9);
  if (kind <= 3) {  // disk
    Halfspace2 h;
    h.name = "c" + id;
    h.kind = HalfspaceKind2::Disk;
    h.center = PointQ2{rng.half(-6, 6), rng.half(-6, 6)};
    h.radius = rng.half(1, 6);
    return add(h);
  }
  if (kind <= 5) {  // axis box
    const Rational x0 = rng.half(-8, 6), y0 = rng.half(-8, 6);
    const Rational x1 = x0 + rng.half(1, 6), y1 = y0 + rng.half(1, 6);
    if (polygons) return add(make_polygon("s" + id, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}));
    return csg::intersect({add(make_halfplane("s" + id + ".xmin", {Rational(-1), Rational(0)}, {x0, y0})),
                           add(make_halfplane("s" + id + ".xmax", {Rational(1), Rational(0)}, {x1, y1})),
                           add(make_halfplane("s" + id + ".ymin", {Rational(0), Rational(-1)}, {x0, y0})),
                           add(make_halfplane("s" + id + ".ymax", {Rational(0), Rational(1)}, {x1, y1}))});
  }
  if (kind <= 7) {  // triangle
    std::vector<PointQ2> v;
    Rational area2;
    do {
      v = {{rng.half(-8, 8), rng.half(-8, 8)}, {rng.half(-8, 8), rng.half(-8, 8)}, {rng.half(-8, 8), rng.half(-8, 8)}};
      area2 = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    } while (area2 == 0);
    if (area2 < 0) std::swap(v[1], v[2]);  // counter-clockwise
    if (polygons) return add(make_polygon("t" + id, v));
    std::vector<csg::ExprPtr> sides;
    for (int i = 0; i < 3; ++i) {
      const PointQ2& p = v[at(i)];
      const PointQ2& q = v[at((i + 1) % 3)];
      sides.push_back(add(make_halfplane("t" + id + "." + std::to_string(i), {q.y - p.y, p.x - q.x}, p)));
    }
    return csg::intersect(sides);
  }
  // a lone half-plane: one of the 16 primitive directions of max-norm <= 2, through a grid point
  static const int kDirections[16][2] = {{1, 0},   {2, 1},   {1, 1},  {1, 2},  {0, 1},   {-1, 2},
                                         {-1, 1},  {-2, 1},  {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2},
                                         {0, -1},  {1, -2},  {1, -1}, {2, -1}};
  const long d = rng.in(0, 15);
  return add(make_halfplane("h" + id, {Rational(kDirections[d][0]), Rational(kDirections[d][1])},
                            {rng.half(-6, 6), rng.half(-6, 6)}));
}

// ---- one solid through the pipeline -------------------------------------------------------------------------------

/// A solid ready for the pipeline: the whole-plane scene (no samples), its arrangement, the solid's cells.
struct Case {
  std::string name;           ///< unique within the run, used for kept files
  std::string origin;         ///< where it came from, for the note
  Scene2 scene;
  Arranged2 arranged;
  std::vector<char> solid;
  csg::ExprPtr expression;    ///< the source's own expression, when there is one
  /// The same solid on the arrangement of the scene's own domain, when that differs (BSH scenes, CSGNet): the
  /// survey also evaluates there and counts verdicts that change.
  std::optional<Arranged2> own_arranged;
  std::vector<char> own_solid;
};

enum class Status { Done, Empty, Unbounded };

Status check_solid(const Case& c) {
  bool any = false;
  for (std::size_t k = 0; k < c.solid.size(); ++k) {
    if (!c.solid[k]) continue;
    if (c.arranged.complex.cells[k].outer) return Status::Unbounded;
    any = true;
  }
  return any ? Status::Done : Status::Empty;
}

/// Holes of the solid: connected components of non-solid cells (adjacent across a patch) with no outer cell.
int count_holes(const Complex& complex, const std::vector<char>& solid) {
  std::vector<std::vector<int>> adjacent(complex.cells.size());
  for (const Patch& p : complex.patches) {
    adjacent[at(p.inside_cell)].push_back(p.outside_cell);
    adjacent[at(p.outside_cell)].push_back(p.inside_cell);
  }
  std::vector<char> seen(complex.cells.size(), 0);
  int holes = 0;
  for (std::size_t start = 0; start < complex.cells.size(); ++start) {
    if (solid[start] || seen[start]) continue;
    bool outer = false;
    std::vector<int> stack{static_cast<int>(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      outer = outer || complex.cells[at(k)].outer;
      for (int n : adjacent[at(k)])
        if (!solid[at(n)] && !seen[at(n)]) {
          seen[at(n)] = 1;
          stack.push_back(n);
        }
    }
    if (!outer) ++holes;
  }
  return holes;
}

struct Outcome {
  std::vector<std::string> problems;  ///< violated structural checks and pipeline errors
  bool evaluated = false;
  nhrep::BuildResult built;
  nhrep::Evaluation eval;
};

Outcome run_pipeline(const Arranged2& arranged, const std::vector<char>& solid, bool nest_holes) {
  Outcome o;
  try {
    nhrep::BuildOptions options;
    options.nest_holes = nest_holes;
    o.built = nhrep::build_tree(nhrep::build_patch_graph(boundary_from_arrangement2(arranged, solid)), options);
    for (const std::string& p : nhrep::check_tree(o.built)) o.problems.push_back("check_tree: " + p);
    o.eval = nhrep::evaluate_tree(o.built, arranged.complex, solid);
    o.evaluated = true;
    for (const std::string& p : o.eval.violations) o.problems.push_back("evaluation: " + p);
    if (!o.eval.describable && o.eval.correct) o.problems.push_back("evaluation: correct but not describable");
  } catch (const std::exception& e) {
    o.problems.push_back(std::string("error: ") + e.what());
  }
  return o;
}

// ---- tallies and kept examples ------------------------------------------------------------------------------------

struct Tally {
  explicit Tally(std::string name) : source(std::move(name)) {}
  std::string source;
  long solids = 0;          ///< evaluated (or failed) solids
  long empty = 0, unbounded = 0, malformed = 0;
  long check_failures = 0;  ///< solids with a violated structural check or a pipeline error
  long decomposed = 0, decompositions = 0;
  long correct = 0, describable_fails = 0, not_describable = 0;
  long fails_with_holes = 0;  ///< describable-but-fails solids that have a hole
  long own_domain_runs = 0, own_domain_differs = 0;  ///< verdict on the scene's own (smaller) domain differs
  long patches = 0, cells = 0;
  double seconds = 0;
  std::vector<std::string> examples;  ///< names of the kept "describable but fails" solids
  std::string note;                   ///< e.g. "skipped: corpus not present"
};

std::string tree_with_names(const nhrep::Tree& tree, int node, const std::vector<nhrep::NaturalHalfspace>& leaves,
                            const std::vector<std::string>& names) {
  const nhrep::TreeNode& n = tree.nodes.at(at(node));
  std::string s = std::string(nhrep::op_name(n.op)) + "(";
  const char* sep = "";
  for (int p : n.leaves) {
    const nhrep::NaturalHalfspace& h = leaves.at(at(p));
    s += sep;
    s += (h.complemented ? "~" : "") + (h.halfspace >= 0 ? names.at(at(h.halfspace)) : std::string("?")) + "#" +
         std::to_string(p);
    sep = ", ";
  }
  for (int ch : n.children) {
    s += sep + tree_with_names(tree, ch, leaves, names);
    sep = ", ";
  }
  return s + ")";
}

/// The union of the solid's canonical terms over the natural halfspaces (the solid is describable by them).
csg::ExprPtr canonical_union(const Case& c, const nhrep::Evaluation& e) {
  std::vector<std::vector<char>> terms;
  for (std::size_t k = 0; k < c.solid.size(); ++k) {
    if (!c.solid[k]) continue;
    std::vector<char> signs;
    for (int h : e.natural_halfspaces) signs.push_back(c.arranged.complex.cells[k].inside.at(at(h)));
    if (std::find(terms.begin(), terms.end(), signs) == terms.end()) terms.push_back(signs);
  }
  std::vector<csg::ExprPtr> parts;
  for (const auto& signs : terms) {
    std::vector<csg::ExprPtr> literals;
    for (std::size_t i = 0; i < signs.size(); ++i) {
      csg::ExprPtr l = csg::leaf(e.natural_halfspaces[i]);
      literals.push_back(signs[i] ? l : csg::complement(l));
    }
    parts.push_back(literals.size() == 1 ? literals.front() : csg::intersect(literals));
  }
  return parts.size() == 1 ? parts.front() : csg::unite(parts);
}

std::string cell_list(const Complex& complex, const std::vector<int>& cells, std::size_t max = 6) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < max; ++i) {
    const auto& w = complex.cells.at(at(cells[i])).witness;
    s += (i ? ", " : "") + std::to_string(cells[i]) + " at (" + decimal_string(w[0], 6) + ", " +
         decimal_string(w[1], 6) + ")";
  }
  if (cells.size() > max) s += ", ...";
  return s;
}

std::string example_note(const Case& c, const Outcome& o) {
  const auto& names = c.arranged.complex.halfspace_names;
  std::ostringstream note;
  note << "NH-Rep natural-halfspace counterexample (hsx nhsurvey, " << c.origin << "). The solid is describable by "
       << "its " << o.eval.natural_halfspaces.size() << " patches' natural halfspaces {";
  for (std::size_t i = 0; i < o.eval.natural_halfspaces.size(); ++i)
    note << (i ? ", " : "") << names.at(at(o.eval.natural_halfspaces[i]));
  note << "}, but Algorithm 1's tree with those halfspaces at its leaves, "
       << tree_with_names(o.built.tree, o.built.tree.root, o.eval.leaf_halfspace, names) << ", is wrong on "
       << o.eval.wrong_inside.size() + o.eval.wrong_outside.size() << " cells";
  if (!o.eval.wrong_inside.empty()) note << "; it misses solid cells " << cell_list(c.arranged.complex, o.eval.wrong_inside);
  if (!o.eval.wrong_outside.empty()) note << "; it adds cells " << cell_list(c.arranged.complex, o.eval.wrong_outside);
  note << ". NH-Rep needs extended surfaces here (Appendix B).";
  const int holes = count_holes(c.arranged.complex, c.solid);
  if (holes > 0)
    note << " The solid has " << holes << " hole(s): Algorithm 1's min root over the boundary loops cannot leave a "
         << "hole out with natural halfspaces.";
  else
    note << " The solid has no hole: a natural halfspace, extended past its patch, reaches cells it must not.";
  if (!o.built.decompositions.empty()) note << " The tree used " << o.built.decompositions.size() << " patch decomposition(s).";
  return note.str();
}

void keep_example(const SurveyOptions& opt, const Case& c, const Outcome& o) {
  if (opt.keep_dir.empty()) return;
  const std::string note = example_note(c, o);
  csg::ExprPtr expr = c.expression;
  if (!expr) {
    const csg::BhcResult bhc = csg::bhc(c.arranged.complex, c.solid);
    expr = bhc.describable && bhc.verified ? bhc.tree : canonical_union(c, o.eval);
  }
  if (csg::evaluate(*expr, c.arranged.complex) != c.solid)
    throw std::logic_error(c.name + ": the kept expression is not the solid");
  Scene2 scene = c.scene;
  scene.description = note;
  std::filesystem::create_directories(opt.keep_dir);
  const std::string base = (std::filesystem::path(opt.keep_dir) / c.name).string();
  write_file_atomically(base + ".json", write_scene2(scene).dump(2) + "\n");
  const nlohmann::json doc{{"description", "the solid of " + c.name + ".json (" + c.origin + ")"},
                           {"csg", csg::to_text(*expr, c.arranged.complex.halfspace_names)}};
  write_file_atomically(base + ".csg", doc.dump(2) + "\n");
}

class Survey {
 public:
  explicit Survey(const SurveyOptions& o) : opt_(o) {}

  /// Runs one solid of `tally`'s source.
  void add(Tally& tally, const Case& c) {
    switch (check_solid(c)) {
      case Status::Empty: ++tally.empty; return;
      case Status::Unbounded: ++tally.unbounded; return;
      case Status::Done: break;
    }
    ++tally.solids;
    const Outcome o = run_pipeline(c.arranged, c.solid, opt_.nest_holes);
    std::optional<Outcome> own;
    if (c.own_arranged) own = run_pipeline(*c.own_arranged, c.own_solid, opt_.nest_holes);
    std::vector<std::string> problems = o.problems;
    if (own)
      for (const std::string& p : own->problems) problems.push_back("on the scene's own domain: " + p);
    if (!problems.empty()) {
      ++tally.check_failures;
      ++failures_;
      std::cout << "CHECK FAILED " << c.name << " (" << c.origin << "):\n";
      for (std::size_t i = 0; i < problems.size() && i < 5; ++i) std::cout << "  " << problems[i] << "\n";
    }
    if (!o.evaluated) return;
    if (own && own->evaluated) {
      ++tally.own_domain_runs;
      if (own->eval.verdict != o.eval.verdict) {
        ++tally.own_domain_differs;
        if (opt_.verbose)
          std::cout << c.name << ": on the scene's own domain: " << nhrep::verdict_name(own->eval.verdict) << "\n";
      }
    }
    tally.patches += static_cast<long>(o.built.graph.live_patches().size());
    tally.cells += static_cast<long>(c.arranged.complex.cells.size());
    if (!o.built.decompositions.empty()) ++tally.decomposed;
    tally.decompositions += static_cast<long>(o.built.decompositions.size());
    switch (o.eval.verdict) {
      case nhrep::Verdict::TreeCorrect: ++tally.correct; break;
      case nhrep::Verdict::DescribableButFails:
        ++tally.describable_fails;
        if (count_holes(c.arranged.complex, c.solid) > 0) ++tally.fails_with_holes;
        break;
      case nhrep::Verdict::NotDescribable: ++tally.not_describable; break;
    }
    if (opt_.verbose)
      std::cout << c.name << ": " << nhrep::verdict_name(o.eval.verdict) << "; " << o.built.graph.live_patches().size()
                << " patches, " << o.built.decompositions.size() << " decompositions, "
                << o.eval.wrong_inside.size() + o.eval.wrong_outside.size() << " of "
                << c.arranged.complex.cells.size() << " cells wrong\n";
    if (o.eval.verdict == nhrep::Verdict::DescribableButFails &&
        static_cast<int>(tally.examples.size()) < opt_.keep_count) {
      tally.examples.push_back(c.name + " (" + c.origin + ")");
      keep_example(opt_, c, o);
    }
  }

  long failures() const { return failures_; }

 private:
  const SurveyOptions& opt_;
  long failures_ = 0;
};

// ---- sources --------------------------------------------------------------------------------------------------------

/// Random solid `index`: see the header comment.
Case random_case(const SurveyOptions& o, long index, bool cells, int* redraws) {
  Rng rng(splitmix64(o.seed + static_cast<std::uint64_t>(index)));
  for (int attempt = 0;; ++attempt) {
    Case c;
    c.name = std::string(cells ? "random-cells-" : "random-csg-") + std::to_string(index);
    c.origin = "random solid " + std::to_string(index) + " of --seed " + std::to_string(o.seed) + ", " +
               (cells ? "a random set of cells" : "a random CSG expression") +
               (o.random_polygons ? ", --random-polygons" : "") +
               (attempt ? ", draw " + std::to_string(attempt + 1) : "");
    Scene2 scene;
    const int primitives = static_cast<int>(rng.in(2, 4));
    std::vector<csg::ExprPtr> parts;
    for (int k = 0; k < primitives; ++k) parts.push_back(random_primitive(rng, k, o.random_polygons, scene));
    scene.description = c.origin;
    validate_and_resolve(scene);  // chooses the domain: every vertex strictly inside
    c.scene = scene;
    c.arranged = arrange(scene);
    const Complex& complex = c.arranged.complex;
    if (cells) {
      c.solid.assign(complex.cells.size(), 0);
      for (std::size_t k = 0; k < complex.cells.size(); ++k)
        c.solid[k] = complex.cells[k].outer ? 0 : static_cast<char>(rng.in(0, 1));
    } else {
      while (parts.size() > 1) {  // combine two random parts until one is left
        const std::size_t i = static_cast<std::size_t>(rng.in(0, static_cast<long>(parts.size()) - 1));
        csg::ExprPtr a = parts[i];
        parts.erase(parts.begin() + static_cast<long>(i));
        const std::size_t j = static_cast<std::size_t>(rng.in(0, static_cast<long>(parts.size()) - 1));
        csg::ExprPtr b = parts[j];
        switch (rng.in(0, 3)) {
          case 0: parts[j] = csg::unite({a, b}); break;
          case 1: parts[j] = csg::intersect({a, b}); break;
          case 2: parts[j] = csg::difference(a, b); break;
          default: parts[j] = csg::difference(b, a); break;
        }
      }
      c.expression = parts.front();
      c.solid = csg::evaluate(*c.expression, complex);
    }
    if (check_solid(c) == Status::Done || attempt + 1 >= kMaxRedraws) {
      *redraws += attempt;
      return c;
    }
  }
}

bool is_scene_file(const std::filesystem::path& path) {
  try {
    const nlohmann::json doc = read_exact_json_file(path.string());
    return doc.is_object() && doc.contains("format") && doc.at("format") == "hsx-scene/1";
  } catch (const InputError&) {
    return false;
  }
}

/// Scene files from the arguments: files as given (they must be scenes), directories' *.json scenes, sorted.
std::vector<std::string> scene_files(const std::vector<std::string>& args, long* skipped) {
  std::vector<std::string> files;
  for (const std::string& arg : args) {
    const std::filesystem::path path(arg);
    if (std::filesystem::is_directory(path)) {
      std::vector<std::string> here;
      for (const auto& entry : std::filesystem::directory_iterator(path))
        if (entry.path().extension() == ".json") {
          if (is_scene_file(entry.path()))
            here.push_back(entry.path().string());
          else
            ++*skipped;
        }
      std::sort(here.begin(), here.end());
      files.insert(files.end(), here.begin(), here.end());
    } else if (std::filesystem::is_regular_file(path)) {
      files.push_back(arg);
    } else {
      throw InputError(arg + ": no such file or directory");
    }
  }
  return files;
}

std::string file_stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

std::string percent(long part, long whole) {
  if (whole == 0) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << 100.0 * static_cast<double>(part) / static_cast<double>(whole) << "%";
  return s.str();
}

void print_table(const std::vector<Tally>& tallies, bool timings) {
  std::ostringstream out;
  auto cell = [&](long n, long whole) { return std::to_string(n) + " (" + percent(n, whole) + ")"; };
  out << std::left << std::setw(16) << "source" << std::right << std::setw(7) << "solids" << std::setw(8) << "skipped"
      << std::setw(11) << "check-fail" << std::setw(14) << "decomposed" << std::setw(15) << "tree correct"
      << std::setw(19) << "describable-fails" << std::setw(12) << "(holes)" << std::setw(16) << "not describable"
      << std::setw(13) << "own-domain";
  if (timings) out << std::setw(9) << "seconds";
  out << "\n";
  for (const Tally& t : tallies) {
    out << std::left << std::setw(16) << t.source << std::right;
    if (!t.note.empty()) {
      out << "  " << t.note << "\n";
      continue;
    }
    out << std::setw(7) << t.solids << std::setw(8) << t.empty + t.unbounded + t.malformed << std::setw(11)
        << t.check_failures << std::setw(14) << cell(t.decomposed, t.solids) << std::setw(15)
        << cell(t.correct, t.solids) << std::setw(19) << cell(t.describable_fails, t.solids) << std::setw(12)
        << t.fails_with_holes << std::setw(16) << cell(t.not_describable, t.solids) << std::setw(13)
        << (t.own_domain_runs ? std::to_string(t.own_domain_differs) + "/" + std::to_string(t.own_domain_runs)
                              : std::string("-"));
    if (timings) out << std::setw(9) << std::fixed << std::setprecision(2) << t.seconds;
    out << "\n";
  }
  out << "skipped: empty or unbounded solids and malformed programs; decomposed: trees that needed a patch "
         "decomposition;\n(holes): describable-fails solids with a hole; own-domain: verdicts that change when "
         "evaluated on the scene's own domain instead of the whole plane\n";
  for (const Tally& t : tallies) {
    if (!t.note.empty()) continue;
    out << t.source << ": " << t.patches << " patches, " << t.cells << " cells, " << t.decompositions
        << " decompositions in all";
    if (t.empty + t.unbounded + t.malformed > 0)
      out << "; skipped " << t.empty << " empty, " << t.unbounded << " unbounded, " << t.malformed << " malformed";
    out << "\n";
    for (const std::string& e : t.examples) out << "  describable but fails: " << e << "\n";
  }
  std::cout << out.str();
}

int run_survey(const SurveyOptions& o) {
  if (o.random < 0) throw InputError("--random: must be >= 0");
  if (o.random_mode != "mixed" && o.random_mode != "csg" && o.random_mode != "cells")
    throw InputError("--random-mode: csg, cells or mixed, got \"" + o.random_mode + "\"");
  if (o.keep_count < 0) throw InputError("--keep-count: must be >= 0");
  if (o.max_states < 1) throw InputError("--max-states: must be at least 1");
  if (o.from < 1) throw InputError("--from: lines count from 1");
  if (o.limit < 0) throw InputError("--limit: must be >= 0");
  std::vector<bsh::Method> methods;
  {
    std::stringstream list(o.methods);
    std::string name;
    while (std::getline(list, name, ',')) {
      if (name == "graphcut") methods.push_back(bsh::Method::GraphCut);
      else if (name == "best-first") methods.push_back(bsh::Method::BestFirst);
      else throw InputError("--methods: graphcut and/or best-first, comma-separated, got \"" + name + "\"");
    }
  }
  if (o.random == 0 && o.scenes.empty() && o.csgnet.empty())
    throw InputError("nothing to survey: give --random N, SCENE files or directories, or --csgnet FILE");
  long skipped_files = 0;
  const std::vector<std::string> files = scene_files(o.scenes, &skipped_files);

  Survey survey(o);
  std::vector<Tally> tallies;
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };

  // (a) random solids
  if (o.random > 0) {
    Tally csg_tally{"random csg"}, cells_tally{"random cells"};
    int redraws = 0;
    double csg_seconds = 0, cells_seconds = 0;
    for (long i = 0; i < o.random; ++i) {
      const bool cells = o.random_mode == "cells" || (o.random_mode == "mixed" && i % 2 == 1);
      const auto start = Clock::now();
      const Case c = random_case(o, i, cells, &redraws);
      survey.add(cells ? cells_tally : csg_tally, c);
      (cells ? cells_seconds : csg_seconds) += seconds_since(start);
    }
    csg_tally.seconds = csg_seconds;
    cells_tally.seconds = cells_seconds;
    if (o.random_mode != "cells") tallies.push_back(csg_tally);
    if (o.random_mode != "csg") tallies.push_back(cells_tally);
    std::cout << "random: " << o.random << " solids from --seed " << o.seed << " (" << redraws
              << " empty or unbounded draws redrawn)\n";
  }

  // (b) BSH shapes of scene files
  if (!files.empty()) {
    for (bsh::Method method : methods) {
      Tally t{std::string("bsh ") + bsh::to_string(method)};
      const auto start = Clock::now();
      long unfinished = 0;
      for (const std::string& file : files) {
        const Scene2 original = read_scene_file(file);
        const Arranged2 arranged = arrange(original);
        const bsh::Problem problem(arranged.complex);
        bsh::ExtractOptions options;
        options.method = method;
        options.max_states = o.max_states;
        options.enumerate_ties = false;
        const bsh::ExtractResult r = bsh::extract(problem, options);
        if (!r.stopped_by.empty()) ++unfinished;
        Case c;
        c.name = std::string("bsh-") + bsh::to_string(method) + "-" + file_stem(file);
        c.origin = "the " + std::string(bsh::to_string(method)) + " BSH shape of " + file +
                   (r.stopped_by.empty() ? "" : " (search stopped by " + r.stopped_by + ")");
        c.scene = whole_plane_scene(original);
        c.arranged = arrange(c.scene);
        c.solid = carry_to_whole_plane(arranged, r.labelling, c.arranged);
        if (c.arranged.complex.cells.size() != arranged.complex.cells.size() || c.scene.domain.min != original.domain.min ||
            c.scene.domain.max != original.domain.max) {
          c.own_arranged = arranged;
          c.own_solid = r.labelling;
        }
        survey.add(t, c);
      }
      t.seconds = seconds_since(start);
      if (unfinished)
        std::cout << t.source << ": " << unfinished << " searches stopped at --max-states " << o.max_states
                  << " (their best shape so far is used)\n";
      tallies.push_back(t);
    }
    std::cout << "scenes: " << files.size() << " files";
    if (skipped_files) std::cout << " (" << skipped_files << " JSON files in the directories are not scenes, skipped)";
    std::cout << "\n";
  }

  // (c) CSGNet programs
  if (!o.csgnet.empty()) {
    Tally t{"csgnet"};
    std::ifstream in(o.csgnet);
    if (!in) {
      t.note = "skipped: corpus not present at " + o.csgnet;
    } else {
      const auto start = Clock::now();
      std::string line;
      long number = 0;
      while (std::getline(in, line)) {
        ++number;
        if (line.empty() || number < o.from) continue;
        if (o.limit > 0 && number >= o.from + o.limit) break;
        std::optional<CsgnetProgram> program;
        try {
          program = read_csgnet(line, "line " + std::to_string(number));
        } catch (const InputError&) {
          ++t.malformed;
          continue;
        }
        Case c;
        c.name = "csgnet-line-" + std::to_string(number);
        c.origin = "CSGNet " + o.csgnet + " line " + std::to_string(number) + ": " + line;
        c.scene = whole_plane_scene(program->scene);
        c.arranged = arrange(c.scene);
        c.expression = program->expression;
        c.solid = csg::evaluate(*c.expression, c.arranged.complex);
        c.own_arranged = arrange(program->scene);
        c.own_solid = csg::evaluate(*c.expression, c.own_arranged->complex);
        survey.add(t, c);
      }
      t.seconds = seconds_since(start);
    }
    tallies.push_back(t);
  }

  print_table(tallies, o.timings);
  if (!o.keep_dir.empty()) {
    long kept = 0;
    for (const Tally& t : tallies) kept += static_cast<long>(t.examples.size());
    std::cout << "kept " << kept << " example(s) in " << o.keep_dir << "\n";
  }
  if (survey.failures() > 0) {
    std::cout << "STRUCTURAL CHECKS FAILED on " << survey.failures() << " solid(s)\n";
    return kCheckFailed;
  }
  std::cout << "all structural checks hold\n";
  return 0;
}

}  // namespace

void add_nhsurvey_command(CLI::App& app) {
  auto o = std::make_shared<SurveyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "nhsurvey", "NH-Rep trees with natural halfspaces over many 2D solids (random, BSH scenes, CSGNet): how often "
                  "the tree is exactly the solid, and when not, whether the solid is describable; exit 3 when a "
                  "structural check fails");
  cmd->add_option("SCENE", o->scenes, "hsx-scene/1 files or directories of them (BSH shapes are extracted)");
  cmd->add_option("--random", o->random, "survey N random solids (default 0)");
  cmd->add_option("--seed", o->seed, "seed of the random solids (default 1)");
  cmd->add_option("--random-mode", o->random_mode, "csg, cells or mixed (default: even solids csg, odd cells)");
  cmd->add_flag("--random-polygons", o->random_polygons, "random boxes and triangles as polygon halfspaces");
  cmd->add_option("--methods", o->methods, "BSH methods for scenes: graphcut,best-first (default both)");
  cmd->add_option("--max-states", o->max_states, "best-first: stop after N expanded states (default 20000)");
  cmd->add_option("--csgnet", o->csgnet, "a CSGNet corpus file, one postfix program per line");
  cmd->add_option("--from", o->from, "CSGNet: start at this line (1-based, default 1)");
  cmd->add_option("--limit", o->limit, "CSGNet: at most N lines (default: all)");
  cmd->add_option("--keep", o->keep_dir, "write the kept 'describable but fails' examples to DIR (scene + .csg)");
  cmd->add_option("--keep-count", o->keep_count, "keep the first K examples of each source (default 3)");
  cmd->add_flag("--timings", o->timings, "add seconds per source to the table");
  cmd->add_flag("-v,--verbose", o->verbose, "one line per solid");
  cmd->add_flag("--nest-holes", o->nest_holes,
                "extension: holes' trees intersected with their part's tree (hsx nhtree --nest-holes)");
  run_with_status(cmd, o, &run_survey);
}

}  // namespace hsx::cli
