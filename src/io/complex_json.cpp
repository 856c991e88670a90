// The hsx-complex/1 document: see complex_json.hpp.
#include <hsx/io/complex_json.hpp>

#include "geometry/planar_measures.hpp"
#include "io/complex_json3.hpp"
#include "io/complex_json_detail.hpp"
#include <hsx/io/exact_json.hpp>
#include <hsx/io/json_values.hpp>
#include <hsx/kernel/interval.hpp>

#include <mpfr.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>

namespace hsx {

namespace complex_json_detail {

using json = nlohmann::json;

// ---------------------------------------------------------------------------------------------------------------
// Closed forms and one-root numbers

/// Limits on a closed form, so that hostile input fails fast (the kernel compares radicands pairwise).
constexpr std::size_t kMaxClosedFormChars = 200000;
constexpr std::size_t kMaxClosedFormTerms = 4096;
constexpr std::size_t kMaxRadicandChars = 1000;

struct Term {
  Rational coefficient;
  std::optional<Rational> radicand;  ///< nullopt: a rational term (or pi)
  bool pi = false;                   ///< coefficient*pi
};

bool fail_with(std::string* why, std::string reason) {
  if (why != nullptr) *why = std::move(reason);
  return false;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Terms of "t1 + t2 - t3 ...", each t: q | q*sqrt(m) | sqrt(m) | q*pi | pi, each optionally with its own sign.
bool parse_terms(std::string_view text, std::vector<Term>& terms, std::string* why) {
  const std::size_t n = text.size();
  std::size_t i = 0;
  auto skip = [&] {
    while (i < n && is_space(text[i])) ++i;
  };
  auto at = [&](std::size_t k) { return "at character " + std::to_string(k + 1); };
  auto parse_sqrt = [&](Rational& m) {  // at "sqrt"
    if (text.substr(i, 4) != "sqrt") return fail_with(why, "expected a number or sqrt(...) " + at(i));
    i += 4;
    skip();
    if (i >= n || text[i] != '(') return fail_with(why, "expected '(' after sqrt " + at(i));
    const std::size_t open = i++;
    const std::size_t close = text.find_first_of("()", i);
    if (close == std::string_view::npos || text[close] != ')') {
      return fail_with(why, close == std::string_view::npos ? "unbalanced parenthesis " + at(open)
                                                            : "nested radicals are not accepted " + at(close));
    }
    std::string_view inner = text.substr(i, close - i);
    while (!inner.empty() && is_space(inner.front())) inner.remove_prefix(1);
    while (!inner.empty() && is_space(inner.back())) inner.remove_suffix(1);
    if (inner.size() > kMaxRadicandChars) {
      return fail_with(why, "a radicand longer than " + std::to_string(kMaxRadicandChars) + " characters");
    }
    std::string reason;
    auto q = parse_rational(inner, &reason);
    if (!q) return fail_with(why, "bad radicand \"" + std::string(inner.substr(0, 40)) + "\": " + reason);
    if (sgn(*q) < 0) return fail_with(why, "negative radicand " + exact_string(*q));
    m = *q;
    i = close + 1;
    return true;
  };
  if (n > kMaxClosedFormChars) {
    return fail_with(why, "longer than " + std::to_string(kMaxClosedFormChars) + " characters");
  }
  skip();
  if (i >= n) return fail_with(why, "empty");
  bool first = true;
  while (true) {
    skip();
    if (i >= n) break;
    int sign = 1;
    if (!first) {
      if (text[i] != '+' && text[i] != '-') return fail_with(why, "expected '+' or '-' " + at(i));
      sign = text[i] == '-' ? -1 : 1;
      ++i;
      skip();
    }
    if (i < n && (text[i] == '+' || text[i] == '-')) {
      if (text[i] == '-') sign = -sign;
      ++i;
      skip();
    }
    if (i >= n) return fail_with(why, "missing term at the end");
    Term term;
    auto parse_pi = [&] {  // at "pi"
      if (text.substr(i, 2) != "pi") return false;
      i += 2;
      return term.pi = true;
    };
    if (text[i] == 'p') {
      if (!parse_pi()) return fail_with(why, "expected a number, sqrt(...) or pi " + at(i));
      term.coefficient = sign;
    } else if (text[i] == 's') {
      Rational m;
      if (!parse_sqrt(m)) return false;
      term.coefficient = sign;
      term.radicand = m;
    } else if (is_digit(text[i]) || text[i] == '.') {
      const std::size_t start = i;
      while (i < n) {
        const char c = text[i];
        if (is_digit(c) || c == '.' || c == '/') {
          ++i;
        } else if ((c == 'e' || c == 'E') && i + 1 < n &&
                   (is_digit(text[i + 1]) || ((text[i + 1] == '+' || text[i + 1] == '-') && i + 2 < n &&
                                              is_digit(text[i + 2])))) {
          i += 2;
        } else {
          break;
        }
      }
      std::string reason;
      auto q = parse_rational(text.substr(start, i - start), &reason);
      if (!q) {
        return fail_with(why, "bad number \"" + std::string(text.substr(start, std::min<std::size_t>(i - start, 40))) +
                                  "\": " + reason);
      }
      term.coefficient = sign > 0 ? *q : Rational(-*q);
      skip();
      if (i < n && text[i] == '*') {
        ++i;
        skip();
        if (i < n && text[i] == 'p') {
          if (!parse_pi()) return fail_with(why, "expected sqrt(...) or pi " + at(i));
        } else {
          Rational m;
          if (!parse_sqrt(m)) return false;
          term.radicand = m;
        }
      }
    } else {
      return fail_with(why, "expected a number or sqrt(...) " + at(i));
    }
    if (terms.size() >= kMaxClosedFormTerms) {
      return fail_with(why, "more than " + std::to_string(kMaxClosedFormTerms) + " terms");
    }
    terms.push_back(std::move(term));
    first = false;
  }
  return true;
}

Measure sum_of(const std::vector<Term>& terms) {
  Measure m;
  for (const Term& t : terms) {
    if (t.pi) {
      m += Measure::pi(t.coefficient);
    } else if (!t.radicand) {
      m += Measure(t.coefficient);
    } else {
      m += Measure::sqrt_of(*t.radicand) * t.coefficient;
    }
  }
  return m;
}

// ---------------------------------------------------------------------------------------------------------------
// Decimals

struct DecimalText {
  Rational value;
  bool zero = false;
  long leading_exponent = 0;  ///< 10^E <= |value| < 10^(E+1)
  long last_exponent = 0;     ///< the last written digit's place
};

/// A decimal "[-+]d*[.d*][e[-+]d+]" (at least one digit), or nullopt with *why.
std::optional<DecimalText> parse_decimal(const std::string& text, std::string* why) {
  std::string reason;
  auto q = parse_rational(text, &reason);
  if (!q || text.find('/') != std::string::npos) {
    fail_with(why, "expected a decimal number, got \"" + text.substr(0, 40) + "\"" +
                       (reason.empty() ? "" : " (" + reason + ")"));
    return std::nullopt;
  }
  DecimalText d;
  d.value = *q;
  std::size_t i = 0;
  const std::size_t n = text.size();
  if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
  long leading = -1;  // number of mantissa digits from the first non-zero digit to the end
  long frac = 0;
  bool in_frac = false;
  for (; i < n && (is_digit(text[i]) || text[i] == '.'); ++i) {
    if (text[i] == '.') {
      in_frac = true;
      continue;
    }
    if (in_frac) ++frac;
    if (leading >= 0) {
      ++leading;
    } else if (text[i] != '0') {
      leading = 1;
    }
  }
  long exponent = 0;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    int s = 1;
    if (i < n && (text[i] == '+' || text[i] == '-')) s = text[i++] == '-' ? -1 : 1;
    for (; i < n && is_digit(text[i]); ++i) exponent = std::min<long>(exponent * 10 + (text[i] - '0'), 1000000000L);
    exponent *= s;
  }
  d.zero = sgn(d.value) == 0;
  d.last_exponent = exponent - frac;
  d.leading_exponent = d.zero ? d.last_exponent : d.last_exponent + leading - 1;
  return d;
}

/// True unless `value` is proven to differ from the decimal by more than one unit in its last digit (at least 6,
/// at most 60 significant digits considered).
bool decimal_agrees(const Measure& value, const DecimalText& d) {
  if (d.zero) return value.is_zero();
  const long E = d.leading_exponent;
  long t = std::min(d.last_exponent, E - 5);
  t = std::max(t, E - 59);
  Rational tolerance = 1;
  const Integer p = [&] {
    Integer r;
    mpz_ui_pow_ui(r.get_mpz_t(), 10, static_cast<unsigned long>(t < 0 ? -t : t));
    return r;
  }();
  tolerance = t < 0 ? make_rational(1, p) : Rational(p);
  const mpfr_prec_t bits = static_cast<mpfr_prec_t>(128 + 4 * (E - t));
  const Measure diff = value - Measure(d.value);
  const Interval I = diff.enclose(bits);
  const Interval T(tolerance, bits);
  const Interval minus_T = -T;
  const bool above = mpfr_cmp(I.lo(), T.hi()) > 0;
  const bool below = mpfr_cmp(I.hi(), minus_T.lo()) < 0;
  return !above && !below;
}

/// The text of a "decimal" field: a string, a JSON integer or an exact-number marker.
std::string decimal_text(const JsonField& f) {
  const json& v = f.json();
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (is_exact_number(v)) return v.find(kExactNumberKey)->get<std::string>();
  f.fail("expected a decimal number, got " + describe_json(v));
}

DecimalText read_decimal(const JsonField& f) {
  std::string why;
  auto d = parse_decimal(decimal_text(f), &why);
  if (!d) f.fail(why);
  return *d;
}

// ---------------------------------------------------------------------------------------------------------------
// Measures in documents

json measure_json(const Measure& m) { return measure_to_json(m); }

struct MeasureFields {
  std::optional<JsonField> exact, decimal;
};

MeasureFields measure_fields(const JsonField& f) {
  const json& v = f.json();
  MeasureFields out;
  if (v.is_string() || v.is_number() || is_exact_number(v)) {
    out.exact = f;
    return out;
  }
  if (!v.is_object()) f.fail("expected a measure {\"decimal\": ..., \"exact\": ...}, got " + describe_json(v));
  f.check_keys({"certified", "decimal", "exact"}, "a measure");
  if (auto e = f.get("exact"); e && !e->json().is_null()) out.exact = e;
  if (auto d = f.get("decimal"); d && !d->json().is_null()) out.decimal = d;
  return out;
}

/// The exact value of an "exact" field: a number, or a closed-form string; nullopt (with *why) when the string
/// is not in the accepted grammar.
std::optional<Measure> exact_value(const JsonField& f, std::string* why, Budget& budget) {
  const json& v = f.json();
  if (!v.is_string()) return Measure(f.rational());
  std::vector<Term> terms;
  if (!parse_terms(v.get<std::string>(), terms, why)) return std::nullopt;
  budget.spend(terms.size(), f);
  return sum_of(terms);
}

std::string show(const Measure& m) {
  const auto e = m.exact_string();
  return e ? "\"" + *e + "\" = " + m.decimal_string(20) : m.decimal_string(20);
}

/// A measure read without geometry.
Measure measure_from_fields(const JsonField& f, Budget& budget) {
  const MeasureFields m = measure_fields(f);
  if (m.exact) {
    std::string why;
    auto value = exact_value(*m.exact, &why, budget);
    if (!value) m.exact->fail("not an accepted closed form (" + why + "); give a \"decimal\" instead, or a geometry section");
    if (m.decimal && !decimal_agrees(*value, read_decimal(*m.decimal))) {
      m.decimal->fail("does not agree with the exact value " + show(*value));
    }
    return *value;
  }
  if (m.decimal) return Measure(read_decimal(*m.decimal).value);
  f.fail("needs \"exact\" or \"decimal\"");
}

/// A length or area read without geometry: it must be positive (a proven sign <= 0 is refused).
Measure positive_measure_from_fields(const JsonField& f, Budget& budget, const std::string& what) {
  Measure value = measure_from_fields(f, budget);
  const std::optional<int> sign = value.sign();
  if (sign && *sign <= 0) f.fail("a " + what + " must be positive, not " + show(value));
  return value;
}

/// Checks given measure fields against a value recomputed from the geometry.
void check_measure(const JsonField& f, const Measure& recomputed, const std::string& what, Budget& budget) {
  const MeasureFields m = measure_fields(f);
  if (m.exact) {
    std::string why;
    const auto given = exact_value(*m.exact, &why, budget);
    bool ok;
    if (given) {
      ok = compare(*given, recomputed) == Order::Equal;
    } else {
      // Outside the parser's grammar (a nested radical): it must be the recomputed closed form itself.
      const auto text = recomputed.exact_string();
      ok = m.exact->json().is_string() && text && *text == m.exact->json().get<std::string>();
    }
    if (!ok) m.exact->fail("differs from the " + what + " recomputed from the geometry, " + show(recomputed));
  }
  if (m.decimal && !decimal_agrees(recomputed, read_decimal(*m.decimal))) {
    m.decimal->fail("differs from the " + what + " recomputed from the geometry, " + show(recomputed));
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Reading helpers

/// "patch" -> "patches", "vertex" -> "vertices", "cell" -> "cells".
std::string plural(const std::string& noun) {
  if (noun.size() > 2 && noun.compare(noun.size() - 2, 2, "ex") == 0) return noun.substr(0, noun.size() - 2) + "ices";
  if (noun.size() > 1 && (noun.back() == 's' || noun.back() == 'x' || noun.compare(noun.size() - 2, 2, "ch") == 0))
    return noun + "es";
  return noun + "s";
}

int read_index(const JsonField& f, std::size_t count, const std::string& what) {
  const std::int64_t v = f.integer();
  if (v < 0 || static_cast<std::uint64_t>(v) >= count) {
    f.fail(what + " " + std::to_string(v) + " is out of range (there " + (count == 1 ? "is " : "are ") +
           std::to_string(count) + " " + (count == 1 ? what : plural(what)) + ")");
  }
  return static_cast<int>(v);
}

void check_id(const JsonField& element, std::size_t position) {
  if (auto id = element.get("id")) {
    const std::int64_t v = id->integer();
    if (v < 0 || static_cast<std::uint64_t>(v) != position) {
      id->fail("is " + std::to_string(v) + " but ids are array positions; expected " + std::to_string(position));
    }
  }
}

/// Indices in range, sorted, no duplicates.
std::vector<int> read_index_set(const JsonField& f, std::size_t count, const std::string& what) {
  std::vector<int> out;
  const std::size_t n = f.size();
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) out.push_back(read_index(f.at(k), count, what));
  std::vector<int> sorted = out;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] == sorted[k - 1]) f.fail("lists " + what + " " + std::to_string(sorted[k]) + " twice");
  return sorted;
}


std::string name_of(const std::vector<std::string>& names, int h) {
  return describe_json(json(names.at(static_cast<std::size_t>(h))));
}

}  // namespace complex_json_detail

