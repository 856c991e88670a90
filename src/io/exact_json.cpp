// Exact JSON: see exact_json.hpp.
//
// How numbers stay exact. nlohmann's SAX interface hands over the text of a decimal, but its parser refuses any
// number whose double conversion overflows (a 400-digit integer, 1e400) before calling the handler. So a first pass
// (scan_numbers) finds every number token outside strings, in document order, and replaces each one that is not a
// short plain integer by "0" padded with spaces to the same length (positions, hence line/column of errors, are
// unchanged). The SAX handler counts number events in the same order and substitutes the original text. The first
// pass only replaces tokens that match the JSON number grammar exactly, so it never turns invalid JSON into valid
// JSON, and on valid JSON its tokens are exactly the lexer's.
#include <hsx/io/exact_json.hpp>
#include <hsx/io/files.hpp>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

namespace hsx {

namespace {

using json = nlohmann::json;

constexpr std::size_t kNoOffset = static_cast<std::size_t>(-1);

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The JSON number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
bool is_json_number(std::string_view t) {
  std::size_t i = 0, n = t.size();
  if (i < n && t[i] == '-') ++i;
  if (i >= n || !is_digit(t[i])) return false;
  if (t[i] == '0') {
    ++i;
  } else {
    while (i < n && is_digit(t[i])) ++i;
  }
  if (i < n && t[i] == '.') {
    ++i;
    if (i >= n || !is_digit(t[i])) return false;
    while (i < n && is_digit(t[i])) ++i;
  }
  if (i < n && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
    if (i >= n || !is_digit(t[i])) return false;
    while (i < n && is_digit(t[i])) ++i;
  }
  return i == n;
}

bool is_plain_integer(std::string_view t) { return t.find_first_of(".eE") == std::string_view::npos; }

struct Scan {
  struct Replaced {
    std::size_t ordinal;        ///< among all number tokens, in document order
    std::size_t offset, size;   ///< the original text of the token
  };
  std::vector<Replaced> replaced;
  std::string rewritten;                                      ///< the text with replacements, when any
  std::size_t too_deep_offset = kNoOffset;                    ///< first '[' or '{' nested deeper than allowed
};

Scan scan_numbers(std::string_view text, int max_depth) {
  Scan scan;
  const std::size_t n = text.size();
  std::size_t ordinal = 0;
  long depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < n;) {
    char c = text[i];
    if (in_string) {
      if (c == '\\') {
        i += 2;
        continue;
      }
      if (c == '"') in_string = false;
      ++i;
      continue;
    }
    if (c == '"') {
      in_string = true;
      ++i;
      continue;
    }
    if (c == '[' || c == '{') {
      ++depth;
      if (depth > max_depth && scan.too_deep_offset == kNoOffset) scan.too_deep_offset = i;
      ++i;
      continue;
    }
    if (c == ']' || c == '}') {
      --depth;
      ++i;
      continue;
    }
    if (c == '-' || is_digit(c)) {
      std::size_t j = i;
      while (j < n && (is_digit(text[j]) || text[j] == '+' || text[j] == '-' || text[j] == '.' || text[j] == 'e' ||
                       text[j] == 'E')) {
        ++j;
      }
      std::string_view token = text.substr(i, j - i);
      if (is_json_number(token)) {
        std::size_t digits = token.size() - (token[0] == '-' ? 1 : 0);
        if (!is_plain_integer(token) || digits > 18) {
          if (scan.rewritten.empty()) scan.rewritten.assign(text.data(), text.size());
          scan.replaced.push_back({ordinal, i, j - i});
          scan.rewritten[i] = '0';
          for (std::size_t k = i + 1; k < j; ++k) scan.rewritten[k] = ' ';
        }
      }
      ++ordinal;
      i = j;
      continue;
    }
    ++i;
  }
  return scan;
}

/// 1-based line and column (in bytes) of the byte at `offset`.
std::string line_column(std::string_view text, std::size_t offset) {
  if (offset > text.size()) offset = text.size();
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(offset - line_start + 1);
}

/// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1, column 2: " prefix.
std::string strip_nlohmann_prefix(const std::string& what) {
  std::size_t col = what.find("column ");
  if (col != std::string::npos) {
    std::size_t colon = what.find(": ", col);
    if (colon != std::string::npos) return what.substr(colon + 2);
  }
  std::size_t bracket = what.find("] ");
  if (bracket != std::string::npos) return what.substr(bracket + 2);
  return what;
}

std::string truncate(const std::string& s, std::size_t max) {
  if (s.size() <= max) return s;
  return s.substr(0, max) + "...";
}

/// Builds the DOM, with exact numbers, depth limit, and rejection of duplicate and reserved keys.
class ExactSax {
 public:
  ExactSax(json& root, const Scan& scan, std::string_view original, int max_depth)
      : root_(root), scan_(scan), original_(original), max_depth_(max_depth) {}

