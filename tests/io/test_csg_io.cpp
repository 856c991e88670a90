// CSG text and JSON forms (io/csg_text.hpp), CSGNet programs (io/csgnet.hpp) and the OpenSCAD export
// (io/openscad.hpp).
//
// The CSGNet corpus test ("[corpus]") reads /work/shared/data/csgnet/best_st_expressions.txt (or the file named by
// the environment variable HSX_CSGNET_CORPUS). When the file is absent it does NOT pass silently: it emits
// WARN("... skipped: corpus not present") and returns without any assertion, which Catch2 reports as a test case
// with no assertions (visible with -w NoAssertions, which makes it fail).
#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/csg_text.hpp>
#include <hsx/geometry/tessellate3.hpp>
#include <hsx/io/csgnet.hpp>
#include <hsx/io/openscad.hpp>
#include <hsx/io/scene_json.hpp>

#include "support/random_expressions.hpp"

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

using namespace hsx;
using namespace hsx::csg;

namespace {

using hsx::test::random_expr;
using hsx::test::raw;

const std::vector<std::string> kNames = {"A", "B", "C", "D", "E"};

Rational R(long n, long d = 1) { return make_rational(Integer(n), Integer(d)); }

bool same_tree(const Expr& a, const Expr& b) {
  if (a.op != b.op || a.children.size() != b.children.size()) return false;
  if (a.op == Op::Halfspace && a.halfspace != b.halfspace) return false;
  for (std::size_t i = 0; i < a.children.size(); ++i)
    if (!same_tree(*a.children[i], *b.children[i])) return false;
  return true;
}

bool same_truth_table(const Expr& a, const Expr& b, int n) {
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    std::vector<char> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = (mask >> i) & 1u ? 1 : 0;
    if (evaluate(a, v) != evaluate(b, v)) return false;
  }
  return true;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

std::string parse_error(const std::string& text, const std::vector<std::string>& names = kNames) {
  return error_of([&] { parse_csg_text(text, names); });
}

std::string json_error(const std::string& text) {
  return error_of([&] { csg_from_json(parse_exact_json(text), kNames); });
}

std::string csgnet_error(const std::string& line) {
  return error_of([&] { read_csgnet(line, "line 7"); });
}

/// A fresh temporary directory, removed at scope exit.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("hsx_csg_test_" + std::to_string(std::rand()) + "_" + std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::string write(const std::string& name, const std::string& content) const {
    const auto p = path / name;
    std::ofstream(p) << content;
    return p.string();
  }
};

Measure solid_area(const Complex& c, const std::vector<char>& labels) {
  Measure total;
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    if (labels[k]) total += c.cells[k].measure;
  return total;
}

bool equal(const Measure& a, const Measure& b) { return compare(a, b) == Order::Equal; }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

std::vector<std::string> names_of(const Scene2& s) {
  std::vector<std::string> names;
  for (const auto& h : s.halfspaces) names.push_back(h.name);
  return names;
}

}  // namespace

// ---------------------------------------------------------------- text form

TEST_CASE("csg text: precedence ~ > & > - > |, left-associative difference", "[csg][io]") {
  auto p = [](const std::string& text) { return to_text(*parse_csg_text(text, kNames), kNames); };
  CHECK(p("(A & B) | ~C") == "A & B | ~C");
  CHECK(p("A | B & C") == "A | B & C");
  CHECK(same_tree(*parse_csg_text("A | B & C", kNames), *unite({leaf(0), intersect({leaf(1), leaf(2)})})));
  CHECK(same_tree(*parse_csg_text("A - B - C", kNames), *difference(difference(leaf(0), leaf(1)), leaf(2))));
  CHECK(same_tree(*parse_csg_text("A - (B - C)", kNames), *difference(leaf(0), difference(leaf(1), leaf(2)))));
  CHECK(same_tree(*parse_csg_text("A - B & C", kNames), *difference(leaf(0), intersect({leaf(1), leaf(2)}))));
  CHECK(same_tree(*parse_csg_text("A - B | C", kNames), *unite({difference(leaf(0), leaf(1)), leaf(2)})));
  CHECK(same_tree(*parse_csg_text("A | B - C", kNames), *unite({leaf(0), difference(leaf(1), leaf(2))})));
  CHECK(same_tree(*parse_csg_text("~A & B", kNames), *intersect({complement(leaf(0)), leaf(1)})));
  CHECK(same_tree(*parse_csg_text("~(A & B)", kNames), *complement(intersect({leaf(0), leaf(1)}))));
  CHECK(same_tree(*parse_csg_text("~~A", kNames), *leaf(0)));
  // Synonyms, blanks, constants and their simplification.
  CHECK(same_tree(*parse_csg_text(" A+B *C\n", kNames), *unite({leaf(0), intersect({leaf(1), leaf(2)})})));
  CHECK(parse_csg_text("empty", kNames)->op == Op::Empty);
  CHECK(parse_csg_text("full & A", kNames)->op == Op::Halfspace);
  CHECK(parse_csg_text("A | full", kNames)->op == Op::Full);
  CHECK(parse_csg_text("~empty", kNames)->op == Op::Full);
  // Quoted names and names with dots.
  const std::vector<std::string> odd = {"s1.x+", "empty", "a\"b\\c", "t2.0"};
  CHECK(same_tree(*parse_csg_text("\"s1.x+\" & \"empty\" & t2.0 | \"a\\\"b\\\\c\"", odd),
                  *unite({intersect({leaf(0), leaf(1), leaf(3)}), leaf(2)})));
  CHECK(parse_csg_text("empty", odd)->op == Op::Empty);  // the bare word is the constant
}

