#include "cli/distribute.hpp"

#include <hsx/geometry/scene.hpp>  // InputError

#include <cstdlib>
#include <iostream>

#ifdef HSX_WITH_MPI
#include <mpi.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <thread>
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

constexpr int kLineTag = 1;

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
  const std::size_t n = indices.size(), ranks = static_cast<std::size_t>(size_);
  std::vector<std::uint64_t> mine;
  for (std::size_t k = static_cast<std::size_t>(rank_); k < n; k += ranks) mine.push_back(indices[k]);
  if (rank_ != 0) {
    try {
      work(mine, [](std::string&& line) {
        MPI_Send(line.data(), static_cast<int>(line.size()), MPI_CHAR, 0, kLineTag, MPI_COMM_WORLD);
      });
    } catch (const std::exception& e) {
      abort_run(e.what(), rank_);
    }
    return;
  }
  // Rank 0: its own share on a worker thread (which makes no MPI call), the other ranks' lines here.
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<std::string> local;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      work(mine, [&](std::string&& line) {
        std::lock_guard<std::mutex> lock(mutex);
        local.push_back(std::move(line));
        wake.notify_one();
      });
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      failure = std::current_exception();
      wake.notify_one();
    }
  });
  std::vector<std::size_t> received(ranks, 0);  // lines had from each rank: the next one is at rank + received * P
  std::map<std::size_t, std::string> waiting;    // lines by position, until every earlier one is there
  std::size_t next = 0;
  try {
    while (next < n) {
      bool progress = false;
      {
        std::unique_lock<std::mutex> lock(mutex);
        if (failure) std::rethrow_exception(failure);
        while (!local.empty()) {
          waiting.emplace(received[0]++ * ranks, std::move(local.front()));
          local.pop_front();
          progress = true;
        }
      }
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kLineTag, MPI_COMM_WORLD, &flag, &status);
      if (flag) {
        int count = 0;
        MPI_Get_count(&status, MPI_CHAR, &count);
        std::string line(static_cast<std::size_t>(count), '\0');
        MPI_Recv(line.data(), count, MPI_CHAR, status.MPI_SOURCE, kLineTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const auto from = static_cast<std::size_t>(status.MPI_SOURCE);
        waiting.emplace(from + received[from]++ * ranks, std::move(line));
        progress = true;
      }
      while (!waiting.empty() && waiting.begin()->first == next) {
        sink(std::move(waiting.begin()->second));
        waiting.erase(waiting.begin());
        ++next;
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
