#include <hsx/io/result_json.hpp>

#include <hsx/io/json_values.hpp>
#include <hsx/geometry/scene.hpp>

#include <boost/uuid/detail/sha1.hpp>

#include <cstdio>

namespace hsx {

std::vector<int> patches_of_supports(const Complex& complex, const std::vector<char>& supports) {
  std::vector<int> out;
  for (std::size_t g = 0; g < supports.size() && g < complex.supports.size(); ++g)
    if (supports[g])
      for (int p : complex.supports[g]) out.push_back(p);
  std::sort(out.begin(), out.end());
  return out;
}

std::string complex_identity(const Complex& c) {
  std::string text = "hsx-complex-id/1\ndimension " + std::to_string(c.dimension) + "\nhalfspaces " +
                     std::to_string(c.halfspace_names.size()) + "\n";
  for (const std::string& name : c.halfspace_names) text += nlohmann::json(name).dump() + "\n";
  text += "cells " + std::to_string(c.cells.size()) + "\n";
  for (const Cell& cell : c.cells) {
    text += cell.outer ? "1 " : "0 ";
    for (char in : cell.inside) text += in ? '1' : '0';
    text += '\n';
  }
  text += "patches " + std::to_string(c.patches.size()) + "\n";
  for (const Patch& p : c.patches) {
    text += std::to_string(p.halfspace) + " " + std::to_string(p.inside_cell) + " " + std::to_string(p.outside_cell) +
            " :";
    for (int j : p.junctions) text += " " + std::to_string(j);
    text += '\n';
  }
  text += "supports " + std::to_string(c.supports.size()) + "\n";
  for (const std::vector<int>& group : c.supports) {
    for (std::size_t k = 0; k < group.size(); ++k) text += (k ? " " : "") + std::to_string(group[k]);
    text += '\n';
  }
  boost::uuids::detail::sha1 sha;
  sha.process_bytes(text.data(), text.size());
  boost::uuids::detail::sha1::digest_type digest;
  sha.get_digest(digest);
  char hex[41];
  for (int k = 0; k < 5; ++k) std::snprintf(hex + 8 * k, 9, "%08x", static_cast<unsigned>(digest[k]));
  return std::string("sha1:") + hex;
}

std::vector<char> read_result_labelling(const nlohmann::json& doc, const Complex& complex) {
  if (!doc.is_object() || !doc.contains("format") || doc.at("format") != kResultFormat)
    throw InputError("format: expected \"" + std::string(kResultFormat) + "\"");
  const std::string identity = complex_identity(complex);
  if (!doc.contains("complex_id") || !doc.at("complex_id").is_string())
    throw InputError("complex_id: missing (a result names cells of the input it was computed from; this one does "
                     "not say which: compute it again with hsx extract)");
  if (doc.at("complex_id").get<std::string>() != identity)
    throw InputError("complex_id: " + doc.at("complex_id").get<std::string>() +
                     " is not this input's (" + identity + "): the result was computed from another scene or complex");
  if (!doc.contains("inside_cells") || !doc.at("inside_cells").is_array())
    throw InputError("inside_cells: expected an array of cell ids");
  const int cell_count = static_cast<int>(complex.cells.size());
  std::vector<char> labelling(cell_count, 0);
  const auto& cells = doc.at("inside_cells");
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const auto& v = cells[k];
    if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= cell_count)
      throw InputError("inside_cells[" + std::to_string(k) + "]: not a cell id of this input (it has " +
                       std::to_string(cell_count) + " cells)");
    labelling[v.get<long long>()] = 1;
  }
  return labelling;
}

int oriented_patch(const Complex& complex, int support, const std::vector<char>& labelling) {
  const std::vector<int>& group = complex.supports.at(static_cast<std::size_t>(support));
  for (int p : group) {
    const int inside = complex.patches[p].inside_cell;
    if (inside >= 0 && static_cast<std::size_t>(inside) < labelling.size() && labelling[inside]) return p;
  }
  return group.front();
}

std::size_t closed_form_terms(const std::string& text) {
  if (text.empty()) return 0;
  std::size_t terms = 1;
  int depth = 0;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] == '(') ++depth;
    if (text[k] == ')') --depth;
    if (depth == 0 && k > 0 && k + 2 < text.size() && text[k] == ' ' && (text[k + 1] == '+' || text[k + 1] == '-') &&
        text[k + 2] == ' ')
      ++terms;
  }
  return terms;
}

