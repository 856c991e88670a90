// Mesh exports of 3D arrangements: see mesh_export.hpp.
#include <hsx/io/mesh_export.hpp>

#include <hsx/io/svg.hpp>  // svg_palette_colour

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace hsx {
namespace {

void check_fit(const Scene3& scene, const Arranged3& a) {
  const int n = static_cast<int>(scene.halfspaces.size());
  if (a.arrangement.halfspace_count() != n || a.complex.halfspace_count() != n ||
      a.arrangement.cells().size() != a.complex.cells.size())
    throw std::invalid_argument("mesh export: the arrangement was not built from this scene");
}

/// For each triangle, the patch of its lowest-index halfspace that contains it (-1: none).
std::vector<int> patch_of_triangles(const Arranged3& a) {
  std::vector<int> patch(a.arrangement.triangles().size(), -1);
  const auto& patches = a.complex.patches;
  for (std::size_t p = 0; p < patches.size(); ++p)
    for (int t : patches[p].pieces) {
      int& current = patch.at(static_cast<std::size_t>(t));
      if (current < 0 || patches[static_cast<std::size_t>(current)].halfspace > patches[p].halfspace)
        current = static_cast<int>(p);
    }
  return patch;
}

std::string decimal(const Rational& q) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", q.get_d());
  return buffer;
}

std::string coordinates(const PointQ3& p, bool exact) {
  if (exact) return exact_string(p.x) + " " + exact_string(p.y) + " " + exact_string(p.z);
  return decimal(p.x) + " " + decimal(p.y) + " " + decimal(p.z);
}

std::array<int, 3> rgb(int halfspace) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(svg_palette_colour(halfspace), "#%02x%02x%02x", &r, &g, &b);
  return {static_cast<int>(r), static_cast<int>(g), static_cast<int>(b)};
}

/// Text for a one-line comment: control characters replaced.
std::string comment_text(const std::string& s) {
  std::string out;
  for (char c : s) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  return out;
}

}  // namespace

VertexNumbering renumber_vertices(const Arrangement3& arr, const std::vector<ExportedFace>& faces) {
  VertexNumbering n;
  n.id.assign(arr.vertices().size(), -1);
  for (const ExportedFace& f : faces)
    for (int v : f.vertices) n.id.at(static_cast<std::size_t>(v)) = 0;  // at: a vertex the arrangement lacks throws
  int next = 0;
  for (std::size_t v = 0; v < n.id.size(); ++v)
    if (n.id[v] == 0) {
      n.id[v] = next++;
      n.used.push_back(static_cast<int>(v));
    }
  return n;
}

std::vector<ExportedFace> exported_faces(const Arranged3& a) {
  const std::vector<int> patch = patch_of_triangles(a);
  const auto& triangles = a.arrangement.triangles();
  std::vector<ExportedFace> faces;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const ArrTriangle3& t = triangles[k];
    if (t.on_box || t.halfspaces.empty()) continue;
    ExportedFace f;
    f.triangle = static_cast<int>(k);
    f.halfspace = t.halfspaces.front();
    f.patch = patch[k];
    f.vertices = t.vertices;
    f.front_cell = t.front_cell;
    f.back_cell = t.back_cell;
    if (!t.front_inside.empty() && t.front_inside.front()) {  // turn the normal out of the halfspace
      std::swap(f.vertices[1], f.vertices[2]);
      std::swap(f.front_cell, f.back_cell);
    }
    faces.push_back(f);
  }
  return faces;
}

