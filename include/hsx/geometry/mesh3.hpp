// Closed triangle meshes with exact rational vertices, read from `.obj` + `.fea` files: the 3D input of NH-Rep
// patch graphs (complex/boundary_from_mesh.hpp turns a Mesh3 into a BoundarySurface).
//
// Conventions (owned here):
// - Vertex and face ids are 0-based everywhere in hsx (the .obj file is 1-based, the .fea file 0-based). Error
//   messages name a vertex by its 0-based id and the .obj line that defined it.
// - Coordinates are read exactly with parse_rational: "0.1" is 1/10, "1e-3" is 1/1000, "-7/3" is accepted too.
// - .obj: `v x y z` (a 4th coordinate w must be 1; 6 numbers = x y z r g b, the colour is ignored) and `f` lines
//   with 3 indices, each "i", "i/t", "i//n" or "i/t/n" (only i is used; negative i counts back from the last
//   vertex read so far). Faces with more than 3 vertices are rejected rather than fan-triangulated: a fan adds
//   edges the .fea file knows nothing about and its shape depends on which vertex starts the polygon. `#` starts a
//   comment; every other keyword (vn, vt, o, g, s, usemtl, mtllib, l, ...) is ignored.
// - .fea: the first non-blank line is the number N of feature edges, then N lines of two 0-based vertex ids.
//   Blank lines are skipped. An entry "a a" (both ends the same vertex) is skipped with a note: NH-Rep's own data
//   contains such entries (00000006_0.fea lines 652 and 871; 00007974_5.fea four times) and they mark no edge. An
//   edge listed twice is kept once, with a note.
// - A valid Mesh3 is closed, edge-manifold (every undirected edge in exactly two faces), consistently oriented
//   (the two faces traverse their shared edge in opposite directions), vertex-manifold (the faces around each
//   used vertex form a single cycle), has no zero-area triangle and no edge where two faces fold back onto each
//   other (coplanar, on the same side of the edge), and has positive signed volume (outward normals). Inward input
//   is flipped as a whole, with a note. Geometric self-intersection is not checked. Several shells are allowed
//   (an inner shell of a hollow solid has negative volume of its own; only the total must be positive).
// - Zero-area (collinear) triangles are rejected: their normal is zero, so the dihedral type of their edges is not
//   defined. The shared NH-Rep models have none (checked exactly).
// - Edge shape, exact: for edge (a,b) between T1 (containing a->b, third vertex w1) and T2 (containing b->a,
//   third vertex w2), det(b-a, w1-a, w2-a) < 0 (w2 below T1's plane) is Convex, > 0 Concave, = 0 Flat.
#pragma once

#include <hsx/geometry/scene.hpp>  // InputError
#include <hsx/kernel/interval.hpp>
#include <hsx/kernel/rational.hpp>

#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hsx {

struct PointQ3 {
  Rational x, y, z;
  friend bool operator==(const PointQ3& a, const PointQ3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  friend bool operator!=(const PointQ3& a, const PointQ3& b) { return !(a == b); }
};

/// Bounds on one input, so that hostile files fail fast (the fuzzer sets small ones).
struct MeshReadLimits {
  NumberLimits numbers;                      ///< per coordinate
  std::size_t max_vertices = 20'000'000;
  std::size_t max_faces = 40'000'000;
  std::size_t max_feature_edges = 60'000'000;
};

/// An .obj file as read, before validation. `faces` are 0-based and in range, each with 3 distinct vertices.
struct ObjMesh {
  std::string source;                        ///< file name (or a label) used in error messages
  std::vector<PointQ3> vertices;
  std::vector<std::array<int, 3>> faces;
  std::vector<long> vertex_lines, face_lines;  ///< 1-based line of each vertex / face
};

/// Reads .obj text. Throws InputError "SOURCE:LINE: problem" on a bad number, a bad or out-of-range index, a face
/// that is not a triangle or repeats a vertex, a limit exceeded, or a file without faces.
ObjMesh read_obj(std::istream& in, const std::string& source, const MeshReadLimits& limits = {});
ObjMesh read_obj_file(const std::string& path, const MeshReadLimits& limits = {});

/// Reads ASCII OFF text: "OFF", then "nv nf ne", nv lines "x y z" (extra values on a line, such as colours, are
/// ignored), nf lines "3 a b c" (0-based ids; other counts refused); `#` starts a comment. The same ObjMesh as
/// read_obj gives for the same mesh (lines are the OFF file's).
ObjMesh read_off(std::istream& in, const std::string& source, const MeshReadLimits& limits = {});

/// Reads ASCII PLY text: a header ("ply", "format ascii 1.0", "element vertex N" with properties including x, y,
/// z, "element face M" whose first property is the list vertex_indices (or vertex_index), other elements skipped,
/// "end_header"), then one line per element entry. Binary PLY is refused. Faces must be triangles.
ObjMesh read_ply(std::istream& in, const std::string& source, const MeshReadLimits& limits = {});

/// Reads an .obj, .off or .ply file (by extension, case-insensitive); errors "PATH:LINE: problem".
ObjMesh read_mesh_file(const std::string& path, const MeshReadLimits& limits = {});

/// A .fea file as read: `edges[i]` (two 0-based vertex ids, in file order) came from line `lines[i]`.
struct FeatureEdgeList {
  std::string source;
  std::vector<std::pair<int, int>> edges;
  std::vector<long> lines;
};

/// Reads .fea text. Throws InputError "SOURCE:LINE: problem" on a bad count or entry, a negative id, or a count that
/// does not match the entries. Whether ids name mesh edges is checked by resolve_feature_edges.
FeatureEdgeList read_fea(std::istream& in, const std::string& source, const MeshReadLimits& limits = {});
FeatureEdgeList read_fea_file(const std::string& path, const MeshReadLimits& limits = {});

enum class EdgeShape : char { Flat = 0, Convex = 1, Concave = 2 };
const char* edge_shape_name(EdgeShape shape);  ///< "flat", "convex", "concave"

struct MeshEdge {
  int a = -1, b = -1;            ///< vertex ids, a < b
  int face_ab = -1, face_ba = -1;  ///< the face traversing a->b, and the one traversing b->a (outward orientation)
  EdgeShape shape = EdgeShape::Flat;
};

/// A validated, outward-oriented closed triangle mesh (see the conventions above).
struct Mesh3 {
  std::string source;
  std::vector<PointQ3> vertices;
  std::vector<std::array<int, 3>> faces;       ///< outward: counter-clockwise seen from outside
  std::vector<PointQ3> normals;                ///< per face, a positive multiple of (f1-f0) x (f2-f0): outward, non-zero
  std::vector<long> vertex_lines, face_lines;  ///< from the .obj
  std::vector<MeshEdge> edges;                 ///< every undirected edge once, sorted by (a, b)
  std::vector<std::array<int, 3>> face_edges;  ///< face_edges[f][k] = edge of faces[f][k] -> faces[f][(k+1)%3]
  Rational volume;                             ///< exact enclosed volume, > 0
  bool flipped = false;                        ///< the input was inward-oriented and every face was reversed
  int shells = 0;                              ///< connected components of faces
  std::vector<std::string> notes;              ///< what was accepted but worth saying (flip, unused vertices)

