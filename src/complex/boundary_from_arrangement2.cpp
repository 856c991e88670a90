// A 2D solid's boundary as a BoundarySurface: see boundary_from_arrangement2.hpp.
#include <hsx/complex/boundary_from_arrangement2.hpp>

#include "complex/solid_components.hpp"
#include "geometry/planar_corners.hpp"

#include <stdexcept>
#include <string>

namespace hsx {

namespace {

FeatureType feature_type_of(CornerAngle angle) {
  switch (angle) {
    case CornerAngle::Convex: return FeatureType::Convex;
    case CornerAngle::Concave: return FeatureType::Concave;
    case CornerAngle::Smooth: return FeatureType::Smooth;
  }
  return FeatureType::Smooth;
}

}  // namespace

BoundarySurface boundary_from_arrangement2(const Arranged2& arranged, const std::vector<char>& solid_cells) {
  const Arrangement2& arr = arranged.arrangement;
  const Complex& complex = arranged.complex;
  if (complex.cells.size() != arr.faces().size())
    throw std::invalid_argument("boundary_from_arrangement2: the complex's cells are not the arrangement's faces");
  if (solid_cells.size() != complex.cells.size())
    throw std::invalid_argument("boundary_from_arrangement2: " + std::to_string(solid_cells.size()) +
                                " solid flags for " + std::to_string(complex.cells.size()) + " cells");
  const SolidBoundary2 boundary = solid_boundary2(arr, solid_cells);

  // Nesting. Solid parts and void components alternate outwards: rooted at the void that reaches the box, each
  // solid part's parent is the void around it, and its other adjacent voids are its holes (an island in a hole
  // of another part has that hole as its outside).
  std::vector<char> part_touches_box, void_touches_box;
  const std::vector<int> solid_part = detail::solid_components(complex, solid_cells, 1, part_touches_box);
  const std::vector<int> void_part = detail::solid_components(complex, solid_cells, 0, void_touches_box);
  const std::size_t parts = part_touches_box.size(), voids = void_touches_box.size();
  std::vector<std::vector<int>> part_voids(parts), void_parts(voids);
  for (const SolidBoundaryEdge2& b : boundary.edges) {
    const ArrEdge2& e = arr.edges()[static_cast<std::size_t>(b.edge)];
    const int p = solid_part.at(static_cast<std::size_t>(b.forward ? e.left_face : e.right_face));
    const int v = void_part.at(static_cast<std::size_t>(b.forward ? e.right_face : e.left_face));
    part_voids[static_cast<std::size_t>(p)].push_back(v);
    void_parts[static_cast<std::size_t>(v)].push_back(p);
  }
  std::vector<int> outside_of(parts, -1);  // per solid part, the void component around it
  std::vector<char> void_seen(voids, 0);
  std::vector<int> queue;
  for (std::size_t v = 0; v < voids; ++v)
    if (void_touches_box[v]) {
      void_seen[v] = 1;
      queue.push_back(static_cast<int>(v));
    }
  for (std::size_t k = 0; k < queue.size(); ++k)
    for (int p : void_parts[static_cast<std::size_t>(queue[k])]) {
      if (outside_of[static_cast<std::size_t>(p)] >= 0) continue;
      outside_of[static_cast<std::size_t>(p)] = queue[k];
      for (int v : part_voids[static_cast<std::size_t>(p)])
        if (!void_seen[static_cast<std::size_t>(v)]) {
          void_seen[static_cast<std::size_t>(v)] = 1;
          queue.push_back(v);
        }
    }

  BoundarySurface surface;
  surface.dimension = 2;
  std::vector<int> piece_of_edge(arr.edges().size(), -1);
  for (const SolidBoundaryEdge2& b : boundary.edges) {
    const ArrEdge2& edge = arr.edges()[static_cast<std::size_t>(b.edge)];
    if (edge.halfspaces.empty())
      throw std::logic_error("boundary_from_arrangement2: boundary edge " + std::to_string(b.edge) +
                             " lies on no halfspace");
    const int solid_cell = b.forward ? edge.left_face : edge.right_face;
    const auto& inside = complex.cells.at(static_cast<std::size_t>(solid_cell)).inside;
    BoundaryPiece piece;
    piece.origin = b.edge;
    const int void_cell = b.forward ? edge.right_face : edge.left_face;
    piece.region = solid_part.at(static_cast<std::size_t>(solid_cell));
    piece.hole = void_part.at(static_cast<std::size_t>(void_cell)) != outside_of.at(static_cast<std::size_t>(piece.region));
    piece.carrier = edge.halfspaces.front();
    piece.carrier_complemented = true;
    for (int h : edge.halfspaces)  // ascending
      if (inside.at(static_cast<std::size_t>(h))) {
        piece.carrier = h;
        piece.carrier_complemented = false;
        break;
      }
    piece_of_edge[static_cast<std::size_t>(b.edge)] = static_cast<int>(surface.pieces.size());
    surface.pieces.push_back(piece);
  }

  // A piece's start link is the corner where it is outgoing; its end link the corner where it is incoming.
  std::vector<int> start_link(surface.pieces.size(), -1), end_link(surface.pieces.size(), -1);
  for (const SolidCorner2& corner : boundary.corners) {
    BoundaryLink link;
    link.piece_a = piece_of_edge.at(static_cast<std::size_t>(corner.in_edge));
    link.piece_b = piece_of_edge.at(static_cast<std::size_t>(corner.out_edge));
    link.origin = corner.vertex;
    link.type = feature_type_of(corner.angle);
    const BoundaryPiece& a = surface.pieces.at(static_cast<std::size_t>(link.piece_a));
    const BoundaryPiece& b = surface.pieces.at(static_cast<std::size_t>(link.piece_b));
    link.feature = a.carrier != b.carrier || a.carrier_complemented != b.carrier_complemented;
    const int id = static_cast<int>(surface.links.size());
    end_link.at(static_cast<std::size_t>(link.piece_a)) = id;
    start_link.at(static_cast<std::size_t>(link.piece_b)) = id;
    surface.links.push_back(link);
  }
  for (std::size_t p = 0; p < surface.pieces.size(); ++p)
    surface.pieces[p].links = {start_link[p], end_link[p]};

  const std::vector<std::string> problems = check_boundary(surface);
  if (!problems.empty()) throw std::logic_error("boundary_from_arrangement2: " + problems.front());
  return surface;
}

}  // namespace hsx
