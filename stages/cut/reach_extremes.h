#pragma once

#include <cstddef>
#include <vector>

namespace areagraph {

// Indices of a window that only slides forwards whose values are its running
// maximum (or minimum): the front is the window's extreme.
class MonotoneQueue {
 public:
  MonotoneQueue(const std::vector<double>& value, bool maximum);
  void Push(int i);
  void DropBefore(int first);  // drops indices below `first`
  bool Empty() const { return head_ == index_.size(); }
  double Front() const { return value_[index_[head_]]; }

 private:
  const std::vector<double>& value_;
  const bool maximum_;
  std::vector<int> index_;
  size_t head_ = 0;
};

// The extremes of a profile's samples within a reach of each sample, on
// either side of it (the sample itself left out), as the door search found
// them by scanning outwards from each sample until the first sample out of
// reach: before i, j = i - 1, i - 2, ... while arc[i] - arc[j] <= reach;
// after i, j = i + 1, ... while arc[j] - arc[i] <= reach. When the arc
// lengths never decrease (always, but for rounding) those runs slide along
// with i, and one pass with monotone queues gives them; else each is scanned.
struct ReachExtremes {
  // Maxima start from 0 (widths are not negative), minima from +infinity.
  std::vector<double> before_max, before_min, after_max, after_min;
  // Whether the reach passes the first (last) sample: no sample before (after)
  // i lies beyond it.
  std::vector<char> reaches_start, reaches_end;
};
ReachExtremes ExtremesWithinReach(const std::vector<double>& value, const std::vector<double>& arc,
                                  double reach);

// Prefix and suffix maxima of a profile, for the widest sample within a reach
// of either end, found by binary search where the arc lengths never decrease.
struct EndMaxima {
  std::vector<double> from_start;  // max of value[0..i]
  std::vector<double> from_end;    // max of value[i..n-1]
  bool monotone = true;            // arc never decreases
};
EndMaxima MaximaFromEnds(const std::vector<double>& value, const std::vector<double>& arc);
// max(`widest`, every value[i] for i = 0, 1, ... while arc[i] <= reach).
double WidestFromStart(const EndMaxima& maxima, const std::vector<double>& value,
                       const std::vector<double>& arc, double reach, double widest);
// max(`widest`, every value[i] for i = n - 1, n - 2, ... while
// arc.back() - arc[i] <= reach).
double WidestFromEnd(const EndMaxima& maxima, const std::vector<double>& value,
                     const std::vector<double>& arc, double reach, double widest);

// Runs of steady values: from a start i, the end (exclusive) of the run
// value[i..j) that grows while the spread max - min of the samples taken
// stays within `spread`(min), as FindCorridors grows it one sample at a time.
// `spread` must not decrease as min grows. Starts must not decrease between
// calls: a run from a later start holds at least the samples of one from an
// earlier start (less spread, more tolerance), so the end only moves on.
class SteadyRuns {
 public:
  SteadyRuns(const std::vector<double>& value, double (*spread)(double min));
  int EndFrom(int start);

 private:
  const std::vector<double>& value_;
  double (*const spread_)(double);
  MonotoneQueue max_, min_;
  int end_ = 0;
};

// Whether `arc` never decreases.
bool NonDecreasing(const std::vector<double>& arc);

}  // namespace areagraph
