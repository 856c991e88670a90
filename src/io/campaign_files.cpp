// A campaign's files: see campaign_files.hpp.
#include <hsx/io/campaign_files.hpp>

#include <hsx/io/files.hpp>
#include <hsx/io/scene_json.hpp>
#include <hsx/io/svg.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <type_traits>

namespace hsx {
namespace fs = std::filesystem;
using campaign::CheckStatus;
using campaign::SceneOutcome;
using campaign::SceneRecord;
using campaign::StatusCounts;
using campaign::Summary;

std::vector<std::uint64_t> CampaignPlan::indices() const {
  return campaign::shard_indices(start, count, shard, shards);
}

namespace {

/// campaign.json's "limits".
nlohmann::json limits_json(const campaign::CampaignSettings& s) {
  return {{"max_cells", s.limits.max_cells},
          {"max_side_entries", s.limits.max_side_entries},
          {"brute_force_limit", s.brute_force_limit},
          {"max_states", s.max_states},
          {"max_graph_cuts", s.max_graph_cuts},
          {"precision_bits", s.precision_bits},
          {"time_limit", s.time_limit}};
}

/// campaign_to_json for a 3D campaign: "dimension": 3 and the 3D generator's settings.
nlohmann::json campaign3_to_json(const campaign::CampaignSettings& s, const CampaignPlan& plan,
                                 const nlohmann::json& checks) {
  const campaign::Scene3Settings& g = s.scene3;
  nlohmann::json weights = nlohmann::json::object();
  for (int k = 0; k < campaign::kDegeneracy3Count; ++k)
    weights[to_string(static_cast<campaign::Degeneracy3>(k))] = g.degeneracy_weight[static_cast<std::size_t>(k)];
  return {{"format", kCampaignFormat},
          {"seed", s.seed},
          {"dimension", 3},
          {"plan", {{"start", plan.start}, {"count", plan.count}, {"shard", plan.shard}, {"shards", plan.shards}}},
          {"generator",
           {{"min_primitives", g.solid.min_primitives},
            {"max_primitives", g.solid.max_primitives},
            {"segments", g.solid.segments},
            {"hollow", g.solid.hollow},
            {"max_draws", g.solid.max_draws},
            {"min_degeneracies", g.min_degeneracies},
            {"max_degeneracies", g.max_degeneracies},
            {"degeneracy_weights", weights},
            {"max_samples", g.max_samples},
            {"sample_policy", campaign::to_string(s.sample_policy)}}},
          {"checks", checks},
          {"limits", limits_json(s)}};
}

}  // namespace

nlohmann::json campaign_to_json(const campaign::CampaignSettings& s, const CampaignPlan& plan) {
  const RandomSceneSettings& g = s.scene;
  nlohmann::json weights = nlohmann::json::object();
  for (int k = 0; k < kDegeneracyCount; ++k)
    weights[to_string(static_cast<Degeneracy>(k))] = g.degeneracy_weight[static_cast<std::size_t>(k)];
  nlohmann::json checks = nlohmann::json::array();
  for (const std::string& c : s.checks.empty() ? campaign::default_checks() : s.checks) checks.push_back(c);
  if (s.dimension == 3) return campaign3_to_json(s, plan, checks);
  nlohmann::json out = {{"format", kCampaignFormat},
          {"seed", s.seed},
          {"plan", {{"start", plan.start}, {"count", plan.count}, {"shard", plan.shard}, {"shards", plan.shards}}},
          {"generator",
           {{"min_halfspaces", g.min_halfspaces},
            {"max_halfspaces", g.max_halfspaces},
            {"halfplanes", g.halfplanes},
            {"disks", g.disks},
            {"polygons", g.polygons},
            {"complement_percent", g.complement_percent},
            {"denominator", g.denominator},
            {"coordinate_bound", g.coordinate_bound},
            {"max_radius", g.max_radius},
            {"min_degeneracies", g.min_degeneracies},
            {"max_degeneracies", g.max_degeneracies},
            {"degeneracy_weights", weights},
            {"max_samples", g.max_samples},
            {"near_percent", g.near_percent}}},
          {"checks", checks},
          {"limits", limits_json(s)}};
  // Only when not the default, so that the manifests of uniform campaigns stay as before.
  if (s.sample_policy != campaign::SamplePolicy::Uniform)
    out["generator"]["sample_policy"] = campaign::to_string(s.sample_policy);
  return out;
}

nlohmann::ordered_json record_to_json(const SceneRecord& r) {
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  for (const campaign::CheckOutcome& c : r.checks)
    checks.push_back({{"check", c.check}, {"status", to_string(c.status)}, {"witness", c.witness}});
  nlohmann::ordered_json j = {{"index", r.index},         {"seed", r.seed},       {"halfspaces", r.halfspaces},
                              {"cells", r.cells},         {"patches", r.patches}, {"samples", r.samples},
                              {"degeneracies", r.degeneracies}, {"outcome", to_string(r.outcome)}};
  if (!r.note.empty()) j["note"] = r.note;
  if (r.timed_out) j["timed_out"] = true;
  if (!r.intended.empty()) j["intended"] = r.intended;
  j["checks"] = checks;
  return j;
}

namespace {

template <class T>
T field(const nlohmann::json& j, const char* name) {
  if (!j.is_object() || !j.contains(name)) throw InputError(std::string("missing field \"") + name + "\"");
  try {
    return j.at(name).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(std::string("field \"") + name + "\" has the wrong type");
  }
}

/// A whole-number field: a JSON integer (not 0.9 nor 1e300) within T's range.
template <class T>
T whole_field(const nlohmann::json& j, const char* name) {
  if (!j.is_object() || !j.contains(name)) throw InputError(std::string("missing field \"") + name + "\"");
  const nlohmann::json& v = j.at(name);
  const auto most = static_cast<std::uint64_t>(std::numeric_limits<T>::max());
  const auto least = static_cast<std::int64_t>(std::numeric_limits<T>::min());
  if (v.is_number_unsigned() && v.get<std::uint64_t>() <= most) return static_cast<T>(v.get<std::uint64_t>());
  if (v.is_number_integer() && !v.is_number_unsigned()) {
    const std::int64_t i = v.get<std::int64_t>();
    if (i >= least && (i < 0 || static_cast<std::uint64_t>(i) <= most)) return static_cast<T>(i);
  }
  throw InputError(std::string("field \"") + name + "\" is not a whole number from " + std::to_string(least) +
                   " to " + std::to_string(most));
}

/// Refuses a campaign file that exists and is not a regular file: a FIFO would block its reading or writing, a
/// device never end.
void require_regular_or_missing(const fs::path& file) {
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(file.string() + ": not a regular file (a FIFO, device or folder); a campaign's files are");
}

std::string percent(double rate) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << 100 * rate << "%";
  return s.str();
}

nlohmann::json counts_json(const StatusCounts& c) {
  const campaign::RateInterval i = c.held_interval();
  return {{"held", c.held},         {"failed", c.failed},          {"skipped", c.skipped},
          {"stopped", c.stopped},   {"held_rate", c.held_rate()}, {"wilson95", {i.low, i.high}}};
}

std::string counts_row(const std::string& label, const StatusCounts& c) {
  std::ostringstream s;
  const campaign::RateInterval i = c.held_interval();
  s << "  " << std::setw(10) << label << std::setw(9) << c.total() << std::setw(9) << c.held << std::setw(8)
    << c.failed << std::setw(9) << c.skipped << std::setw(9) << c.stopped << std::setw(11)
    << (c.held + c.failed ? percent(c.held_rate()) : "-") << "  "
    << (c.held + c.failed ? "[" + percent(i.low) + ", " + percent(i.high) + "]" : "-") << "\n";
  return s.str();
}


/// A results.jsonl as read: its complete lines' records, and its sizes.
struct ResultsFile {
  std::vector<SceneRecord> records;
  std::size_t complete = 0, size = 0;  ///< the bytes up to the last newline, and all of them
};

/// The longest line a results.jsonl may have: a record is a few hundred bytes (its note and intended cells
/// included), so a longer line is not one, and is refused before it fills memory.
constexpr std::size_t kMaxRecordBytes = std::size_t(1) << 20;

/// Reads the complete lines of `path` (a regular file), which must be the first scenes of `plan_indices` in order,
/// of the campaign's `seed` (a damaged line before the last newline is refused). Streamed: one line in memory at a
/// time besides the records.
ResultsFile read_results(const std::string& path, const std::vector<std::uint64_t>& plan_indices, std::uint64_t seed) {
  ResultsFile out;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path + ": " + std::strerror(errno));
  long line_number = 0;
  const auto record = [&](const std::string& line) {
    ++line_number;
    const std::string where = path + ": line " + std::to_string(line_number) + ": ";
    SceneRecord r;
    try {
      r = record_from_json(nlohmann::json::parse(line));
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where + "not a JSON record (" + e.what() + "); only the last line may be torn");
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    }
    const std::size_t k = out.records.size();
    if (r.seed != seed)
      throw InputError(where + "seed " + std::to_string(r.seed) + ", not the campaign's " + std::to_string(seed) +
                       " (the file is not this campaign's)");
    if (k >= plan_indices.size() || r.index != plan_indices[k])
      throw InputError(where + "scene " + std::to_string(r.index) + " is not the plan's scene number " +
                       std::to_string(k + 1) + " (the file is not this campaign's)");
    out.records.push_back(std::move(r));
  };
  std::string pending;  // the current line's bytes so far
  std::vector<char> block(std::size_t(1) << 16);
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const std::size_t n = static_cast<std::size_t>(in.gcount());
    for (std::size_t at = 0; at < n;) {
      const char* newline = static_cast<const char*>(std::memchr(block.data() + at, '\n', n - at));
      const std::size_t end = newline ? static_cast<std::size_t>(newline - block.data()) : n;
      pending.append(block.data() + at, end - at);
      if (pending.size() > kMaxRecordBytes)
        throw InputError(path + ": line " + std::to_string(line_number + 1) + " is longer than " +
                         std::to_string(kMaxRecordBytes) + " bytes: not a campaign record");
      out.size += end - at;
      at = end;
      if (!newline) break;
      ++out.size;
      ++at;
      record(pending);
      pending.clear();
      out.complete = out.size;
    }
  }
  if (in.bad()) throw InputError("cannot read " + path + ": a read error");
  return out;
}

