// Starting worker threads when the system may refuse some (private to the library).
#pragma once

#include <system_error>
#include <thread>
#include <vector>

namespace hsx {

/// Starts one thread running body(k) for each k in [first, end), in order, and stops at the first thread the
/// system refuses (std::system_error: no memory for its stack, a process limit); the threads started so far keep
/// running. Returns them, for the caller to join: fewer than end - first when one was refused, so the caller's
/// work must not depend on how many run. `body` is copied into each thread.
template <class Body>
std::vector<std::thread> start_threads(int first, int end, const Body& body) {
  std::vector<std::thread> started;
  for (int k = first; k < end; ++k) {
    try {
      started.emplace_back(body, k);
    } catch (const std::system_error&) {
      break;
    }
  }
  return started;
}

}  // namespace hsx