namespace {

using namespace complex_json_detail;  // NOLINT: this file's own helpers

OneRoot read_one_root(const JsonField& f) {
  if (f.json().is_string()) {
    std::string why;
    auto v = parse_one_root(f.json().get<std::string>(), &why);
    if (!v) f.fail("expected an exact number \"a\" or \"a + b*sqrt(c)\", got " + describe_json(f.json()) + " (" + why + ")");
    return *v;
  }
  return OneRoot(f.rational());
}

OneRootPoint read_one_root_point(const JsonField& f) {
  if (f.size() != 2) f.fail("expected a point [x, y], got " + std::to_string(f.size()) + " coordinates");
  return OneRootPoint(read_one_root(f.at(std::size_t{0})), read_one_root(f.at(std::size_t{1})));
}

bool same_point(const OneRootPoint& a, const OneRootPoint& b) { return a.x == b.x && a.y == b.y; }

OneRoot minus(const OneRoot& a, const Rational& c) { return OneRoot(a.a0 - c, a.a1, a.root); }

/// |p - c|^2 == r^2 exactly.
bool on_circle(const OneRootPoint& p, const PointQ2& c, const Rational& r) {
  const OneRoot dx = minus(p.x, c.x), dy = minus(p.y, c.y);
  const Measure d = Measure::product(dx, dx) + Measure::product(dy, dy) - Measure(r * r);
  return d.is_zero();
}

// ---------------------------------------------------------------------------------------------------------------
// Geometry section: vertices, edges (then the vertex degrees they imply), faces

/// geometry.vertices: the points. Their degrees are known once the edges are read (check_vertex_degrees).
void read_vertices(const JsonField& jv, ComplexDocument& doc) {
  const std::size_t nv = jv.size();
  doc.vertices.resize(nv);
  for (std::size_t k = 0; k < nv; ++k) {
    const JsonField v = jv.at(k);
    v.check_keys({"id", "point", "degree"}, "a vertex");
    check_id(v, k);
    doc.vertices[k].point = read_one_root_point(v.at("point"));
  }
}

/// An edge's "shape", with the fields that shape allows.
EdgeShape2 read_edge_shape(const JsonField& e) {
  const std::string shape = e.at("shape").string();
  if (shape == "segment") {
    e.check_keys({"id", "source", "target", "halfspaces", "on_box", "left_face", "right_face", "shape", "line"},
                 "a segment edge");
    return EdgeShape2::Segment;
  }
  if (shape == "arc") {
    e.check_keys({"id", "source", "target", "halfspaces", "on_box", "left_face", "right_face", "shape", "center",
                  "radius", "ccw"},
                 "an arc edge");
    return EdgeShape2::Arc;
  }
  e.at("shape").fail("expected \"segment\" or \"arc\", got " + describe_json(e.at("shape").json()));
}

/// The halfspaces an edge lies on: names, none twice; ascending indices.
std::vector<int> read_edge_halfspaces(const JsonField& hs, const Names& names) {
  std::vector<int> out;
  for (std::size_t i = 0; i < hs.size(); ++i) out.push_back(names(hs.at(i)));
  std::sort(out.begin(), out.end());
  if (std::adjacent_find(out.begin(), out.end()) != out.end()) hs.fail("lists a halfspace twice");
  return out;
}

/// "left_face" or "right_face": -1 (outside the domain) or one of the cell_count faces.
int read_edge_face(const JsonField& f, std::size_t cell_count) {
  const std::int64_t v = f.integer();
  if (v < -1 || (v >= 0 && static_cast<std::uint64_t>(v) >= cell_count)) {
    f.fail("face " + std::to_string(v) + " is out of range (-1 for outside the domain, or one of the " +
           std::to_string(cell_count) + " faces)");
  }
  return static_cast<int>(v);
}

/// A segment from p to q: distinct end points, and the optional supporting line a*x + b*y + c = 0 (it makes
/// lengths exact sums of square roots) through both.
void read_segment(const JsonField& e, const OneRootPoint& p, const OneRootPoint& q, ArrEdge2& edge) {
  if (edge.source == edge.target || same_point(p, q)) e.fail("a segment whose source and target coincide");
  const auto line = e.get("line");
  if (!line) return;
  if (line->size() != 3) line->fail("expected [a, b, c]");
  edge.line_a = line->at(0).rational();
  edge.line_b = line->at(1).rational();
  edge.line_c = line->at(2).rational();
  if (edge.line_a == 0 && edge.line_b == 0) line->fail("a and b are both zero");
  for (const OneRootPoint* v : {&p, &q}) {
    Measure value = Measure::product(OneRoot(edge.line_a), v->x) + Measure::product(OneRoot(edge.line_b), v->y) +
                    Measure(edge.line_c);
    if (!value.is_zero()) line->fail("an end point of the segment is not on this line");
  }
}

/// An arc from p to q: its circle (center, positive radius) through both end points, and its direction.
void read_arc(const JsonField& e, const OneRootPoint& p, const OneRootPoint& q, ArrEdge2& edge) {
  edge.center = e.at("center").point2();
  edge.radius = e.at("radius").rational();
  if (sgn(edge.radius) <= 0) e.at("radius").fail("must be positive");
  edge.ccw = e.at("ccw").boolean();
  if (!on_circle(p, edge.center, edge.radius)) e.at("source").fail("the vertex does not lie on the arc's circle");
  if (!on_circle(q, edge.center, edge.radius)) e.at("target").fail("the vertex does not lie on the arc's circle");
}

/// geometry.edges[k] (its length: planar_measures.hpp's edge_length).
ArrEdge2 read_edge(const JsonField& e, std::size_t k, const Names& names, std::size_t cell_count,
                   const std::vector<ArrVertex2>& vertices) {
  ArrEdge2 edge;
  edge.shape = read_edge_shape(e);
  check_id(e, k);
  edge.source = read_index(e.at("source"), vertices.size(), "vertex");
  edge.target = read_index(e.at("target"), vertices.size(), "vertex");
  edge.halfspaces = read_edge_halfspaces(e.at("halfspaces"), names);
  edge.on_box = e.at("on_box").boolean();
  edge.left_face = read_edge_face(e.at("left_face"), cell_count);
  edge.right_face = read_edge_face(e.at("right_face"), cell_count);
  const OneRootPoint& p = vertices[edge.source].point;
  const OneRootPoint& q = vertices[edge.target].point;
  if (edge.shape == EdgeShape2::Segment) {
    read_segment(e, p, q, edge);
  } else {
    read_arc(e, p, q, edge);
  }
  return edge;
}

void read_edges(const JsonField& je, const Names& names, std::size_t cell_count, ComplexDocument& doc) {
  const std::size_t ne = je.size();
  doc.edges.resize(ne);
  doc.edge_lengths.resize(ne);
  for (std::size_t k = 0; k < ne; ++k) {
    const ArrEdge2& edge = doc.edges[k] = read_edge(je.at(k), k, names, cell_count, doc.vertices);
    doc.edge_lengths[k] = edge_length(edge, doc.vertices[edge.source].point, doc.vertices[edge.target].point);
  }
}

/// Each vertex's degree (edge ends there), checked against its optional "degree" field.
void check_vertex_degrees(const JsonField& jv, ComplexDocument& doc) {
  std::vector<int> degree(doc.vertices.size(), 0);
  for (const ArrEdge2& edge : doc.edges) {
    ++degree[edge.source];
    ++degree[edge.target];
  }
  for (std::size_t k = 0; k < doc.vertices.size(); ++k) {
    doc.vertices[k].degree = degree[k];
    if (auto d = jv.at(k).get("degree"); d && d->integer() != degree[k]) {
      d->fail("is " + std::to_string(d->integer()) + " but " + std::to_string(degree[k]) + " edges end there");
    }
  }
}

/// One boundary walk of face `face`: [edge, forward] steps with the face on their left, closed.
std::vector<std::pair<int, bool>> read_walk(const JsonField& walk, int face, const std::vector<ArrEdge2>& edges) {
  if (walk.size() == 0) walk.fail("an empty boundary walk");
  std::vector<std::pair<int, bool>> steps;
  for (std::size_t s = 0; s < walk.size(); ++s) {
    const JsonField step = walk.at(s);
    if (step.size() != 2) step.fail("expected [edge, forward]");
    const int e = read_index(step.at(std::size_t{0}), edges.size(), "edge");
    const bool forward = step.at(std::size_t{1}).boolean();
    const ArrEdge2& edge = edges[e];
    if ((forward ? edge.left_face : edge.right_face) != face) {
      step.fail(std::string("edge ") + std::to_string(e) + " walked " + (forward ? "forward" : "backward") +
                " does not have face " + std::to_string(face) + " on its left");
    }
    steps.emplace_back(e, forward);
  }
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const auto& [e1, f1] = steps[s];
    const auto& [e2, f2] = steps[(s + 1) % steps.size()];
    const int end = f1 ? edges[e1].target : edges[e1].source;
    const int start = f2 ? edges[e2].source : edges[e2].target;
    if (end != start) walk.at(s).fail("the walk is not closed: this step ends where the next does not start");
  }
  return steps;
}

