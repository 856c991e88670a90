// A campaign's files (algorithms/campaign/campaign.hpp runs it; `hsx campaign` is the CLI, docs/campaigns.md).
//
// The folder (CampaignFolder) holds, and hsx writes nothing else in it:
//   campaign.json   the settings and the plan (format "hsx-campaign/1"), written first; a resumed campaign must
//                   match it exactly (with --against, the CLI adds "against": {"command", "input",
//                   "weight_scale"}, so a resume with another program is refused)
//   results.jsonl   one JSON line per scene (record_to_json), in the plan's index order, each line flushed as it
//                   is written; a line is complete when its newline is written
//   failures/       scene-<index>.json: each scene with a failed check or an error, as an hsx-scene/1 file
//                   (`hsx check` reads it) whose description is a one-line note (what failed, and how to
//                   regenerate it); written before the scene's line, so a recorded failure always has its file
//   summary.json    the tallies (summary_to_json), written when the plan is done
// The folder policy (no file that is not ours is ever replaced): a new folder is made when its parent exists; an
// existing folder must be empty, or hold a campaign (campaign.json) and be resumed; --resume of a campaign with
// other settings is refused. Every refusal is an InputError (exit 2 in the CLI).
#pragma once

#include <hsx/algorithms/campaign/campaign.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace hsx {

inline constexpr const char* kCampaignFormat = "hsx-campaign/1";
inline constexpr const char* kCampaignSummaryFormat = "hsx-campaign-summary/1";

/// Which scenes: shard `shard` of `shards` of the indices start .. start + count - 1 (campaign::shard_indices).
struct CampaignPlan {
  std::uint64_t start = 0;
  std::uint64_t count = 0;
  std::uint64_t shard = 0;
  std::uint64_t shards = 1;
  /// The plan's indices, in order (campaign::shard_indices).
  std::vector<std::uint64_t> indices() const;
};

/// campaign.json: {"format": "hsx-campaign/1", "seed", "plan": {start, count, shard, shards}, "generator": every
/// RandomSceneSettings field (degeneracy weights by to_string(Degeneracy)) and, when not uniform, "sample_policy"
/// (to_string(SamplePolicy)), "checks": [names], "limits": {...}}.
/// 64-bit values (seed, start, count) are JSON unsigned integers.
nlohmann::json campaign_to_json(const campaign::CampaignSettings& settings, const CampaignPlan& plan);

/// One results.jsonl line's object: {"index", "seed", "halfspaces", "cells", "patches", "samples", "degeneracies":
/// [names], "outcome": "checked" | "refused" | "error", "note" (only when not empty), "timed_out" (only when
/// true), "intended": [cells] (only when not empty: SceneRecord::intended), "checks": [{"check", "status", "witness"}]}, keys in that order. Its dump() (no spaces) plus "\n" is the
/// line.
nlohmann::ordered_json record_to_json(const campaign::SceneRecord& record);
/// The inverse of record_to_json (SceneRecord::scene is left empty). Throws InputError naming the bad field.
campaign::SceneRecord record_from_json(const nlohmann::json& line);

/// summary.json: {"format": "hsx-campaign-summary/1", "scenes", "checked", "refused", "errors", "timed_out",
/// "failed_scenes", "checks": [{"check", "held", "failed", "skipped", "stopped", "held_rate", "wilson95": [low,
/// high], "by_halfspaces": [{"halfspaces", the same counts, rate and interval}]}], and per tallied beam check
/// (beam1, beam2, beam4) "beamK_optimality": {"optimal", "sub_optimal", "rate", "wilson95", "by_halfspaces": [...]}
/// (Summary::beam_optimal), when describability or nhrep is tallied "CHECK_verdicts": {"all": {verdict: count},
/// "by_halfspaces": [{"halfspaces", "verdicts": {verdict: count}}]} (Summary::verdicts), and when the against check is tallied "against": {"valid", "optimal", "suboptimal",
/// "invalid", "no_answer", "undecided", "not_run", "optimal_rate" (optimal / (optimal + suboptimal + invalid + no
/// answer)), "wilson95", "gap": {"suboptimal", "with_missing_samples" (gaps with M > 0), and when there is one
/// "median" (the lower median) and "max", each {"missing_samples", "measure"} in lexicographic order}}
/// (Summary::against); rates are held / (held + failed), 0 with an interval [0, 1] when no scene decided.
nlohmann::json summary_to_json(const campaign::Summary& summary);
/// The summary as a text table per check (rows by number of halfspaces, then "all"), with a first line of scene
/// counts, beam1's optimality table when beam1 is tallied, and the against verdicts and gap (median, max) when
/// against is tallied. The same bytes for the same summary.
std::string summary_table(const campaign::Summary& summary);

/// The one-line note of a kept scene: which checks failed (or the error), the first failure's witness (cut at
/// 400 characters), and the command that regenerates the scene.
std::string failure_note(const campaign::SceneRecord& record);

/// A campaign folder under the policy above.
class CampaignFolder {
 public:
  /// Opens `dir` for the campaign `manifest` (campaign_to_json): makes it, or checks that it is empty, or (with
  /// `resume`) that it holds the same campaign, whose complete records are then read (records()) and whose torn
  /// last line, if any (no newline: the run was killed while writing it), is cut off. The records read must be
  /// the first ones of `plan_indices`, in order. Writes campaign.json when the folder is new or empty. Throws
  /// InputError (an OutputError for what cannot be written).
  CampaignFolder(const std::string& dir, const nlohmann::json& manifest, bool resume,
                 const std::vector<std::uint64_t>& plan_indices);

  /// The records of a resumed campaign, in order (empty for a new one).
  const std::vector<campaign::SceneRecord>& records() const { return records_; }
  /// Whether the torn last line of a resumed results.jsonl was cut off.
  bool cut_torn_line() const { return cut_torn_line_; }

  /// Keeps a record: its scene as failures/scene-<index>.json first when record.failed() (record.scene must be
  /// set then), then its line appended to results.jsonl and flushed. Throws OutputError.
  void append(const campaign::SceneRecord& record);
  /// Writes summary.json (atomically). Throws OutputError.
  void write_summary(const campaign::Summary& summary);

  const std::string& path() const { return dir_; }

 private:
  std::string dir_;
  std::vector<campaign::SceneRecord> records_;
  bool cut_torn_line_ = false;
  std::ofstream results_;
};

}  // namespace hsx