namespace {

std::string ply_text(const Scene3& scene, const Arranged3& a, const std::vector<ExportedFace>& faces,
                     const std::string& what) {
  const VertexNumbering numbering = renumber_vertices(a.arrangement, faces);
  const std::vector<int>& id = numbering.id;
  const std::vector<int>& used = numbering.used;
  std::string s = "ply\nformat ascii 1.0\ncomment hsx " + what + "\n";
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i)
    s += "comment halfspace " + std::to_string(i) + " " + comment_text(scene.halfspaces[i].name) + "\n";
  s += "element vertex " + std::to_string(used.size()) +
       "\nproperty double x\nproperty double y\nproperty double z\n"
       "element face " +
       std::to_string(faces.size()) +
       "\nproperty list uchar int vertex_indices\nproperty int patch\nproperty int halfspace\n"
       "property int front_cell\nproperty int back_cell\n"
       "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (int v : used) s += coordinates(a.arrangement.vertices()[static_cast<std::size_t>(v)], false) + "\n";
  for (const ExportedFace& f : faces) {
    const auto c = rgb(f.halfspace);
    s += "3 " + std::to_string(id[f.vertices[0]]) + " " + std::to_string(id[f.vertices[1]]) + " " +
         std::to_string(id[f.vertices[2]]) + " " + std::to_string(f.patch) + " " + std::to_string(f.halfspace) + " " +
         std::to_string(f.front_cell) + " " + std::to_string(f.back_cell) + " " + std::to_string(c[0]) + " " +
         std::to_string(c[1]) + " " + std::to_string(c[2]) + "\n";
  }
  return s;
}

ObjText obj_text(const Scene3& scene, const Arranged3& a, std::vector<ExportedFace> faces,
                 const std::string& mtl_name, const MeshExportOptions& options, const std::string& what) {
  if (mtl_name.empty() || mtl_name.find_first_of("\r\n") != std::string::npos)
    throw std::invalid_argument("OBJ export: bad material library name");
  const VertexNumbering numbering = renumber_vertices(a.arrangement, faces);
  const std::vector<int>& id = numbering.id;
  const std::vector<int>& used = numbering.used;
  std::stable_sort(faces.begin(), faces.end(),
                   [](const ExportedFace& x, const ExportedFace& y) { return x.patch < y.patch; });
  ObjText out;
  out.obj = "# hsx " + what + ", " + std::to_string(faces.size()) + " triangles, one group per patch\n";
  out.obj += "mtllib " + mtl_name + "\n";
  for (int v : used)
    out.obj += "v " + coordinates(a.arrangement.vertices()[static_cast<std::size_t>(v)], options.exact) + "\n";
  const ExportedFace* previous = nullptr;  // a new group starts where the patch or the halfspace changes
  for (const ExportedFace& f : faces) {
    if (!previous || f.patch != previous->patch || f.halfspace != previous->halfspace) {
      previous = &f;
      out.obj += (f.patch >= 0 ? "g patch_" + std::to_string(f.patch) : std::string("g no_patch")) +
                 "\nusemtl halfspace_" + std::to_string(f.halfspace) + "\n";
    }
    out.obj += "f " + std::to_string(id[f.vertices[0]] + 1) + " " + std::to_string(id[f.vertices[1]] + 1) + " " +
               std::to_string(id[f.vertices[2]] + 1) + "\n";
  }
  out.mtl = "# hsx " + what + ": one material per halfspace\n";
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i) {
    const auto c = rgb(static_cast<int>(i));
    char kd[64];
    std::snprintf(kd, sizeof kd, "Kd %.4f %.4f %.4f\n", c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    out.mtl += "# " + comment_text(scene.halfspaces[i].name) + "\nnewmtl halfspace_" + std::to_string(i) + "\n" + kd;
  }
  return out;
}

/// "# patch <k> halfspace <i> faces <first> <count>" for each run of faces of one patch (faces in patch order).
std::string patch_ranges(const std::vector<ExportedFace>& faces) {
  std::string s;
  for (std::size_t first = 0; first < faces.size();) {
    std::size_t end = first;
    while (end < faces.size() && faces[end].patch == faces[first].patch) ++end;
    s += "# patch " + std::to_string(faces[first].patch) + " halfspace " + std::to_string(faces[first].halfspace) +
         " faces " + std::to_string(first) + " " + std::to_string(end - first) + "\n";
    first = end;
  }
  return s;
}

const char* const kArrangementWhat = "arrangement: the refined surfaces, one face per triangle";
const char* const kShapeWhat = "shape boundary: outward (normals out of the shape), one face per triangle";

}  // namespace

