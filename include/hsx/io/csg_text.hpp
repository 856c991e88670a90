// CSG expressions as text and as JSON (see algorithms/csg/expression.hpp for the expressions themselves).
//
// Text form (what csg::to_text writes), for example `(A & B) | ~C`:
//   expr  := diff ('|' diff)*          union, lowest precedence
//   diff  := conj ('-' conj)*          difference, left-associative: A - B - C = (A - B) - C
//   conj  := unary ('&' unary)*        intersection
//   unary := '~' unary | '(' expr ')' | NAME | "quoted name" | 'empty' | 'full'
// - `+` is accepted as a synonym of `|` and `*` of `&` (CSGNet's spelling); to_text writes `|` and `&`.
// - NAME is [A-Za-z_][A-Za-z0-9_.]* and must be a halfspace name; `empty` and `full` are the constants (a
//   halfspace actually named "empty" or "full" is written quoted). A quoted name may contain any character;
//   `\"` and `\\` escape a quote and a backslash.
// - Blanks (space, tab, newline, carriage return) between tokens are ignored.
// - Limits: 100,000 characters, nesting depth 200 (each '(' and each '~' is one level).
// Errors are hsx::InputError "--csg: <what> at column N" (columns count bytes from 1), e.g.
//   --csg: unknown halfspace "X" at column 7
//
// JSON form:
//   {"halfspace": "A"}
//   {"op": "union" | "intersection", "args": [at least one tree]}
//   {"op": "difference", "args": [a, b]}          a minus b
//   {"op": "complement", "args": [a]}
//   {"op": "empty"} / {"op": "full"}               ("args", if present, must be empty)
// Errors name the JSON path ("csg.args[1].halfspace: unknown halfspace \"X\"").
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/io/exact_json.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace hsx {

inline constexpr std::size_t kCsgTextMaxChars = 100000;
inline constexpr int kCsgMaxDepth = 200;

/// Parses the text form against the halfspace `names` (a name given twice resolves to its first index).
/// `where` prefixes every error message ("--csg" by default).
csg::ExprPtr parse_csg_text(std::string_view text, const std::vector<std::string>& names,
                            const std::string& where = "--csg");

/// Reads the JSON form; `path` is the JSON path of `value` for error messages ("" = the document root).
/// Nesting deeper than kCsgMaxDepth is refused.
csg::ExprPtr csg_from_json(const nlohmann::json& value, const std::vector<std::string>& names,
                           const std::string& path = "");

/// Writes the JSON form (union and intersection keep all their children in one "args").
nlohmann::json csg_to_json(const csg::Expr& e, const std::vector<std::string>& names);

/// The --csg argument of the command line:
/// - the name of an existing regular file: read as JSON (read_exact_json_file), either a bare expression tree or
///   an object {"csg": tree-or-text} (an optional "description" string is allowed beside it); errors are
///   prefixed with the file path;
/// - text starting with '{' (after blanks): the same JSON, inline;
/// - anything else: the text form.
/// A file wins over a halfspace of the same name: write `(A)` to mean the halfspace.
csg::ExprPtr read_csg_argument(const std::string& arg, const std::vector<std::string>& names);

}  // namespace hsx