/// A results.jsonl read one line at a time (a regular file: see require_regular_or_missing).
struct LineStream {
  std::ifstream in;
  explicit LineStream(const std::string& path) {
    require_regular_or_missing(path);
    in.open(path, std::ios::binary);
  }
  /// The next line (without its newline); false at the end. `torn`: it has no newline (the file's last line).
  bool next(std::string& line, bool& torn) {
    if (!std::getline(in, line)) return false;
    torn = in.eof();
    return true;
  }
};

/// One results.jsonl line's record; InputError starting with `where` when it is not one.
SceneRecord parse_line(const std::string& line, const std::string& where) {
  try {
    return record_from_json(nlohmann::json::parse(line));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + "not a JSON record (" + e.what() + ")");
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
}

}  // namespace

SceneRecord record_from_json(const nlohmann::json& j) {
  SceneRecord r;
  r.index = whole_field<std::uint64_t>(j, "index");
  r.seed = whole_field<std::uint64_t>(j, "seed");
  r.halfspaces = whole_field<int>(j, "halfspaces");
  r.cells = whole_field<long>(j, "cells");
  r.patches = whole_field<long>(j, "patches");
  r.samples = whole_field<int>(j, "samples");
  r.degeneracies = field<std::vector<std::string>>(j, "degeneracies");
  const auto outcome = campaign::scene_outcome_from_string(field<std::string>(j, "outcome"));
  if (!outcome) throw InputError("field \"outcome\": checked, refused or error");
  r.outcome = *outcome;
  if (j.contains("note")) r.note = field<std::string>(j, "note");
  if (j.contains("timed_out")) r.timed_out = field<bool>(j, "timed_out");
  if (j.contains("intended")) {
    const nlohmann::json intended = field<nlohmann::json>(j, "intended");
    if (!intended.is_array()) throw InputError("field \"intended\" is not a list");
    for (const nlohmann::json& cell : intended)
      r.intended.push_back(whole_field<int>({{"intended", cell}}, "intended"));
  }
  const nlohmann::json checks = field<nlohmann::json>(j, "checks");
  if (!checks.is_array()) throw InputError("field \"checks\" is not a list");
  for (const nlohmann::json& c : checks) {
    const auto status = campaign::check_status_from_string(field<std::string>(c, "status"));
    if (!status) throw InputError("a check's \"status\": held, failed, skipped or stopped");
    r.checks.push_back({field<std::string>(c, "check"), *status, field<std::string>(c, "witness")});
  }
  return r;
}

