// JSON that keeps numbers exact, and a reader of JSON fields whose errors name the JSON path.
//
// nlohmann::json parses decimals into binary doubles (0.1 would not be 1/10) and rejects numbers beyond the double
// range. parse_exact_json instead builds a DOM in which
//   - an integer that fits int64/uint64 is a JSON integer, as usual;
//   - every other number (decimal, exponent, or an integer too large) is the marker object {"$exact": "<text>"}
//     holding the number exactly as written, so a number never silently becomes a string or a double.
// The key "$exact" is reserved: a document that uses it itself is rejected. Duplicate keys are rejected.
//
// Errors are hsx::InputError with messages of the form
//   "line 3, column 7: syntax error while parsing object - unexpected '}'; expected string literal"
//   "halfspaces[2].radius: expected a number, got \"abc\""
#pragma once

#include <hsx/geometry/scene.hpp>  // InputError, PointQ2
#include <hsx/kernel/rational.hpp>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace hsx {

struct JsonLimits {
  std::size_t max_bytes = std::size_t{64} << 20;  ///< 64 MiB of text
  int max_depth = 64;                             ///< nesting of arrays and objects
};

/// Parses `text` keeping numbers exact (see above). Throws InputError "line L, column C: ..." on invalid JSON, too
/// deep nesting, duplicate or reserved keys; "input is N bytes; the limit is M" when too large.
nlohmann::json parse_exact_json(std::string_view text, const JsonLimits& limits = {});

/// Reads a whole file with read_file (io/files.hpp: "-" is standard input; the size is checked before reading) and
/// parses it with parse_exact_json. Parse errors are prefixed with the path: "scene.json: line 3, column 7: ...".
nlohmann::json read_exact_json_file(const std::string& path, const JsonLimits& limits = {});

/// The reserved marker key.
inline constexpr const char* kExactNumberKey = "$exact";
/// True for {"$exact": "<text>"}.
bool is_exact_number(const nlohmann::json& value);
/// Builds the marker {"$exact": text}.
nlohmann::json make_exact_number(std::string text);

/// An exact rational from a JSON value: an integer, an exact-number marker, or a string spelling an integer, a
/// decimal, a fraction or a scientific number (parse_rational). Binary doubles (from a plain nlohmann parse) are
/// refused: their decimal text is lost. On failure returns nullopt and sets *why, e.g.
/// "expected a number, got \"abc\"".
std::optional<Rational> json_rational(const nlohmann::json& value, std::string* why = nullptr,
                                      const NumberLimits& limits = {});

/// JSON for an exact rational, for writing: a JSON integer when it is an integer fitting int64, otherwise the
/// exact string ("-7/3", or the digits of a big integer). json_rational reads it back exactly.
nlohmann::json rational_to_json(const Rational& q);

/// Short rendering of a value for error messages: "\"abc\"" (truncated), "3", "1e999" (a marker's text), "true",
/// "null", "an object", "an array".
std::string describe_json(const nlohmann::json& value);

/// Path text of an object member: `parent.key`, or `parent["odd key"]` when the key is not an identifier; the
/// document root is the empty path.
std::string json_member_path(const std::string& parent, std::string_view key);
/// Path text of an array element: `parent[i]`.
std::string json_element_path(const std::string& parent, std::size_t index);

/// A JSON value together with its path in the document. Every accessor checks the type and throws InputError
/// "<path>: <what>" (the root is named "document"). Cheap to copy (holds a reference to the value).
class JsonField {
 public:
  JsonField(const nlohmann::json& value, std::string path) : value_(&value), path_(std::move(path)) {}

  const nlohmann::json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  /// The path as printed in messages ("document" for the root).
  std::string where() const { return path_.empty() ? "document" : path_; }
  [[noreturn]] void fail(const std::string& what) const;

  // Objects
  void expect_object() const;
  /// Rejects any member not in `allowed`: "<path>: unknown field \"color\" (expected one of: name, kind, ...)".
  /// `what` (e.g. "a disk") is added to the message when non-empty.
  void check_keys(std::initializer_list<std::string_view> allowed, const std::string& what = "") const;
  bool has(std::string_view key) const;
  /// Required member: "<path>: missing field \"radius\"".
  JsonField at(std::string_view key) const;
  /// Optional member (nullopt when absent).
  std::optional<JsonField> get(std::string_view key) const;

  // Arrays
  /// Number of elements; "<path>: expected an array, got ..." otherwise.
  std::size_t size() const;
  JsonField at(std::size_t index) const;

  // Scalars
  std::string string() const;
  /// A halfspace's name: a non-empty string without control characters (U+0000-U+001F, U+007F; hsx prints names
  /// in its reports, where they would reach a terminal as escape sequences). Fails naming the field otherwise.
  std::string name() const;
  bool boolean() const;
  std::int64_t integer() const;  ///< a JSON integer (no decimals, no strings)
  Rational rational(const NumberLimits& limits = {}) const;
  /// [x, y], two exact numbers.
  PointQ2 point2(const NumberLimits& limits = {}) const;

 private:
  const nlohmann::json* value_;
  std::string path_;
};

}  // namespace hsx