/// geometry.faces: one per cell, each with its boundary walks and exact area.
void read_faces(const JsonField& jf, std::size_t cell_count, ComplexDocument& doc, Budget& budget) {
  const std::size_t nf = jf.size();
  if (nf != cell_count) {
    jf.fail("has " + std::to_string(nf) + " faces but there are " + std::to_string(cell_count) +
            " cells (faces and cells correspond one to one)");
  }
  doc.faces.resize(nf);
  doc.face_areas.resize(nf);
  for (std::size_t k = 0; k < nf; ++k) {
    const JsonField f = jf.at(k);
    f.check_keys({"id", "boundary"}, "a face");
    check_id(f, k);
    const JsonField walks = f.at("boundary");
    if (walks.size() == 0) walks.fail("a face needs at least one boundary walk");
    std::uint64_t steps_total = 0;
    for (std::size_t w = 0; w < walks.size(); ++w) steps_total += walks.at(w).size();
    budget.spend(steps_total, walks);
    auto& boundary = doc.faces[k].boundary;
    for (std::size_t w = 0; w < walks.size(); ++w)
      boundary.push_back(read_walk(walks.at(w), static_cast<int>(k), doc.edges));
    doc.face_areas[k] = enclosed_area(boundary, doc.edges, doc.vertices);
  }
}

