// A 2D solid's boundary as a BoundarySurface: see boundary_from_arrangement2.hpp.
#include "complex/boundary_from_arrangement2.hpp"

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