std::vector<ExportedFace> shape_faces(const Arranged3& a, const std::vector<char>& labelling) {
  const Complex& c = a.complex;
  if (labelling.size() != c.cells.size())
    throw std::invalid_argument("shape_faces: the labelling has " + std::to_string(labelling.size()) +
                                " entries for " + std::to_string(c.cells.size()) + " cells");
  for (std::size_t k = 0; k < c.cells.size(); ++k)
    if (c.cells[k].outer && labelling[k])
      throw std::invalid_argument("shape_faces: outer cell " + std::to_string(k) + " is labelled inside");
  auto inside = [&](int cell) { return cell >= 0 && labelling[static_cast<std::size_t>(cell)] != 0; };
  const auto& triangles = a.arrangement.triangles();
  std::vector<ExportedFace> faces;
  for (const std::vector<int>& group : c.supports) {
    if (group.empty()) continue;
    const Patch& first = c.patches.at(static_cast<std::size_t>(group.front()));
    if (inside(first.inside_cell) == inside(first.outside_cell)) continue;  // not on the boundary
    int patch = group.front();
    for (int p : group)
      if (inside(c.patches[static_cast<std::size_t>(p)].inside_cell)) {
        patch = p;
        break;
      }
    for (int t : c.patches[static_cast<std::size_t>(patch)].pieces) {
      const ArrTriangle3& tri = triangles.at(static_cast<std::size_t>(t));
      ExportedFace f;
      f.triangle = t;
      f.patch = patch;
      f.halfspace = c.patches[static_cast<std::size_t>(patch)].halfspace;
      f.vertices = tri.vertices;
      f.front_cell = tri.front_cell;
      f.back_cell = tri.back_cell;
      if (inside(f.front_cell)) {  // turn the normal out of the shape
        std::swap(f.vertices[1], f.vertices[2]);
        std::swap(f.front_cell, f.back_cell);
      }
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const ExportedFace& x, const ExportedFace& y) {
    return x.patch != y.patch ? x.patch < y.patch : x.triangle < y.triangle;
  });
  return faces;
}

std::string arrangement_ply(const Scene3& scene, const Arranged3& a) {
  check_fit(scene, a);
  return ply_text(scene, a, exported_faces(a), kArrangementWhat);
}

ObjText arrangement_obj(const Scene3& scene, const Arranged3& a, const std::string& mtl_name,
                        const MeshExportOptions& options) {
  check_fit(scene, a);
  return obj_text(scene, a, exported_faces(a), mtl_name, options, kArrangementWhat);
}

std::string shape_ply(const Scene3& scene, const Arranged3& a, const std::vector<char>& labelling) {
  check_fit(scene, a);
  return ply_text(scene, a, shape_faces(a, labelling), kShapeWhat);
}

ObjText shape_obj(const Scene3& scene, const Arranged3& a, const std::vector<char>& labelling,
                  const std::string& mtl_name, const MeshExportOptions& options) {
  check_fit(scene, a);
  return obj_text(scene, a, shape_faces(a, labelling), mtl_name, options, kShapeWhat);
}

std::string shape_off(const Scene3& scene, const Arranged3& a, const std::vector<char>& labelling,
                      const MeshExportOptions& options) {
  check_fit(scene, a);
  const std::vector<ExportedFace> faces = shape_faces(a, labelling);
  const VertexNumbering numbering = renumber_vertices(a.arrangement, faces);
  const std::vector<int>& id = numbering.id;
  const std::vector<int>& used = numbering.used;
  std::string s = "OFF\n# hsx " + std::string(kShapeWhat) + "; face colours by halfspace\n";
  for (std::size_t i = 0; i < scene.halfspaces.size(); ++i)
    s += "# halfspace " + std::to_string(i) + " " + comment_text(scene.halfspaces[i].name) + "\n";
  s += patch_ranges(faces);
  s += std::to_string(used.size()) + " " + std::to_string(faces.size()) + " 0\n";
  for (int v : used) s += coordinates(a.arrangement.vertices()[static_cast<std::size_t>(v)], options.exact) + "\n";
  for (const ExportedFace& f : faces) {
    const auto c = rgb(f.halfspace);
    s += "3 " + std::to_string(id[f.vertices[0]]) + " " + std::to_string(id[f.vertices[1]]) + " " +
         std::to_string(id[f.vertices[2]]) + " " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " +
         std::to_string(c[2]) + "\n";
  }
  return s;
}

std::string mtl_path_for(const std::string& obj_path) {
  return std::filesystem::path(obj_path).replace_extension(".mtl").string();
}

}  // namespace hsx