/// The optional "geometry" section: the arrangement the cells and patches come from.
void read_geometry(const JsonField& g, const Names& names, std::size_t cell_count, ComplexDocument& doc,
                   Budget& budget) {
  if (doc.complex.dimension == 3) return read_geometry3(g, names, cell_count, doc);
  g.check_keys({"vertices", "edges", "faces"}, "a geometry section");
  read_vertices(g.at("vertices"), doc);
  read_edges(g.at("edges"), names, cell_count, doc);
  check_vertex_degrees(g.at("vertices"), doc);
  read_faces(g.at("faces"), cell_count, doc, budget);
  doc.has_geometry = true;
}

// ---------------------------------------------------------------------------------------------------------------
// The document, section by section

/// No unknown top-level field; "format", "dimension" and the optional "description".
void read_header(const JsonField& root, Complex& c) {
  root.check_keys({"format", "dimension", "description", "halfspaces", "domain", "counts", "cells", "patches",
                   "supports", "junctions", "samples", "geometry"},
                  "an hsx-complex/1 document");
  const JsonField format = root.at("format");
  if (format.string() != kComplexFormat) {
    format.fail("expected \"" + std::string(kComplexFormat) + "\", got " + describe_json(format.json()));
  }
  const JsonField dimension = root.at("dimension");
  const std::int64_t d = dimension.integer();
  if (d != 2 && d != 3) dimension.fail("expected 2 or 3, got " + std::to_string(d));
  c.dimension = static_cast<int>(d);
  if (auto f = root.get("description")) (void)f->string();
}

/// "halfspaces": distinct non-empty names.
void read_halfspaces(const JsonField& f, Complex& c) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const JsonField h = f.at(i);
    std::string name = h.name();
    if (!seen.insert(name).second) h.fail("duplicate halfspace name " + describe_json(json(name)));
    c.halfspace_names.push_back(std::move(name));
  }
}

/// The optional "domain" box.
void read_domain(const JsonField& f, ComplexDocument& doc) {
  if (doc.complex.dimension == 3) {
    doc.domain3 = read_domain3(f);
    return;
  }
  f.check_keys({"min", "max"}, "a domain");
  Box2 box{f.at("min").point2(), f.at("max").point2()};
  if (!(box.min.x < box.max.x && box.min.y < box.max.y)) f.fail("min must be below max in both coordinates");
  doc.domain = box;
}

/// Dense per-cell and per-patch tables over the halfspaces must stay within kMaxTableEntries.
void check_table_size(const JsonField& root, std::size_t n_cells, std::size_t n_patches, std::size_t n_half) {
  if (std::uint64_t(n_cells) * n_half > kMaxTableEntries || std::uint64_t(n_patches) * n_half > kMaxTableEntries) {
    root.fail("too large: " + std::to_string(n_cells) + " cells and " + std::to_string(n_patches) + " patches over " +
              std::to_string(n_half) + " halfspaces exceed the limit of " + std::to_string(kMaxTableEntries) +
              " (cells or patches) x halfspaces");
  }
}

