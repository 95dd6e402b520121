#pragma once

#include <numeric>
#include <vector>

namespace areagraph {

// Union-find over 0..n-1 with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }

  int Find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  // Returns false when a and b were already in one set.
  bool Union(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }

  // A label 0..count-1 per element, numbered in order of first appearance.
  std::vector<int> DenseLabels(int* count) {
    std::vector<int> label_of_root(parent_.size(), -1);
    std::vector<int> labels(parent_.size());
    int next = 0;
    for (size_t i = 0; i < parent_.size(); ++i) {
      int& label = label_of_root[Find(int(i))];
      if (label < 0) label = next++;
      labels[i] = label;
    }
    if (count != nullptr) *count = next;
    return labels;
  }

 private:
  std::vector<int> parent_;
  std::vector<int> size_;
};

}  // namespace areagraph