TEST_CASE("csg text round trip: parse(to_text(e)) has the same value on all sign vectors", "[csg][io][property]") {
  rc::prop("round trip", [] {
    const int n = *rc::gen::inRange(1, 6);
    const bool raw_nodes = *rc::gen::arbitrary<bool>();
    const ExprPtr e = random_expr(n, 4, raw_nodes);
    const std::vector<std::string> names(kNames.begin(), kNames.begin() + n);
    const std::string text = to_text(*e, names);
    const ExprPtr back = parse_csg_text(text, names);
    RC_ASSERT(same_truth_table(*e, *back, n));
    // A tree built by the constructors comes back node for node, and the text is a fixed point.
    if (!raw_nodes) RC_ASSERT(same_tree(*e, *back));
    RC_ASSERT(to_text(*back, names) == to_text(*parse_csg_text(to_text(*back, names), names), names));
  });
}

TEST_CASE("csg text errors name the column", "[csg][io]") {
  CHECK(parse_error("A & X") == "--csg: unknown halfspace \"X\" at column 5");
  CHECK(parse_error("(A | B") == "--csg: missing ')' for the '(' at column 1: found end of the expression at column 7");
  CHECK(parse_error("A | B)") == "--csg: unmatched ')' at column 6");
  CHECK(parse_error("A B") == "--csg: unexpected 'B' (expected an operator or the end) at column 3");
  CHECK(parse_error("") == "--csg: empty expression at column 1");
  CHECK(parse_error("   ") == "--csg: empty expression at column 4");
  CHECK(parse_error("A & ") ==
        "--csg: expected a halfspace name, '(', '~', empty or full, found end of the expression at column 5");
  CHECK(parse_error("A & #") == "--csg: expected a halfspace name, '(', '~', empty or full, found '#' at column 5");
  CHECK(parse_error("A & \"B") == "--csg: unterminated quoted name starting at column 5");
  CHECK(parse_error("\"A\\n\"") == "--csg: unknown escape \\n (only \\\" and \\\\) at column 3");
  CHECK(parse_error("A & \x01") ==
        "--csg: expected a halfspace name, '(', '~', empty or full, found byte \\x01 at column 5");
  CHECK(error_of([] { parse_csg_text("B | Y", kNames, "f.json: csg"); }) ==
        "f.json: csg: unknown halfspace \"Y\" at column 5");

  // Nesting: 200 levels are fine, 201 are refused; '~' counts like '('.
  CHECK(parse_csg_text(std::string(200, '(') + "A" + std::string(200, ')'), kNames)->op == Op::Halfspace);
  CHECK(parse_error(std::string(201, '(') + "A" + std::string(201, ')')) == "--csg: nesting deeper than 200 at column 201");
  CHECK(parse_error(std::string(201, '~') + "A") == "--csg: nesting deeper than 200 at column 201");
  CHECK(parse_csg_text(std::string(200, '~') + "A", kNames)->op == Op::Halfspace);
  // Length.
  std::string long_text = "A";
  while (long_text.size() <= kCsgTextMaxChars) long_text += " | A";
  CHECK(parse_error(long_text) ==
        "--csg: the expression is " + std::to_string(long_text.size()) + " characters; the limit is 100000");
}

// ---------------------------------------------------------------- JSON form