nlohmann::json summary_to_json(const Summary& s) {
  nlohmann::json checks = nlohmann::json::array();
  for (const std::string& name : s.checks) {
    nlohmann::json c = counts_json(s.by_check.at(name));
    c["check"] = name;
    nlohmann::json rows = nlohmann::json::array();
    const auto it = s.by_check_and_halfspaces.find(name);
    if (it != s.by_check_and_halfspaces.end())
      for (const auto& [halfspaces, counts] : it->second) {
        nlohmann::json row = counts_json(counts);
        row["halfspaces"] = halfspaces;
        rows.push_back(row);
      }
    c["by_halfspaces"] = rows;
    checks.push_back(c);
  }
  nlohmann::json out = {{"format", kCampaignSummaryFormat}, {"scenes", s.scenes},       {"checked", s.checked},
                        {"refused", s.refused},             {"errors", s.errors},       {"timed_out", s.timed_out},
                        {"failed_scenes", s.failed_scenes}, {"checks", checks}};
  for (const std::string& beam : s.checks) {
    if (!s.beam_optimal.count(beam)) continue;
    const StatusCounts& total = s.beam_optimal.at(beam);
    const auto optimality = [](const StatusCounts& c) {
      const campaign::RateInterval i = c.held_interval();
      return nlohmann::json{{"optimal", c.held}, {"sub_optimal", c.failed}, {"rate", c.held_rate()},
                            {"wilson95", {i.low, i.high}}};
    };
    nlohmann::json b = optimality(total);
    nlohmann::json rows = nlohmann::json::array();
    const auto it = s.beam_optimal_by_halfspaces.find(beam);
    if (it != s.beam_optimal_by_halfspaces.end())
      for (const auto& [halfspaces, counts] : it->second) {
        nlohmann::json row = optimality(counts);
        row["halfspaces"] = halfspaces;
        rows.push_back(row);
      }
    b["by_halfspaces"] = rows;
    out[beam + "_optimality"] = b;
  }
  for (const auto& [check, counts] : s.verdicts) {
    nlohmann::json v = {{"all", counts}};
    nlohmann::json rows = nlohmann::json::array();
    const auto it = s.verdicts_by_halfspaces.find(check);
    if (it != s.verdicts_by_halfspaces.end())
      for (const auto& [halfspaces, row] : it->second) rows.push_back({{"halfspaces", halfspaces}, {"verdicts", row}});
    v["by_halfspaces"] = rows;
    out[check + "_verdicts"] = v;
  }
  if (s.against) {
    const Summary::AgainstTally& t = *s.against;
    const StatusCounts decided{t.optimal, t.suboptimal + t.invalid + t.no_answer, 0, 0};
    const campaign::RateInterval i = decided.held_interval();
    const auto gap = [](const std::pair<long, double>& g) {
      return nlohmann::json{{"missing_samples", g.first}, {"measure", g.second}};
    };
    long sample_gaps = 0;
    for (const auto& g : t.gaps) sample_gaps += g.first > 0;
    nlohmann::json gaps = {{"suboptimal", static_cast<long>(t.gaps.size())}, {"with_missing_samples", sample_gaps}};
    if (!t.gaps.empty()) {
      gaps["median"] = gap(t.gaps[(t.gaps.size() - 1) / 2]);
      gaps["max"] = gap(t.gaps.back());
    }
    out["against"] = {{"valid", t.valid()},         {"optimal", t.optimal},     {"suboptimal", t.suboptimal},
                      {"invalid", t.invalid},       {"no_answer", t.no_answer}, {"undecided", t.undecided},
                      {"not_run", t.not_run},       {"optimal_rate", decided.held_rate()},
                      {"wilson95", {i.low, i.high}}, {"gap", gaps}};
  }
  return out;
}