  bool null() { return value(json(nullptr)); }
  bool boolean(bool b) { return value(json(b)); }
  bool number_integer(json::number_integer_t v) { return number(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return number(json(v)); }
  bool number_float(json::number_float_t /*v*/, const json::string_t& text) { return number(make_exact_number(text)); }
  bool string(json::string_t& s) { return value(json(std::move(s))); }
  bool binary(json::binary_t& /*b*/) {
    message_ = "binary values are not supported";
    return false;
  }

  bool start_object(std::size_t /*elements*/) { return open(json::object()); }
  bool start_array(std::size_t /*elements*/) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(json::string_t& k) {
    Level& top = stack_.back();
    if (k == kExactNumberKey) {
      message_ = (top.path.empty() ? std::string("document") : top.path) + ": the key \"" + kExactNumberKey +
                 "\" is reserved";
      return false;
    }
    if (top.node->contains(k)) {
      message_ = (top.path.empty() ? std::string("document") : top.path) + ": duplicate key " +
                 describe_json(json(k));
      return false;
    }
    top.key = std::move(k);
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& ex) {
    // nlohmann counts the bytes read, end of input included, up to the end of the offending token. We point at the
    // last byte read (where parsing failed), except for string and number tokens, which the lexer collects afresh
    // so that their text is exact: there we point at the token's first byte. Control characters are spelt
    // "<U+0001>" in the token text, so those tokens fall back to the last byte. End of input: just past the end.
    const std::string what = ex.what();
    const bool token_error = what.find("unexpected string literal") != std::string::npos ||
                             what.find("unexpected number literal") != std::string::npos ||
                             what.find("invalid string") != std::string::npos ||
                             what.find("invalid number") != std::string::npos;
    if (position > original_.size()) {
      error_offset_ = original_.size();
    } else if (position == 0) {
      error_offset_ = 0;
    } else if (token_error && !last_token.empty() && last_token.size() <= position &&
               last_token.find("<U+") == std::string::npos) {
      error_offset_ = position - last_token.size();
    } else {
      error_offset_ = position - 1;
      // an unexpected literal was read whole: point at its first letter
      for (const char* literal : {"true", "false", "null"}) {
        const std::size_t len = std::strlen(literal);
        if (what.find(std::string("unexpected ") + literal + " literal") != std::string::npos && position >= len) {
          error_offset_ = position - len;
        }
      }
    }
    message_ = strip_nlohmann_prefix(what);
    // "last read: '...'" quotes the text nlohmann parsed, in which long numbers were replaced by "0   ": quote the
    // original bytes (same offsets) instead.
    const std::string quoted_token = "last read: '" + last_token + "'";
    std::size_t at = message_.find(quoted_token);
    if (at != std::string::npos && last_token.find("<U+") == std::string::npos && last_token.size() <= position &&
        position <= original_.size()) {
      message_.replace(at, quoted_token.size(),
                       "last read: '" + std::string(original_.substr(position - last_token.size(), last_token.size())) +
                           "'");
    }
    return false;
  }

  const std::string& message() const { return message_; }
  std::size_t error_offset() const { return error_offset_; }

 private:
  struct Level {
    json* node;
    std::string path;
    std::string key;  // current key (objects)
  };

  std::string child_path() const {
    if (stack_.empty()) return "";
    const Level& top = stack_.back();
    if (top.node->is_array()) return json_element_path(top.path, top.node->size());
    return json_member_path(top.path, top.key);
  }

  json* place(json v) {
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Level& top = stack_.back();
    if (top.node->is_array()) {
      top.node->push_back(std::move(v));
      return &top.node->back();
    }
    json& slot = (*top.node)[top.key];
    slot = std::move(v);
    return &slot;
  }

  bool value(json v) {
    place(std::move(v));
    return true;
  }

  bool number(json v) {
    std::size_t ordinal = ordinal_++;
    if (next_ < scan_.replaced.size() && scan_.replaced[next_].ordinal == ordinal) {
      const Scan::Replaced& r = scan_.replaced[next_++];
      std::string text(original_.substr(r.offset, r.size));
      if (is_plain_integer(text)) {
        errno = 0;
        char* end = nullptr;
        if (text[0] == '-') {
          long long s = std::strtoll(text.c_str(), &end, 10);
          if (errno == 0 && *end == '\0') return value(json(static_cast<json::number_integer_t>(s)));
        } else {
          unsigned long long u = std::strtoull(text.c_str(), &end, 10);
          if (errno == 0 && *end == '\0') return value(json(static_cast<json::number_unsigned_t>(u)));
        }
      }
      return value(make_exact_number(std::move(text)));
    }
    return value(std::move(v));
  }

  bool open(json v) {
    if (static_cast<long>(stack_.size()) + 1 > max_depth_) {
      message_ = "nesting deeper than " + std::to_string(max_depth_) + " levels";
      error_offset_ = scan_.too_deep_offset;
      return false;
    }
    std::string path = child_path();
    json* node = place(std::move(v));
    stack_.push_back({node, std::move(path), {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  json& root_;
  const Scan& scan_;
  std::string_view original_;  // the text as given (before number replacement); same length as the parsed one
  long max_depth_;
  std::vector<Level> stack_;
  std::size_t ordinal_ = 0, next_ = 0;
  std::string message_;
  std::size_t error_offset_ = kNoOffset;
};

bool is_identifier(std::string_view key) {
  if (key.empty()) return false;
  for (std::size_t i = 0; i < key.size(); ++i) {
    char c = key[i];
    bool ok = c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (i > 0 && is_digit(c));
    if (!ok) return false;
  }
  return true;
}

}  // namespace

// -----------------------------------------------------------------------------------------------------------------

json parse_exact_json(std::string_view text, const JsonLimits& limits) {
  if (text.size() > limits.max_bytes) {
    throw InputError("input is " + std::to_string(text.size()) + " bytes; the limit is " +
                     std::to_string(limits.max_bytes));
  }
  Scan scan = scan_numbers(text, limits.max_depth);
  std::string_view input = scan.rewritten.empty() ? text : std::string_view(scan.rewritten);
  json root;
  ExactSax sax(root, scan, text, limits.max_depth);
  bool ok = json::sax_parse(input.data(), input.data() + input.size(), &sax, json::input_format_t::json,
                            /*strict=*/true, /*ignore_comments=*/false);
  if (!ok) {
    std::string message = sax.message().empty() ? std::string("invalid JSON") : sax.message();
    if (sax.error_offset() != kNoOffset) message = line_column(text, sax.error_offset()) + ": " + message;
    throw InputError(message);
  }
  return root;
}

namespace {
json parse_file_text(const std::string& path, const std::string& text, const JsonLimits& limits) {
  try {
    return parse_exact_json(text, limits);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}
}  // namespace

json read_exact_json_file(const std::string& path, const JsonLimits& limits) {
  return parse_file_text(path, read_file(path, limits.max_bytes), limits);  // a FIFO or device: never blocks
}

bool is_exact_number(const json& value) {
  if (!value.is_object() || value.size() != 1) return false;
  auto it = value.find(kExactNumberKey);
  return it != value.end() && it->is_string();
}

json make_exact_number(std::string text) {
  json j(json::value_t::object);
  j.get_ref<json::object_t&>().emplace(kExactNumberKey, std::move(text));
  return j;
}

std::optional<Rational> json_rational(const json& value, std::string* why, const NumberLimits& limits) {
  auto set_why = [&](std::string s) {
    if (why != nullptr) *why = std::move(s);
  };
  if (value.is_number_unsigned()) return Rational(Integer(std::to_string(value.get<std::uint64_t>())));
  if (value.is_number_integer()) return Rational(Integer(std::to_string(value.get<std::int64_t>())));
  if (is_exact_number(value)) {
    const std::string& text = value.find(kExactNumberKey)->get_ref<const std::string&>();
    std::string reason;
    if (auto q = parse_rational(text, &reason, limits)) return q;
    set_why("the number " + truncate(text, 40) + " is not accepted" + (reason.empty() ? "" : ": " + reason));
    return std::nullopt;
  }
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    std::string reason;
    if (auto q = parse_rational(text, &reason, limits)) return q;
    bool looks_numeric = !text.empty() && (is_digit(text[0]) || text[0] == '-' || text[0] == '+' || text[0] == '.');
    set_why("expected a number, got " + describe_json(value) +
            (looks_numeric && !reason.empty() ? " (" + reason + ")" : ""));
    return std::nullopt;
  }
  if (value.is_number_float()) {
    set_why("got the binary floating-point number " + value.dump() +
            ", whose decimal text is lost (parse the document with parse_exact_json)");
    return std::nullopt;
  }
  set_why("expected a number, got " + describe_json(value));
  return std::nullopt;
}

json rational_to_json(const Rational& q) {
  if (q.get_den() == 1 && q.get_num().fits_slong_p() && sizeof(long) == sizeof(std::int64_t)) {
    return json(static_cast<std::int64_t>(q.get_num().get_si()));
  }
  return json(exact_string(q));
}

std::string describe_json(const json& value) {
  constexpr std::size_t kMax = 40;
  if (is_exact_number(value)) return truncate(value.find(kExactNumberKey)->get<std::string>(), kMax);
  switch (value.type()) {
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    case json::value_t::string: {
      std::string s = value.dump(-1, ' ', false, json::error_handler_t::replace);
      if (s.size() > kMax) s = s.substr(0, kMax) + "...\"";
      return s;
    }
    case json::value_t::number_float:
      return value.dump() + " (a binary floating-point number)";
    case json::value_t::binary:
      return "binary data";
    case json::value_t::discarded:
      return "nothing";
    default:
      return value.dump();
  }
}

std::string json_member_path(const std::string& parent, std::string_view key) {
  if (is_identifier(key)) return parent.empty() ? std::string(key) : parent + "." + std::string(key);
  return parent + "[" + describe_json(json(std::string(key))) + "]";
}

std::string json_element_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

// -----------------------------------------------------------------------------------------------------------------
// JsonField

void JsonField::fail(const std::string& what) const { throw InputError(where() + ": " + what); }

void JsonField::expect_object() const {
  if (!value_->is_object() || is_exact_number(*value_)) fail("expected an object, got " + describe_json(*value_));
}

void JsonField::check_keys(std::initializer_list<std::string_view> allowed, const std::string& what) const {
  expect_object();
  for (const auto& [key, v] : value_->items()) {
    (void)v;
    bool ok = false;
    for (std::string_view a : allowed) ok = ok || key == a;
    if (ok) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail("unknown field " + describe_json(nlohmann::json(key)) + (what.empty() ? "" : " for " + what) +
         " (expected one of: " + list + ")");
  }
}

bool JsonField::has(std::string_view key) const {
  expect_object();
  return value_->find(std::string(key)) != value_->end();
}

JsonField JsonField::at(std::string_view key) const {
  expect_object();
  auto it = value_->find(std::string(key));
  if (it == value_->end()) fail("missing field " + describe_json(nlohmann::json(std::string(key))));
  return JsonField(*it, json_member_path(path_, key));
}

std::optional<JsonField> JsonField::get(std::string_view key) const {
  expect_object();
  auto it = value_->find(std::string(key));
  if (it == value_->end()) return std::nullopt;
  return JsonField(*it, json_member_path(path_, key));
}

std::size_t JsonField::size() const {
  if (!value_->is_array()) fail("expected an array, got " + describe_json(*value_));
  return value_->size();
}

JsonField JsonField::at(std::size_t index) const {
  if (index >= size()) fail("index " + std::to_string(index) + " is out of range");
  return JsonField((*value_)[index], json_element_path(path_, index));
}

std::string JsonField::string() const {
  if (!value_->is_string()) fail("expected a string, got " + describe_json(*value_));
  return value_->get<std::string>();
}

std::string JsonField::name() const {
  std::string s = string();
  if (s.empty()) fail("the name must not be empty");
  for (const char c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      fail("the name " + describe_json(*value_) + " has a control character; names are printed in reports");
  return s;
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + describe_json(*value_));
  return value_->get<bool>();
}

std::int64_t JsonField::integer() const {
  if (value_->is_number_unsigned()) {
    auto u = value_->get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(INT64_MAX)) fail("integer " + value_->dump() + " is too large");
    return static_cast<std::int64_t>(u);
  }
  if (!value_->is_number_integer()) fail("expected an integer, got " + describe_json(*value_));
  return value_->get<std::int64_t>();
}

Rational JsonField::rational(const NumberLimits& limits) const {
  std::string why;
  auto q = json_rational(*value_, &why, limits);
  if (!q) fail(why);
  return *q;
}

PointQ2 JsonField::point2(const NumberLimits& limits) const {
  if (!value_->is_array()) fail("expected a point [x, y], got " + describe_json(*value_));
  if (value_->size() != 2) {
    fail("expected a point [x, y] with 2 coordinates, got " + std::to_string(value_->size()));
  }
  return PointQ2{at(std::size_t{0}).rational(limits), at(std::size_t{1}).rational(limits)};
}

}  // namespace hsx
