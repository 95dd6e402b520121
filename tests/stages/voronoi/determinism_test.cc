// Results must not depend on where the heap puts things: CGAL's edge
// iterator picks the side of each edge by comparing face addresses, so the
// code walks faces in order instead. Each check runs once with the usual
// allocator and once with one that hands out memory downwards, which
// reverses how the addresses of the triangulation's blocks compare.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <new>
#include <random>
#include <set>
#include <string>

#include "stages/geometry/alpha_shape.h"
#include "stages/voronoi/voronoi_builder.h"

namespace {

// While `top` is set, operator new takes memory from [bottom, top)
// downwards and operator delete leaves it there.
char* arena_bottom = nullptr;
char* arena_top = nullptr;
char* arena_end = nullptr;

void* Allocate(std::size_t size) {
  if (arena_top != nullptr) {
    const std::size_t rounded = (size + 15) / 16 * 16;
    if (arena_top - arena_bottom < std::ptrdiff_t(rounded)) throw std::bad_alloc();
    arena_top -= rounded;
    return arena_top;
  }
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}

void Release(void* memory) {
  const char* bytes = static_cast<char*>(memory);
  if (bytes >= arena_bottom && bytes < arena_end) return;
  std::free(memory);
}

}  // namespace

void* operator new(std::size_t size) { return Allocate(size); }
void* operator new[](std::size_t size) { return Allocate(size); }
void operator delete(void* memory) noexcept { Release(memory); }
void operator delete[](void* memory) noexcept { Release(memory); }
void operator delete(void* memory, std::size_t) noexcept { Release(memory); }
void operator delete[](void* memory, std::size_t) noexcept { Release(memory); }

namespace areagraph {
namespace {

std::vector<Eigen::Vector2d> GridSites(unsigned seed, int count, int span) {
  std::mt19937 random(seed);
  std::set<std::pair<int, int>> cells;
  while (int(cells.size()) < count) cells.insert({int(random() % span), int(random() % span)});
  std::vector<Eigen::Vector2d> sites;
  for (const auto& [col, row] : cells) sites.emplace_back(col + 0.5, row + 0.5);
  return sites;
}

// `compute` with the usual allocator, then with the downward one.
std::pair<std::string, std::string> TwoHeapLayouts(const std::function<std::string()>& compute) {
  const std::string usual = compute();
  const std::size_t size = std::size_t(256) << 20;
  arena_bottom = static_cast<char*>(std::malloc(size));
  arena_end = arena_top = arena_bottom + size;
  std::string downward;
  try {
    downward = compute();
  } catch (...) {
    arena_top = nullptr;
    throw;
  }
  arena_top = nullptr;
  return {usual, downward};
}

TEST(Determinism, VoronoiDiagramDoesNotDependOnTheHeap) {
  const auto sites = GridSites(5, 15000, 250);
  const auto [usual, downward] =
      TwoHeapLayouts([&] { return BuildVoronoiDiagram(sites).SerializeAsString(); });
  EXPECT_GT(usual.size(), 100000u);
  EXPECT_TRUE(usual == downward);
}

TEST(Determinism, AlphaComplexDoesNotDependOnTheHeap) {
  const auto points = GridSites(6, 15000, 250);
  const auto [usual, downward] = TwoHeapLayouts([&] {
    std::string edges;
    for (const AlphaShapeEdge& edge : ComputeAlphaComplex(points, 2.5).boundary_edges) {
      edges += std::to_string(edge.a) + "," + std::to_string(edge.b) + (edge.singular ? "s " : " ");
    }
    return edges;
  });
  EXPECT_GT(usual.size(), 1000u);
  EXPECT_TRUE(usual == downward);
}

}  // namespace
}  // namespace areagraph
