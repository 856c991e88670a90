// Repeated timing (kernel/timing.hpp), with an injected clock: nothing here depends on real time.
#include <hsx/kernel/timing.hpp>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hsx;

TEST_CASE("summarize_times: median, quartiles, extremes", "[kernel][timing]") {
  const TimingSummary odd = summarize_times({3, 1, 2});
  CHECK(odd.repetitions == 3);
  CHECK(odd.median == 2);
  CHECK(odd.q1 == 1.5);
  CHECK(odd.q3 == 2.5);
  CHECK(odd.min == 1);
  CHECK(odd.max == 3);
  CHECK(odd.total == 6);
  CHECK(odd.runs == std::vector<double>{3, 1, 2});
  const TimingSummary even = summarize_times({4, 1, 3, 2});
  CHECK(even.median == 2.5);
  CHECK(even.q1 == 1.75);
  CHECK(even.q3 == 3.25);
  CHECK(even.iqr() == 1.5);
  const TimingSummary one = summarize_times({0.5});
  CHECK(one.median == 0.5);
  CHECK(one.q1 == 0.5);
  CHECK(one.q3 == 0.5);
  CHECK_THROWS_AS(summarize_times({}), std::invalid_argument);
  CHECK_THROWS_AS(summarize_times({1, -1}), std::invalid_argument);
  CHECK_THROWS_AS(summarize_times({1, std::numeric_limits<double>::infinity()}), std::invalid_argument);
}

TEST_CASE("summarize_times: order statistics bracket each other, any order of runs", "[kernel][timing]") {
  rc::prop("min <= q1 <= median <= q3 <= max, independent of order", [](std::vector<unsigned> raw) {
    RC_PRE(!raw.empty());
    std::vector<double> runs;
    for (unsigned r : raw) runs.push_back(static_cast<double>(r % 100000) / 1000);
    const TimingSummary t = summarize_times(runs);
    RC_ASSERT(t.min <= t.q1);
    RC_ASSERT(t.q1 <= t.median);
    RC_ASSERT(t.median <= t.q3);
    RC_ASSERT(t.q3 <= t.max);
    std::vector<double> reversed(runs.rbegin(), runs.rend());
    const TimingSummary r = summarize_times(reversed);
    RC_ASSERT(r.median == t.median);
    RC_ASSERT(r.q1 == t.q1);
    RC_ASSERT(r.q3 == t.q3);
    // Brute-force median: the middle element, or the mean of the two middle ones.
    std::sort(runs.begin(), runs.end());
    const std::size_t n = runs.size();
    const double median = n % 2 ? runs[n / 2] : (runs[n / 2 - 1] + runs[n / 2]) / 2;
    RC_ASSERT(std::abs(t.median - median) <= 1e-12 * (1 + median));
  });
}

TEST_CASE("time_repeatedly: a minimum count and a minimum total time", "[kernel][timing]") {
  double now = 0;
  int runs = 0, prepared = 0;
  RepeatOptions options;
  options.clock = [&] { return now; };
  auto work = [&] {
    ++runs;
    now += 0.01;
  };
  SECTION("the total time decides when runs are fast") {
    options.min_repetitions = 5;
    options.min_seconds = 0.2;
    const TimingSummary t = time_repeatedly(work, options);
    CHECK(runs == t.repetitions);
    CHECK(t.repetitions >= 20);
    CHECK(t.repetitions <= 21);  // 20 runs of 0.01 s, give or take one rounding of the sum
    CHECK(t.median == Approx(0.01));
  }
  SECTION("the count decides when runs are slow") {
    options.min_repetitions = 7;
    options.min_seconds = 0.01;
    CHECK(time_repeatedly(work, options).repetitions == 7);
  }
  SECTION("preparation runs before each run and is not timed") {
    options.min_repetitions = 5;
    options.min_seconds = 0;
    const TimingSummary t = time_repeatedly(work, options, [&] {
      ++prepared;
      now += 1;
    });
    CHECK(t.repetitions == 5);
    CHECK(prepared == 5);
    CHECK(t.max == Approx(0.01));
  }
  SECTION("the cap stops work that takes no time") {
    options.min_repetitions = 2;
    options.max_repetitions = 50;
    options.min_seconds = 1;
    CHECK(time_repeatedly([&] { ++runs; }, options).repetitions == 50);
    CHECK(runs == 50);
  }
  SECTION("bad options") {
    options.min_repetitions = 0;
    CHECK_THROWS_AS(time_repeatedly(work, options), std::invalid_argument);
    options.min_repetitions = 5;
    options.max_repetitions = 4;
    CHECK_THROWS_AS(time_repeatedly(work, options), std::invalid_argument);
    options.max_repetitions = 10;
    options.min_seconds = -1;
    CHECK_THROWS_AS(time_repeatedly(work, options), std::invalid_argument);
    CHECK(runs == 0);
  }
}