std::string summary_table(const Summary& s) {
  std::ostringstream out;
  out << s.scenes << " scenes: " << s.checked << " checked, " << s.refused << " refused by the arrangement limits, "
      << s.errors << " errors; " << s.timed_out << " timed out; " << s.failed_scenes << " with a failed check\n";
  const auto& catalogue = campaign::check_catalogue();
  for (const std::string& name : s.checks) {
    const auto info = std::find_if(catalogue.begin(), catalogue.end(),
                                   [&](const campaign::CheckInfo& c) { return name == c.name; });
    out << "\n" << name
        << (info != catalogue.end()         ? std::string(": ") + info->description
            : name == campaign::kAgainstCheck ? std::string(": their program's answer graded (held: optimal)")
                                              : std::string())
        << "\n";
    out << "  halfspaces   scenes     held  failed  skipped  stopped  held rate  95% interval (Wilson)\n";
    const auto it = s.by_check_and_halfspaces.find(name);
    if (it != s.by_check_and_halfspaces.end())
      for (const auto& [halfspaces, counts] : it->second) out << counts_row(std::to_string(halfspaces), counts);
    out << counts_row("all", s.by_check.at(name));
  }
  for (const std::string& beam : s.checks) {  // in catalogue order (beam2 before beam16)
    if (!s.beam_optimal.count(beam)) continue;
    const StatusCounts& total = s.beam_optimal.at(beam);
    out << "\n" << beam << " optimality: the K=" << beam.substr(4) << " beam's energy equals the optimum, on the scenes where "
        << beam << " held\n";
    out << "  halfspaces  optimal  sub-optimal       rate  95% interval (Wilson)\n";
    const auto row = [&](const std::string& label, const StatusCounts& c) {
      const campaign::RateInterval i = c.held_interval();
      out << "  " << std::setw(10) << label << std::setw(9) << c.held << std::setw(13) << c.failed << std::setw(11)
          << (c.held + c.failed ? percent(c.held_rate()) : "-") << "  "
          << (c.held + c.failed ? "[" + percent(i.low) + ", " + percent(i.high) + "]" : "-") << "\n";
    };
    const auto it = s.beam_optimal_by_halfspaces.find(beam);
    if (it != s.beam_optimal_by_halfspaces.end())
      for (const auto& [halfspaces, counts] : it->second) row(std::to_string(halfspaces), counts);
    row("all", total);
  }
  for (const auto& entry : s.verdicts) {
    const std::string& check = entry.first;
    const std::map<std::string, long>& counts = entry.second;
    out << "\n" << check << " verdicts, on the scenes where " << check << " held\n  halfspaces";
    for (const auto& [verdict, n] : counts) out << "  " << verdict;
    out << "\n";
    const auto row = [&](const std::string& label, const std::map<std::string, long>& of) {
      long total = 0;
      for (const auto& [verdict, n] : of) total += n;
      out << "  " << std::setw(10) << label;
      for (const auto& [verdict, n] : counts) {
        const auto it = of.find(verdict);
        const long k = it == of.end() ? 0 : it->second;
        const std::string cell = std::to_string(k) + (total ? " (" + percent(static_cast<double>(k) / total) + ")" : "");
        out << "  " << std::setw(static_cast<int>(verdict.size())) << cell;
      }
      out << "\n";
    };
    const auto it = s.verdicts_by_halfspaces.find(check);
    if (it != s.verdicts_by_halfspaces.end())
      for (const auto& [halfspaces, of] : it->second) row(std::to_string(halfspaces), of);
    row("all", counts);
  }
  if (s.against) {
    const Summary::AgainstTally& t = *s.against;
    out << "\nagainst: their answers graded (by halfspaces: the against rows above, held = optimal)\n";
    out << "  valid  optimal  suboptimal  invalid  no answer  undecided  not run\n";
    out << "  " << std::setw(5) << t.valid() << std::setw(9) << t.optimal << std::setw(12) << t.suboptimal
        << std::setw(9) << t.invalid << std::setw(11) << t.no_answer << std::setw(11) << t.undecided << std::setw(9)
        << t.not_run << "\n";
    if (!t.gaps.empty()) {
      const auto gap = [](const std::pair<long, double>& g) {
        std::ostringstream text;
        text << g.first << " missing sample" << (g.first == 1 ? "" : "s") << ", measure " << std::setprecision(6)
             << g.second;
        return text.str();
      };
      long sample_gaps = 0;
      for (const auto& g : t.gaps) sample_gaps += g.first > 0;
      out << "  energy gap of the " << t.gaps.size() << " suboptimal answers (" << sample_gaps
          << " missing more samples): median " << gap(t.gaps[(t.gaps.size() - 1) / 2]) << "; max "
          << gap(t.gaps.back()) << "\n";
    }
  }
  return out.str();
}