/// An index into the geometry's `what`s (count of them) when the document has a geometry section; without one,
/// any non-negative int (the caller's own numbering of `free_what`s).
int read_geometry_index(const JsonField& f, const ComplexDocument& doc, std::size_t count, const std::string& what,
                        const std::string& free_what) {
  if (doc.has_geometry) return read_index(f, count, what);
  const std::int64_t v = f.integer();
  if (v < 0 || v > INT32_MAX) f.fail("expected a non-negative " + free_what + " index, got " + std::to_string(v));
  return static_cast<int>(v);
}

/// cells[k] without its measure: outer, the optional witness point, the halfspaces it is inside.
Cell read_cell(const JsonField& f, std::size_t k, const Names& names, int dimension, std::size_t n_half) {
  f.check_keys({"id", "outer", "witness", "inside", "measure"}, "a cell");
  check_id(f, k);
  Cell cell;
  cell.outer = f.at("outer").boolean();
  if (auto w = f.get("witness")) {
    if (w->size() != static_cast<std::size_t>(dimension)) {
      w->fail("expected " + std::to_string(dimension) + " coordinates, got " + std::to_string(w->size()));
    }
    std::vector<Rational> point;
    for (std::size_t i = 0; i < w->size(); ++i) point.push_back(w->at(i).rational());
    cell.witness = std::move(point);
  }
  cell.inside.assign(n_half, 0);
  const JsonField in = f.at("inside");
  for (std::size_t i = 0; i < in.size(); ++i) {
    const int h = names(in.at(i));
    if (cell.inside[h]) in.at(i).fail("halfspace listed twice");
    cell.inside[h] = 1;
  }
  return cell;
}

/// "cells"; with geometry, each cell's area is its face's (a given "measure" is checked against it) and the face
/// takes the cell's outer flag, sides and witness.
void read_cells(const JsonField& cells, const Names& names, ComplexDocument& doc, Budget& budget) {
  Complex& c = doc.complex;
  c.cells.resize(cells.size());
  const std::vector<Rational> volumes =
      doc.has_geometry && c.dimension == 3 ? geometry3_volumes(doc, cells.size()) : std::vector<Rational>();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const JsonField f = cells.at(k);
    Cell& cell = c.cells[k] = read_cell(f, k, names, c.dimension, c.halfspace_names.size());
    if (!volumes.empty()) {
      if (sgn(volumes[k]) <= 0)
        f.fail("its triangles enclose a volume of " + exact_string(volumes[k]) + ", not a positive one");
      cell.measure = Measure(volumes[k]);
      if (auto m = f.get("measure")) check_measure(*m, cell.measure, "volume", budget);
    } else if (doc.has_geometry) {
      cell.measure = doc.face_areas[k];
      if (auto m = f.get("measure")) check_measure(*m, cell.measure, "area", budget);
      ArrFace2& face = doc.faces[k];
      face.outer = cell.outer;
      face.inside = cell.inside;
    } else {
      cell.measure = positive_measure_from_fields(f.at("measure"), budget, c.dimension == 3 ? "cell's volume" : "cell's area");
    }
  }
}

/// patches[p] without its measure: halfspace, the cells on its two sides (checked against the halfspace), pieces.
Patch read_patch(const JsonField& f, std::size_t p, const Names& names, const ComplexDocument& doc) {
  const Complex& c = doc.complex;
  f.check_keys({"id", "halfspace", "inside_cell", "outside_cell", "measure", "samples", "sample_ids", "support",
                "junctions", "pieces"},
               "a patch");
  check_id(f, p);
  Patch patch;
  patch.halfspace = names(f.at("halfspace"));
  patch.inside_cell = read_index(f.at("inside_cell"), c.cells.size(), "cell");
  patch.outside_cell = read_index(f.at("outside_cell"), c.cells.size(), "cell");
  const std::string hname = name_of(c.halfspace_names, patch.halfspace);
  if (patch.inside_cell == patch.outside_cell) f.at("outside_cell").fail("is the same cell as inside_cell");
  if (!c.cells[patch.inside_cell].inside[patch.halfspace]) {
    f.at("inside_cell").fail("cell " + std::to_string(patch.inside_cell) + " is not inside halfspace " + hname);
  }
  if (c.cells[patch.outside_cell].inside[patch.halfspace]) {
    f.at("outside_cell").fail("cell " + std::to_string(patch.outside_cell) + " is inside halfspace " + hname);
  }
  if (auto pieces = f.get("pieces"))
    for (std::size_t k = 0; k < pieces->size(); ++k)
      patch.pieces.push_back(c.dimension == 3
                                 ? read_geometry_index(pieces->at(k), doc, doc.triangles3.size(), "triangle", "piece")
                                 : read_geometry_index(pieces->at(k), doc, doc.edges.size(), "edge", "piece"));
  return patch;
}

/// With geometry: the patch's length from its edges, each checked to be a distinct edge on the patch's halfspace
/// between its two cells, off the box, sharing a vertex with the one before.
Measure patch_length(const JsonField& f, const Patch& patch, const ComplexDocument& doc, Budget& budget) {
  if (patch.pieces.empty()) f.fail("needs \"pieces\" (its edges) when the document has a geometry section");
  const JsonField pieces = f.at("pieces");
  budget.spend(patch.pieces.size(), pieces);
  std::vector<int> sorted = patch.pieces;
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) pieces.fail("lists edge " + std::to_string(*twice) + " twice");
  const std::string hname = name_of(doc.complex.halfspace_names, patch.halfspace);
  Measure length;
  for (std::size_t k = 0; k < patch.pieces.size(); ++k) {
    const JsonField where = pieces.at(k);
    const ArrEdge2& e = doc.edges[patch.pieces[k]];
    if (e.on_box) where.fail("edge " + std::to_string(patch.pieces[k]) + " lies on the domain box");
    if (!std::binary_search(e.halfspaces.begin(), e.halfspaces.end(), patch.halfspace)) {
      where.fail("edge " + std::to_string(patch.pieces[k]) + " is not on the boundary of halfspace " + hname);
    }
    if (std::minmax(e.left_face, e.right_face) != std::minmax(patch.inside_cell, patch.outside_cell)) {
      where.fail("edge " + std::to_string(patch.pieces[k]) + " separates faces " + std::to_string(e.left_face) +
                 " and " + std::to_string(e.right_face) + ", not the patch's cells");
    }
    if (k > 0) {
      const ArrEdge2& prev = doc.edges[patch.pieces[k - 1]];
      if (e.source != prev.source && e.source != prev.target && e.target != prev.source && e.target != prev.target) {
        where.fail("edge " + std::to_string(patch.pieces[k]) + " does not share a vertex with the previous piece");
      }
    }
    length += doc.edge_lengths[static_cast<std::size_t>(patch.pieces[k])];
  }
  return length;
}