TEST_CASE("csg JSON: form, round trip and errors", "[csg][io]") {
  const ExprPtr e = unite({intersect({leaf(0), leaf(1)}), complement(leaf(2)), difference(leaf(3), leaf(0))});
  const nlohmann::json j = csg_to_json(*e, kNames);
  CHECK(j.dump() ==
        R"({"args":[{"args":[{"halfspace":"A"},{"halfspace":"B"}],"op":"intersection"},)"
        R"({"args":[{"halfspace":"C"}],"op":"complement"},)"
        R"({"args":[{"halfspace":"D"},{"halfspace":"A"}],"op":"difference"}],"op":"union"})");
  CHECK(same_tree(*csg_from_json(j, kNames), *e));
  CHECK(csg_to_json(*empty(), kNames).dump() == R"({"op":"empty"})");
  CHECK(csg_from_json(parse_exact_json(R"({"op": "full", "args": []})"), kNames)->op == Op::Full);
  CHECK(csg_from_json(parse_exact_json(R"({"op": "union", "args": [{"halfspace": "B"}]})"), kNames)->halfspace == 1);

  CHECK(json_error(R"({"op": "union", "args": [{"halfspace": "A"}, {"halfspace": "Q"}]})") ==
        "args[1].halfspace: unknown halfspace \"Q\"");
  CHECK(json_error(R"({"op": "xor", "args": []})") ==
        "op: unknown operation \"xor\" (expected union, intersection, difference, complement, empty or full)");
  CHECK(json_error(R"({"op": "difference", "args": [{"halfspace": "A"}]})") ==
        "args: \"difference\" needs exactly two arguments, got 1");
  CHECK(json_error(R"({"op": "complement"})") == "document: missing field \"args\" (\"complement\" needs exactly one argument)");
  CHECK(json_error(R"({"op": "union", "args": []})") == "args: \"union\" needs at least one argument, got 0");
  CHECK(json_error(R"({"op": "empty", "args": [{"halfspace": "A"}]})") == "args: \"empty\" takes no argument, got 1");
  CHECK(json_error(R"({"halfspace": "A", "op": "union"})").find("unknown field \"op\"") != std::string::npos);
  CHECK(json_error(R"({"args": []})") == "document: missing field \"op\" (or \"halfspace\" for a leaf)");
  CHECK(json_error(R"([1])").find("document: expected an object") == 0);
  CHECK(error_of([] { csg_from_json(nlohmann::json{{"halfspace", 3}}, kNames, "csg"); }).find("csg.halfspace: ") == 0);

  // Depth: 200 nested complements are fine, 201 are not.
  auto nested = [](int levels) {
    nlohmann::json j = {{"halfspace", "A"}};
    for (int i = 0; i < levels; ++i) j = nlohmann::json{{"op", "complement"}, {"args", nlohmann::json::array({j})}};
    return j;
  };
  CHECK(csg_from_json(nested(200), kNames)->op == Op::Halfspace);
  CHECK(error_of([&] { csg_from_json(nested(201), kNames); }).find("expression nested deeper than 200") !=
        std::string::npos);
}

TEST_CASE("csg JSON round trip on random trees", "[csg][io][property]") {
  rc::prop("csg_from_json(csg_to_json(e)) == e", [] {
    const int n = *rc::gen::inRange(1, 6);
    const bool raw_nodes = *rc::gen::arbitrary<bool>();
    const ExprPtr e = random_expr(n, 4, raw_nodes);
    const std::vector<std::string> names(kNames.begin(), kNames.begin() + n);
    // Through text, as a file would be read.
    const ExprPtr back = csg_from_json(parse_exact_json(csg_to_json(*e, names).dump()), names);
    RC_ASSERT(same_truth_table(*e, *back, n));
    if (!raw_nodes) RC_ASSERT(same_tree(*e, *back));
  });
}

TEST_CASE("csg argument: text, inline JSON, or a file", "[csg][io]") {
  const ExprPtr expected = difference(leaf(0), leaf(1));
  CHECK(same_tree(*read_csg_argument("A - B", kNames), *expected));
  CHECK(same_tree(*read_csg_argument(R"( {"csg": "A - B"})", kNames), *expected));
  CHECK(same_tree(
      *read_csg_argument(R"({"op": "difference", "args": [{"halfspace": "A"}, {"halfspace": "B"}]})", kNames),
      *expected));
  CHECK(error_of([] { read_csg_argument("A - Z", kNames); }) == "--csg: unknown halfspace \"Z\" at column 5");
  CHECK(error_of([] { read_csg_argument(R"({"csg": "A - Z"})", kNames); }) ==
        "--csg: csg: unknown halfspace \"Z\" at column 5");
  CHECK(error_of([] { read_csg_argument(R"({"csg": {"halfspace": "Z"}})", kNames); }) ==
        "--csg: csg.halfspace: unknown halfspace \"Z\"");
  CHECK(error_of([] { read_csg_argument(R"({"csg": 1)", kNames); }).find("--csg: line 1, column ") == 0);

  TempDir dir;
  const std::string bare = dir.write("bare.json", csg_to_json(*expected, kNames).dump(2));
  CHECK(same_tree(*read_csg_argument(bare, kNames), *expected));
  const std::string wrapped_text = dir.write("text.json", R"({"description": "a test", "csg": "A - B"})");
  CHECK(same_tree(*read_csg_argument(wrapped_text, kNames), *expected));
  const std::string wrapped_tree = dir.write("tree.json", R"({"csg": {"op": "complement", "args": [{"halfspace": "E"}]}})");
  CHECK(same_tree(*read_csg_argument(wrapped_tree, kNames), *complement(leaf(4))));
  const std::string bad_text = dir.write("bad_text.json", R"({"csg": "A | W"})");
  CHECK(error_of([&] { read_csg_argument(bad_text, kNames); }) == bad_text + ": csg: unknown halfspace \"W\" at column 5");
  const std::string bad_tree = dir.write("bad_tree.json", R"({"csg": {"op": "union", "args": [{"halfspace": "W"}]}})");
  CHECK(error_of([&] { read_csg_argument(bad_tree, kNames); }) == bad_tree + ": csg.args[0].halfspace: unknown halfspace \"W\"");
  const std::string extra = dir.write("extra.json", R"({"csg": "A", "colour": 1})");
  CHECK(error_of([&] { read_csg_argument(extra, kNames); }).find(extra + ": document: unknown field \"colour\"") == 0);
  const std::string broken = dir.write("broken.json", "{\"csg\": ");
  CHECK(error_of([&] { read_csg_argument(broken, kNames); }).find(broken + ": line 1") == 0);
}

