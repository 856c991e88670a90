// CSG text and JSON forms: see csg_text.hpp.
#include <hsx/io/csg_text.hpp>

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace hsx {

namespace {

using json = nlohmann::json;

std::unordered_map<std::string, int> name_index(const std::vector<std::string>& names) {
  std::unordered_map<std::string, int> index;
  for (std::size_t i = 0; i < names.size(); ++i) index.emplace(names[i], static_cast<int>(i));
  return index;
}

std::string quote_name(const std::string& s) { return describe_json(json(s)); }

bool name_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool name_char(char c) { return name_start(c) || (c >= '0' && c <= '9') || c == '.'; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string show_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "\\x%02X", u);
  return std::string("byte ") + buffer;
}

class TextParser {
 public:
  TextParser(std::string_view text, const std::vector<std::string>& names, const std::string& where)
      : text_(text), index_(name_index(names)), where_(where) {}

  csg::ExprPtr parse() {
    if (text_.size() > kCsgTextMaxChars) {
      throw InputError(where_ + ": the expression is " + std::to_string(text_.size()) +
                       " characters; the limit is " + std::to_string(kCsgTextMaxChars));
    }
    skip();
    if (pos_ == text_.size()) fail("empty expression", pos_);
    csg::ExprPtr e = expr();
    skip();
    if (pos_ < text_.size()) {
      if (text_[pos_] == ')') fail("unmatched ')'", pos_);
      fail("unexpected " + describe(pos_) + " (expected an operator or the end)", pos_);
    }
    return e;
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::size_t at) const {
    throw InputError(where_ + ": " + what + " at column " + std::to_string(at + 1));
  }

  void skip() {
    while (pos_ < text_.size() && blank(text_[pos_])) ++pos_;
  }

  /// Skips blanks and returns the next character (0 at the end).
  char peek() {
    skip();
    return pos_ < text_.size() ? text_[pos_] : '\0';
  }

  std::string describe(std::size_t at) const {
    if (at >= text_.size()) return "end of the expression";
    return show_char(text_[at]);
  }

  csg::ExprPtr expr() {
    std::vector<csg::ExprPtr> terms{diff()};
    for (char c = peek(); c == '|' || c == '+'; c = peek()) {
      ++pos_;
      terms.push_back(diff());
    }
    return terms.size() == 1 ? terms[0] : csg::unite(std::move(terms));
  }

  csg::ExprPtr diff() {
    csg::ExprPtr e = conj();
    while (peek() == '-') {
      ++pos_;
      e = csg::difference(std::move(e), conj());
    }
    return e;
  }

  csg::ExprPtr conj() {
    std::vector<csg::ExprPtr> factors{unary()};
    for (char c = peek(); c == '&' || c == '*'; c = peek()) {
      ++pos_;
      factors.push_back(unary());
    }
    return factors.size() == 1 ? factors[0] : csg::intersect(std::move(factors));
  }

  csg::ExprPtr unary() {
    const char c = peek();
    const std::size_t start = pos_;
    if (c == '~' || c == '(') {
      if (depth_ >= kCsgMaxDepth) fail("nesting deeper than " + std::to_string(kCsgMaxDepth), start);
      ++depth_;
      ++pos_;
      csg::ExprPtr e;
      if (c == '~') {
        e = csg::complement(unary());
      } else {
        e = expr();
        if (peek() != ')') {
          fail("missing ')' for the '(' at column " + std::to_string(start + 1) + ": found " + describe(pos_),
               pos_);
        }
        ++pos_;
      }
      --depth_;
      return e;
    }
    if (c == '"') return quoted_name();
    if (pos_ < text_.size() && name_start(c)) {
      while (pos_ < text_.size() && name_char(text_[pos_])) ++pos_;
      const std::string name(text_.substr(start, pos_ - start));
      if (name == "empty") return csg::empty();
      if (name == "full") return csg::full();
      return lookup(name, start);
    }
    fail("expected a halfspace name, '(', '~', empty or full, found " + describe(pos_), pos_);
  }

  csg::ExprPtr quoted_name() {
    const std::size_t start = pos_;
    ++pos_;
    std::string name;
    while (true) {
      if (pos_ >= text_.size()) fail("unterminated quoted name starting", start);
      const char c = text_[pos_++];
      if (c == '"') break;
      if (c == '\\') {
        if (pos_ >= text_.size()) fail("unterminated quoted name starting", start);
        const char d = text_[pos_++];
        if (d != '"' && d != '\\') fail("unknown escape \\" + std::string(1, d) + " (only \\\" and \\\\)", pos_ - 2);
        name += d;
      } else {
        name += c;
      }
    }
    return lookup(name, start);
  }

  csg::ExprPtr lookup(const std::string& name, std::size_t at) const {
    auto it = index_.find(name);
    if (it == index_.end()) fail("unknown halfspace " + quote_name(name), at);
    return csg::leaf(it->second);
  }

  std::string_view text_;
  std::unordered_map<std::string, int> index_;
  std::string where_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

csg::ExprPtr from_json(const JsonField& f, const std::unordered_map<std::string, int>& index, int depth) {
  f.expect_object();
  if (depth > kCsgMaxDepth) f.fail("expression nested deeper than " + std::to_string(kCsgMaxDepth));
  if (f.has("halfspace")) {
    f.check_keys({"halfspace"}, "a halfspace leaf");
    JsonField h = f.at("halfspace");
    const std::string name = h.string();
    auto it = index.find(name);
    if (it == index.end()) h.fail("unknown halfspace " + quote_name(name));
    return csg::leaf(it->second);
  }
  if (!f.has("op")) f.fail("missing field \"op\" (or \"halfspace\" for a leaf)");
  f.check_keys({"op", "args"}, "an operation");
  JsonField opf = f.at("op");
  const std::string op = opf.string();
  std::vector<csg::ExprPtr> args;
  const auto args_field = f.get("args");
  if (args_field) {
    const std::size_t n = args_field->size();
    if (op == "union" || op == "intersection" || op == "difference" || op == "complement") {
      args.reserve(n);
      for (std::size_t i = 0; i < n; ++i) args.push_back(from_json(args_field->at(i), index, depth + 1));
    }
  }
  const std::size_t n = args_field ? args_field->size() : 0;
  auto need = [&](bool ok, const std::string& what) {
    if (ok) return;
    if (args_field) args_field->fail(what + ", got " + std::to_string(n));
    f.fail("missing field \"args\" (" + what + ")");
  };
  if (op == "union" || op == "intersection") {
    need(n >= 1, "\"" + op + "\" needs at least one argument");
    return op == "union" ? csg::unite(std::move(args)) : csg::intersect(std::move(args));
  }
  if (op == "difference") {
    need(n == 2, "\"difference\" needs exactly two arguments");
    return csg::difference(args[0], args[1]);
  }
  if (op == "complement") {
    need(n == 1, "\"complement\" needs exactly one argument");
    return csg::complement(args[0]);
  }
  if (op == "empty" || op == "full") {
    if (n != 0) args_field->fail("\"" + op + "\" takes no argument, got " + std::to_string(n));
    return op == "empty" ? csg::empty() : csg::full();
  }
  opf.fail("unknown operation " + quote_name(op) +
           " (expected union, intersection, difference, complement, empty or full)");
}


/// A tree of depth kCsgMaxDepth nests two JSON levels per node (the object and its "args"), plus the wrapper.
JsonLimits csg_json_limits() {
  JsonLimits limits;
  limits.max_bytes = std::size_t{64} << 20;
  limits.max_depth = 2 * kCsgMaxDepth + 4;
  return limits;
}

csg::ExprPtr interpret_document(const json& doc, const std::vector<std::string>& names, const std::string& where) {
  if (doc.is_string()) return parse_csg_text(doc.get<std::string>(), names, where);
  JsonField root(doc, "");
  root.expect_object();
  if (root.has("csg")) {
    root.check_keys({"csg", "description"}, "a CSG file");
    if (auto d = root.get("description")) (void)d->string();
    JsonField c = root.at("csg");
    if (c.json().is_string()) return parse_csg_text(c.json().get<std::string>(), names, where + ": csg");
    return csg_from_json(c.json(), names, "csg");
  }
  return csg_from_json(doc, names, "");
}

}  // namespace

csg::ExprPtr parse_csg_text(std::string_view text, const std::vector<std::string>& names, const std::string& where) {
  return TextParser(text, names, where).parse();
}

csg::ExprPtr csg_from_json(const json& value, const std::vector<std::string>& names, const std::string& path) {
  return from_json(JsonField(value, path), name_index(names), 0);
}

json csg_to_json(const csg::Expr& e, const std::vector<std::string>& names) {
  return csg::fold<json>(e, [&](const csg::Expr& n, std::vector<json> v) -> json {
    auto op = [&](const char* name) {
      json out = json::object();
      out["op"] = name;
      out["args"] = json::array();
      for (json& a : v) out["args"].push_back(std::move(a));
      return out;
    };
    switch (n.op) {
      case csg::Op::Halfspace:
        if (n.halfspace < 0 || static_cast<std::size_t>(n.halfspace) >= names.size())
          throw std::invalid_argument("csg_to_json: halfspace index " + std::to_string(n.halfspace) + " out of range");
        return json{{"halfspace", names[static_cast<std::size_t>(n.halfspace)]}};
      case csg::Op::Empty: return json{{"op", "empty"}};
      case csg::Op::Full: return json{{"op", "full"}};
      case csg::Op::Complement: return op("complement");
      case csg::Op::Union: return op("union");
      case csg::Op::Intersection: return op("intersection");
      case csg::Op::Difference: return op("difference");
    }
    return json();
  });
}

csg::ExprPtr read_csg_argument(const std::string& arg, const std::vector<std::string>& names) {
  std::error_code ec;
  if (!arg.empty() && std::filesystem::is_regular_file(arg, ec)) {
    const json doc = read_exact_json_file(arg, csg_json_limits());
    try {
      return interpret_document(doc, names, arg);
    } catch (const InputError& e) {
      const std::string what = e.what();
      // Text errors already carry the path (interpret_document passed it as `where`).
      if (what.compare(0, arg.size() + 1, arg + ":") == 0) throw;
      throw InputError(arg + ": " + what);
    }
  }
  std::size_t first = 0;
  while (first < arg.size() && blank(arg[first])) ++first;
  if (first < arg.size() && arg[first] == '{') {
    try {
      const json doc = parse_exact_json(arg, csg_json_limits());
      return interpret_document(doc, names, "--csg");
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (what.compare(0, 6, "--csg:") == 0) throw;
      throw InputError("--csg: " + what);
    }
  }
  return parse_csg_text(arg, names, "--csg");
}

}  // namespace hsx