/// "patches": the fields that stand alone, and each patch's measure (with geometry, its length recomputed and a
/// given "measure" checked against it).
void read_patches(const JsonField& patches, const Names& names, ComplexDocument& doc, Budget& budget) {
  Complex& c = doc.complex;
  c.patches.resize(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const JsonField f = patches.at(p);
    Patch& patch = c.patches[p] = read_patch(f, p, names, doc);
    const bool d3 = c.dimension == 3;
    if (doc.has_geometry) {
      patch.measure = d3 ? patch_area3(f, patch, doc, budget) : patch_length(f, patch, doc, budget);
      if (auto m = f.get("measure")) check_measure(*m, patch.measure, d3 ? "area" : "length", budget);
    } else {
      patch.measure = positive_measure_from_fields(f.at("measure"), budget, d3 ? "patch's area" : "patch's length");
    }
  }
}

/// "supports" given: groups of coinciding patches (on distinct halfspaces, separating the same cells), every
/// patch in exactly one.
void read_support_groups(const JsonField& s, Complex& c) {
  const std::size_t n_patches = c.patches.size();
  std::vector<int> group_of(n_patches, -1);
  c.supports.resize(s.size());
  for (std::size_t g = 0; g < s.size(); ++g) {
    const JsonField group = s.at(g);
    c.supports[g] = read_index_set(group, n_patches, "patch");
    if (c.supports[g].empty()) group.fail("an empty support group");
    std::set<int> group_halfspaces;
    const Patch& first = c.patches[c.supports[g].front()];
    for (int p : c.supports[g]) {
      if (group_of[p] >= 0) {
        group.fail("patch " + std::to_string(p) + " is already in support group " + std::to_string(group_of[p]));
      }
      group_of[p] = static_cast<int>(g);
      const Patch& patch = c.patches[p];
      if (!group_halfspaces.insert(patch.halfspace).second) {
        group.fail("two of its patches lie on halfspace " + name_of(c.halfspace_names, patch.halfspace));
      }
      if (std::minmax(patch.inside_cell, patch.outside_cell) != std::minmax(first.inside_cell, first.outside_cell)) {
        group.fail("patches " + std::to_string(c.supports[g].front()) + " and " + std::to_string(p) +
                   " separate different cells, so they cannot coincide");
      }
    }
  }
  for (std::size_t p = 0; p < n_patches; ++p) {
    if (group_of[p] < 0) s.fail("patch " + std::to_string(p) + " is in no support group");
    c.patches[p].support = group_of[p];
  }
}

/// The support groups ("supports", or one group per patch without it), then each patch's optional "support"
/// field checked against its group.
void read_supports(const std::optional<JsonField>& s, const JsonField& patches, Complex& c) {
  if (s) {
    read_support_groups(*s, c);
  } else {
    for (std::size_t p = 0; p < c.patches.size(); ++p) {
      c.supports.push_back({static_cast<int>(p)});
      c.patches[p].support = static_cast<int>(p);
    }
  }
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    if (auto f = patches.at(p).get("support")) {
      const std::int64_t v = f->integer();
      if (v != c.patches[p].support) {
        f->fail("is " + std::to_string(v) + " but the patch is in support group " +
                std::to_string(c.patches[p].support) +
                (s ? "" : " (without \"supports\", every patch is its own group)"));
      }
    }
  }
}

/// "samples": each on a patch of its halfspace.
void read_sample_sites(const JsonField& s, const Names& names, Complex& c) {
  c.samples.resize(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    const JsonField f = s.at(k);
    f.check_keys({"id", "halfspace", "patch"}, "a sample");
    check_id(f, k);
    SampleSite& site = c.samples[k];
    site.halfspace = names(f.at("halfspace"));
    site.patch = read_index(f.at("patch"), c.patches.size(), "patch");
    if (c.patches[site.patch].halfspace != site.halfspace) {
      f.at("halfspace").fail("is " + name_of(c.halfspace_names, site.halfspace) + " but patch " +
                             std::to_string(site.patch) + " lies on halfspace " +
                             name_of(c.halfspace_names, c.patches[site.patch].halfspace));
    }
  }
}

/// Each patch's samples (those sitting on it, ascending), checked against its optional "sample_ids" and
/// "samples" (a count) fields.
void attach_samples(const JsonField& patches, Complex& c) {
  std::vector<std::vector<int>> samples_on(c.patches.size());
  for (std::size_t k = 0; k < c.samples.size(); ++k) samples_on[c.samples[k].patch].push_back(static_cast<int>(k));
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const JsonField f = patches.at(p);
    Patch& patch = c.patches[p];
    patch.samples = samples_on[p];
    if (auto ids = f.get("sample_ids")) {
      const std::vector<int> given = read_index_set(*ids, c.samples.size(), "sample");
      for (int s : given)
        if (c.samples[s].patch != static_cast<int>(p)) {
          ids->fail("lists sample " + std::to_string(s) + ", which sits on patch " + std::to_string(c.samples[s].patch));
        }
      for (int s : patch.samples)
        if (!std::binary_search(given.begin(), given.end(), s)) {
          ids->fail("does not list sample " + std::to_string(s) + ", which sits on this patch");
        }
    }
    if (auto count = f.get("samples")) {
      const std::int64_t v = count->integer();
      if (v != static_cast<std::int64_t>(patch.samples.size())) {
        count->fail("is " + std::to_string(v) + " but " + std::to_string(patch.samples.size()) +
                    " samples sit on this patch");
      }
    }
  }
}

/// "junctions": each a set of patches and an optional vertex (a geometry vertex when there is geometry).
void read_junction_list(const JsonField& js, ComplexDocument& doc) {
  Complex& c = doc.complex;
  c.junctions.resize(js.size());
  for (std::size_t j = 0; j < js.size(); ++j) {
    const JsonField f = js.at(j);
    f.check_keys({"id", "patches", "vertex"}, "a junction");
    check_id(f, j);
    Junction& junction = c.junctions[j];
    junction.patches = read_index_set(f.at("patches"), c.patches.size(), "patch");
    if (auto v = f.get("vertex"))
      junction.piece = read_geometry_index(*v, doc, doc.vertices.size(), "vertex", "vertex");
  }
}

/// Each patch's junctions: its optional "junctions" field, which must list exactly the junctions that list the
/// patch (in any order); without it, those junctions ascending.
void attach_junctions(const JsonField& patches, Complex& c, Budget& budget) {
  std::vector<std::vector<int>> junctions_of(c.patches.size());
  for (std::size_t j = 0; j < c.junctions.size(); ++j)
    for (int p : c.junctions[j].patches) junctions_of[p].push_back(static_cast<int>(j));
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    Patch& patch = c.patches[p];
    auto list = patches.at(p).get("junctions");
    budget.spend(std::max<std::size_t>(junctions_of[p].size(), list ? list->size() : 0), patches.at(p));
    if (!list) {
      patch.junctions = junctions_of[p];
      continue;
    }
    for (std::size_t k = 0; k < list->size(); ++k) {
      const JsonField jf = list->at(k);
      const int j = read_index(jf, c.junctions.size(), "junction");
      if (!std::binary_search(c.junctions[j].patches.begin(), c.junctions[j].patches.end(), static_cast<int>(p))) {
        jf.fail("junction " + std::to_string(j) + " does not list this patch");
      }
      patch.junctions.push_back(j);
    }
    for (int j : junctions_of[p])
      if (std::find(patch.junctions.begin(), patch.junctions.end(), j) == patch.junctions.end()) {
        list->fail("does not list junction " + std::to_string(j) + ", which lists this patch");
      }
  }
}

