// The geometric content of a 3D hsx scene (`"dimension": 3`), independent of its file format (io/scene_json.hpp
// reads hsx-scene/1 files, io/bsh_config.hpp the BSH authors' config.json).
//
// Conventions (owned here):
// - A halfspace is a closed region of R^3; its inside is given below and swapped by `complement`.
//     plane:  { x : normal . x <= offset }, normal non-zero (the outward normal, need not be unit). Its boundary is
//             clipped to the domain box by the arrangement; it has no triangles here.
//     every other kind (mesh, box, sphere, cylinder, cone, torus): the closed region bounded by `surface`, a
//             closed, edge-manifold, consistently outward-oriented, non-degenerate triangle mesh with exact
//             rational vertices. Curved primitives are replaced by their tessellation (geometry/tessellate3.hpp
//             says exactly which vertices and triangles): hsx arranges the polyhedra, never the curved surfaces.
// - The domain is an axis-aligned box containing every surface vertex and every sample. It is not a halfspace:
//   planes are clipped to it, cells touching it are outer.
// - Samples: `at` must lie exactly on the (tessellated) boundary of its halfspace; `near` is moved to the nearest
//   point of that boundary (exact: the nearest point of a triangle with rational vertices to a rational point is
//   rational), and `distance2` is the squared distance moved. For a plane it is the orthogonal projection; for a
//   surface the nearest point over all triangles (faces, edges and vertices), compared exactly by squared distance;
//   when several different points are equally near, the one found on the lowest-numbered triangle is taken.
#pragma once

#include <hsx/geometry/mesh3.hpp>   // PointQ3
#include <hsx/geometry/scene.hpp>   // InputError
#include <hsx/kernel/rational.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace hsx {

struct Box3 {
  PointQ3 min, max;  ///< min < max in every coordinate
  bool contains(const PointQ3& p) const {
    return min.x <= p.x && p.x <= max.x && min.y <= p.y && p.y <= max.y && min.z <= p.z && p.z <= max.z;
  }
};

/// A closed triangle surface with exact vertices: triangles are counter-clockwise seen from outside (their
/// normal (b-a)x(c-a) points out of the enclosed region).
struct TriangleSurface {
  std::vector<PointQ3> vertices;
  std::vector<std::array<int, 3>> triangles;  ///< 0-based vertex ids
};

enum class HalfspaceKind3 { Plane, Mesh, Box, Sphere, Cylinder, Cone, Torus };
const char* to_string(HalfspaceKind3 kind);  ///< "plane", "mesh", "box", "sphere", "cylinder", "cone", "torus"

/// How a curved primitive is cut into triangles (geometry/tessellate3.hpp says exactly how).
struct Tessellation3 {
  enum class Mode { Segments, EdgeLength };
  Mode mode = Mode::Segments;
  int segments = 32;        ///< Segments: segments per full turn of every circle (torus: of the circles about its axis)
  int minor_segments = 0;   ///< Segments, torus only: per turn of the tube's circles; 0 = `segments`
  Rational edge_length;     ///< EdgeLength: target chord length (> 0); each circle gets its own segment count
  /// How the frame (u, v, w) of an axis is chosen (geometry/tessellate3.hpp): SmallestAxis is hsx's own rule, Bsh the
  /// BSH authors' (u from w x +x; a sphere in the coordinate frame).
  enum class Frame { SmallestAxis, Bsh };
  Frame frame = Frame::SmallestAxis;
  int bands = 0;            ///< sphere only: latitude bands (2..kMaxSegments); 0 = ceil(n / 2) for n segments
};

/// A primitive's parameters as written (for tessellating, for messages and for writing the scene back). Only the
/// fields of the halfspace's kind are meaningful.
struct Primitive3 {
  PointQ3 min, max;                     ///< box: opposite corners, min < max in every coordinate
  PointQ3 center;                       ///< sphere, torus
  Rational radius;                      ///< sphere, cylinder, cone (the base radius); > 0
  PointQ3 point1, point2;               ///< cylinder: axis_point1, axis_point2; cone: apex, base_center; distinct
  bool infinite = false;                ///< cylinder: unbounded along its axis, clipped by the domain box
  PointQ3 axis;                         ///< torus: axis direction (non-zero, need not be unit)
  Rational major_radius, minor_radius;  ///< torus: 0 < minor_radius < major_radius
  Tessellation3 tessellation;
  std::string file;                     ///< mesh: the path as written in the scene (relative to the scene file)
};

struct Halfspace3 {
  std::string name;
  HalfspaceKind3 kind = HalfspaceKind3::Plane;
  bool complement = false;
  // plane
  PointQ3 normal;
  Rational offset;
  // every other kind: the boundary, outward-oriented (complement does not flip it; it swaps inside and outside)
  TriangleSurface surface;
  Primitive3 primitive;  ///< every kind but plane: the parameters the surface was made from
  std::string origin;  ///< where the surface came from, for messages: a mesh file, "sphere, 24 segments", ...

  /// Exact side of a rational point: +1 strictly inside, 0 on the boundary, -1 strictly outside (complement
  /// applied). For surfaces, by exact ray parity (O(triangles)).
  int side(const PointQ3& p) const;
};

struct Sample3 {
  int halfspace = -1;      ///< index into Scene3::halfspaces
  PointQ3 given;           ///< as written in the file
  bool snapped = false;    ///< true for `near`
  PointQ3 location;        ///< exact point on the boundary (== given for `at`)
  Rational distance2;      ///< squared distance from `given` to `location` (0 for `at`)
};

struct Scene3 {
  std::string description;
  Box3 domain;
  bool domain_given = false;  ///< false: chosen by hsx (choose_domain3)
  std::vector<Halfspace3> halfspaces;
  std::vector<Sample3> samples;
  std::vector<std::string> notes;  ///< accepted but worth saying (a mesh flipped to outward orientation, ...)

  int find_halfspace(const std::string& name) const;  ///< index or -1
};

/// Checks everything that needs geometry but not the arrangement, and resolves samples (see the conventions):
/// plane normals non-zero; every surface closed, edge- and vertex-manifold, consistently oriented, with no
/// zero-area triangle, no fold and non-zero enclosed volume (build_mesh3's checks); a surface whose triangles are
/// all inward (negative volume) is reversed as a whole, with a note in `notes` (the solid it bounds is the same,
/// as for .obj meshes); the domain (given or chosen) contains
/// every surface vertex and sample; `at` samples exactly on their boundary, `near` samples snapped; at least one
/// halfspace. Self-intersection of a surface is decided exactly by the arrangement (Arrangement3::build), which
/// has the triangle pairs at hand. Throws InputError naming the halfspace or sample ("halfspaces[2] (\"C\"): ...").
void validate_and_resolve(Scene3& scene);

/// choose_domain3 visits every triple of planes: beyond this many planes it refuses (InputError "domain: ...").
inline constexpr std::size_t kMaxPlanesWithoutDomain = 150;

/// A box strictly containing every surface vertex and every sample, with margin; when the scene has planes, also
/// every point where three planes meet, and every plane crosses it; deterministic. The margin is a tenth of the
/// extent's largest side (at least 1 when the extent is a point), added on every side.
Box3 choose_domain3(const Scene3& scene);

}  // namespace hsx
