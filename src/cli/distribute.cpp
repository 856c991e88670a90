#include "cli/distribute.hpp"

#include <hsx/geometry/scene.hpp>  // InputError

#include <cstdlib>
#include <iostream>

#ifdef HSX_WITH_MPI
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#endif

namespace hsx::cli {

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* value = std::getenv(name);
    if (value && std::atol(value) > 1) return true;
  }
  return false;
}

#ifndef HSX_WITH_MPI

bool built_with_mpi() { return false; }

MpiRun::MpiRun() {
  throw InputError("this hsx was built without MPI (CMake found no MPI: install libopenmpi-dev and build again), so "
                   "under mpirun every process would run the whole campaign; run it without mpirun, or with "
                   "--shard i/k per process");
}
MpiRun::~MpiRun() = default;
std::vector<std::uint64_t> MpiRun::broadcast(const std::vector<std::uint64_t>& indices) const { return indices; }
bool MpiRun::broadcast(bool value) const { return value; }
void MpiRun::distribute(const std::vector<std::uint64_t>& indices, const LineWork& work,
                        const std::function<void(std::string&&)>& sink) const {
  work(indices, sink);
}

#else

namespace {

constexpr int kLineTag = 1;  // a line: its position in the list (8 bytes, host order) and its text
constexpr int kAskTag = 2;   // an empty message: "the next chunk, please"
constexpr int kGiveTag = 3;  // the answer: two uint64 positions [begin, end); empty when nothing is left

/// Positions [begin, end) of the list.
struct Chunk {
  std::uint64_t begin = 0, end = 0;
};

/// Hands out the list's positions in order, in chunks that shrink as the list runs out (guided scheduling): large
/// enough early that asking costs little, small at the end so that no rank waits long for another's last chunk.
/// Which rank gets which chunk depends on timing; the output does not, since rank 0 writes lines by position.
class Dispenser {
 public:
  Dispenser(std::uint64_t n, std::uint64_t ranks) : n_(n), ranks_(ranks) {}
  Chunk next() {
    const std::uint64_t left = n_ - next_;
    const std::uint64_t size = std::min<std::uint64_t>(left, std::clamp<std::uint64_t>(left / (8 * ranks_), 1, 64));
    const Chunk c{next_, next_ + size};
    next_ += size;
    return c;
  }

 private:
  std::uint64_t n_, ranks_, next_ = 0;
};

Chunk receive_chunk() {
  std::uint64_t bounds[2] = {0, 0};
  MPI_Recv(bounds, 2, MPI_UINT64_T, 0, kGiveTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return {bounds[0], bounds[1]};
}

/// A worker rank's lines on their way to rank 0, sent without waiting (MPI_Isend). A blocking MPI_Send of a line
/// waits until rank 0 has taken it whenever the line does not fit Open MPI's shared-memory mailbox, and rank 0 looks
/// only every millisecond: measured, 3-4 % of a worker rank's time went to that wait. A message's buffer lives
/// until its send completes; at each new line the completed ones at the front are let go, and `finish` waits for
/// the rest. Rank 0 receives lines until it has all of them, so the pending sends are at most the lines it has not
/// taken yet (about a kilobyte each), and waiting for them always ends.
class LineSender {
 public:
  LineSender() = default;
  LineSender(const LineSender&) = delete;
  LineSender& operator=(const LineSender&) = delete;
  ~LineSender() { finish(); }

  void send(std::uint64_t position, const std::string& line) {
    release_completed();
    auto message = std::make_unique<std::string>(sizeof position, '\0');
    std::memcpy(message->data(), &position, sizeof position);
    *message += line;
    requests_.push_back(MPI_REQUEST_NULL);
    MPI_Isend(message->data(), static_cast<int>(message->size()), MPI_CHAR, 0, kLineTag, MPI_COMM_WORLD,
              &requests_.back());
    messages_.push_back(std::move(message));
  }

  /// Waits until every line sent has left this rank (after the last chunk, and on destruction).
  void finish() {
    MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
    requests_.clear();
    messages_.clear();
  }

 private:
  void release_completed() {  // from the oldest on, up to the first send still under way
    std::size_t done = 0;
    for (int flag = 1; done < requests_.size(); ++done) {
      MPI_Test(&requests_[done], &flag, MPI_STATUS_IGNORE);
      if (!flag) break;
    }
    requests_.erase(requests_.begin(), requests_.begin() + static_cast<std::ptrdiff_t>(done));
    messages_.erase(messages_.begin(), messages_.begin() + static_cast<std::ptrdiff_t>(done));
  }

  std::vector<MPI_Request> requests_;  // a few at a time, so erasing from the front is cheap
  std::vector<std::unique_ptr<std::string>> messages_;
};

/// The line announced by `status` (a kLineTag message), with its position.
std::pair<std::uint64_t, std::string> receive_line(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string message(static_cast<std::size_t>(count), '\0');
  MPI_Recv(message.data(), count, MPI_CHAR, status.MPI_SOURCE, kLineTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::uint64_t position = 0;
  if (message.size() < sizeof position) throw std::runtime_error("a line message without its position");
  std::memcpy(&position, message.data(), sizeof position);
  return {position, message.substr(sizeof position)};
}

[[noreturn]] void abort_run(const std::string& what, int rank) {
  std::cerr << "hsx: rank " << rank << ": " << what << "; stopping every rank\n" << std::flush;
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::abort();
}

}  // namespace

bool built_with_mpi() { return true; }

MpiRun::MpiRun() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_FUNNELED) abort_run("the MPI library does not support threads (MPI_THREAD_FUNNELED)", rank_);
}

