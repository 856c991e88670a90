// CSGNet 2D programs (data/csgnet/README.md) as an hsx scene plus a CSG expression over its halfspaces.
//
// A program is postfix: primitives push a solid, `+` (union), `*` (intersection) and `-` (difference: `A B -` is A
// minus B) pop two and push one; exactly one solid must remain. Blanks between tokens are ignored. Numbers are
// read exactly (parse_rational: "0.5" is 1/2); the README's constants are exact decimals, 0.706 = 706/1000 and
// 0.866 = 866/1000.
//
// Halfspaces, named after the primitive's position k among the program's primitives (0-based, in reading order,
// so repeated identical primitives get their own halfspaces):
//   c(x,y,r)  disk, centre (x, y), radius r                         "c<k>"
//   s(x,y,l)  square, half side h = 706/1000 * l, four half-planes:  "s<k>.xmin"  X >= x - h
//                                                                    "s<k>.xmax"  X <= x + h
//                                                                    "s<k>.ymin"  Y >= y - h
//                                                                    "s<k>.ymax"  Y <= y + h
//   t(x,y,l)  triangle with vertices v0 = (x - a, y + l/2), v1 = (x + a, y + l/2), v2 = (x, y - l), a = 866/1000 * l,
//             three half-planes, each containing the triangle:      "t<k>.<i>"  bounded by the line v_i v_(i+1 mod 3)
// The names are identifiers in the CSG text form (io/csg_text.hpp), so no quoting is needed. Half-plane normals are
// the outward normals scaled to coprime integers (the triangle's slanted edges get (+-750, -433) up to sign).
// A primitive's expression is the intersection of its half-planes (a disk is its one halfspace).
//
// Domain: the bounding box of all primitives, rounded outward to integers and widened by a margin
// m = max(8, ceil(W / 8)) on every side, W the larger side of the bounding box; it is given (domain_given), so a
// scene written to JSON keeps it. Every solid of the program lies strictly inside it. No samples.
//
// Errors are hsx::InputError "<origin>: token N at column C: <what>" (token numbers and columns from 1): unknown
// token, malformed primitive or number, radius or size not positive, stack underflow, leftover solids, empty
// program, or a program longer than 100,000 characters.
#pragma once

#include <hsx/algorithms/csg/expression.hpp>
#include <hsx/geometry/scene.hpp>

#include <string>
#include <string_view>

namespace hsx {

inline constexpr std::size_t kCsgnetMaxChars = 100000;

struct CsgnetProgram {
  Scene2 scene;               ///< validated (validate_and_resolve); description names the origin and the program
  csg::ExprPtr expression;    ///< over scene.halfspaces (by index)
};

/// One program line; `origin` (e.g. "line 17") prefixes error messages and the scene description.
CsgnetProgram read_csgnet(std::string_view program_line, const std::string& origin);

}  // namespace hsx
