// Work split over the processes of an MPI run (`mpirun -np P hsx campaign ...`), merged at rank 0 in a fixed order,
// so that P processes give the same output bytes as one. Compiled with MPI when CMake finds it (HSX_WITH_MPI);
// without it, a run started by mpirun is refused with a clear message instead of running P copies side by side.
//
// The protocol: every rank gets the same list of indices (broadcast from rank 0). Rank 0 hands out positions of the
// list in chunks, in order, to whichever rank asks (itself included, on a worker thread), large chunks first and
// single positions at the end, so a rank that drew slow scenes does not hold the others back; every rank turns each
// index of its chunk into one line of text and sends it to rank 0 with its position, and rank 0 hands every line to
// its sink in the order of the list. Which rank ran which index depends on timing, the output does not. Only rank 0
// reads or writes files.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hsx::cli {

/// True when this process was started by mpirun/mpiexec with more than one process (Open MPI's
/// OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_SIZE of other launchers).
bool launched_by_mpi();

/// True when this hsx was built with MPI.
bool built_with_mpi();

/// Turns the indices `mine` into one line each, handing them to `out` in order (from any one thread).
using LineWork = std::function<void(const std::vector<std::uint64_t>& mine, const std::function<void(std::string&&)>& out)>;

/// An MPI run of this process: initialised on construction (MPI_THREAD_FUNNELED), finalised on destruction.
/// Throws InputError when hsx was built without MPI.
class MpiRun {
 public:
  MpiRun();
  ~MpiRun();
  MpiRun(const MpiRun&) = delete;
  MpiRun& operator=(const MpiRun&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0's `indices`, on every rank.
  std::vector<std::uint64_t> broadcast(const std::vector<std::uint64_t>& indices) const;
  /// Rank 0's flag, on every rank (e.g. "the folder was accepted": every rank stops when rank 0 refuses).
  bool broadcast(bool value) const;

  /// Runs `work` on the chunks of `indices` (the same list on every rank) that this rank is given, one call per
  /// chunk; on rank 0, `sink` receives every rank's lines in the order of `indices`, as soon as all earlier ones are
  /// there. An exception from `work` or `sink` aborts the whole
  /// run (MPI_Abort) after printing it, since the other ranks cannot be told to stop otherwise.
  void distribute(const std::vector<std::uint64_t>& indices, const LineWork& work,
                  const std::function<void(std::string&&)>& sink) const;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace hsx::cli