  /// The edge joining vertices u and v (either order), or -1.
  int find_edge(int u, int v) const;
};

/// Validates and orients. Throws InputError naming the .obj line, face, edge or vertex at fault.
Mesh3 build_mesh3(ObjMesh obj);

/// read_obj_file + build_mesh3.
Mesh3 read_mesh3_file(const std::string& path, const MeshReadLimits& limits = {});

/// Per mesh edge, 1 if `features` marks it. Throws InputError "FEA_SOURCE:LINE: ..." for an id out of range or a
/// pair of vertices that is not a mesh edge. Skipped self-edges and duplicates are reported in *notes (if given).
std::vector<char> resolve_feature_edges(const Mesh3& mesh, const FeatureEdgeList& features,
                                        std::vector<std::string>* notes = nullptr);

/// NH-Rep's sharpness angle delta (degrees, 0 <= delta < 180): an edge whose two face normals make an angle theta
/// < delta (a dihedral deviation from flat below delta) counts as smooth; theta >= delta is sharp. Decided
/// without floating-point error: cos^2(theta) is rational; cos^2(delta) is rational exactly when delta is a
/// multiple of 30 or 45 degrees (Niven's theorem applied to cos(2 delta)) and is then compared exactly, otherwise
/// it is irrational, never equals cos^2(theta), and certified MPFR intervals at doubling precision separate them.
class SharpnessAngle {
 public:
  /// Throws InputError unless 0 <= degrees < 180.
  explicit SharpnessAngle(const Rational& degrees = Rational(0));

  const Rational& degrees() const { return degrees_; }
  /// cos^2(delta) when it is rational.
  const std::optional<Rational>& exact_cos2() const { return cos2_exact_; }

  /// True if the angle between the non-zero vectors n1 and n2 is smaller than delta.
  bool closer_than(const PointQ3& n1, const PointQ3& n2) const;

  /// True if edge `edge` of `mesh` counts as smooth: Flat, or its face normals are closer than delta.
  bool smooth(const Mesh3& mesh, int edge) const;

  /// Enclosure of cos^2(delta) at `bits` of precision (certified; exact ends when cos^2(delta) is rational).
  Interval cos2_enclosure(mpfr_prec_t bits) const;

 private:
  Rational degrees_;
  int cos_sign_ = 1;                   ///< sign of cos(delta)
  std::optional<Rational> cos2_exact_;
  Interval cos2_;                      ///< at 128 bits; refined on demand (locally, the object stays immutable)
};

/// A mesh edge's type under a sharpness angle: Flat when the edge is Flat or smooth under `sharpness`.
EdgeShape classify_edge(const Mesh3& mesh, int edge, const SharpnessAngle& sharpness);

/// Whether point `p` lies inside the closed surface made of `faces` (triangle ids of `mesh` forming one or more
/// closed shells), by the exact parity of crossings of a ray from p. Rays that meet an edge or a vertex, or lie in
/// a triangle's plane, are replaced by the next of a fixed sequence of directions (finitely many are degenerate,
/// so this ends). Returns nullopt when p lies on the surface.
std::optional<bool> point_inside_faces(const Mesh3& mesh, const std::vector<int>& faces, const PointQ3& p);

/// The same test over a triangle list (`triangles` index `vertices`; together one or more closed shells).
std::optional<bool> point_inside_triangles(const std::vector<PointQ3>& vertices,
                                           const std::vector<std::array<int, 3>>& triangles, const PointQ3& p);

/// Exact geometric helpers (public for tests).
PointQ3 triangle_normal(const PointQ3& a, const PointQ3& b, const PointQ3& c);  ///< (b-a) x (c-a)
Rational dot3(const PointQ3& u, const PointQ3& v);

}  // namespace hsx