std::string failure_note(const SceneRecord& r) {
  std::string what;
  const campaign::CheckOutcome* first = nullptr;
  for (const campaign::CheckOutcome& c : r.checks)
    if (c.status == CheckStatus::Failed) {
      what += (what.empty() ? "" : ", ") + c.check;
      if (!first) first = &c;
    }
  std::string note = "hsx campaign --seed " + std::to_string(r.seed) + ", scene " + std::to_string(r.index) + ": ";
  if (r.outcome == SceneOutcome::Error) note += "error: " + r.note;
  else note += "failed " + what + ": " + (first ? first->witness : std::string());
  if (note.size() > 400) note = note.substr(0, 397) + "...";
  for (char& c : note)
    if (c == '\n' || c == '\r') c = ' ';
  return note + " (regenerate: hsx campaign --seed " + std::to_string(r.seed) + " --start " + std::to_string(r.index) +
         " --count 1 with this campaign's generator options, campaign.json)";
}

CampaignFolder::CampaignFolder(const std::string& dir, const nlohmann::json& manifest, bool resume,
                               const std::vector<std::uint64_t>& plan_indices)
    : dir_(dir) {
  if (dir.empty()) throw InputError("--out: an empty path");
  std::error_code ec;
  const fs::path path(dir);
  const fs::path manifest_path = path / "campaign.json", results_path = path / "results.jsonl";
  bool fresh = true;
  if (fs::exists(path, ec)) {
    if (!fs::is_directory(path, ec)) throw InputError("--out: " + dir + " exists and is not a folder");
    if (fs::exists(manifest_path, ec)) {
      if (!resume)
        throw InputError("--out: " + dir + " holds a campaign already (campaign.json): add --resume to continue it, "
                         "or give a new folder");
      nlohmann::json existing;
      try {
        existing = nlohmann::json::parse(read_file(manifest_path.string()));
      } catch (const nlohmann::json::exception& e) {
        throw InputError(manifest_path.string() + ": not a campaign file: " + e.what());
      }
      if (existing != manifest)
        throw InputError("--resume: " + manifest_path.string() +
                         " was written for other settings (seed, plan, generator, checks, limits or --against); resume with "
                         "the same options, or give a new folder");
      fresh = false;
    } else if (!fs::is_empty(path, ec)) {
      throw InputError("--out: " + dir + " is not empty and holds no campaign (campaign.json); hsx writes only to a "
                       "new or empty folder");
    }
  } else {
    const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(parent, ec))
      throw InputError("--out: the folder " + parent.string() + " (where " + dir + " would be made) does not exist");
    if (!fs::create_directory(path, ec) && ec)
      throw OutputError("--out: cannot make the folder " + dir + ": " + ec.message());
  }
  require_regular_or_missing(results_path);
  if (fresh) {
    write_file_atomically(manifest_path.string(), manifest.dump(2) + "\n");
  } else if (fs::exists(results_path, ec)) {
    ResultsFile file = read_results(results_path.string(), plan_indices, manifest.at("seed").get<std::uint64_t>());
    records_ = std::move(file.records);
    if (file.complete < file.size) {
      fs::resize_file(results_path, file.complete, ec);
      if (ec) throw OutputError(results_path.string() + ": cannot cut its torn last line: " + ec.message());
      cut_torn_line_ = true;
    }
  }
  results_.open(results_path, std::ios::out | std::ios::app | std::ios::binary);
  if (!results_) throw OutputError(results_path.string() + ": cannot open it for writing: " + std::strerror(errno));
}

void CampaignFolder::append(const SceneRecord& record, const std::optional<Scene2>& minimised,
                            const std::optional<Scene3>& minimised3) {
  if (record.failed()) {
    if (!record.scene && !record.scene3)
      throw std::logic_error("CampaignFolder::append: a failed record without its scene");
    std::error_code ec;
    const fs::path failures = fs::path(dir_) / "failures";
    if (!fs::is_directory(failures, ec) && !fs::create_directory(failures, ec) && ec)
      throw OutputError(failures.string() + ": cannot make the folder: " + ec.message());
    const std::string name = "scene-" + std::to_string(record.index);
    std::string text;
    if (record.scene) {
      Scene2 scene = *record.scene;
      scene.description = failure_note(record);
      text = write_scene2(scene).dump(2);
    } else {
      Scene3 scene = *record.scene3;
      scene.description = failure_note(record);
      text = write_scene3(scene).dump(2);
    }
    write_file_atomically((failures / (name + ".json")).string(), text + "\n");
    if (minimised)
      write_file_atomically((failures / (name + ".min.json")).string(), write_scene2(*minimised).dump(2) + "\n");
    if (minimised3)
      write_file_atomically((failures / (name + ".min.json")).string(), write_scene3(*minimised3).dump(2) + "\n");
  }
  append_line(record_to_json(record).dump());
}

void CampaignFolder::append_line(const std::string& line) {
  results_ << line << '\n';
  results_.flush();
  if (!results_) throw OutputError(dir_ + "/results.jsonl: cannot write to it (a full disk?)");
}

