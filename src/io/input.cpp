#include <hsx/io/input.hpp>

#include <hsx/io/bsh_config.hpp>
#include <hsx/io/exact_json.hpp>
#include <hsx/io/scene_json.hpp>

#include <algorithm>
#include <filesystem>

namespace hsx {

namespace fs = std::filesystem;

PlanarPieces LoadedInput::pieces() const {
  if (arranged) return {&arranged->arrangement.vertices(), &arranged->arrangement.edges()};
  if (document && document->has_geometry && document->complex.dimension == 2)
    return {&document->vertices, &document->edges};
  return {};
}

namespace {

/// `doc` read from `source` (a path, or a name for text; empty: errors carry no prefix).
LoadedInput load_document(const nlohmann::json& doc, const std::string& source, const ArrangementLimits& limits) {
  LoadedInput in;
  in.path = source;
  const std::string prefix = source.empty() ? "" : source + ": ";
  const nlohmann::json* format = doc.is_object() && doc.contains("format") ? &doc.at("format") : nullptr;
  if (format && format->is_string() && format->get<std::string>() == kComplexFormat) {
    try {
      in.document = complex_document_from_json(doc);
    } catch (const InputError& e) {
      throw InputError(prefix + e.what());
    }
    return in;
  }
  const std::size_t max_surface_triangles = static_cast<std::size_t>(std::max<long>(0, limits.max_triangles));
  // The BSH authors' config names `source` in its messages itself (or its grid or samples file).
  if (is_bsh_config(doc)) {
    BshReadOptions options;
    options.max_surface_triangles = max_surface_triangles;
    in.scene3 = read_bsh_config(doc, fs::path(source).parent_path().string(), source.empty() ? "config.json" : source,
                                options, &in.files);  // its grid and samples files, as it opens them
  }
  try {
    if (in.scene3) {
      in.arranged3 = arrange(*in.scene3, limits);
    } else if (scene_dimension(doc) == 3) {
      SceneReadLimits read_limits;
      read_limits.max_surface_triangles = max_surface_triangles;
      in.scene3 = read_scene3(doc, fs::path(source).parent_path().string(), read_limits);
      for (const Halfspace3& h : in.scene3->halfspaces)  // its mesh files, as read_scene3 opens them
        if (h.kind == HalfspaceKind3::Mesh)
          in.files.push_back((fs::path(source).parent_path() / h.primitive.file).string());
      in.arranged3 = arrange(*in.scene3, limits);
    } else {
      in.scene = read_scene2(doc);
      in.arranged = arrange(*in.scene, limits);
    }
  } catch (const InputError& e) {
    throw InputError(prefix + e.what());
  }
  return in;
}

}  // namespace

LoadedInput load_input(const std::string& path, const ArrangementLimits& limits) {
  return load_document(read_exact_json_file(path), path, limits);
}

LoadedInput load_input_text(const std::string& text, const std::string& source, const ArrangementLimits& limits) {
  nlohmann::json doc;
  try {
    doc = parse_exact_json(text);
  } catch (const InputError& e) {
    throw InputError((source.empty() ? "" : source + ": ") + e.what());
  }
  return load_document(doc, source, limits);
}

}  // namespace hsx