namespace {

nlohmann::json boundary_json(const bsh::Problem& problem, const bsh::Labelling& labelling,
                             const PlanarPieces& geometry) {
  const Complex& c = problem.complex();
  nlohmann::json out = nlohmann::json::array();
  for (int g : bsh::boundary_supports(problem, labelling)) {
    const bsh::SupportTerm& s = problem.supports()[g];
    const int oriented = oriented_patch(c, g, labelling);
    const Patch& patch = c.patches[oriented];
    nlohmann::json item;
    item["patch"] = oriented;
    item["halfspace"] = c.halfspace_names[patch.halfspace];
    nlohmann::json coincident = nlohmann::json::array();
    for (int p : s.patches)
      if (p != oriented) coincident.push_back(c.halfspace_names[c.patches[p].halfspace]);
    item["coincident"] = coincident;
    item["measure"] = measure_to_json(s.measure);
    if (c.dimension == 3) {
      item["inside_cell"] = labelling[patch.inside_cell] ? patch.inside_cell : patch.outside_cell;
      item["outside_cell"] = labelling[patch.inside_cell] ? patch.outside_cell : patch.inside_cell;
      item["triangles"] = patch.pieces.size();
    }
    if (geometry.known() && !patch.pieces.empty()) {
      nlohmann::json pieces = nlohmann::json::array();
      for (int e : patch.pieces) {
        const ArrEdge2& edge = geometry.edges->at(e);
        // Run each piece with the shape on its left.
        const bool forward = edge.left_face >= 0 && labelling[edge.left_face];
        const OneRootPoint& from = geometry.vertices->at(forward ? edge.source : edge.target).point;
        const OneRootPoint& to = geometry.vertices->at(forward ? edge.target : edge.source).point;
        nlohmann::json piece{{"from", point_to_json(from)}, {"to", point_to_json(to)}};
        if (edge.shape == EdgeShape2::Segment) {
          piece["shape"] = "segment";
        } else {
          piece["shape"] = "arc";
          piece["center"] = point_to_json(edge.center);
          piece["radius"] = exact_string(edge.radius);
          piece["ccw"] = forward == edge.ccw;
        }
        pieces.push_back(std::move(piece));
      }
      item["pieces"] = std::move(pieces);
    }
    out.push_back(std::move(item));
  }
  return out;
}

nlohmann::json cells_json(const bsh::Labelling& labelling) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < labelling.size(); ++k)
    if (labelling[k]) out.push_back(k);
  return out;
}

}  // namespace

nlohmann::json result_to_json(const bsh::Problem& problem, const bsh::ExtractResult& r, const PlanarPieces& geometry,
                              bool include_seconds) {
  const Complex& c = problem.complex();
  nlohmann::json j;
  j["format"] = kResultFormat;
  j["complex_id"] = complex_identity(c);
  j["method"] = bsh::to_string(r.method);
  j["optimal"] = r.optimal;
  if (!r.stopped_by.empty()) j["stopped_by"] = r.stopped_by;
  if (!r.optimality_note.empty()) j["optimality_note"] = r.optimality_note;
  j["energy"] = {{"missing_samples", r.energy.missing_samples}, {"measure", measure_to_json(r.energy.measure())}};
  j[c.dimension == 3 ? "volume" : "area"] = measure_to_json(bsh::inside_measure(c, r.labelling));
  if (c.dimension == 3) {
    j["boundary_area"] = j["energy"]["measure"];
    if (j["boundary_area"]["exact"].is_string())
      j["boundary_area"]["terms"] = closed_form_terms(j["boundary_area"]["exact"].get<std::string>());
  }
  j["sample_connected"] = r.sample_connected;
  j["ties"] = {{"count", r.ties.count},
               {"checked", r.ties.checked},
               {"certified", r.ties.certified},
               {"capped", r.ties.capped}};
  if (!r.ties.stopped_by.empty()) j["ties"]["stopped_by"] = r.ties.stopped_by;
  j["boundary"] = boundary_json(problem, r.labelling, geometry);
  j["inside_cells"] = cells_json(r.labelling);
  j["removed_patches"] = patches_of_supports(c, r.removed);
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& removed : r.steps) {
    std::vector<char> flags(c.supports.size(), 0);
    for (int g : removed) flags[g] = 1;
    steps.push_back(patches_of_supports(c, flags));
  }
  j["steps"] = steps;
  nlohmann::json tied = nlohmann::json::array();
  for (const auto& l : r.tied) tied.push_back(cells_json(l));
  j["tied"] = tied;
  nlohmann::json stats{{"graph_cuts", r.stats.graph_cuts},
                       {"uncertified_cuts", r.stats.uncertified_cuts},
                       {"reused_cuts", r.stats.reused_cuts},
                       {"states_expanded", r.stats.states_expanded},
                       {"states_created", r.stats.states_created},
                       {"max_queue", r.stats.max_queue},
                       {"labellings_enumerated", r.stats.labellings_enumerated}};
  if (r.method == bsh::Method::Exact) {
    auto bound = [](const bsh::EnergyBound& b) {
      return nlohmann::json{{"missing_samples", b.missing_samples}, {"measure", b.measure}};
    };
    stats["branch_and_bound"] = {{"nodes", r.stats.nodes},
                                 {"nodes_created", r.stats.nodes_created},
                                 {"pruned_by_bound", r.stats.pruned_by_bound},
                                 {"pruned_by_islands", r.stats.pruned_by_islands},
                                 {"island_branches", r.stats.island_branches},
                                 {"certified_bounds", r.stats.certified_bounds},
                                 {"lower_bound", bound(r.stats.lower_bound)},
                                 {"gap", bound(r.stats.gap)},
                                 {"max_gap", bound(r.stats.max_gap)}};
  }
  if (include_seconds) stats["seconds"] = r.stats.seconds;
  j["stats"] = stats;
  return j;
}

}  // namespace hsx
