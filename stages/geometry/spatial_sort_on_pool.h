#pragma once

// CGAL's 2D spatial sort with its independent parts on OpenCV's pool.
// Heavy templates: include only from the .cc files that triangulate.

#include <CGAL/Hilbert_sort_median_2.h>
#include <CGAL/Multiscale_sort.h>
#include <CGAL/algorithm.h>
#include <CGAL/spatial_sort.h>

#include <boost/random/linear_congruential.hpp>
#include <boost/random/random_number_generator.hpp>
#include <cstddef>
#include <iterator>

#include "stages/geometry/parallel_ranges.h"
#include "stages/geometry/pool_tasks.h"

namespace areagraph {

// Below this many points the sort stays in the caller's thread (a pool call
// costs more than it saves on a few thousand points).
inline constexpr std::ptrdiff_t kSpatialSortOnPoolMin = 8192;

// The order CGAL::spatial_sort(begin, end, traits) gives (Hilbert median
// policy, CGAL's default thresholds 4 and 16 and ratio 0.25, CGAL 5.5's
// steps: a seeded shuffle, then Multiscale_sort, which Hilbert-sorts the
// last three quarters and recurses on the first), with the insertion that
// follows it started early: insert(first, last) is called for [begin, end)
// in order, in consecutive pieces, on the calling thread. The first quarter
// comes first and is sorted on its own, so it is sorted and inserted on the
// calling thread while a pool thread Hilbert-sorts the other three quarters:
// every part is sorted exactly as in the serial sort, so what is inserted,
// and in which order, is what insert(begin, end) after CGAL::spatial_sort
// would insert (the triangulation's faces and their container order stay).
// The insertion itself stays serial.
template <class Traits, class Iterator, class Insert>
void SpatialSortThenInsert(Iterator begin, Iterator end, const Traits& traits,
                           const Insert& insert) {
  using Diff = typename std::iterator_traits<Iterator>::difference_type;
  const Diff count = end - begin;
  if (count < kSpatialSortOnPoolMin || cv::getNumThreads() <= 1) {
    CGAL::spatial_sort(begin, end, traits);
    insert(begin, end);
    return;
  }
  using Sort = CGAL::Hilbert_sort_median_2<Traits, CGAL::Sequential_tag>;
  boost::rand48 random;
  boost::random_number_generator<boost::rand48, Diff> rng(random);
  CGAL::cpp98::random_shuffle(begin, end, rng);
  const Sort sort(traits, 4);
  const CGAL::Multiscale_sort<Sort> multiscale(sort, 16, 0.25);
  const Iterator middle = begin + Diff(double(count) * 0.25);
  RunTasks({[&] {
              multiscale(begin, middle);
              insert(begin, middle);
            },
            [&] { sort(middle, end); }},
           /*on_caller=*/1);
  insert(middle, end);
}

}  // namespace areagraph