// ---------------------------------------------------------------- CSGNet

TEST_CASE("csgnet: a square is four exact half-planes", "[csg][csgnet]") {
  const CsgnetProgram p = read_csgnet("s(32,30,10)", "line 1");
  const Scene2& s = p.scene;
  REQUIRE(s.halfspaces.size() == 4);
  CHECK(names_of(s) == std::vector<std::string>{"s0.xmin", "s0.xmax", "s0.ymin", "s0.ymax"});
  CHECK(to_text(*p.expression, names_of(s)) == "s0.xmin & s0.xmax & s0.ymin & s0.ymax");
  const Rational h = R(706, 100);  // 0.706 * 10
  for (const Halfspace2& hs : s.halfspaces) CHECK(hs.kind == HalfspaceKind2::Halfplane);
  // Corners lie exactly on two boundaries; the centre is strictly inside all four.
  const PointQ2 corner{R(32) + h, R(30) - h};
  CHECK(s.halfspaces[1].side(corner) == 0);
  CHECK(s.halfspaces[2].side(corner) == 0);
  CHECK(s.halfspaces[0].side(corner) == 1);
  CHECK(s.halfspaces[3].side(corner) == 1);
  for (const Halfspace2& hs : s.halfspaces) CHECK(hs.side(PointQ2{R(32), R(30)}) == 1);
  CHECK(s.halfspaces[1].side(PointQ2{R(32) + h + R(1, 1000000), R(30)}) == -1);
  CHECK(s.samples.empty());
  CHECK(s.domain_given);
  CHECK(s.description == "CSGNet program (line 1): s(32,30,10)");
  // Domain: bounding box [24.94, 39.06] x [22.94, 37.06] rounded out to [24, 40] x [22, 38], margin 8.
  CHECK(s.domain.min == PointQ2{R(16), R(14)});
  CHECK(s.domain.max == PointQ2{R(48), R(46)});

  const Arranged2 a = arrange(s);
  const std::vector<char> labels = evaluate(*p.expression, a.complex);
  CHECK(equal(solid_area(a.complex, labels), Measure(R(1412, 100) * R(1412, 100))));
  for (std::size_t k = 0; k < labels.size(); ++k)
    if (a.complex.cells[k].outer) CHECK(labels[k] == 0);
}

TEST_CASE("csgnet: a triangle is three exact half-planes", "[csg][csgnet]") {
  const CsgnetProgram p = read_csgnet("t(32,32,10)", "line 2");
  const Scene2& s = p.scene;
  REQUIRE(s.halfspaces.size() == 3);
  CHECK(names_of(s) == std::vector<std::string>{"t0.0", "t0.1", "t0.2"});
  const Rational a = R(866, 100);
  const PointQ2 v[3] = {PointQ2{R(32) - a, R(37)}, PointQ2{R(32) + a, R(37)}, PointQ2{R(32), R(22)}};
  for (int i = 0; i < 3; ++i) {
    // Edge i joins v[i] and v[i+1]; the third vertex is strictly inside half-plane i.
    CHECK(s.halfspaces[i].side(v[i]) == 0);
    CHECK(s.halfspaces[i].side(v[(i + 1) % 3]) == 0);
    CHECK(s.halfspaces[i].side(v[(i + 2) % 3]) == 1);
    CHECK(s.halfspaces[i].side(PointQ2{R(32), R(32)}) == 1);
  }
  CHECK(s.halfspaces[0].normal == PointQ2{R(0), R(1)});
  CHECK(s.halfspaces[1].normal == PointQ2{R(750), R(-433)});
  CHECK(s.halfspaces[2].normal == PointQ2{R(-750), R(-433)});
  const Arranged2 arr = arrange(s);
  const std::vector<char> labels = evaluate(*p.expression, arr.complex);
  // Area: base 2 * 8.66, height 15.
  CHECK(equal(solid_area(arr.complex, labels), Measure(R(866, 100) * R(15))));
}