TEST_CASE("time_alternately: rounds of every piece, until each meets the bounds", "[kernel][timing]") {
  double now = 0;
  std::string order;
  RepeatOptions options;
  options.clock = [&] { return now; };
  auto piece = [&](char name, double seconds) {
    return [&, name, seconds] {
      order += name;
      now += seconds;
    };
  };
  SECTION("the pieces alternate; the one with the least total time decides when to stop") {
    options.min_repetitions = 2;
    options.min_seconds = 0.1;
    const auto t = time_alternately({piece('a', 0.01), piece('b', 0.04)}, options);
    REQUIRE(t.size() == 2);
    CHECK(t[0].repetitions == t[1].repetitions);
    CHECK(t[0].repetitions >= 10);  // a needs 10 runs of 0.01 s, so b runs 10 times too
    CHECK(t[0].repetitions <= 11);
    CHECK(t[0].median == Approx(0.01));
    CHECK(t[1].median == Approx(0.04));
    std::string expected;
    for (int k = 0; k < t[0].repetitions; ++k) expected += "ab";
    CHECK(order == expected);
    CHECK(t[1].runs.size() == static_cast<std::size_t>(t[1].repetitions));
  }
  SECTION("the count decides when every piece is slow") {
    options.min_repetitions = 4;
    options.min_seconds = 0.01;
    const auto t = time_alternately({piece('a', 1), piece('b', 2), piece('c', 3)}, options);
    CHECK(order == "abcabcabcabc");
    CHECK(t[2].total == Approx(12));
  }
  SECTION("the cap stops rounds of work that takes no time") {
    options.min_repetitions = 1;
    options.max_repetitions = 6;
    options.min_seconds = 1;
    const auto t = time_alternately({piece('a', 0), piece('b', 0)}, options);
    CHECK(t[0].repetitions == 6);
    CHECK(order.size() == 12);
  }
  SECTION("no work and bad options") {
    CHECK_THROWS_AS(time_alternately({}, options), std::invalid_argument);
    options.min_repetitions = 0;
    CHECK_THROWS_AS(time_alternately({piece('a', 1)}, options), std::invalid_argument);
    options.min_repetitions = 3;
    options.max_repetitions = 2;
    CHECK_THROWS_AS(time_alternately({piece('a', 1)}, options), std::invalid_argument);
    options.max_repetitions = 3;
    options.min_seconds = std::nan("");
    CHECK_THROWS_AS(time_alternately({piece('a', 1)}, options), std::invalid_argument);
    CHECK(order.empty());
  }
  SECTION("an exception from a piece propagates") {
    options.min_repetitions = 3;
    int calls = 0;
    auto failing = [&] {
      if (++calls == 2) throw std::runtime_error("boom");
    };
    CHECK_THROWS_AS(time_alternately({piece('a', 1), failing}, options), std::runtime_error);
    CHECK(order == "aa");
  }
}

TEST_CASE("time_repeatedly: the real clock gives non-negative times", "[kernel][timing]") {
  RepeatOptions options;
  options.min_repetitions = 3;
  options.min_seconds = 0;
  int runs = 0;
  const TimingSummary t = time_repeatedly([&] { ++runs; }, options);
  CHECK(t.repetitions == 3);
  CHECK(runs == 3);
  CHECK(t.min >= 0);
}

TEST_CASE("peak_memory_of: the child's peak, the parent untouched, failures reported", "[kernel][timing]") {
  int touched = 0;
  const std::size_t bytes = std::size_t(64) << 20;
  const auto peak = peak_memory_of([&] {
    std::vector<char> block(bytes, 1);  // written: resident
    touched = block[bytes / 2];
  });
  REQUIRE(peak.has_value());
  CHECK(*peak >= static_cast<long>(bytes));
  CHECK(touched == 0);  // the work ran in the child
  CHECK_FALSE(peak_memory_of([] { throw std::runtime_error("fails"); }).has_value());
}
