// Kept examples of the NH-Rep survey: see nhrep_survey.hpp.
#include <hsx/io/nhrep_survey.hpp>

#include <hsx/io/files.hpp>
#include <hsx/io/scene_json.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace hsx {
namespace {

std::size_t at(int i) { return static_cast<std::size_t>(i); }

std::string tree_with_names(const nhrep::Tree& tree, int node, const std::vector<nhrep::NaturalHalfspace>& leaves,
                            const std::vector<std::string>& names) {
  const nhrep::TreeNode& n = tree.nodes.at(at(node));
  std::string s = std::string(nhrep::op_name(n.op)) + "(";
  const char* sep = "";
  for (int p : n.leaves) {
    const nhrep::NaturalHalfspace& h = leaves.at(at(p));
    s += sep;
    s += (h.complemented ? "~" : "") + (h.halfspace >= 0 ? names.at(at(h.halfspace)) : std::string("?")) + "#" +
         std::to_string(p);
    sep = ", ";
  }
  for (int ch : n.children) {
    s += sep + tree_with_names(tree, ch, leaves, names);
    sep = ", ";
  }
  return s + ")";
}

std::string cell_list(const Complex& complex, const std::vector<int>& cells, std::size_t max = 6) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < max; ++i) {
    const auto& w = complex.cells.at(at(cells[i])).witness.get();
    s += (i ? ", " : "") + std::to_string(cells[i]) + " at (";
    for (std::size_t d = 0; d < w.size(); ++d) s += (d ? ", " : "") + decimal_string(w[d], 6);
    s += ")";
  }
  if (cells.size() > max) s += ", ...";
  return s;
}

template <class Solid>
std::string note_of(const Solid& c, const nhrep::SurveyOutcome& outcome) {
  if (!outcome.whole.evaluated) throw std::logic_error(c.name + ": no note for a solid that was not evaluated");
  const nhrep::PipelineRun& o = outcome.whole;
  const auto& names = c.arranged.complex.halfspace_names;
  std::ostringstream note;
  note << "NH-Rep natural-halfspace counterexample (hsx nhsurvey, " << c.origin << "). The solid is describable by "
       << "its " << o.eval.natural_halfspaces.size() << " patches' natural halfspaces {";
  for (std::size_t i = 0; i < o.eval.natural_halfspaces.size(); ++i)
    note << (i ? ", " : "") << names.at(at(o.eval.natural_halfspaces[i]));
  note << "}, but Algorithm 1's tree with those halfspaces at its leaves, "
       << tree_with_names(o.built.tree, o.built.tree.root, o.eval.leaf_halfspace, names) << ", is wrong on "
       << o.eval.wrong_inside.size() + o.eval.wrong_outside.size() << " cells";
  if (!o.eval.wrong_inside.empty()) note << "; it misses solid cells " << cell_list(c.arranged.complex, o.eval.wrong_inside);
  if (!o.eval.wrong_outside.empty()) note << "; it adds cells " << cell_list(c.arranged.complex, o.eval.wrong_outside);
  note << ". NH-Rep needs extended surfaces here (Appendix B).";
  const bool three = c.arranged.complex.dimension == 3;
  if (outcome.holes > 0)
    note << " The solid has " << outcome.holes << (three ? " cavity(ies) (or tunnels' voids)" : " hole(s)")
         << ": Algorithm 1's min root over the boundary " << (three ? "shells" : "loops")
         << " cannot leave a " << (three ? "cavity" : "hole") << " out with natural halfspaces.";
  else
    note << " The solid has no " << (three ? "cavity" : "hole")
         << ": a natural halfspace, extended past its patch, reaches cells it must not.";
  if (!o.built.decompositions.empty()) note << " The tree used " << o.built.decompositions.size() << " patch decomposition(s).";
  return note.str();
}

std::string scene_text(Scene2 scene, const std::string& note) {
  scene.description = note;
  return write_scene2(scene).dump(2) + "\n";
}

std::string scene_text(Scene3 scene, const std::string& note) {
  scene.description = note;
  scene.domain_given = true;  // the survey's domain, written out (else chosen again when read)
  return write_scene3(scene).dump(2) + "\n";
}

template <class Solid>
void write_example(const std::string& dir, const Solid& c, const nhrep::SurveyOutcome& o) {
  const std::string note = note_of(c, o);
  const csg::ExprPtr expr = nhrep::example_expression(c, o);
  std::filesystem::create_directories(dir);
  const std::string base = (std::filesystem::path(dir) / c.name).string();
  write_file_atomically(base + ".json", scene_text(c.scene, note));
  const nlohmann::json doc{{"description", "the solid of " + c.name + ".json (" + c.origin + ")"},
                           {"csg", csg::to_text(*expr, c.arranged.complex.halfspace_names)}};
  write_file_atomically(base + ".csg", doc.dump(2) + "\n");
}

}  // namespace

std::string survey_example_note(const nhrep::SurveySolid& c, const nhrep::SurveyOutcome& o) { return note_of(c, o); }

std::string survey_example_note(const nhrep::SurveySolid3& c, const nhrep::SurveyOutcome& o) { return note_of(c, o); }

void write_survey_example(const std::string& dir, const nhrep::SurveySolid& c, const nhrep::SurveyOutcome& o) {
  write_example(dir, c, o);
}

void write_survey_example(const std::string& dir, const nhrep::SurveySolid3& c, const nhrep::SurveyOutcome& o) {
  write_example(dir, c, o);
}

}  // namespace hsx
