// Repeated timing of a piece of work: how `hsx bench` measures (BSH methods, NH-Rep stages).
//
// Conventions (owned here):
// - Times are wall-clock seconds from a monotone clock (std::chrono::steady_clock unless one is injected).
// - A measurement repeats the work at least `min_repetitions` times AND until the timed runs add up to at least
//   `min_seconds`, never more than `max_repetitions` times (time_alternately: each piece of work, in rounds). Each run is timed on its own; an optional `prepare`
//   step runs before each run, untimed (e.g. copying an input that the work consumes).
// - Summaries: median and quartiles by linear interpolation between order statistics (the "type 7" rule of R and
//   NumPy's default), min, max and total. Timings are not reproducible; nothing exact depends on them.
// - Peak memory (peak_memory_of) is the peak resident set size of a child process (fork) that runs the work once:
//   getrusage's ru_maxrss as wait4 reports it. It counts the pages the child inherited and touched (the caller's
//   resident memory at the fork, typically a few MB) as well as what the work allocated; POSIX systems only.
#pragma once

#include <functional>
#include <optional>
#include <vector>

namespace hsx {

struct RepeatOptions {
  int min_repetitions = 5;          ///< at least this many runs; >= 1
  double min_seconds = 0.2;         ///< and at least this much timed work in total, seconds; finite, >= 0
  int max_repetitions = 1000000;    ///< at most this many runs; >= min_repetitions
  /// Monotone clock in seconds; empty: std::chrono::steady_clock. Tests inject a fake one.
  std::function<double()> clock;
};

struct TimingSummary {
  int repetitions = 0;
  double total = 0;                 ///< sum of the runs, seconds
  double median = 0, q1 = 0, q3 = 0, min = 0, max = 0;  ///< seconds
  std::vector<double> runs;         ///< each run's seconds, in the order run
  double iqr() const { return q3 - q1; }
};

/// Summary statistics of `seconds` (one entry per run, any order). Throws std::invalid_argument when it is empty
/// or holds a negative or non-finite time.
TimingSummary summarize_times(const std::vector<double>& seconds);

/// Times `run` repeatedly as the conventions say, calling `prepare` (if given) before each run without timing it.
/// Exceptions from `run` or `prepare` propagate (nothing is summarised then). Throws std::invalid_argument when
/// `options` break the bounds above.
TimingSummary time_repeatedly(const std::function<void()>& run, const RepeatOptions& options = {},
                              const std::function<void()>& prepare = {});

/// Times several pieces of work side by side: rounds of one run of each, in the order given, repeated until every
/// piece meets the conventions' bounds (at least `min_repetitions` runs and `min_seconds` in total each; at most
/// `max_repetitions` rounds). Every piece gets the same number of runs, and a change of the machine's load during
/// the measurement falls on all of them alike (a ratio of their medians compares runs made at the same times).
/// Returns one summary per piece, in the order of `runs`. Exceptions propagate; std::invalid_argument when `runs`
/// is empty or `options` break the bounds.
std::vector<TimingSummary> time_alternately(const std::vector<std::function<void()>>& runs,
                                            const RepeatOptions& options = {});

/// Runs `run` once in a forked child process and returns the child's peak resident set size in bytes (see the
/// conventions), or nullopt when the child did not finish normally (`run` threw, the child crashed or was killed)
/// or no child could be made. The parent's state is untouched by `run` (it runs in the child only); the child ends
/// with _exit, so no buffered output is flushed twice. Call it when no other thread of the caller is running.
std::optional<long> peak_memory_of(const std::function<void()>& run);

}  // namespace hsx
