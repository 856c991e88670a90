// Campaigns from Python (algorithms/campaign/campaign.hpp): hsx._Campaign, an iterator of per-scene records in
// index order, and the check catalogue.
//
// The library's run_scenes runs on a worker thread that never touches Python; its sink puts each record in a
// bounded queue (at most 4 x jobs records wait there, so a slow consumer holds the campaign back instead of
// letting it run ahead without bound). __next__ waits for the next record with the GIL released, taking the GIL
// every 20 ms to let the interpreter run its signal handlers (PyErr_CheckSignals, as cancel.cpp's Guard does for
// a search): Ctrl-C stops the campaign (the sink refuses the next record, so run_scenes stops, and run_scenes'
// cancel hook cuts the scenes in progress short at their next check; an arrangement in progress is not
// interrupted) and raises KeyboardInterrupt. Closing or dropping the iterator stops it the same way.
#include "bindings.hpp"

#include <hsx/algorithms/campaign/campaign.hpp>
#include <hsx/io/scene_json.hpp>

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace hsxpy {
namespace {

namespace campaign = hsx::campaign;

/// Thrown by the sink once the consumer asked to stop (run_scenes rethrows it; the worker swallows it).
struct StopRequested {};

class CampaignRun {
 public:
  CampaignRun(campaign::CampaignSettings settings, std::vector<std::uint64_t> indices, int jobs)
      : settings_(std::move(settings)), indices_(std::move(indices)), jobs_(jobs),
        capacity_(4 * static_cast<std::size_t>(jobs)) {}
  ~CampaignRun() {
    // May run with the GIL held (the iterator dropped): the worker never takes it, so joining cannot deadlock.
    stop_and_join();
  }
  CampaignRun(const CampaignRun&) = delete;
  CampaignRun& operator=(const CampaignRun&) = delete;

  /// The next record; std::nullopt at the end. With the GIL held on entry and on return.
  std::optional<campaign::SceneRecord> next() {
    if (!started_ && !stop_) start();  // (no worker yet: nothing else reads stop_) closed before the first record
    std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
    while (true) {
      {
        py::gil_scoped_release release;
        lock.lock();
        ready_cv_.wait_for(lock, std::chrono::milliseconds(20), [&] { return !queue_.empty() || done_; });
      }
      if (!queue_.empty()) {
        campaign::SceneRecord r = std::move(queue_.front());
        queue_.pop_front();
        lock.unlock();
        space_cv_.notify_all();
        return r;
      }
      if (done_) {
        std::exception_ptr error = error_;
        error_ = nullptr;
        lock.unlock();
        if (error) std::rethrow_exception(error);
        return std::nullopt;
      }
      lock.unlock();
      if (PyErr_CheckSignals() != 0) {  // KeyboardInterrupt (or another handler's exception) is now set
        py::error_already_set e;
        {
          py::gil_scoped_release release;
          stop_and_join();
        }
        throw e;
      }
    }
  }

  /// Stops the campaign and waits for the worker (the scenes being run finish first). Idempotent.
  void stop_and_join() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
      cancel_ = true;  // with stop_ set first: a record the cancel cut short is refused by the sink
    }
    space_cv_.notify_all();
    if (worker_.joinable()) worker_.join();
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.clear();
    done_ = true;
  }

 private:
  /// Starts the worker. When the system refuses the thread (no memory for its stack, a process limit), nothing
  /// has started: RuntimeError, and the next call tries again.
  void start() {
    try {
      worker_ = std::thread([this] { work(); });
    } catch (const std::system_error& e) {
      throw std::runtime_error(std::string("hsx.campaign: the system refused the campaign's thread (") + e.what() +
                               "); nothing has run");
    }
    started_ = true;
  }

  /// The worker thread: run_scenes, its records into the queue.
  void work() {
    std::exception_ptr error;
    try {
      campaign::run_scenes(settings_, indices_, jobs_, [this](campaign::SceneRecord&& r) {
        std::unique_lock<std::mutex> lock(mutex_);
        space_cv_.wait(lock, [&] { return queue_.size() < capacity_ || stop_; });
        if (stop_) throw StopRequested{};
        queue_.push_back(std::move(r));
        lock.unlock();
        ready_cv_.notify_all();
      }, [this] { return cancel_.load(std::memory_order_relaxed); });
    } catch (const StopRequested&) {
    } catch (...) {
      error = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
      if (!stop_) error_ = error;
    }
    ready_cv_.notify_all();
  }

  const campaign::CampaignSettings settings_;
  const std::vector<std::uint64_t> indices_;
  const int jobs_;
  const std::size_t capacity_;
  bool started_ = false;

  std::mutex mutex_;
  std::condition_variable ready_cv_;  // a record arrived or the worker ended
  std::condition_variable space_cv_;  // the queue has room or the consumer stopped
  std::deque<campaign::SceneRecord> queue_;
  bool done_ = false;
  bool stop_ = false;
  std::atomic<bool> cancel_{false};  // run_scenes' cancel hook: the scenes in progress end at their next check
  std::exception_ptr error_;
  std::thread worker_;
};