void CampaignFolder::write_summary(const Summary& summary) {
  write_file_atomically((fs::path(dir_) / "summary.json").string(), summary_to_json(summary).dump(2) + "\n");
  write_file_atomically((fs::path(dir_) / "summary.svg").string(), summary_svg(summary));
}

namespace {

/// minimised_failure's note (either dimension).
template <class Scene>
std::string minimised_note(const SceneRecord& record, const campaign::Minimised<Scene>& m) {
  const int halfspaces = static_cast<int>(m.scene.halfspaces.size()), samples = static_cast<int>(m.scene.samples.size());
  constexpr bool three = std::is_same_v<Scene, Scene3>;
  const int changes = three ? m.lowered_segments : m.simplified_coordinates;
  std::ostringstream head;
  head << "hsx campaign --seed " << record.seed << ", scene " << record.index << " minimised ("
       << halfspaces + m.removed_halfspaces << " -> " << halfspaces << " halfspaces, " << samples + m.removed_samples
       << " -> " << samples << " samples, " << changes << (three ? " segment count" : " coordinate")
       << (changes == 1 ? "" : "s") << (three ? " lowered, " : " simplified, ") << m.steps << " step"
       << (m.steps == 1 ? "" : "s") << (m.exhausted ? ", the step budget ran out" : "") << "): ";
  std::string what;
  if (m.record.outcome == SceneOutcome::Error) {
    what = "error: " + m.record.note;
  } else {
    std::string names;
    const campaign::CheckOutcome* first = nullptr;
    for (const campaign::CheckOutcome& c : m.record.checks)
      if (std::find(m.target.begin(), m.target.end(), c.check) != m.target.end()) {
        names += (names.empty() ? "" : ", ") + c.check;
        if (!first) first = &c;
      }
    what = "failed " + names + ": " + (first ? first->witness : std::string());
  }
  if (what.size() > 400) what = what.substr(0, 397) + "...";
  std::string shape;
  if (!m.record.intended.empty()) {
    shape = " [the intended shape carried to it: cells {";
    for (std::size_t k = 0; k < m.record.intended.size(); ++k)
      shape += (k ? "," : "") + std::to_string(m.record.intended[k]);
    shape += "} of its complex]";
  }
  std::string note =
      head.str() + what + shape + " (the original: failures/scene-" + std::to_string(record.index) + ".json)";
  for (char& c : note)
    if (c == '\n' || c == '\r') c = ' ';
  return note;
}

}  // namespace

std::optional<Scene2> minimised_failure(const SceneRecord& record, const campaign::MinimiseResult& m) {
  if (!m.reproduced) return std::nullopt;
  Scene2 scene = m.scene;
  scene.description = minimised_note(record, m);
  return scene;
}

std::optional<Scene3> minimised_failure(const SceneRecord& record, const campaign::MinimiseResult3& m) {
  if (!m.reproduced) return std::nullopt;
  Scene3 scene = m.scene;
  scene.description = minimised_note(record, m);
  return scene;
}

namespace {

/// The summary's panels: a title and rates by number of halfspaces.
struct Panel {
  std::string title;
  std::map<int, StatusCounts> rows;
  StatusCounts all;
};

std::string rate_text(const StatusCounts& c) {
  if (c.held + c.failed == 0) return "no scene decided";
  const campaign::RateInterval i = c.held_interval();
  return percent(c.held_rate()) + " of " + std::to_string(c.held + c.failed) + " [" + percent(i.low) + ", " +
         percent(i.high) + "]";
}

}  // namespace