TEST_CASE("csgnet: disks, repeated primitives and operators", "[csg][csgnet]") {
  const CsgnetProgram d = read_csgnet("c(32,32,28)", "");
  REQUIRE(d.scene.halfspaces.size() == 1);
  CHECK(d.scene.halfspaces[0].name == "c0");
  CHECK(d.scene.halfspaces[0].kind == HalfspaceKind2::Disk);
  CHECK(d.scene.halfspaces[0].center == PointQ2{R(32), R(32)});
  CHECK(d.scene.halfspaces[0].radius == R(28));
  CHECK(d.expression->op == Op::Halfspace);
  CHECK(d.scene.description == "CSGNet program: c(32,32,28)");
  CHECK(d.scene.domain.min == PointQ2{R(-4), R(-4)});  // [4, 60]^2, W = 56, margin 8
  CHECK(d.scene.domain.max == PointQ2{R(68), R(68)});

  const CsgnetProgram rep = read_csgnet("c(32,32,28)c(32,32,28)*", "x");
  CHECK(names_of(rep.scene) == std::vector<std::string>{"c0", "c1"});
  CHECK(to_text(*rep.expression, names_of(rep.scene)) == "c0 & c1");

  const CsgnetProgram p = read_csgnet("s(40,32,24)s(32,40,20)c(32,24,16)+*s(40,40,16)s(24,40,24)*-", "line 1");
  const auto names = names_of(p.scene);
  CHECK(names.size() == 17);
  CHECK(to_text(*p.expression, names) ==
        "s0.xmin & s0.xmax & s0.ymin & s0.ymax & (s1.xmin & s1.xmax & s1.ymin & s1.ymax | c2) - "
        "s3.xmin & s3.xmax & s3.ymin & s3.ymax & s4.xmin & s4.xmax & s4.ymin & s4.ymax");
  // The text form parses back to the same tree.
  CHECK(same_tree(*parse_csg_text(to_text(*p.expression, names), names), *p.expression));
  CHECK(same_tree(*read_csgnet("c(1,2,3)c(4,5,6)-", "").expression, *difference(leaf(0), leaf(1))));
  CHECK(same_tree(*read_csgnet(" c(1,2,3) c(4,5,6) + \r\n", "").expression, *unite({leaf(0), leaf(1)})));
  // Exact decimals in the numbers.
  CHECK(read_csgnet("c(1.5,2,0.25)", "").scene.halfspaces[0].radius == R(1, 4));
}

TEST_CASE("csgnet: malformed programs", "[csg][csgnet]") {
  CHECK(csgnet_error("c(1,2,3)x(1,2,3)+") ==
        "line 7: token 2 at column 9: unknown token starting with 'x' (expected c(...), s(...), t(...), +, * or -)");
  CHECK(csgnet_error("c(1,2,3)+") == "line 7: token 2 at column 9: stack underflow: '+' needs two solids, the stack has 1");
  CHECK(csgnet_error("-") == "line 7: token 1 at column 1: stack underflow: '-' needs two solids, the stack has 0");
  CHECK(csgnet_error("c(1,2,3)c(1,2,3)") ==
        "line 7: the program leaves 2 solids on the stack (expected one; an operator is missing)");
  CHECK(csgnet_error("  ") == "line 7: empty program");
  CHECK(csgnet_error("c(1,2,0)") == "line 7: token 1 at column 1: the radius must be positive, got 0");
  CHECK(csgnet_error("c(1,2,3)s(1,2,-1)+") == "line 7: token 2 at column 9: the size must be positive, got -1");
  CHECK(csgnet_error("t(1,2,-0.5)") == "line 7: token 1 at column 1: the size must be positive, got -0.5");
  CHECK(csgnet_error("c(1,2)") == "line 7: token 1 at column 1: malformed primitive: expected three numbers in c(x,y,r), got 2");
  CHECK(csgnet_error("c(1,2,3,4)") ==
        "line 7: token 1 at column 1: malformed primitive: expected three numbers in c(x,y,r), got more");
  CHECK(csgnet_error("s(1,2,3") == "line 7: token 1 at column 1: malformed primitive: missing ')' in s(x,y,l)");
  CHECK(csgnet_error("c 1,2,3)") == "line 7: token 1 at column 1: malformed primitive: expected c(x,y,r)");
  CHECK(csgnet_error("c(1,a,3)").find("line 7: token 1 at column 1: malformed number \"a\" in c(x,y,r): ") == 0);
  CHECK(csgnet_error("c(1,,3)").find("line 7: token 1 at column 1: malformed number \"\" in c(x,y,r)") == 0);
  CHECK(csgnet_error(std::string(kCsgnetMaxChars + 1, ' ')) ==
        "line 7: the program is 100001 characters; the limit is 100000");
}

TEST_CASE("csgnet corpus: the first 50 programs import, arrange and evaluate", "[csg][csgnet][corpus]") {
  const char* env = std::getenv("HSX_CSGNET_CORPUS");
  const std::string path = env ? env : "/work/shared/data/csgnet/best_st_expressions.txt";
  std::ifstream in(path);
  if (!in) {
    WARN("csgnet corpus test skipped: corpus not present (" << path << ")");
    return;  // no assertion: not counted as a pass
  }
  std::string line;
  int read = 0, refused = 0;
  while (read < 50 && std::getline(in, line)) {
    ++read;
    const std::string origin = "line " + std::to_string(read);
    INFO(origin << ": " << line);
    // Some corpus lines are truncated (33 of the 1000 leave three solids on the stack, line 40 among the first
    // 50): an independent stack count decides which lines must be refused.
    int depth = 0;
    bool in_primitive = false;
    for (char c : line) {
      if (c == '(') in_primitive = true;
      if (c == ')') in_primitive = false;
      if (in_primitive) continue;
      if (c == 'c' || c == 's' || c == 't') ++depth;
      if (c == '+' || c == '*' || c == '-') --depth;
    }
    if (depth != 1) {
      ++refused;
      CHECK(error_of([&] { read_csgnet(line, origin); }) ==
            origin + ": the program leaves " + std::to_string(depth) +
                " solids on the stack (expected one; an operator is missing)");
      continue;
    }
    const CsgnetProgram p = read_csgnet(line, origin);
    const auto names = names_of(p.scene);
    // Each primitive adds its halfspaces; every halfspace is used exactly once by the expression.
    const ExprStats st = stats(*p.expression);
    CHECK(st.leaves == static_cast<int>(names.size()));
    CHECK(st.distinct_halfspaces == static_cast<int>(names.size()));
    CHECK(st.duplicated_halfspaces == 0);
    CHECK(same_tree(*parse_csg_text(to_text(*p.expression, names), names), *p.expression));
    CHECK(same_tree(*csg_from_json(csg_to_json(*p.expression, names), names), *p.expression));
    // The scene survives a JSON round trip, domain included.
    const Scene2 again = read_scene2(parse_exact_json(write_scene2(p.scene).dump()));
    CHECK(again.domain.min == p.scene.domain.min);
    CHECK(again.domain.max == p.scene.domain.max);
    const Arranged2 a = arrange(p.scene);
    const std::vector<char> labels = evaluate(*p.expression, a.complex);
    for (std::size_t k = 0; k < labels.size(); ++k)
      if (a.complex.cells[k].outer) CHECK(labels[k] == 0);
  }
  CHECK(read == 50);
  CHECK(refused < 5);
  SUCCEED("csgnet corpus: " << read << " programs checked, " << refused << " truncated ones refused");
}

