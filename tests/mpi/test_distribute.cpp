// cli/distribute.hpp under mpirun: rank 0 must receive every rank's lines in the order of the index list, whatever
// order they arrive in, each index turned into a line exactly once, and every rank must be given work. The work
// sleeps a little on every index (so that no rank can take the whole list before the others ask) and longer on some
// indices of some ranks, so that lines do arrive out of order.
// Usage: mpirun -np P test_distribute [N]; prints "N passed, M failed" on rank 0 and exits non-zero on a failure.
#include "cli/distribute.hpp"

#include <chrono>
#include <iostream>
#include <map>
#include <string>
#include <thread>
#include <vector>

int main(int argc, char** argv) {
  const std::uint64_t n = argc > 1 ? std::stoull(argv[1]) : 2000;
  hsx::cli::MpiRun run;
  // A list that is not sorted: the positions, not the values, fix the order.
  std::vector<std::uint64_t> indices;
  if (run.rank() == 0)
    for (std::uint64_t k = 0; k < n; ++k) indices.push_back((k * 7919) % n);
  indices = run.broadcast(indices);
  const int rank = run.rank();
  std::vector<std::string> got;
  run.distribute(
      indices,
      [rank](const std::vector<std::uint64_t>& mine, const std::function<void(std::string&&)>& out) {
        for (std::uint64_t i : mine) {
          std::this_thread::sleep_for(std::chrono::microseconds(200));
          if ((i + static_cast<std::uint64_t>(rank)) % 97 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(3));
          out("scene " + std::to_string(i) + " squared " + std::to_string(i * i) + " by " + std::to_string(rank));
        }
      },
      [&](std::string&& line) { got.push_back(std::move(line)); });
  if (run.rank() != 0) return 0;
  int passed = 0, failed = 0;
  if (got.size() == indices.size()) ++passed; else ++failed;
  std::map<std::string, std::size_t> lines_by_rank;
  for (std::size_t k = 0; k < got.size() && k < indices.size(); ++k) {
    const std::string want = "scene " + std::to_string(indices[k]) + " squared " + std::to_string(indices[k] * indices[k]) + " by ";
    if (got[k].compare(0, want.size(), want) == 0) {
      ++passed;
      ++lines_by_rank[got[k].substr(want.size())];
    } else {
      ++failed;
      if (failed < 5) std::cerr << "FAIL: line " << k << " is \"" << got[k] << "\", expected \"" << want << "\"\n";
    }
  }
  for (int r = 0; r < run.size(); ++r) {
    const std::size_t lines = lines_by_rank[std::to_string(r)];
    std::cout << "rank " << r << ": " << lines << " lines\n";
    if (lines > 0) ++passed; else ++failed, std::cerr << "FAIL: rank " << r << " was given no work\n";
  }
  if (run.size() < 2) {
    ++failed;
    std::cerr << "FAIL: run with mpirun -np 2 or more (this run has " << run.size() << " process)\n";
  }
  std::cout << passed << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}
