#include "stages/cut/reach_extremes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

namespace areagraph {
namespace {

// Widths and arc lengths as the door search samples them: widths on a coarse
// grid (many ties), arc steps of 0 to 1.5 (repeated arcs), and now and then an
// arc one ulp below the last (rounding), which leaves the sliding pass.
struct Profile {
  std::vector<double> value, arc;
};

Profile RandomProfile(std::mt19937& random, int n, bool with_dips) {
  Profile p;
  std::uniform_int_distribution<int> width(0, 12), step(0, 6), dip(0, 40);
  double arc = 0;
  for (int i = 0; i < n; ++i) {
    p.value.push_back(0.05 * width(random));
    if (i > 0) arc += 0.25 * step(random);
    if (with_dips && i > 0 && dip(random) == 0) arc = std::nextafter(arc, -1.0);
    p.arc.push_back(arc);
  }
  return p;
}

TEST(ReachExtremesTest, EqualsScanningOutwardsFromEachSample) {
  std::mt19937 random(14);
  for (int round = 0; round < 2000; ++round) {
    const Profile p = RandomProfile(random, 1 + random() % 40, round % 3 == 0);
    const double reach = 0.25 * (random() % 12);
    const ReachExtremes got = ExtremesWithinReach(p.value, p.arc, reach);
    const int n = static_cast<int>(p.value.size());
    for (int i = 0; i < n; ++i) {
      double before_max = 0, after_max = 0;
      double before_min = std::numeric_limits<double>::infinity(), after_min = before_min;
      int j = i - 1;
      for (; j >= 0 && p.arc[i] - p.arc[j] <= reach; --j) {
        before_max = std::max(before_max, p.value[j]);
        before_min = std::min(before_min, p.value[j]);
      }
      EXPECT_EQ(got.reaches_start[i] != 0, j < 0) << round << " " << i;
      for (j = i + 1; j < n && p.arc[j] - p.arc[i] <= reach; ++j) {
        after_max = std::max(after_max, p.value[j]);
        after_min = std::min(after_min, p.value[j]);
      }
      EXPECT_EQ(got.reaches_end[i] != 0, j >= n) << round << " " << i;
      EXPECT_EQ(got.before_max[i], before_max) << round << " " << i;
      EXPECT_EQ(got.before_min[i], before_min) << round << " " << i;
      EXPECT_EQ(got.after_max[i], after_max) << round << " " << i;
      EXPECT_EQ(got.after_min[i], after_min) << round << " " << i;
    }
  }
}

TEST(ReachExtremesTest, WidestFromEitherEndEqualsScanningFromIt) {
  std::mt19937 random(15);
  for (int round = 0; round < 2000; ++round) {
    const Profile p = RandomProfile(random, 1 + random() % 30, round % 3 == 0);
    const EndMaxima maxima = MaximaFromEnds(p.value, p.arc);
    EXPECT_EQ(maxima.monotone, std::is_sorted(p.arc.begin(), p.arc.end()));
    for (const double reach : {-0.5, 0.0, 0.25, 1.0, 2.5, 100.0}) {
      for (const double widest : {0.0, 0.3}) {
        double from_start = widest, from_end = widest;
        for (size_t i = 0; i < p.value.size() && p.arc[i] <= reach; ++i) {
          from_start = std::max(from_start, p.value[i]);
        }
        for (size_t i = p.value.size(); i-- > 0 && p.arc.back() - p.arc[i] <= reach;) {
          from_end = std::max(from_end, p.value[i]);
        }
        EXPECT_EQ(WidestFromStart(maxima, p.value, p.arc, reach, widest), from_start) << round;
        EXPECT_EQ(WidestFromEnd(maxima, p.value, p.arc, reach, widest), from_end) << round;
      }
    }
  }
}

// FindCorridors' run, grown one sample at a time from each start.
size_t GrownEnd(const std::vector<double>& value, size_t i, double tolerance, double ratio) {
  double low = value[i], high = value[i];
  size_t j = i + 1;
  for (; j < value.size(); ++j) {
    const double new_low = std::min(low, value[j]), new_high = std::max(high, value[j]);
    if (new_high - new_low > std::max(tolerance, ratio * new_low)) break;
    low = new_low, high = new_high;
  }
  return j;
}

TEST(SteadyRunsTest, EndsWhereGrowingEachRunEnds) {
  std::mt19937 random(16);
  for (int round = 0; round < 2000; ++round) {
    const Profile p = RandomProfile(random, 1 + random() % 60, false);
    SteadyRuns runs(p.value, [](double low) { return std::max(0.1, 0.1 * low); });
    // Starts as FindCorridors takes them: one on, or a jump to a run's end.
    for (size_t i = 0; i < p.value.size();) {
      const size_t end = runs.EndFrom(static_cast<int>(i));
      ASSERT_EQ(end, GrownEnd(p.value, i, 0.1, 0.1)) << round << " " << i;
      i = random() % 2 == 0 ? i + 1 : end;
    }
  }
}

}  // namespace
}  // namespace areagraph
