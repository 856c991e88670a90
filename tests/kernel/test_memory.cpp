// Tests of kernel/memory: a failed GMP allocation throws std::bad_alloc instead of aborting the process.
#include <hsx/kernel/memory.hpp>
#include <hsx/kernel/rational.hpp>

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <memory>
#include <new>
#include <vector>

namespace {

/// Runs `body` in a child process whose address space is capped at `cap` bytes; returns the wait status (the
/// child exits with what `body` returns, or is killed by a signal).
template <typename Body>
int in_child(rlim_t cap, Body body) {
  const pid_t pid = fork();
  if (pid == 0) {
    const rlimit limit{cap, cap};
    setrlimit(RLIMIT_AS, &limit);
    _exit(body());
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

/// In a child process with a 1 GiB address-space cap: asks GMP for a 2^33-bit (1 GiB) number. Exit status 0:
/// std::bad_alloc was caught; 1: the allocation succeeded. Abort (GMP's default handler) shows as a signal.
int child_asks_gmp_for_a_gibibyte(bool install) {
  return in_child(rlim_t(1) << 30, [install] {
    if (install) hsx::install_gmp_allocation_handlers();
    try {
      hsx::Integer z;
      mpz_realloc2(z.get_mpz_t(), mp_bitcnt_t(1) << 33);
      return 1;
    } catch (const std::bad_alloc&) {
      hsx::Integer after = 12345;  // GMP still works after the failure
      return after == 12345 ? 0 : 3;
    }
  });
}

}  // namespace

TEST_CASE("a failed GMP allocation throws std::bad_alloc once the handlers are installed", "[kernel][memory]") {
  const int status = child_asks_gmp_for_a_gibibyte(true);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("without the handlers, GMP aborts the process (what the handlers prevent)", "[kernel][memory]") {
  const int status = child_asks_gmp_for_a_gibibyte(false);
  CHECK(WIFSIGNALED(status));
}

namespace {

/// In a child process with a 256 MiB address-space cap (and, when `reserve`, a 32 MiB out-of-memory reserve):
/// allocates 1 MiB blocks until std::bad_alloc, keeps them, then asks for 4 MiB more, as unwinding code might.
/// Exit status 0: that allocation succeeded; 1: it failed; 2: memory never ran out; 3: nothing fitted at all.
int child_allocates_after_running_out(bool reserve) {
  return in_child(rlim_t(1) << 28, [reserve] {
    if (reserve) hsx::install_out_of_memory_reserve(std::size_t{32} << 20);
    std::vector<std::unique_ptr<char[]>> blocks;
    blocks.reserve(1025);
    try {
      for (int k = 0; k < 1024; ++k) blocks.emplace_back(new char[std::size_t{1} << 20]);
      return 2;
    } catch (const std::bad_alloc&) {
      try {
        blocks.emplace_back(new char[std::size_t{4} << 20]);  // kept, so the allocation cannot be elided
        return blocks.size() > 1 ? 0 : 3;
      } catch (const std::bad_alloc&) {
        return 1;
      }
    }
  });
}

}  // namespace

TEST_CASE("the out-of-memory reserve leaves room to allocate after the first failure", "[kernel][memory]") {
  const int with = child_allocates_after_running_out(true);
  REQUIRE(WIFEXITED(with));
  CHECK(WEXITSTATUS(with) == 0);
  const int without = child_allocates_after_running_out(false);  // the control: the test can fail
  REQUIRE(WIFEXITED(without));
  CHECK(WEXITSTATUS(without) == 1);
}