/// The optional "counts": each given count must match the document (vertices and edges only with geometry).
void check_counts(const JsonField& counts, const ComplexDocument& doc) {
  const Complex& c = doc.complex;
  counts.check_keys({"vertices", "edges", "triangles", "cells", "outer_cells", "patches", "junctions", "samples"},
                    "counts");
  auto check = [&](const char* key, std::size_t actual, bool defined) {
    auto f = counts.get(key);
    if (!f || f->json().is_null()) return;
    if (!defined) f->fail("given, but the document has no geometry section");
    const std::int64_t v = f->integer();
    if (v < 0 || static_cast<std::uint64_t>(v) != actual) {
      f->fail("is " + std::to_string(v) + " but the document has " + std::to_string(actual));
    }
  };
  const bool d3 = c.dimension == 3;
  check("vertices", d3 ? doc.vertices3.size() : doc.vertices.size(), doc.has_geometry);
  check("edges", d3 ? edge_count3(doc.triangles3) : doc.edges.size(), doc.has_geometry);
  if (d3) check("triangles", doc.triangles3.size(), doc.has_geometry);
  check("cells", c.cells.size(), true);
  check("outer_cells", static_cast<std::size_t>(c.outer_cell_count()), true);
  check("patches", c.patches.size(), true);
  check("junctions", c.junctions.size(), true);
  check("samples", c.samples.size(), true);
}

/// The complex's own invariants (check_complex), the first 20 problems in the message.
void check_consistency(const Complex& c) {
  const std::vector<std::string> problems = check_complex(c);
  if (problems.empty()) return;
  std::string message = "the complex is inconsistent: ";
  const std::size_t shown = std::min<std::size_t>(problems.size(), 20);
  for (std::size_t k = 0; k < shown; ++k) message += (k ? "; " : "") + problems[k];
  if (problems.size() > shown) message += "; and " + std::to_string(problems.size() - shown) + " more";
  throw InputError(message);
}

/// The document in its outline's order: header, halfspaces, domain, geometry, cells, patches, supports, samples,
/// junctions, then the cross-checks (counts, the complex's invariants). Errors name the field and index.
ComplexDocument read_document(const json& document) {
  const JsonField root(document, "");
  ComplexDocument doc;
  Complex& c = doc.complex;
  Budget budget;
  read_header(root, c);
  read_halfspaces(root.at("halfspaces"), c);
  const Names names(c.halfspace_names);
  if (auto f = root.get("domain")) read_domain(*f, doc);
  const JsonField cells = root.at("cells");
  if (cells.size() == 0) cells.fail("a complex has at least one cell (the domain itself, when nothing divides it)");
  const JsonField patches = root.at("patches");
  check_table_size(root, cells.size(), patches.size(), c.halfspace_names.size());
  if (auto g = root.get("geometry")) read_geometry(*g, names, cells.size(), doc, budget);
  read_cells(cells, names, doc, budget);
  if (doc.has_geometry && c.dimension == 3) check_triangle_sides3(root.at("geometry").at("triangles"), doc);
  read_patches(patches, names, doc, budget);
  read_supports(root.get("supports"), patches, c);
  if (auto s = root.get("samples")) read_sample_sites(*s, names, c);
  attach_samples(patches, c);
  if (auto js = root.get("junctions")) read_junction_list(*js, doc);
  attach_junctions(patches, c, budget);
  if (auto counts = root.get("counts")) check_counts(*counts, doc);
  check_consistency(c);
  return doc;
}

json exact_pair(const Rational& x, const Rational& y) {
  json a = json::array();
  a.push_back(exact_string(x));
  a.push_back(exact_string(y));
  return a;
}

}  // namespace

// -----------------------------------------------------------------------------------------------------------------
// Public

std::optional<Measure> parse_closed_form(std::string_view text, std::string* why) {
  std::vector<Term> terms;
  if (!parse_terms(text, terms, why)) return std::nullopt;
  return sum_of(terms);
}

std::optional<OneRoot> parse_one_root(std::string_view text, std::string* why) {
  std::vector<Term> terms;
  if (!parse_terms(text, terms, why)) return std::nullopt;
  Rational a0 = 0, a1 = 0;
  std::optional<Rational> root;
  for (const Term& t : terms) {
    if (!t.radicand) {
      a0 += t.coefficient;
      continue;
    }
    if (sgn(*t.radicand) == 0) continue;
    if (root && *root != *t.radicand) {
      fail_with(why, "two different radicands; a one-root number has one");
      return std::nullopt;
    }
    root = *t.radicand;
    a1 += t.coefficient;
  }
  return OneRoot(a0, root ? a1 : Rational(0), root ? *root : Rational(0));
}

namespace {

/// cells[k] of the document.
json cell_json(const Complex& c, std::size_t k) {
  const Cell& cell = c.cells[k];
  json j = json::object();
  j["id"] = k;
  j["outer"] = cell.outer;
  json w = json::array();
  for (const Rational& x : cell.witness.get()) w.push_back(exact_string(x));
  j["witness"] = w;
  json inside = json::array();
  for (std::size_t i = 0; i < cell.inside.size(); ++i)
    if (cell.inside[i]) inside.push_back(c.halfspace_names.at(i));
  j["inside"] = inside;
  j["measure"] = measure_json(cell.measure);
  return j;
}

/// What a document says about the geometry the complex came from; null members are left out.
struct GeometryParts {
  json domain;
  json counts = json::object();  ///< vertices, edges (and triangles in 3D)
  json geometry;
};

/// The document without its "cells".
json complex_json_without_cells(const Complex& c, GeometryParts parts) {
  auto name = [&](int h) { return c.halfspace_names.at(static_cast<std::size_t>(h)); };
  json doc = json::object();
  doc["format"] = kComplexFormat;
  doc["dimension"] = c.dimension;
  doc["halfspaces"] = c.halfspace_names;
  if (!parts.domain.is_null()) doc["domain"] = std::move(parts.domain);
  json counts = std::move(parts.counts);
  counts["cells"] = c.cells.size();
  counts["outer_cells"] = c.outer_cell_count();
  counts["patches"] = c.patches.size();
  counts["junctions"] = c.junctions.size();
  counts["samples"] = c.samples.size();
  doc["counts"] = counts;


  json patches = json::array();
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const Patch& patch = c.patches[p];
    json j = json::object();
    j["id"] = p;
    j["halfspace"] = name(patch.halfspace);
    j["inside_cell"] = patch.inside_cell;
    j["outside_cell"] = patch.outside_cell;
    j["measure"] = measure_json(patch.measure);
    j["samples"] = patch.samples.size();
    j["sample_ids"] = patch.samples;
    j["support"] = patch.support;
    j["junctions"] = patch.junctions;
    j["pieces"] = patch.pieces;
    patches.push_back(std::move(j));
  }
  doc["patches"] = std::move(patches);
  doc["supports"] = c.supports;