std::string summary_svg(const Summary& s) {
  std::vector<Panel> panels;
  for (const std::string& name : s.checks) {
    Panel p;
    p.title = name + ": held / (held + failed), 95% Wilson; all: " + rate_text(s.by_check.at(name));
    const auto it = s.by_check_and_halfspaces.find(name);
    if (it != s.by_check_and_halfspaces.end()) p.rows = it->second;
    p.all = s.by_check.at(name);
    panels.push_back(std::move(p));
  }
  if (std::find(s.checks.begin(), s.checks.end(), "beam1") != s.checks.end()) {
    Panel p;
    p.title = "beam1 optimality: K=1 energy = optimum, where beam1 held; all: " + rate_text(s.beam1_optimal);
    p.rows = s.beam1_optimal_by_halfspaces;
    p.all = s.beam1_optimal;
    panels.push_back(std::move(p));
  }
  std::set<int> xs;
  for (const Panel& p : panels)
    for (const auto& row : p.rows) xs.insert(row.first);
  const double width = 720, panel_height = 170, left = 56, right = 16, top = 28, plot_height = 110;
  const double height = 8 + panel_height * static_cast<double>(panels.size());
  const std::vector<int> x_values(xs.begin(), xs.end());
  const double step = x_values.empty() ? 0 : (width - left - right) / static_cast<double>(x_values.size());
  const auto x_of = [&](std::size_t k) { return left + step * (static_cast<double>(k) + 0.5); };
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << svg_number(width) << "\" height=\""
      << svg_number(height) << "\" viewBox=\"0 0 " << svg_number(width) << " " << svg_number(height)
      << "\" font-family=\"sans-serif\">\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << svg_number(width) << "\" height=\"" << svg_number(height)
      << "\" fill=\"white\"/>\n";
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const Panel& p = panels[k];
    const double y0 = 8 + panel_height * static_cast<double>(k), base = y0 + top + plot_height;
    const auto y_of = [&](double rate) { return base - rate * plot_height; };
    out << "<g class=\"panel\">\n";
    out << "<text class=\"title\" x=\"" << svg_number(left) << "\" y=\"" << svg_number(y0 + 16)
        << "\" font-size=\"12\">" << svg_escape(p.title) << "</text>\n";
    for (int g = 0; g <= 4; ++g) {
      const double y = y_of(g / 4.0);
      out << "<line class=\"grid\" x1=\"" << svg_number(left) << "\" y1=\"" << svg_number(y) << "\" x2=\""
          << svg_number(width - right) << "\" y2=\"" << svg_number(y) << "\" stroke=\"#dddddd\"/>\n";
      out << "<text class=\"label\" x=\"" << svg_number(left - 6) << "\" y=\"" << svg_number(y + 4)
          << "\" font-size=\"10\" text-anchor=\"end\">" << 25 * g << "%</text>\n";
    }
    out << "<path class=\"axis\" d=\"M " << svg_number(left) << " " << svg_number(y_of(1)) << " L "
        << svg_number(left) << " " << svg_number(base) << " L " << svg_number(width - right) << " "
        << svg_number(base) << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (std::size_t j = 0; j < x_values.size(); ++j)
      out << "<text class=\"label\" x=\"" << svg_number(x_of(j)) << "\" y=\"" << svg_number(base + 14)
          << "\" font-size=\"10\" text-anchor=\"middle\">" << x_values[j] << "</text>\n";
    out << "<text class=\"label\" x=\"" << svg_number(width - right) << "\" y=\"" << svg_number(base + 27)
        << "\" font-size=\"10\" text-anchor=\"end\">halfspaces</text>\n";
    for (std::size_t j = 0; j < x_values.size(); ++j) {
      const auto row = p.rows.find(x_values[j]);
      if (row == p.rows.end() || row->second.held + row->second.failed == 0) continue;
      const StatusCounts& c = row->second;
      const campaign::RateInterval i = c.held_interval();
      const double x = x_of(j);
      out << "<path class=\"interval\" d=\"M " << svg_number(x) << " " << svg_number(y_of(i.low)) << " L "
          << svg_number(x) << " " << svg_number(y_of(i.high)) << " M " << svg_number(x - 4) << " "
          << svg_number(y_of(i.low)) << " L " << svg_number(x + 4) << " " << svg_number(y_of(i.low)) << " M "
          << svg_number(x - 4) << " " << svg_number(y_of(i.high)) << " L " << svg_number(x + 4) << " "
          << svg_number(y_of(i.high)) << "\" fill=\"none\" stroke=\"#1f77b4\"/>\n";
      out << "<circle class=\"rate\" cx=\"" << svg_number(x) << "\" cy=\"" << svg_number(y_of(c.held_rate()))
          << "\" r=\"3\" fill=\"#1f77b4\"><title>" << x_values[j] << " halfspaces: " << svg_escape(rate_text(c))
          << "</title></circle>\n";
    }
    out << "</g>\n";
  }
  out << "</svg>\n";
  return out.str();
}

