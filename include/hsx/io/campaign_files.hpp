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
//                   regenerate it); written before the scene's line, so a recorded failure always has its file;
//                   scene-<index>.min.json beside it when the scene was minimised (algorithms/campaign/
//                   minimise.hpp), its description the minimised scene's note (minimised_note). The folder is laid
//                   out as data/counterexamples/: scene files whose descriptions say what fails.
//   summary.json    the tallies (summary_to_json), written when the plan is done, with summary.svg (summary_svg)
// The records never depend on minimisation (a minimised scene is a file of failures/ only), so a campaign run with
// or without it has the same results.jsonl and summary bytes.
// The folder policy (no file that is not ours is ever replaced): a new folder is made when its parent exists; an
// existing folder must be empty, or hold a campaign (campaign.json) and be resumed; --resume of a campaign with
// other settings is refused. Every refusal is an InputError (exit 2 in the CLI).
#pragma once

#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/algorithms/campaign/minimise.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <fstream>
#include <functional>
#include <optional>
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

/// The rates as an SVG picture (deterministic bytes: numbers with 4 decimals, fixed order): one panel per tallied
/// check, in the summary's order, plotting against the number of halfspaces its held rate held / (held + failed)
/// as a dot ("rate" circles) with its 95% Wilson interval as a bar ("interval" lines), only where some scene
/// decided; then, when beam1 is tallied, a panel of beam K=1's optimality rate likewise. Every panel has the same
/// x axis (each number of halfspaces any check saw) and a y axis 0..100%; its title gives the rate over all
/// halfspace counts. Element classes: "panel", "axis", "grid", "rate", "interval", "title", "label".
std::string summary_svg(const campaign::Summary& summary);

/// The one-line note of a kept scene: which checks failed (or the error), the first failure's witness (cut at
/// 400 characters), and the command that regenerates the scene.
std::string failure_note(const campaign::SceneRecord& record);

/// The minimised scene of `record` (a failed record) as failures/scene-<index>.min.json keeps it: result.scene with
/// its description the one-line note "hsx campaign --seed S, scene K minimised (H -> h halfspaces, N -> n samples,
/// C coordinates simplified, T steps[, the step budget ran out]): failed CHECKS: WITNESS" (the minimised scene's
/// first target witness, cut at 400 characters; "error: MESSAGE" for an error), then, when the minimised record
/// has an intended shape (SamplePolicy::Intended, carried by minimise_scene), " [the intended shape carried to
/// it: cells {A,B,...} of its complex]", ending with where the original is. std::nullopt when the scene did not
/// fail again under the restricted checks (result.reproduced false).
std::optional<Scene2> minimised_failure(const campaign::SceneRecord& record, const campaign::MinimiseResult& result);
/// The same for a 3D scene: "S segment counts lowered" in place of "C coordinates simplified".
std::optional<Scene3> minimised_failure(const campaign::SceneRecord& record, const campaign::MinimiseResult3& result);

/// hsx campaign --merge: the shard folders `shards` (finished campaigns --shard i/k of one campaign: campaign.json
/// equal but for plan.shard, every shard 0/k .. (k-1)/k given once, each with all its scenes) merged into `out`, a
/// new or empty folder (the folder policy above), as the folder a single run of the whole range would have written:
/// campaign.json with plan shard 0/1, results.jsonl's lines in index order (the shards' lines, byte for byte),
/// failures/ copied (scene-K.json and scene-K.min.json), summary.json and summary.svg recounted. Everything is
/// checked before `out` is made: differing settings, a shard given twice, missing shards and unfinished shards
/// (with how many of their scenes are missing) are one InputError saying all of it. The shards' results.jsonl are
/// read one line at a time, twice (checked, then merged), so memory does not grow with the campaign. An
/// OutputError, or a shard changed between the two readings, can leave `out` part-written. `each` (when set) is called
/// with every record, in index order. Returns the summary.
campaign::Summary merge_campaigns(const std::string& out, const std::vector<std::string>& shards,
                                  const std::function<void(const campaign::SceneRecord&)>& each = {});

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

  /// Keeps a record: its scene as failures/scene-<index>.json first when record.failed() (record.scene or
  /// record.scene3 must be set then), and `minimised` or `minimised3` (minimised_failure's, description included)
  /// as failures/scene-<index>.min.json, then its line appended to results.jsonl and flushed. Throws OutputError.
  void append(const campaign::SceneRecord& record, const std::optional<Scene2>& minimised = std::nullopt,
              const std::optional<Scene3>& minimised3 = std::nullopt);
  /// Writes summary.json and summary.svg (each atomically). Throws OutputError.
  void write_summary(const campaign::Summary& summary);

  const std::string& path() const { return dir_; }

  /// Appends one results.jsonl line as it is (`line` without its newline) and flushes (merge_campaigns copies the
  /// shards' lines). Throws OutputError.
  void append_line(const std::string& line);

 private:
  std::string dir_;
  std::vector<campaign::SceneRecord> records_;
  bool cut_torn_line_ = false;
  std::ofstream results_;
};

}  // namespace hsx
