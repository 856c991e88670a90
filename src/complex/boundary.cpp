#include <hsx/complex/boundary.hpp>

#include <algorithm>

namespace hsx {

const char* feature_type_name(FeatureType type) {
  switch (type) {
    case FeatureType::Smooth: return "smooth";
    case FeatureType::Convex: return "convex";
    case FeatureType::Concave: return "concave";
    case FeatureType::Hybrid: return "hybrid";
  }
  return "?";
}

FeatureType combine_feature_types(FeatureType a, FeatureType b) {
  if (a == b) return a;
  if (a == FeatureType::Smooth) return b;
  if (b == FeatureType::Smooth) return a;
  return FeatureType::Hybrid;
}

std::vector<std::string> check_boundary(const BoundarySurface& surface) {
  std::vector<std::string> problems;
  const int piece_count = static_cast<int>(surface.pieces.size());
  for (std::size_t l = 0; l < surface.links.size(); ++l) {
    const BoundaryLink& link = surface.links[l];
    const std::string name = "link " + std::to_string(l);
    if (link.piece_a < 0 || link.piece_a >= piece_count || link.piece_b < 0 || link.piece_b >= piece_count) {
      problems.push_back(name + ": piece index out of range");
      continue;
    }
    if (link.piece_a == link.piece_b) problems.push_back(name + ": joins a piece to itself");
    for (int p : {link.piece_a, link.piece_b}) {
      const auto& links = surface.pieces[static_cast<std::size_t>(p)].links;
      if (std::count(links.begin(), links.end(), static_cast<int>(l)) != 1)
        problems.push_back(name + ": piece " + std::to_string(p) + " does not list it exactly once");
    }
    if (link.feature && link.type == FeatureType::Hybrid) problems.push_back(name + ": a single link is hybrid");
    for (int c : {link.corner_a, link.corner_b})
      if (c < -1 || c >= surface.corner_count) problems.push_back(name + ": corner out of range");
  }
  for (std::size_t p = 0; p < surface.pieces.size(); ++p) {
    const BoundaryPiece& piece = surface.pieces[p];
    const std::string name = "piece " + std::to_string(p);
    if (piece.retired != piece.links.empty())
      problems.push_back(name + (piece.retired ? ": retired but has links" : ": has no links"));
    for (int l : piece.links) {
      if (l < 0 || l >= static_cast<int>(surface.links.size())) {
        problems.push_back(name + ": link index out of range");
        continue;
      }
      const BoundaryLink& link = surface.links[static_cast<std::size_t>(l)];
      if (link.piece_a != static_cast<int>(p) && link.piece_b != static_cast<int>(p))
        problems.push_back(name + ": lists link " + std::to_string(l) + " that does not join it");
    }
  }
  return problems;
}

std::vector<int> split_piece(BoundarySurface& surface, int piece) {
  const std::vector<int> old_links = surface.pieces[static_cast<std::size_t>(piece)].links;
  const BoundaryPiece parent = surface.pieces[static_cast<std::size_t>(piece)];
  std::vector<int> parts;
  for (int l : old_links) {
    BoundaryPiece part;
    part.origin = parent.origin;
    part.carrier = parent.carrier;
    part.carrier_complemented = parent.carrier_complemented;
    part.split_of = piece;
    part.region = parent.region;
    part.hole = parent.hole;
    part.kept_link = l;
    part.links.push_back(l);
    const int id = static_cast<int>(surface.pieces.size());
    surface.pieces.push_back(part);
    BoundaryLink& link = surface.links[static_cast<std::size_t>(l)];
    (link.piece_a == piece ? link.piece_a : link.piece_b) = id;
    parts.push_back(id);
  }
  // Sub-pieces meet pairwise: the halves of an edge at the split point, the three triangles of a centroid
  // split along the segments from the centroid to the vertices.
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      BoundaryLink link;
      link.piece_a = parts[i];
      link.piece_b = parts[j];
      const int id = static_cast<int>(surface.links.size());
      surface.links.push_back(link);
      surface.pieces[static_cast<std::size_t>(parts[i])].links.push_back(id);
      surface.pieces[static_cast<std::size_t>(parts[j])].links.push_back(id);
    }
  BoundaryPiece& old = surface.pieces[static_cast<std::size_t>(piece)];
  old.links.clear();
  old.retired = true;
  return parts;
}

}  // namespace hsx
