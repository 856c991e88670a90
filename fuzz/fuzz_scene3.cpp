// Bytes -> a 3D scene (text starting with '{': hsx-scene/1 JSON, or the BSH authors' config) or a mesh (text
// starting with "OFF": OFF, with "ply": PLY, anything else: OBJ). Bad input must end in InputError; anything else
// (crash, sanitizer report, other exception, hang) is a finding. Checked on every accepted scene: every sample lies
// exactly on its halfspace's boundary and `near` ones at the recorded squared distance, the domain contains every
// surface vertex and sample, and write_scene3 reads back to the same triangles and samples. Checked on every
// accepted mesh: written back as OBJ, OFF and PLY text it reads as the same ObjMesh, and build_mesh3 accepts it
// the same way from each. Mesh files named by a scene are not opened (the base folder does not exist), and the
// BSH config's samples and grid files neither, so both end in InputError.
#include "fuzz_support.hpp"

#include <hsx/geometry/mesh3.hpp>
#include <hsx/geometry/scene3.hpp>
#include <hsx/io/bsh_config.hpp>
#include <hsx/io/scene_json.hpp>

#include <sstream>
#include <string>

namespace {

[[noreturn]] void finding(const std::string& what) { hsx::fuzz::finding("fuzz_scene3", what); }

constexpr const char* kNoFolder = "/nonexistent-hsx-fuzz-folder";

void check_scene(const hsx::Scene3& s, const hsx::SceneReadLimits& limits) {
  for (const hsx::Sample3& sample : s.samples) {
    const hsx::Halfspace3& h = s.halfspaces.at(static_cast<std::size_t>(sample.halfspace));
    if (h.side(sample.location) != 0) finding("a sample is not on its boundary");
    const hsx::PointQ3 d{sample.location.x - sample.given.x, sample.location.y - sample.given.y,
                         sample.location.z - sample.given.z};
    if (hsx::dot3(d, d) != sample.distance2) finding("a sample's distance2 is wrong");
    if (!s.domain.contains(sample.location)) finding("a sample outside the domain");
  }
  for (const hsx::Halfspace3& h : s.halfspaces)
    for (const hsx::PointQ3& p : h.surface.vertices)
      if (!s.domain.contains(p)) finding("a surface vertex outside the domain");
  hsx::Scene3 back;
  try {
    back = hsx::read_scene3(hsx::parse_exact_json(hsx::write_scene3(s).dump()), kNoFolder, limits);
  } catch (const hsx::InputError& e) {
    finding(std::string("the written scene is refused: ") + e.what());
  }
  if (back.halfspaces.size() != s.halfspaces.size() || back.samples.size() != s.samples.size())
    finding("round trip changed the counts");
  for (std::size_t i = 0; i < s.halfspaces.size(); ++i)
    if (back.halfspaces[i].surface.vertices != s.halfspaces[i].surface.vertices ||
        back.halfspaces[i].surface.triangles != s.halfspaces[i].surface.triangles)
      finding("round trip changed halfspace " + std::to_string(i));
  for (std::size_t j = 0; j < s.samples.size(); ++j)
    if (back.samples[j].location != s.samples[j].location) finding("round trip moved sample " + std::to_string(j));
}

void check_mesh(const hsx::ObjMesh& mesh, const hsx::MeshReadLimits& limits) {
  std::ostringstream obj, off, ply;
  off << "OFF\n" << mesh.vertices.size() << " " << mesh.faces.size() << " 0\n";
  ply << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.faces.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const hsx::PointQ3& p : mesh.vertices) {
    const std::string line = hsx::exact_string(p.x) + " " + hsx::exact_string(p.y) + " " + hsx::exact_string(p.z) + "\n";
    obj << "v " << line;
    off << line;
    ply << line;
  }
  for (const auto& f : mesh.faces) {
    obj << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
    off << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
    ply << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  }
  hsx::MeshReadLimits wide = limits;
  wide.numbers.max_chars = 100000;  // exact_string of a decimal may be longer than its decimal text
  wide.numbers.max_exponent = 100000;
  std::istringstream a(obj.str()), b(off.str()), c(ply.str());
  hsx::ObjMesh x, y, z;
  try {
    x = hsx::read_obj(a, "back.obj", wide);
    y = hsx::read_off(b, "back.off", wide);
    z = hsx::read_ply(c, "back.ply", wide);
  } catch (const hsx::InputError& e) {
    finding(std::string("a mesh written back is refused: ") + e.what());
  }
  if (x.vertices != mesh.vertices || y.vertices != mesh.vertices || z.vertices != mesh.vertices ||
      x.faces != mesh.faces || y.faces != mesh.faces || z.faces != mesh.faces)
    finding("OBJ, OFF and PLY of the same mesh differ");
  bool accepted[2] = {false, false};
  int k = 0;
  for (const hsx::ObjMesh* m : {&mesh, static_cast<const hsx::ObjMesh*>(&z)}) {
    try {
      hsx::build_mesh3(*m);
      accepted[k] = true;
    } catch (const hsx::InputError&) {
    }
    ++k;
  }
  if (accepted[0] != accepted[1]) finding("build_mesh3 disagrees between formats");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  hsx::SceneReadLimits limits;
  limits.json.max_bytes = 16384;
  limits.numbers.max_chars = 40;
  limits.numbers.max_exponent = 12;
  limits.max_halfspaces = 12;
  limits.max_samples = 12;
  limits.max_segments = 24;
  limits.meshes.numbers = limits.numbers;
  limits.meshes.max_vertices = 200;
  limits.meshes.max_faces = 400;
  if (!text.empty() && text[0] == '{') {
    hsx::Scene3 scene;
    try {
      const nlohmann::json doc = hsx::parse_exact_json(text, limits.json);
      if (hsx::is_bsh_config(doc)) {
        hsx::read_bsh_config(doc, kNoFolder);
        finding("a BSH config was accepted without its grid file");
      }
      scene = hsx::read_scene3(doc, kNoFolder, limits);
    } catch (const hsx::InputError&) {
      return 0;
    }
    check_scene(scene, limits);
    return 0;
  }
  hsx::ObjMesh mesh;
  try {
    std::istringstream in(text);
    if (text.rfind("OFF", 0) == 0) mesh = hsx::read_off(in, "fuzz.off", limits.meshes);
    else if (text.rfind("ply", 0) == 0) mesh = hsx::read_ply(in, "fuzz.ply", limits.meshes);
    else mesh = hsx::read_obj(in, "fuzz.obj", limits.meshes);
  } catch (const hsx::InputError&) {
    return 0;
  }
  check_mesh(mesh, limits.meshes);
  return 0;
}
