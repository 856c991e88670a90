// A 3D solid's boundary as a BoundarySurface: see boundary_from_arrangement3.hpp.
#include <hsx/complex/boundary_from_arrangement3.hpp>

#include "complex/solid_components.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace hsx {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

PointQ3 sub(const PointQ3& a, const PointQ3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
PointQ3 cross(const PointQ3& a, const PointQ3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
int dot_sign(const PointQ3& a, const PointQ3& b) { return sgn(a.x * b.x + a.y * b.y + a.z * b.z); }

}  // namespace

BoundarySurface boundary_from_arrangement3(const Arranged3& arranged, const std::vector<char>& solid_cells) {
  const Arrangement3& arr = arranged.arrangement;
  const Complex& complex = arranged.complex;
  if (complex.cells.size() != arr.cells().size())
    throw std::invalid_argument("boundary_from_arrangement3: the complex's cells are not the arrangement's cells");
  if (solid_cells.size() != complex.cells.size())
    throw std::invalid_argument("boundary_from_arrangement3: " + std::to_string(solid_cells.size()) +
                                " solid flags for " + std::to_string(complex.cells.size()) + " cells");
  for (std::size_t c = 0; c < solid_cells.size(); ++c)
    if (solid_cells[c] && arr.cells()[c].outer)
      throw std::invalid_argument("boundary_from_arrangement3: solid cell " + std::to_string(c) +
                                  " touches the domain box");
  auto solid_at = [&](int cell) { return cell >= 0 && solid_cells[at(cell)] != 0; };
  const auto& tris = arr.triangles();
  const auto& verts = arr.vertices();

  // Nesting (as boundary_from_arrangement2).
  std::vector<char> part_touches_box, void_touches_box;
  const std::vector<int> solid_part = detail::solid_components(complex, solid_cells, 1, part_touches_box);
  const std::vector<int> void_part = detail::solid_components(complex, solid_cells, 0, void_touches_box);
  const std::size_t parts = part_touches_box.size(), voids = void_touches_box.size();
  std::vector<std::vector<int>> part_voids(parts), void_parts(voids);
  for (const ArrTriangle3& t : tris) {
    if (solid_at(t.front_cell) == solid_at(t.back_cell)) continue;
    const int s = solid_at(t.front_cell) ? t.front_cell : t.back_cell;
    const int v = solid_at(t.front_cell) ? t.back_cell : t.front_cell;
    if (v < 0) throw std::logic_error("boundary_from_arrangement3: a solid cell borders the outside of the domain");
    part_voids[at(solid_part.at(at(s)))].push_back(void_part.at(at(v)));
    void_parts[at(void_part.at(at(v)))].push_back(solid_part.at(at(s)));
  }
  std::vector<int> outside_of(parts, -1);
  std::vector<char> void_seen(voids, 0);
  std::vector<int> queue;
  for (std::size_t v = 0; v < voids; ++v)
    if (void_touches_box[v]) {
      void_seen[v] = 1;
      queue.push_back(static_cast<int>(v));
    }
  for (std::size_t k = 0; k < queue.size(); ++k)
    for (int p : void_parts[at(queue[k])]) {
      if (outside_of[at(p)] >= 0) continue;
      outside_of[at(p)] = queue[k];
      for (int v : part_voids[at(p)])
        if (!void_seen[at(v)]) {
          void_seen[at(v)] = 1;
          queue.push_back(v);
        }
    }

  BoundarySurface surface;
  surface.dimension = 3;
  surface.corner_count = static_cast<int>(verts.size());
  std::vector<int> piece_of(tris.size(), -1);
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const ArrTriangle3& t = tris[k];
    if (solid_at(t.front_cell) == solid_at(t.back_cell)) continue;
    if (t.halfspaces.empty())
      throw std::logic_error("boundary_from_arrangement3: boundary triangle " + std::to_string(k) +
                             " lies on no halfspace");
    const bool solid_front = solid_at(t.front_cell);
    const int solid_cell = solid_front ? t.front_cell : t.back_cell;
    const int void_cell = solid_front ? t.back_cell : t.front_cell;
    BoundaryPiece piece;
    piece.origin = static_cast<int>(k);
    piece.region = solid_part.at(at(solid_cell));
    piece.hole = void_part.at(at(void_cell)) != outside_of.at(at(piece.region));
    piece.carrier = t.halfspaces.front();
    piece.carrier_complemented = true;
    for (std::size_t i = 0; i < t.halfspaces.size(); ++i)  // ascending
      if ((t.front_inside.at(i) != 0) == solid_front) {
        piece.carrier = t.halfspaces[i];
        piece.carrier_complemented = false;
        break;
      }
    piece_of[k] = static_cast<int>(surface.pieces.size());
    surface.pieces.push_back(piece);
  }

  // Per piece, its link along each of its three edges (slot 0: v0v1, 1: v1v2, 2: v2v0).
  std::vector<std::array<int, 3>> slot_link(surface.pieces.size(), {-1, -1, -1});
  auto slot_of = [&](int triangle, int a, int b) {
    const auto& v = tris[at(triangle)].vertices;
    for (int s = 0; s < 3; ++s) {
      const int p = v[at(s)], q = v[at((s + 1) % 3)];
      if ((p == a && q == b) || (p == b && q == a)) return s;
    }
    throw std::logic_error("boundary_from_arrangement3: triangle " + std::to_string(triangle) +
                           " does not have edge " + std::to_string(a) + "-" + std::to_string(b));
  };
  const auto& edges = arr.edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const ArrEdge3& edge = edges[e];
    const std::size_t n = edge.triangles.size();
    bool any = false;
    for (int t : edge.triangles) any = any || piece_of[at(t)] >= 0;
    if (!any) continue;
    const PointQ3& a = verts[at(edge.a)];
    const PointQ3 d = sub(verts[at(edge.b)], a);
    // Per triangle in radial order: its direction away from the edge, and the cell in the sector after it
    // (counter-clockwise about a -> b).
    std::vector<PointQ3> away(n);
    std::vector<int> next_cell(n);
    for (std::size_t i = 0; i < n; ++i) {
      const ArrTriangle3& t = tris[at(edge.triangles[i])];
      int w = -1;
      for (int v : t.vertices)
        if (v != edge.a && v != edge.b) w = v;
      away[i] = sub(verts[at(w)], a);
      const PointQ3 normal = cross(sub(verts[at(t.vertices[1])], verts[at(t.vertices[0])]),
                                   sub(verts[at(t.vertices[2])], verts[at(t.vertices[0])]));
      next_cell[i] = dot_sign(normal, cross(d, away[i])) > 0 ? t.front_cell : t.back_cell;
    }
    // A solid sector run starts at a triangle whose previous sector is not solid and whose next one is.
    for (std::size_t i = 0; i < n; ++i) {
      const bool before = solid_at(next_cell[(i + n - 1) % n]), after = solid_at(next_cell[i]);
      if (before || !after) continue;
      std::size_t j = (i + 1) % n;
      while (solid_at(next_cell[j])) j = (j + 1) % n;  // ends: the run started after a non-solid sector
      BoundaryLink link;
      link.piece_a = piece_of[at(edge.triangles[i])];
      link.piece_b = piece_of[at(edge.triangles[j])];
      if (link.piece_a < 0 || link.piece_b < 0)
        throw std::logic_error("boundary_from_arrangement3: a solid sector at edge " + std::to_string(e) +
                               " is not bounded by boundary triangles");
      link.corner_a = edge.a;
      link.corner_b = edge.b;
      link.origin = static_cast<int>(e);
      const int turn = dot_sign(cross(away[i], away[j]), d);  // > 0: the sector is below 180 degrees
      link.type = turn > 0 ? FeatureType::Convex : turn < 0 ? FeatureType::Concave : FeatureType::Smooth;
      const BoundaryPiece& pa = surface.pieces[at(link.piece_a)];
      const BoundaryPiece& pb = surface.pieces[at(link.piece_b)];
      link.feature = pa.carrier != pb.carrier || pa.carrier_complemented != pb.carrier_complemented;
      const int id = static_cast<int>(surface.links.size());
      slot_link[at(link.piece_a)][at(slot_of(edge.triangles[i], edge.a, edge.b))] = id;
      slot_link[at(link.piece_b)][at(slot_of(edge.triangles[j], edge.a, edge.b))] = id;
      surface.links.push_back(link);
    }
  }
  for (std::size_t p = 0; p < surface.pieces.size(); ++p) {
    for (int l : slot_link[p])
      if (l < 0) throw std::logic_error("boundary_from_arrangement3: piece " + std::to_string(p) + " misses a link");
    surface.pieces[p].links = {slot_link[p][0], slot_link[p][1], slot_link[p][2]};
  }

  const std::vector<std::string> problems = check_boundary(surface);
  if (!problems.empty()) throw std::logic_error("boundary_from_arrangement3: " + problems.front());
  return surface;
}

}  // namespace hsx
