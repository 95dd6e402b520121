#pragma once

#include <cstddef>
#include <vector>

namespace areagraph {

// A min-heap of vertices by (cost, vertex) that can change or drop an entry.
// Entries hold their cost (no lookup per comparison) and move into a hole
// instead of being swapped; the minimum, and so every pop, is the same as
// with any heap: (cost, vertex) orders the vertices strictly.
class CostHeap {
 public:
  explicit CostHeap(size_t vertex_count) : slot_(vertex_count, -1), cost_(vertex_count, 0) {}

  bool empty() const { return heap_.empty(); }
  bool contains(int v) const { return slot_[v] >= 0; }
  int top() const { return heap_.front().vertex; }
  double cost(int v) const { return cost_[v]; }

  // Inserts `v` or moves it to its new cost.
  void Set(int v, double cost) {
    cost_[v] = cost;
    if (slot_[v] < 0) {
      slot_[v] = static_cast<int>(heap_.size());
      heap_.push_back({cost, v});
    }
    const int at = slot_[v];
    heap_[at].cost = cost;
    if (!Up(at)) Down(at);
  }

  void Erase(int v) {
    const int at = slot_[v];
    if (at < 0) return;
    const Entry last = heap_.back();
    heap_.pop_back();
    slot_[v] = -1;
    if (last.vertex == v) return;
    heap_[at] = last;
    slot_[last.vertex] = at;
    if (!Up(at)) Down(at);
  }

  void Pop() { Erase(heap_.front().vertex); }

 private:
  struct Entry {
    double cost;
    int vertex;
  };
  static bool Less(const Entry& a, const Entry& b) {
    return a.cost < b.cost || (a.cost == b.cost && a.vertex < b.vertex);
  }
  void Place(int at, const Entry& entry) {
    heap_[at] = entry;
    slot_[entry.vertex] = at;
  }
  // Moves the entry at `at` up to its place; whether it moved.
  bool Up(int at) {
    const Entry entry = heap_[at];
    const int from = at;
    while (at > 0) {
      const int parent = (at - 1) / 2;
      if (!Less(entry, heap_[parent])) break;
      Place(at, heap_[parent]);
      at = parent;
    }
    if (at == from) return false;
    Place(at, entry);
    return true;
  }
  void Down(int at) {
    const Entry entry = heap_[at];
    const int n = static_cast<int>(heap_.size());
    for (;;) {
      const int left = 2 * at + 1, right = left + 1;
      if (left >= n) break;
      const int child = right < n && Less(heap_[right], heap_[left]) ? right : left;
      if (!Less(heap_[child], entry)) break;
      Place(at, heap_[child]);
      at = child;
    }
    Place(at, entry);
  }

  std::vector<Entry> heap_;
  std::vector<int> slot_;
  std::vector<double> cost_;
};

}  // namespace areagraph