campaign::Summary merge_campaigns(const std::string& out, const std::vector<std::string>& shards,
                                  const std::function<void(const SceneRecord&)>& each) {
  if (shards.empty()) throw InputError("--merge: name the shard folders to merge");
  struct Shard {
    std::string dir;
    nlohmann::json manifest;
    CampaignPlan plan;
  };
  std::vector<Shard> given;
  for (const std::string& dir : shards) {
    Shard sh;
    sh.dir = dir;
    const std::string manifest_path = (fs::path(dir) / "campaign.json").string();
    std::error_code ec;
    if (!fs::is_regular_file(manifest_path, ec))
      throw InputError("--merge: " + dir + " holds no campaign (no campaign.json)");
    try {
      sh.manifest = nlohmann::json::parse(read_file(manifest_path));
      const nlohmann::json& plan = sh.manifest.at("plan");
      if (sh.manifest.at("format") != kCampaignFormat) throw InputError("not " + std::string(kCampaignFormat));
      sh.plan.start = plan.at("start").get<std::uint64_t>();
      sh.plan.count = plan.at("count").get<std::uint64_t>();
      sh.plan.shard = plan.at("shard").get<std::uint64_t>();
      sh.plan.shards = plan.at("shards").get<std::uint64_t>();
    } catch (const nlohmann::json::exception& e) {
      throw InputError("--merge: " + manifest_path + ": not a campaign file: " + e.what());
    } catch (const InputError& e) {
      throw InputError("--merge: " + manifest_path + ": " + e.what());
    }
    given.push_back(std::move(sh));
  }
  // The same campaign: the manifests equal but for the shard number.
  const auto without_shard = [](nlohmann::json j) {
    j["plan"].erase("shard");
    return j;
  };
  const nlohmann::json common = without_shard(given.front().manifest);
  for (const Shard& sh : given)
    if (without_shard(sh.manifest) != common) {
      std::string keys;
      for (const auto& [key, value] : common.items())
        if (!sh.manifest.contains(key) || without_shard(sh.manifest)[key] != value) keys += (keys.empty() ? "" : ", ") + key;
      for (const auto& [key, value] : sh.manifest.items())
        if (!common.contains(key)) keys += (keys.empty() ? "" : ", ") + key;
      throw InputError("--merge: " + sh.dir + " is not the same campaign as " + given.front().dir + " (they differ in " +
                       keys + "); only the shards of one campaign merge");
    }
  const std::uint64_t k = given.front().plan.shards;
  std::map<std::uint64_t, const Shard*> by_shard;
  std::vector<std::string> problems;
  for (const Shard& sh : given) {
    const auto [it, fresh] = by_shard.emplace(sh.plan.shard, &sh);
    if (!fresh)
      throw InputError("--merge: shard " + std::to_string(sh.plan.shard) + "/" + std::to_string(k) + " is given twice (" +
                       it->second->dir + " and " + sh.dir + ")");
  }
  std::string missing;
  for (std::uint64_t i = 0; i < k; ++i)
    if (!by_shard.count(i)) {
      if (missing.size() > 200) {
        missing += ", ...";
        break;
      }
      missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(k);
    }
  if (!missing.empty()) problems.push_back("missing shards " + missing);
  // Each shard's lines, streamed (one line in memory at a time): its plan's indices in order, all of them.
  for (Shard& sh : given) {
    const std::uint64_t n = sh.plan.count > sh.plan.shard ? (sh.plan.count - sh.plan.shard + k - 1) / k : 0;
    const std::string name = "shard " + std::to_string(sh.plan.shard) + "/" + std::to_string(k) + " (" + sh.dir + ")";
    const std::string path = (fs::path(sh.dir) / "results.jsonl").string();
    LineStream lines(path);
    std::uint64_t done = 0;
    std::string line;
    bool torn = false, torn_seen = false;
    while (lines.next(line, torn)) {
      if (torn) {
        torn_seen = true;
        break;
      }
      const SceneRecord r = parse_line(line, path + ": line " + std::to_string(done + 1) + ": ");
      if (r.seed != sh.manifest.at("seed").get<std::uint64_t>())
        throw InputError("--merge: " + path + ": line " + std::to_string(done + 1) + ": seed " +
                         std::to_string(r.seed) + ", not the campaign's");
      const std::uint64_t want = sh.plan.start + sh.plan.shard + done * k;
      if (done >= n || r.index != want)
        throw InputError("--merge: " + path + ": line " + std::to_string(done + 1) + ": scene " +
                         std::to_string(r.index) + " is not the shard's scene number " + std::to_string(done + 1));
      std::error_code ec;
      if (r.failed() && !fs::is_regular_file(fs::path(sh.dir) / "failures" / ("scene-" + std::to_string(r.index) + ".json"), ec))
        problems.push_back(name + ": scene " + std::to_string(r.index) + " failed but failures/scene-" +
                           std::to_string(r.index) + ".json is not there");
      ++done;
    }
    if (done < n)
      problems.push_back(name + " has " + std::to_string(done) + " of its " + std::to_string(n) + " scenes (" +
                         std::to_string(n - done) + " missing, the first is scene " +
                         std::to_string(sh.plan.start + sh.plan.shard + done * k) + "): finish it with --resume");
    else if (torn_seen)
      problems.push_back(name + ": results.jsonl ends in a torn line after its last scene");
  }
  if (!problems.empty()) {
    std::string text = "--merge: the shards are not a complete campaign: ";
    for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; " : "") + problems[i];
    throw InputError(text);
  }
  // The whole range's folder, as one run writes it.
  nlohmann::json manifest = given.front().manifest;
  manifest["plan"]["shard"] = 0;
  manifest["plan"]["shards"] = 1;
  CampaignPlan whole = given.front().plan;
  whole.shard = 0;
  whole.shards = 1;
  std::vector<std::string> names = manifest.at("checks").get<std::vector<std::string>>();
  if (manifest.contains("against")) names.push_back(campaign::kAgainstCheck);
  Summary summary(names);
  CampaignFolder folder(out, manifest, false, {});
  std::vector<std::unique_ptr<LineStream>> streams;
  for (std::uint64_t i = 0; i < k; ++i)
    streams.push_back(std::make_unique<LineStream>((fs::path(by_shard.at(i)->dir) / "results.jsonl").string()));
  const std::uint64_t count = whole.count;
  std::string line;
  for (std::uint64_t j = 0; j < count; ++j) {
    const Shard& sh = *by_shard.at(j % k);
    bool torn = false;
    if (!streams[static_cast<std::size_t>(j % k)]->next(line, torn) || torn)
      throw InputError("--merge: " + sh.dir + "/results.jsonl changed while it was merged");
    const SceneRecord r = parse_line(line, sh.dir + "/results.jsonl: ");
    if (r.failed()) {
      std::error_code ec;
      const fs::path from = fs::path(sh.dir) / "failures", to = fs::path(out) / "failures";
      if (!fs::is_directory(to, ec) && !fs::create_directory(to, ec) && ec)
        throw OutputError(to.string() + ": cannot make the folder: " + ec.message());
      const std::string name = "scene-" + std::to_string(r.index);
      for (const std::string& file : {name + ".json", name + ".min.json"})
        if (fs::is_regular_file(from / file, ec)) write_file_atomically((to / file).string(), read_file((from / file).string()));
    }
    folder.append_line(line);
    summary.add(r);
    if (each) each(r);
  }
  folder.write_summary(summary);
  return summary;
}

}  // namespace hsx
