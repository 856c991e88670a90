// Repeated timing: see timing.hpp.
#include <hsx/kernel/timing.hpp>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <stdexcept>
#include <string>

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace hsx {

namespace {

/// The p-quantile of sorted, non-empty values, interpolating linearly between order statistics.
double quantile(const std::vector<double>& sorted, double p) {
  const double h = p * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[lo + 1] - sorted[lo]);
}

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// std::invalid_argument, naming `caller`, when `options` break the bounds of the conventions.
void check_options(const char* caller, const RepeatOptions& options) {
  const std::string name(caller);
  if (options.min_repetitions < 1) throw std::invalid_argument(name + ": min_repetitions must be >= 1");
  if (options.max_repetitions < options.min_repetitions)
    throw std::invalid_argument(name + ": max_repetitions must be >= min_repetitions");
  if (!std::isfinite(options.min_seconds) || options.min_seconds < 0)
    throw std::invalid_argument(name + ": min_seconds must be finite and >= 0");
}

}  // namespace

TimingSummary summarize_times(const std::vector<double>& seconds) {
  if (seconds.empty()) throw std::invalid_argument("summarize_times: no runs");
  for (double s : seconds)
    if (!std::isfinite(s) || s < 0) throw std::invalid_argument("summarize_times: a run time is negative or not finite");
  std::vector<double> sorted = seconds;
  std::sort(sorted.begin(), sorted.end());
  TimingSummary t;
  t.repetitions = static_cast<int>(seconds.size());
  for (double s : seconds) t.total += s;
  t.median = quantile(sorted, 0.5);
  t.q1 = quantile(sorted, 0.25);
  t.q3 = quantile(sorted, 0.75);
  t.min = sorted.front();
  t.max = sorted.back();
  t.runs = seconds;
  return t;
}

namespace {

/// Rounds of one run of each piece of `runs` (each after `prepare`, if given, untimed) until the conventions'
/// bounds are met for every piece; one summary per piece. `caller` names the public function in errors.
std::vector<TimingSummary> time_rounds(const char* caller, const std::vector<std::function<void()>>& runs,
                                       const std::function<void()>& prepare, const RepeatOptions& options) {
  if (runs.empty()) throw std::invalid_argument(std::string(caller) + ": no work to time");
  check_options(caller, options);
  const std::function<double()> clock = options.clock ? options.clock : std::function<double()>(steady_seconds);
  std::vector<std::vector<double>> seconds(runs.size());
  std::vector<double> totals(runs.size(), 0.0);
  auto more = [&] {
    const int rounds = static_cast<int>(seconds.front().size());
    if (rounds >= options.max_repetitions) return false;
    if (rounds < options.min_repetitions) return true;
    return *std::min_element(totals.begin(), totals.end()) < options.min_seconds;
  };
  while (more())
    for (std::size_t k = 0; k < runs.size(); ++k) {
      if (prepare) prepare();
      const double start = clock();
      runs[k]();
      const double elapsed = std::max(0.0, clock() - start);
      seconds[k].push_back(elapsed);
      totals[k] += elapsed;
    }
  std::vector<TimingSummary> out;
  out.reserve(runs.size());
  for (const auto& s : seconds) out.push_back(summarize_times(s));
  return out;
}

}  // namespace

TimingSummary time_repeatedly(const std::function<void()>& run, const RepeatOptions& options,
                              const std::function<void()>& prepare) {
  return time_rounds("time_repeatedly", {run}, prepare, options).front();
}

std::vector<TimingSummary> time_alternately(const std::vector<std::function<void()>>& runs,
                                            const RepeatOptions& options) {
  return time_rounds("time_alternately", runs, {}, options);
}

std::optional<long> peak_memory_of(const std::function<void()>& run) {
  const pid_t child = fork();
  if (child < 0) return std::nullopt;
  if (child == 0) {
    int status = 0;
    try {
      run();
    } catch (...) {
      status = 1;
    }
    _exit(status);
  }
  int status = 0;
  struct rusage usage {};
  pid_t waited;
  do {
    waited = wait4(child, &status, 0, &usage);
  } while (waited < 0 && errno == EINTR);
  if (waited != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  return static_cast<long>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

}  // namespace hsx