// ---------------------------------------------------------------- OpenSCAD

TEST_CASE("openscad export: deterministic, one primitive per leaf", "[csg][openscad]") {
  const CsgnetProgram p = read_csgnet("s(40,32,24)s(32,40,20)c(32,24,16)+*s(40,40,16)s(24,40,24)*-t(30,30,8)+", "l");
  OpenScadOptions o;
  o.circle_segments = 48;
  const std::string scad = to_openscad(*p.expression, p.scene, o);
  CHECK(scad == to_openscad(*p.expression, p.scene, o));
  CHECK(scad.find("a drawing, not exact: circles are polygons with $fn = 48 segments; coordinates rounded to 17 "
                  "significant digits") != std::string::npos);
  // 16 square half-planes + 3 triangle half-planes as polygons, one circle.
  CHECK(count(scad, "polygon(") == 19);
  CHECK(count(scad, "circle(") == 1);
  CHECK(count(scad, "$fn = 48)") == 1);
  CHECK(count(scad, "translate([32, 24]) circle(r = 16, $fn = 48);  // c2") == 1);
  CHECK(count(scad, "union() {") == 2);
  CHECK(count(scad, "intersection() {") == 4);  // s0 & (s1 | c2) flattened, s1, s3 & s4 flattened, t5
  CHECK(count(scad, "difference() {") == 1);
  CHECK(count(scad, "{") == count(scad, "}"));
  // The half-plane X <= 40 + 0.706*24 = 56.944 clipped to the domain box.
  CHECK(scad.find("// s0.xmax") != std::string::npos);
  CHECK(scad.find("56.944") != std::string::npos);
  CHECK(scad.find("$fn = 96") == std::string::npos);
}

TEST_CASE("openscad export: half-plane clipping, complements, constants", "[csg][openscad]") {
  Scene2 s;
  s.domain = Box2{PointQ2{R(0), R(0)}, PointQ2{R(10), R(10)}};
  s.domain_given = true;
  Halfspace2 h;  // x + y <= 5: the triangle (0,0), (5,0), (0,5)
  h.name = "H";
  h.kind = HalfspaceKind2::Halfplane;
  h.normal = PointQ2{R(1), R(1)};
  h.offset = R(5);
  Halfspace2 hc = h;  // complement: x + y >= 5, a pentagon
  hc.name = "Hc";
  hc.complement = true;
  Halfspace2 v;  // x <= 1/3: a rectangle, 17 significant digits
  v.name = "V";
  v.kind = HalfspaceKind2::Halfplane;
  v.normal = PointQ2{R(1), R(0)};
  v.offset = R(1, 3);
  Halfspace2 d;
  d.name = "D";
  d.kind = HalfspaceKind2::Disk;
  d.center = PointQ2{R(5), R(5)};
  d.radius = R(2);
  d.complement = true;
  Halfspace2 poly;
  poly.name = "P";
  poly.kind = HalfspaceKind2::Polygon;
  poly.vertices = {PointQ2{R(1), R(1)}, PointQ2{R(3), R(1)}, PointQ2{R(2), R(3)}};
  s.halfspaces = {h, hc, v, d, poly};
  validate_and_resolve(s);
  const std::vector<std::string> names = names_of(s);

  CHECK(to_openscad(*leaf(0), s) == "// hsx CSG expression as a 2D OpenSCAD program.\n"
                                    "// a drawing, not exact: circles are polygons with $fn = 96 segments; "
                                    "coordinates rounded to 17 significant digits.\n"
                                    "// domain: [0, 0] to [10, 10]\n"
                                    "polygon(points = [[0, 0], [5, 0], [0, 5]]);  // H\n");
  CHECK(to_openscad(*leaf(1), s).find("polygon(points = [[5, 0], [10, 0], [10, 10], [0, 10], [0, 5]]);  // Hc "
                                      "(complement)\n") != std::string::npos);
  CHECK(to_openscad(*leaf(2), s).find("polygon(points = [[0, 0], [0.33333333333333333, 0], "
                                      "[0.33333333333333333, 10], [0, 10]]);  // V\n") != std::string::npos);
  const std::string disk = to_openscad(*leaf(3), s);
  CHECK(disk.find("difference() {  // D (complement)\n"
                  "  translate([0, 0]) square([10, 10]);\n"
                  "  translate([5, 5]) circle(r = 2, $fn = 96);\n"
                  "}\n") != std::string::npos);
  const std::string comp = to_openscad(*complement(leaf(4)), s);
  CHECK(comp.find("difference() {  // complement\n"
                  "  translate([0, 0]) square([10, 10]);\n"
                  "  polygon(points = [[1, 1], [3, 1], [2, 3]]);  // P\n"
                  "}\n") != std::string::npos);
  CHECK(to_openscad(*empty(), s).find("union() {}  // empty\n") != std::string::npos);
  CHECK(to_openscad(*full(), s).find("translate([0, 0]) square([10, 10]);  // full\n") != std::string::npos);
  OpenScadOptions bad;
  bad.circle_segments = 2;
  CHECK(error_of([&] { to_openscad(*leaf(0), s, bad); }) == "OpenSCAD circle segments: expected 3 to 100000, got 2");
  CHECK_THROWS_AS(to_openscad(*leaf(9), s), std::invalid_argument);
}

