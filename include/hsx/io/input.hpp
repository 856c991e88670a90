// What a command or a program reads: an hsx-scene/1 file of dimension 2 or 3 or a BSH authors' config.json (arranged
// here), or an hsx-complex/1 file (an arrangement computed elsewhere). Dispatch is on the document's "format" field
// ("hsx-complex/1", else a scene with its "dimension"), and a JSON object with an "input" list and no "format" is a
// BSH config.json (io/bsh_config.hpp).
#pragma once

#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/complex/from_arrangement3.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/result_json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hsx {

struct LoadedInput {
  std::string path;
  std::optional<Scene2> scene;              ///< set for scene input
  std::optional<Arranged2> arranged;        ///< set for scene input
  std::optional<Scene3> scene3;             ///< set for 3D scene input
  std::optional<Arranged3> arranged3;       ///< set for 3D scene input
  std::optional<ComplexDocument> document;  ///< set for complex input
  /// The files it was read from besides `path`, as opened: a 3D scene's mesh files; a BSH config's grid_64.json and
  /// samples files. (A run must not replace them: OutputFiles::protect.)
  std::vector<std::string> files;

  const Complex& complex() const {
    return arranged ? arranged->complex : arranged3 ? arranged3->complex : document->complex;
  }
  /// 2D pieces for result documents: the 2D arrangement's (or a 2D document's geometry); empty otherwise.
  PlanarPieces pieces() const;
};

/// Reads `path`; a scene is arranged within `limits`. Throws InputError naming the file and field (or the limit).
LoadedInput load_input(const std::string& path, const ArrangementLimits& limits = {});

/// The same for a document held in memory (a host's JSON string, the Python module's dicts): `text` is the JSON,
/// `source` names it in error messages ("scene.json: ..."; empty: no prefix) and becomes LoadedInput::path.
LoadedInput load_input_text(const std::string& text, const std::string& source,
                            const ArrangementLimits& limits = {});

}  // namespace hsx
