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

namespace areagraph {

// Below this many points the sort stays in the caller's thread (three pool
// calls cost more than they save on a few thousand points).
inline constexpr std::ptrdiff_t kSpatialSortOnPoolMin = 8192;

// The order CGAL::spatial_sort(begin, end, traits) gives (Hilbert median
// policy, CGAL's default thresholds 4 and 16 and ratio 0.25, CGAL 5.5's
// steps): a seeded shuffle, then Multiscale_sort, which Hilbert-sorts the
// last three quarters and recurses on the first. Those two parts are
// disjoint, and so are the four quadrants of the Hilbert sort once its
// first three median splits are made, so they run as separate tasks: every
// nth_element and sort sees the same range in the same state as in the
// serial sort, so the order is the same element for element, whatever
// thread runs what. The triangulation's insertion order, and with it its
// faces and their container order, stay as they were.
template <class Traits, class Iterator>
void SpatialSortOnPool(Iterator begin, Iterator end, const Traits& traits) {
  using Diff = typename std::iterator_traits<Iterator>::difference_type;
  using Sort = CGAL::Hilbert_sort_median_2<Traits, CGAL::Sequential_tag>;
  const Diff count = end - begin;
  if (count < kSpatialSortOnPoolMin || cv::getNumThreads() <= 1) {
    CGAL::spatial_sort(begin, end, traits);
    return;
  }
  boost::rand48 random;
  boost::random_number_generator<boost::rand48, Diff> rng(random);
  CGAL::cpp98::random_shuffle(begin, end, rng);
  const Sort sort(traits, 4);
  const CGAL::Multiscale_sort<Sort> multiscale(sort, 16, 0.25);
  // Multiscale_sort's split, then Hilbert_sort_median_2's
  // recursive_sort<0, false, false> on [m0, m4) unrolled one level.
  const Iterator m0 = begin + Diff(double(count) * 0.25), m4 = end;
  Iterator m1, m2, m3;
  using CGAL::internal::Hilbert_cmp_2;
  using CGAL::internal::hilbert_split;
  ForEachRange(2, 2, [&](size_t, size_t, int task) {
    if (task == 0) {
      m2 = hilbert_split(m0, m4, Hilbert_cmp_2<Traits, 0, false>(traits));
    } else {
      multiscale(begin, m0);
    }
  });
  ForEachRange(2, 2, [&](size_t, size_t, int task) {
    if (task == 0) {
      m1 = hilbert_split(m0, m2, Hilbert_cmp_2<Traits, 1, false>(traits));
    } else {
      m3 = hilbert_split(m2, m4, Hilbert_cmp_2<Traits, 1, true>(traits));
    }
  });
  ForEachRange(4, 4, [&](size_t, size_t, int task) {
    switch (task) {
      case 0:
        sort.template recursive_sort<1, false, false>(m0, m1);
        break;
      case 1:
        sort.template recursive_sort<0, false, false>(m1, m2);
        break;
      case 2:
        sort.template recursive_sort<0, false, false>(m2, m3);
        break;
      default:
        sort.template recursive_sort<1, true, true>(m3, m4);
        break;
    }
  });
}

}  // namespace areagraph