MpiRun::~MpiRun() { MPI_Finalize(); }

std::vector<std::uint64_t> MpiRun::broadcast(const std::vector<std::uint64_t>& indices) const {
  std::uint64_t count = indices.size();
  MPI_Bcast(&count, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  std::vector<std::uint64_t> out = rank_ == 0 ? indices : std::vector<std::uint64_t>(count);
  for (std::uint64_t at = 0; at < count;) {  // in chunks: MPI counts are ints
    const int chunk = static_cast<int>(std::min<std::uint64_t>(count - at, 1u << 28));
    MPI_Bcast(out.data() + at, chunk, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    at += static_cast<std::uint64_t>(chunk);
  }
  return out;
}

bool MpiRun::broadcast(bool value) const {
  int v = value ? 1 : 0;
  MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return v != 0;
}

void MpiRun::distribute(const std::vector<std::uint64_t>& indices, const LineWork& work,
                        const std::function<void(std::string&&)>& sink) const {
  const std::size_t n = indices.size();
  const auto share = [&](Chunk c) {
    return std::vector<std::uint64_t>(indices.begin() + static_cast<std::ptrdiff_t>(c.begin),
                                      indices.begin() + static_cast<std::ptrdiff_t>(c.end));
  };
  if (rank_ != 0) {
    try {
      // One request is always outstanding while a chunk is worked on, so the next one is there when it ends.
      LineSender lines;
      MPI_Send(nullptr, 0, MPI_CHAR, 0, kAskTag, MPI_COMM_WORLD);
      for (Chunk c = receive_chunk(); c.begin < c.end;) {
        MPI_Send(nullptr, 0, MPI_CHAR, 0, kAskTag, MPI_COMM_WORLD);
        std::uint64_t position = c.begin;
        work(share(c), [&](std::string&& line) { lines.send(position++, line); });
        c = receive_chunk();
      }
      lines.finish();
    } catch (const std::exception& e) {
      abort_run(e.what(), rank_);
    }
    return;
  }
  // Rank 0: chunks for itself on a worker thread (which makes no MPI call); here, the other ranks' requests
  // answered and their lines received.
  Dispenser dispenser(n, static_cast<std::size_t>(size_));
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::pair<std::uint64_t, std::string>> local;  // rank 0's lines with their positions
  std::exception_ptr failure;
  const auto take_chunk = [&] {  // the worker thread and the answers to other ranks both take from `dispenser`
    std::lock_guard<std::mutex> lock(mutex);
    return dispenser.next();
  };
  const auto work_chunks = [&] {
    try {
      for (;;) {
        const Chunk c = take_chunk();
        if (c.begin == c.end) return;
        std::uint64_t position = c.begin;
        work(share(c), [&](std::string&& line) {
          std::lock_guard<std::mutex> lock(mutex);
          local.emplace_back(position++, std::move(line));
          wake.notify_one();
        });
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      failure = std::current_exception();
      wake.notify_one();
    }
  };
  std::thread worker;
  try {
    worker = std::thread(work_chunks);
  } catch (const std::system_error& e) {  // other ranks wait for answers: stop them all, as any failure here does
    abort_run(std::string("the system refused rank 0's worker thread (") + e.what() + ")", rank_);
  }
  std::map<std::uint64_t, std::string> waiting;  // lines by position, until every earlier one is there
  std::uint64_t next = 0;
  int done_ranks = 0;  // ranks told that nothing is left (each asks once more after its last chunk)
  try {
    while (next < n || done_ranks < size_ - 1) {
      bool progress = false;
      {
        std::unique_lock<std::mutex> lock(mutex);
        if (failure) std::rethrow_exception(failure);
        for (; !local.empty(); local.pop_front()) waiting.insert(std::move(local.front()));
      }
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (flag && status.MPI_TAG == kAskTag) {
        MPI_Recv(nullptr, 0, MPI_CHAR, status.MPI_SOURCE, kAskTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const Chunk c = take_chunk();
        if (c.begin == c.end) ++done_ranks;
        const std::uint64_t bounds[2] = {c.begin, c.end};
        MPI_Send(bounds, 2, MPI_UINT64_T, status.MPI_SOURCE, kGiveTag, MPI_COMM_WORLD);
        progress = true;
      } else if (flag) {
        waiting.insert(receive_line(status));
        progress = true;
      }
      for (; !waiting.empty() && waiting.begin()->first == next; ++next) {
        sink(std::move(waiting.begin()->second));
        waiting.erase(waiting.begin());
      }
      if (!progress) {
        std::unique_lock<std::mutex> lock(mutex);
        wake.wait_for(lock, std::chrono::milliseconds(1), [&] { return !local.empty() || failure; });
      }
    }
  } catch (const std::exception& e) {
    abort_run(e.what(), rank_);
  }
  worker.join();
}

#endif

}  // namespace hsx::cli
