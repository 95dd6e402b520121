#include "stages/cut/reach_extremes.h"

#include <algorithm>
#include <limits>

namespace areagraph {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void ScanEachSample(const std::vector<double>& value, const std::vector<double>& arc, double reach,
                    ReachExtremes* out) {
  const int n = static_cast<int>(value.size());
  for (int i = 0; i < n; ++i) {
    int j = i - 1;
    for (; j >= 0 && arc[i] - arc[j] <= reach; --j) {
      out->before_max[i] = std::max(out->before_max[i], value[j]);
      out->before_min[i] = std::min(out->before_min[i], value[j]);
    }
    out->reaches_start[i] = j < 0;
    for (j = i + 1; j < n && arc[j] - arc[i] <= reach; ++j) {
      out->after_max[i] = std::max(out->after_max[i], value[j]);
      out->after_min[i] = std::min(out->after_min[i], value[j]);
    }
    out->reaches_end[i] = j >= n;
  }
}

}  // namespace

MonotoneQueue::MonotoneQueue(const std::vector<double>& value, bool maximum)
    : value_(value), maximum_(maximum) {}

void MonotoneQueue::Push(int i) {
  // A value no better than the new one can never be the extreme again.
  while (index_.size() > head_ &&
         (maximum_ ? value_[index_.back()] <= value_[i] : value_[index_.back()] >= value_[i])) {
    index_.pop_back();
  }
  index_.push_back(i);
}

void MonotoneQueue::DropBefore(int first) {
  while (head_ < index_.size() && index_[head_] < first) ++head_;
}

bool NonDecreasing(const std::vector<double>& arc) {
  return std::is_sorted(arc.begin(), arc.end());
}

ReachExtremes ExtremesWithinReach(const std::vector<double>& value, const std::vector<double>& arc,
                                  double reach) {
  const int n = static_cast<int>(value.size());
  ReachExtremes out;
  out.before_max.assign(n, 0.0);
  out.after_max.assign(n, 0.0);
  out.before_min.assign(n, kInfinity);
  out.after_min.assign(n, kInfinity);
  out.reaches_start.assign(n, 0);
  out.reaches_end.assign(n, 0);
  if (!NonDecreasing(arc)) {
    ScanEachSample(value, arc, reach, &out);
    return out;
  }
  // With arc sorted, the samples in reach before i are [first, i - 1] and
  // those after it [i + 1, last], and neither bound moves back as i grows.
  MonotoneQueue before_max(value, true), before_min(value, false);
  MonotoneQueue after_max(value, true), after_min(value, false);
  int first = 0, last = 0;
  for (int i = 0; i < n; ++i) {
    if (i > 0) before_max.Push(i - 1), before_min.Push(i - 1);
    while (first < i && !(arc[i] - arc[first] <= reach)) ++first;
    before_max.DropBefore(first), before_min.DropBefore(first);
    if (!before_max.Empty()) {
      out.before_max[i] = std::max(0.0, before_max.Front());
      out.before_min[i] = before_min.Front();
    }
    out.reaches_start[i] = first == 0;

    last = std::max(last, i);
    after_max.DropBefore(i + 1), after_min.DropBefore(i + 1);
    while (last + 1 < n && arc[last + 1] - arc[i] <= reach) {
      ++last;
      after_max.Push(last), after_min.Push(last);
    }
    if (!after_max.Empty()) {
      out.after_max[i] = std::max(0.0, after_max.Front());
      out.after_min[i] = after_min.Front();
    }
    out.reaches_end[i] = last == n - 1;
  }
  return out;
}

EndMaxima MaximaFromEnds(const std::vector<double>& value, const std::vector<double>& arc) {
  EndMaxima maxima;
  maxima.monotone = NonDecreasing(arc);
  const size_t n = value.size();
  maxima.from_start.resize(n);
  maxima.from_end.resize(n);
  for (size_t i = 0; i < n; ++i) {
    maxima.from_start[i] = i == 0 ? value[i] : std::max(maxima.from_start[i - 1], value[i]);
  }
  for (size_t i = n; i-- > 0;) {
    maxima.from_end[i] = i + 1 == n ? value[i] : std::max(maxima.from_end[i + 1], value[i]);
  }
  return maxima;
}

double WidestFromStart(const EndMaxima& maxima, const std::vector<double>& value,
                       const std::vector<double>& arc, double reach, double widest) {
  if (!maxima.monotone) {
    for (size_t i = 0; i < value.size() && arc[i] <= reach; ++i)
      widest = std::max(widest, value[i]);
    return widest;
  }
  const size_t count =
      std::partition_point(arc.begin(), arc.end(), [&](double a) { return a <= reach; }) -
      arc.begin();
  return count == 0 ? widest : std::max(widest, maxima.from_start[count - 1]);
}

double WidestFromEnd(const EndMaxima& maxima, const std::vector<double>& value,
                     const std::vector<double>& arc, double reach, double widest) {
  const double end = arc.empty() ? 0 : arc.back();
  if (!maxima.monotone) {
    for (size_t i = value.size(); i-- > 0 && end - arc[i] <= reach;) {
      widest = std::max(widest, value[i]);
    }
    return widest;
  }
  const size_t first =
      std::partition_point(arc.begin(), arc.end(), [&](double a) { return !(end - a <= reach); }) -
      arc.begin();
  return first == value.size() ? widest : std::max(widest, maxima.from_end[first]);
}

SteadyRuns::SteadyRuns(const std::vector<double>& value, double (*spread)(double min))
    : value_(value), spread_(spread), max_(value, true), min_(value, false) {}

int SteadyRuns::EndFrom(int start) {
  max_.DropBefore(start), min_.DropBefore(start);
  if (end_ <= start) {
    end_ = start + 1;
    max_.Push(start), min_.Push(start);
  }
  const int n = static_cast<int>(value_.size());
  for (; end_ < n; ++end_) {
    const double low = std::min(min_.Front(), value_[end_]);
    const double high = std::max(max_.Front(), value_[end_]);
    if (high - low > spread_(low)) break;
    max_.Push(end_), min_.Push(end_);
  }
  return end_;
}

}  // namespace areagraph
