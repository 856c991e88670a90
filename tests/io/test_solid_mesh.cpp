// Solids given as closed meshes on a 3D scene's halfspaces (io/solid.hpp's mesh_path, geometry/mesh_solid3.hpp):
// each mesh of data/scenes3d/mesh_solids.json's solids gives, cell for cell, the solid of the CSG expression it
// was made for (a box, a union, a difference, a hollow box); a mesh with a face off the halfspaces, outside the
// domain, or intersecting itself is refused with a message naming the file and the face or vertex; 2D scenes
// are refused.
#include <hsx/io/input.hpp>
#include <hsx/io/solid.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace hsx;

namespace {

std::string data(const std::string& name) { return std::string(HSX_SOURCE_DIR) + "/data/" + name; }

std::vector<char> from_mesh(const LoadedInput& in, const std::string& path) {
  SolidSource s;
  s.mesh_path = path;
  return load_solid(in, s).cells;
}

std::vector<char> from_csg(const LoadedInput& in, const std::string& expression) {
  SolidSource s;
  s.csg = expression;
  return load_solid(in, s).cells;
}

std::string refusal(const LoadedInput& in, const std::string& path) {
  try {
    from_mesh(in, path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A mesh file written into a scratch file of the test's own (removed at the end of the scope).
struct ScratchMesh {
  std::string path;
  explicit ScratchMesh(const std::string& text, const std::string& extension = ".obj") {
    path = std::filesystem::temp_directory_path().string() + "/hsx_test_solid_mesh_" + std::to_string(getpid()) +
           extension;
    std::ofstream(path) << text;
  }
  ~ScratchMesh() { std::remove(path.c_str()); }
};

/// The box [lo, hi] as .obj text, outward (the layout of data/meshes/cube.obj).
std::string box_obj(const std::string& lo_x, const std::string& lo_y, const std::string& lo_z,
                    const std::string& hi_x, const std::string& hi_y, const std::string& hi_z) {
  std::string t;
  for (int v = 0; v < 8; ++v) {
    const bool x = v == 1 || v == 2 || v == 5 || v == 6, y = v == 2 || v == 3 || v == 6 || v == 7, z = v >= 4;
    t += "v " + (x ? hi_x : lo_x) + " " + (y ? hi_y : lo_y) + " " + (z ? hi_z : lo_z) + "\n";
  }
  return t + "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\n"
             "f 2 3 7\nf 2 7 6\n";
}

}  // namespace

TEST_CASE("a mesh on the scene's halfspaces gives the CSG solid it bounds, cell for cell", "[solid][mesh]") {
  const LoadedInput in = load_input(data("scenes3d/mesh_solids.json"));
  const std::vector<char> cube = from_mesh(in, data("meshes/cube.obj"));
  CHECK(cube == from_csg(in, "A & B"));
  CHECK(std::count(cube.begin(), cube.end(), 1) == 1);
  CHECK(from_mesh(in, data("meshes/lprism.obj")) == from_csg(in, "A | B"));
  CHECK(from_mesh(in, data("scenes3d/mesh_solid_right.off")) == from_csg(in, "A & ~B"));
  CHECK(from_mesh(in, data("meshes/hollow_cube.obj")) == from_csg(in, "O & ~I"));
  // A mesh given inward is turned round by build_mesh3: the same solid. Swapping the corners mirrors the box in
  // three axes, which reverses its orientation.
  const std::string inward = box_obj("2", "2", "2", "1", "1", "1");
  const ScratchMesh in_mesh(inward);
  CHECK(from_mesh(in, in_mesh.path) == from_csg(in, "I"));
}

TEST_CASE("a mesh off the halfspaces, outside the domain or intersecting itself is refused", "[solid][mesh]") {
  const LoadedInput in = load_input(data("scenes3d/mesh_solids.json"));
  const std::string cut = refusal(in, data("scenes3d/mesh_solid_cut.obj"));
  CHECK_THAT(cut, Catch::Contains("mesh_solid_cut.obj:21: face 10 does not lie on the scene's halfspaces"));
  CHECK_THAT(cut, Catch::Contains("(2 faces are off the halfspaces)"));
  {
    const ScratchMesh outside(box_obj("0", "0", "0", "1", "1", "5"));
    CHECK_THAT(refusal(in, outside.path), Catch::Contains(outside.path + ":5: vertex 4 [0, 0, 5] is outside the "
                                                           "scene's domain"));
  }
  {  // the shells A and B as one mesh: they overlap
    const std::string b = box_obj("0", "0", "0", "1", "2", "1");
    std::string shifted;  // B's faces renumbered after A's 8 vertices
    for (std::size_t k = 0; k < b.size();) {
      const std::size_t e = b.find('\n', k);
      std::string line = b.substr(k, e - k);
      if (line[0] == 'f') {
        int i, j, l;
        std::sscanf(line.c_str(), "f %d %d %d", &i, &j, &l);
        line = "f " + std::to_string(i + 8) + " " + std::to_string(j + 8) + " " + std::to_string(l + 8);
      }
      shifted += line + "\n";
      k = e + 1;
    }
    std::string a = box_obj("0", "0", "0", "2", "1", "1"), text;
    text = a.substr(0, a.find("f ")) + shifted.substr(0, shifted.find("f ")) + a.substr(a.find("f ")) +
           shifted.substr(shifted.find("f "));
    const ScratchMesh both(text);
    CHECK_THAT(refusal(in, both.path), Catch::Contains(both.path + ": the surface intersects itself"));
  }
  {  // a face on the domain box and on no halfspace
    const ScratchMesh boxed(box_obj("-1", "-1", "-1", "0", "0", "0"));
    CHECK_THAT(refusal(in, boxed.path), Catch::Contains("(it is on the domain box, which is no halfspace)"));
  }
  // Open meshes are refused by build_mesh3, naming the file.
  std::string open = box_obj("1", "1", "1", "2", "2", "2");
  open.erase(open.rfind("f "));
  const ScratchMesh open_mesh(open);
  CHECK_THAT(refusal(in, open_mesh.path), Catch::Contains(open_mesh.path));
  // 2D scenes and complexes take no mesh.
  const LoadedInput planar = load_input(data("figures/fig02-1.json"));
  CHECK_THAT(refusal(planar, data("meshes/cube.obj")), Catch::Contains("--mesh: a solid given as a mesh needs a 3D "
                                                                        "scene"));
  // Exactly one source.
  SolidSource two;
  two.csg = "A";
  two.mesh_path = data("meshes/cube.obj");
  CHECK_THROWS_WITH(load_solid(in, two), Catch::Contains("--mesh FILE, exactly one"));
}
