// What a command or a program reads: an hsx-scene/1 file (arranged here) or an hsx-complex/1 file (an arrangement
// computed elsewhere). Dispatch is on the document's "format" field.
#pragma once

#include <hsx/complex/from_arrangement2.hpp>
#include <hsx/io/complex_json.hpp>
#include <hsx/io/result_json.hpp>

#include <optional>
#include <string>

namespace hsx {

struct LoadedInput {
  std::string path;
  std::optional<Scene2> scene;              ///< set for scene input
  std::optional<Arranged2> arranged;        ///< set for scene input
  std::optional<ComplexDocument> document;  ///< set for complex input

  const Complex& complex() const { return arranged ? arranged->complex : document->complex; }
  PlanarPieces pieces() const;
};

/// Reads `path`; a scene is arranged within `limits`. Throws InputError naming the file and field (or the limit).
LoadedInput load_input(const std::string& path, const ArrangementLimits& limits = {});

/// The same for a document held in memory (a host's JSON string, the Python module's dicts): `text` is the JSON,
/// `source` names it in error messages ("scene.json: ..."; empty: no prefix) and becomes LoadedInput::path.
LoadedInput load_input_text(const std::string& text, const std::string& source,
                            const ArrangementLimits& limits = {});

}  // namespace hsx