// ---------------------------------------------------------------- OpenSCAD, 3D

namespace {

/// Six times the signed volume of a polyhedron given by faces counter-clockwise from outside (fan triangulation;
/// exact). Positive for a correctly oriented closed surface.
Rational six_volume(const std::vector<std::vector<PointQ3>>& faces) {
  Rational v = 0;
  for (const auto& f : faces)
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const PointQ3 &a = f[0], &b = f[i], &c = f[i + 1];
      v += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
    }
  return v;
}

/// Every directed edge of the faces appears exactly once, and so does its reverse (a closed, oriented surface).
bool closed(const std::vector<std::vector<PointQ3>>& faces) {
  std::vector<std::pair<PointQ3, PointQ3>> edges;
  for (const auto& f : faces)
    for (std::size_t i = 0; i < f.size(); ++i) edges.push_back({f[i], f[(i + 1) % f.size()]});
  for (const auto& e : edges) {
    const auto same = std::count(edges.begin(), edges.end(), e);
    const auto reverse = std::count(edges.begin(), edges.end(), std::make_pair(e.second, e.first));
    if (same != 1 || reverse != 1) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("box_cut_by_plane: exact convex pieces, closed, outward, volumes", "[csg][openscad][geometry]") {
  const Box3 box{PointQ3{R(0), R(0), R(0)}, PointQ3{R(2), R(2), R(2)}};
  // x + y + z <= 1: the corner tetrahedron of volume 1/6 (six_volume 1): 3 box faces cut to triangles, the cap.
  const auto tet = box_cut_by_plane(box, PointQ3{R(1), R(1), R(1)}, R(1));
  CHECK(tet.size() == 4);
  CHECK(closed(tet));
  CHECK(six_volume(tet) == R(1));
  // Its complement x + y + z >= 1: the rest of the box, 8 - 1/6.
  const auto rest = box_cut_by_plane(box, PointQ3{R(-1), R(-1), R(-1)}, R(-1));
  CHECK(rest.size() == 7);  // 6 faces (3 of them pentagons) and the cap
  CHECK(closed(rest));
  CHECK(six_volume(rest) == R(6 * 8 - 1));
  // A plane through a box edge and the opposite edge: half the box, the cap a rectangle.
  const auto half = box_cut_by_plane(box, PointQ3{R(1), R(-1), R(0)}, R(0));
  CHECK(closed(half));
  CHECK(six_volume(half) == R(24));
  // The plane z <= 2 keeps the box whole, no cap; z <= 0 and z <= -1 keep nothing.
  const auto whole = box_cut_by_plane(box, PointQ3{R(0), R(0), R(1)}, R(2));
  CHECK(whole.size() == 6);
  CHECK(six_volume(whole) == R(48));
  CHECK(box_cut_by_plane(box, PointQ3{R(0), R(0), R(1)}, R(0)).empty());
  CHECK(box_cut_by_plane(box, PointQ3{R(0), R(0), R(1)}, R(-1)).empty());
  CHECK_THROWS_AS(box_cut_by_plane(box, PointQ3{R(0), R(0), R(0)}, R(0)), std::invalid_argument);
}

TEST_CASE("box_cut_by_plane: the two sides of any plane make up the box", "[csg][openscad][geometry]") {
  rc::prop("closed, outward, volumes adding up to the box's", [] {
    const Box3 box{PointQ3{R(-1), R(0), R(0)}, PointQ3{R(2), R(1), R(3)}};  // volume 9, six_volume 54
    const auto c = [] { return *rc::gen::inRange(-3, 4); };
    const PointQ3 n{R(c()), R(c()), R(c())};
    RC_PRE(!(n.x == 0 && n.y == 0 && n.z == 0));
    const Rational o = R(*rc::gen::inRange(-12, 13), *rc::gen::inRange(1, 4));
    const auto below = box_cut_by_plane(box, n, o);
    const auto above = box_cut_by_plane(box, PointQ3{-n.x, -n.y, -n.z}, Rational(-o));
    RC_ASSERT(six_volume(below) + six_volume(above) == R(54));
    RC_ASSERT((below.empty() || closed(below)));
    RC_ASSERT((above.empty() || closed(above)));
    RC_ASSERT((below.empty() || six_volume(below) > 0));
    for (const auto& f : below)
      for (const PointQ3& p : f) RC_ASSERT(dot3(n, p) <= o);
  });
}

TEST_CASE("openscad export 3D: the tessellation explicit, planes clipped, complements subtracted",
          "[csg][openscad]") {
  const Scene3 s = read_scene3_text(R"({"format": "hsx-scene/1", "dimension": 3,
    "domain": {"min": [-2, -2, -2], "max": [2, 2, 2]},
    "halfspaces": [
      {"name": "P", "kind": "plane", "normal": [0, 0, 1], "offset": 0},
      {"name": "Q", "kind": "plane", "normal": [0, 0, 1], "offset": 0, "complement": true},
      {"name": "B", "kind": "box", "min": [-1, -1, -1], "max": [1, 1, 1]},
      {"name": "C", "kind": "cylinder", "axis_point1": [0, 0, -1], "axis_point2": [0, 0, 1], "radius": "1/2",
       "tessellation": {"segments": 8}, "complement": true},
      {"name": "Far", "kind": "plane", "normal": [1, 0, 0], "offset": -5}
    ]})");
  const std::vector<std::string> names = {"P", "Q", "B", "C", "Far"};
  const ExprPtr e = parse_csg_text("(B & P) | C | (Q & Far)", names);
  const std::string scad = to_openscad(*e, s);
  CHECK(scad == to_openscad(*e, s));
  CHECK(scad.rfind("// hsx CSG expression as a 3D OpenSCAD program, with hsx's tessellation made explicit.\n", 0) ==
        0);
  CHECK(scad.find("// domain: [-2, -2, -2] to [2, 2, 2]\n") != std::string::npos);
  // P: the lower half of the domain box, 8 points, 6 quads; the box's corners listed in order of first use, each
  // face clockwise from outside (the box_cut_by_plane face z = -2 is (0,2,3,1) counter-clockwise -> reversed).
  CHECK(scad.find("polyhedron(points = [[-2, -2, -2], [-2, 2, -2], [2, 2, -2], [2, -2, -2], [2, -2, 0], "
                  "[-2, -2, 0], [-2, 2, 0], [2, 2, 0]], faces = [[3, 2, 1, 0], ") != std::string::npos);
  CHECK(scad.find("  // P (plane, the domain box clipped to it)\n") != std::string::npos);
  CHECK(scad.find("  // Q (plane, complement, the domain box clipped to it)\n") != std::string::npos);
  CHECK(scad.find("union() {}  // Far (plane, misses the domain)\n") != std::string::npos);
  // B: its 8 corners in tessellation order, triangle (0,2,3) written [0, 3, 2].
  CHECK(scad.find("polyhedron(points = [[-1, -1, -1], [1, -1, -1], [-1, 1, -1], [1, 1, -1], [-1, -1, 1], "
                  "[1, -1, 1], [-1, 1, 1], [1, 1, 1]], faces = [[0, 3, 2], [0, 1, 3], ") != std::string::npos);
  CHECK(scad.find("  // B (box, 8 vertices, 12 triangles)\n") != std::string::npos);
  // ~C: the domain cube minus the 8-gon prism (8 + 8 ring vertices + 2 cap centres, 32 triangles).
  CHECK(scad.find("difference() {  // C (cylinder, complement, 18 vertices, 32 triangles, subtracted from the "
                  "domain box)\n    translate([-2, -2, -2]) cube([4, 4, 4]);\n    polyhedron(points = [") !=
        std::string::npos);
  CHECK(count(scad, "polyhedron(") == 4);
  CHECK(count(scad, "{") == count(scad, "}"));
  // The polyhedron of C has exactly the surface's vertices, each triangle reversed.
  const TriangleSurface& cs = s.halfspaces[3].surface;
  REQUIRE(cs.triangles.size() == 32);
  const auto& t0 = cs.triangles[0];
  CHECK(scad.find("faces = [[" + std::to_string(t0[0]) + ", " + std::to_string(t0[2]) + ", " +
                  std::to_string(t0[1]) + "], ") != std::string::npos);
  CHECK(to_openscad(*complement(leaf(2)), s).find("difference() {  // complement\n"
                                                   "  translate([-2, -2, -2]) cube([4, 4, 4]);\n"
                                                   "  polyhedron(points = [[-1, -1, -1], ") != std::string::npos);
  CHECK(to_openscad(*full(), s).find("translate([-2, -2, -2]) cube([4, 4, 4]);  // full\n") != std::string::npos);
  CHECK_THROWS_AS(to_openscad(*leaf(7), s), std::invalid_argument);
}