  json junctions = json::array();
  for (std::size_t k = 0; k < c.junctions.size(); ++k) {
    json j = json::object();
    j["id"] = k;
    j["patches"] = c.junctions[k].patches;
    if (c.dimension == 2 && c.junctions[k].piece >= 0) j["vertex"] = c.junctions[k].piece;
    junctions.push_back(std::move(j));
  }
  doc["junctions"] = std::move(junctions);

  json samples = json::array();
  for (std::size_t k = 0; k < c.samples.size(); ++k) {
    json j = json::object();
    j["id"] = k;
    j["halfspace"] = name(c.samples[k].halfspace);
    j["patch"] = c.samples[k].patch;
    samples.push_back(std::move(j));
  }
  doc["samples"] = std::move(samples);
  if (!parts.geometry.is_null()) doc["geometry"] = std::move(parts.geometry);
  return doc;
}

/// The 2D geometry parts: the domain, and the arrangement's vertices, edges and faces.
GeometryParts geometry_parts(const Complex& c, const Arrangement2* geometry, const Box2* domain) {
  auto name = [&](int h) { return c.halfspace_names.at(static_cast<std::size_t>(h)); };
  GeometryParts parts;
  if (domain != nullptr) {
    parts.domain = json::object();
    parts.domain["min"] = exact_pair(domain->min.x, domain->min.y);
    parts.domain["max"] = exact_pair(domain->max.x, domain->max.y);
  }
  if (geometry != nullptr) {
    parts.counts["vertices"] = geometry->vertices().size();
    parts.counts["edges"] = geometry->edges().size();
    json g = json::object();
    json vertices = json::array();
    for (std::size_t k = 0; k < geometry->vertices().size(); ++k) {
      const ArrVertex2& v = geometry->vertices()[k];
      json j = json::object();
      j["id"] = k;
      json point = json::array();
      point.push_back(v.point.x.exact_string());
      point.push_back(v.point.y.exact_string());
      j["point"] = std::move(point);
      j["degree"] = v.degree;
      vertices.push_back(std::move(j));
    }
    json edges = json::array();
    for (std::size_t k = 0; k < geometry->edges().size(); ++k) {
      const ArrEdge2& e = geometry->edges()[k];
      json j = json::object();
      j["id"] = k;
      j["source"] = e.source;
      j["target"] = e.target;
      json hs = json::array();
      for (int h : e.halfspaces) hs.push_back(name(h));
      j["halfspaces"] = std::move(hs);
      j["on_box"] = e.on_box;
      j["left_face"] = e.left_face;
      j["right_face"] = e.right_face;
      if (e.shape == EdgeShape2::Segment) {
        j["shape"] = "segment";
        if (e.line_a != 0 || e.line_b != 0)
          j["line"] = json::array({exact_string(e.line_a), exact_string(e.line_b), exact_string(e.line_c)});
      } else {
        j["shape"] = "arc";
        j["center"] = exact_pair(e.center.x, e.center.y);
        j["radius"] = exact_string(e.radius);
        j["ccw"] = e.ccw;
      }
      edges.push_back(std::move(j));
    }
    json faces = json::array();
    for (std::size_t k = 0; k < geometry->faces().size(); ++k) {
      json walks = json::array();
      for (const auto& walk : geometry->faces()[k].boundary) {
        json steps = json::array();
        for (const auto& [e, forward] : walk) {
          json step = json::array();
          step.push_back(e);
          step.push_back(forward);
          steps.push_back(std::move(step));
        }
        walks.push_back(std::move(steps));
      }
      json j = json::object();
      j["id"] = k;
      j["boundary"] = std::move(walks);
      faces.push_back(std::move(j));
    }
    g["vertices"] = std::move(vertices);
    g["edges"] = std::move(edges);
    g["faces"] = std::move(faces);
    parts.geometry = std::move(g);
  }
  return parts;
}

/// The 3D geometry parts: the domain, and the arrangement's vertices and triangles.
GeometryParts geometry_parts(const Complex& c, const Arrangement3* geometry, const Box3* domain) {
  GeometryParts parts;
  if (domain != nullptr) parts.domain = box3_json(*domain);
  if (geometry != nullptr) {
    parts.counts["vertices"] = geometry->vertices().size();
    parts.counts["edges"] = geometry->edges().size();
    parts.counts["triangles"] = geometry->triangles().size();
    parts.geometry = geometry3_json(c, *geometry);
  }
  return parts;
}

json with_cells(const Complex& c, json doc) {
  json cells = json::array();
  for (std::size_t k = 0; k < c.cells.size(); ++k) cells.push_back(cell_json(c, k));
  doc["cells"] = std::move(cells);
  return doc;
}

/// with_cells(c, doc).dump(2) + "\n", byte for byte, with the cells written as text.
std::string text_with_cells(const Complex& c, json doc) {
  doc["cells"] = json::array();
  const std::string rest = doc.dump(2);
  // Keys are sorted, so the top-level "cells" comes first among the keys indented by two spaces; names inside
  // strings are escaped and cannot end a line with this pattern.
  const std::string placeholder = "\n  \"cells\": []";
  const std::size_t at = rest.find(placeholder);
  if (at == std::string::npos) throw std::logic_error("complex_json_text: no cells placeholder");
  std::string text = rest.substr(0, at);
  if (c.cells.empty()) {
    text += placeholder;
  } else {
    text += "\n  \"cells\": [\n";
    for (std::size_t k = 0; k < c.cells.size(); ++k) {
      text += "    ";
      for (char ch : cell_json(c, k).dump(2)) {
        text += ch;
        if (ch == '\n') text += "    ";
      }
      text += k + 1 < c.cells.size() ? ",\n" : "\n  ]";
    }
  }
  text.append(rest, at + placeholder.size(), std::string::npos);
  text += "\n";
  return text;
}

}  // namespace

json complex_to_json(const Complex& c, const Arrangement2* geometry, const Box2* domain) {
  return with_cells(c, complex_json_without_cells(c, geometry_parts(c, geometry, domain)));
}

std::string complex_json_text(const Complex& c, const Arrangement2* geometry, const Box2* domain) {
  return text_with_cells(c, complex_json_without_cells(c, geometry_parts(c, geometry, domain)));
}

json complex3_to_json(const Complex& c, const Arrangement3* geometry, const Box3* domain) {
  return with_cells(c, complex_json_without_cells(c, geometry_parts(c, geometry, domain)));
}

std::string complex3_json_text(const Complex& c, const Arrangement3* geometry, const Box3* domain) {
  return text_with_cells(c, complex_json_without_cells(c, geometry_parts(c, geometry, domain)));
}

ComplexDocument complex_document_from_json(const json& document) { return read_document(document); }

Complex complex_from_json(const json& document) { return read_document(document).complex; }

Complex read_complex_file(const std::string& path) {
  const json document = read_exact_json_file(path);
  try {
    return complex_from_json(document);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace hsx