/// A record as a dict of its fields (the Python side, hsx/_campaign.py, makes it an hsx.CampaignRecord).
py::dict record_dict(const campaign::SceneRecord& r) {
  py::dict d;
  d["index"] = r.index;
  d["seed"] = r.seed;
  d["halfspaces"] = r.halfspaces;
  d["cells"] = r.cells;
  d["patches"] = r.patches;
  d["samples"] = r.samples;
  d["degeneracies"] = r.degeneracies;
  d["outcome"] = std::string(campaign::to_string(r.outcome));
  d["note"] = r.note;
  d["timed_out"] = r.timed_out;
  py::list checks;
  for (const campaign::CheckOutcome& c : r.checks)
    checks.append(py::make_tuple(c.check, std::string(campaign::to_string(c.status)), c.witness));
  d["checks"] = checks;
  d["failed"] = r.failed();
  d["scene_json"] = r.scene ? py::object(py::str(hsx::write_scene2(*r.scene).dump(2) + "\n")) : py::object(py::none());
  d["intended"] = r.intended;
  return d;
}

template <class T>
T option(const py::dict& options, const char* name, T fallback) {
  return options.contains(name) ? options[name].cast<T>() : fallback;
}

/// The campaign's settings from hsx.campaign's arguments: `checks` a comma-separated list (parse_check_list),
/// `options` the limits (max_labellings, max_states, max_graph_cuts, precision, max_cells, max_side_table; unset
/// ones keep CampaignSettings' defaults), `generator` hsx.random_scene's keyword arguments.
campaign::CampaignSettings campaign_settings(std::uint64_t seed, const std::string& checks, double time_limit,
                                             const py::dict& options, const py::dict& generator) {
  campaign::CampaignSettings s;
  s.seed = seed;
  s.scene = random_settings(generator);
  s.checks = campaign::parse_check_list(checks);
  if (options.contains("sample_policy")) {
    const std::string policy = options["sample_policy"].cast<std::string>();
    const std::optional<campaign::SamplePolicy> p = campaign::sample_policy_from_string(policy);
    if (!p) throw hsx::InputError("sample_policy: \"uniform\" or \"intended\", not \"" + policy + "\"");
    s.sample_policy = *p;
  }
  if (time_limit < 0) throw hsx::InputError("time_limit: must be >= 0 (0: none)");
  s.time_limit = time_limit;
  s.brute_force_limit = option(options, "max_labellings", s.brute_force_limit);
  s.max_states = option(options, "max_states", s.max_states);
  s.max_graph_cuts = option(options, "max_graph_cuts", s.max_graph_cuts);
  s.precision_bits = option(options, "precision", s.precision_bits);
  s.limits.max_cells = option(options, "max_cells", s.limits.max_cells);
  s.limits.max_side_entries = option(options, "max_side_table", s.limits.max_side_entries);
  if (s.brute_force_limit < 0) throw hsx::InputError("max_labellings: must be >= 0");
  if (s.max_states < 0) throw hsx::InputError("max_states: must be >= 0 (0: no limit)");
  if (s.max_graph_cuts < 0) throw hsx::InputError("max_graph_cuts: must be >= 0 (0: no limit)");
  if (s.precision_bits < 1) throw hsx::InputError("precision: must be at least 1");
  if (s.limits.max_cells < 0) throw hsx::InputError("max_cells: must be >= 0 (0: no limit)");
  if (s.limits.max_side_entries < 0) throw hsx::InputError("max_side_table: must be >= 0 (0: no limit)");
  campaign::validate(s);
  return s;
}

}  // namespace

void bind_campaign(py::module_& m) {
  py::class_<CampaignRun, std::shared_ptr<CampaignRun>>(
      m, "_Campaign", "Scenes of a campaign, run on a worker thread; iterate to get their records in index order")
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__",
           [](CampaignRun& run) {
             std::optional<campaign::SceneRecord> r = run.next();
             if (!r) throw py::stop_iteration();
             return record_dict(*r);
           })
      .def("close",
           [](CampaignRun& run) {
             py::gil_scoped_release release;
             run.stop_and_join();
           },
           "Stop the campaign (the scenes being run finish first)");
  m.def("_campaign",
        [](std::uint64_t seed, std::uint64_t start, std::uint64_t count, const std::string& checks, int jobs,
           double time_limit, const py::dict& options, const py::dict& generator) {
          if (jobs < 1) throw hsx::InputError("jobs: at least 1");
          // As `hsx campaign --count`: the indices are listed up front (8 bytes each).
          constexpr std::uint64_t kMaxCount = 100'000'000;
          if (count > kMaxCount)
            throw hsx::InputError("count: at most " + std::to_string(kMaxCount) +
                                  " scenes per call (run larger campaigns in parts with start=)");
          campaign::CampaignSettings s = campaign_settings(seed, checks, time_limit, options, generator);
          std::vector<std::uint64_t> indices = count == 0 ? std::vector<std::uint64_t>{}
                                                          : campaign::shard_indices(start, count, 0, 1);
          return std::make_shared<CampaignRun>(std::move(s), std::move(indices), jobs);
        },
        py::arg("seed"), py::arg("start"), py::arg("count"), py::arg("checks"), py::arg("jobs"),
        py::arg("time_limit"), py::arg("options"), py::arg("generator"));
  m.def(
      "_campaign_scene",
      [](std::uint64_t seed, std::uint64_t index, const std::string& checks, const py::dict& options,
         const py::dict& generator) {
        const campaign::CampaignSettings s = campaign_settings(seed, checks, 0, options, generator);
        py::gil_scoped_release release;
        return hsx::write_scene2(campaign::generate_scene(s, index)).dump(2) + "\n";
      },
      py::arg("seed"), py::arg("index"), py::arg("checks"), py::arg("options"), py::arg("generator"));
  m.def("_campaign_checks", [] {
    py::list l;
    for (const campaign::CheckInfo& c : campaign::check_catalogue())
      l.append(py::make_tuple(std::string(c.name), std::string(c.description)));
    return l;
  });
}

}  // namespace hsxpy
