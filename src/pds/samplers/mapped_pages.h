#pragma once
// Large arrays in 2 MiB huge pages where the system offers them (Linux's
// transparent huge pages, MADV_HUGEPAGE): one page fault per 2 MiB instead of
// one per 4 KiB (about 16 us each on the sandbox VM) and far fewer TLB misses.
// map_zeroed() maps zeroed arrays straight from the system's pages: the
// background grids of bridson.cpp, flat_levels.h, maximal_darts.cpp and
// dunbar_humphreys/cell_grid.h, read at random all over the front; mapped
// without huge pages such an array costs nothing until a page is first
// touched. vector_in_huge_pages() and advise_huge_pages() advise std::vector
// storage instead (ebeida's grid and slots, elimination's arrays, the plain
// patterns' outputs). Where mmap is missing arrays come zeroed from calloc and
// the advice is a no-op: the same bytes, only without those savings.
//
// Advice given to a vector's heap block outlives the vector: glibc may later
// hand that memory to small allocations, which then sit in huge pages too (a
// larger resident size in a long-lived host process, never other results).
#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#define PDS_MAPPED_PAGES 1
#else
#define PDS_MAPPED_PAGES 0
#endif

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "pds/point.h"

namespace pds::detail {

struct UnmapPages {
  std::size_t bytes = 0;
  void operator()(void* p) const {
#if PDS_MAPPED_PAGES
    if (p) munmap(p, bytes);
#else
    std::free(p);
#endif
  }
};

template <class T>
using MappedArray = std::unique_ptr<T[], UnmapPages>;

enum class Pages {
  kLazy,      // each page given (zeroed) when first touched
  kHuge,      // huge pages where offered: the array is about to be touched all over
  kPopulate,  // every page given at once (small arrays read everywhere)
};

/// `count` zeroed values of trivial type T (zero bytes must be a valid T).
template <class T>
MappedArray<T> map_zeroed(std::size_t count, Pages pages) {
  if (count > SIZE_MAX / sizeof(T)) throw std::bad_alloc();
  const std::size_t bytes = count * sizeof(T);
  if (bytes == 0) return MappedArray<T>(nullptr, UnmapPages{0});
#if PDS_MAPPED_PAGES
  int flags = MAP_PRIVATE | MAP_ANONYMOUS;
#ifdef MAP_POPULATE
  if (pages == Pages::kPopulate) flags |= MAP_POPULATE;
#endif
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, flags, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  if (pages == Pages::kHuge) madvise(p, bytes, MADV_HUGEPAGE);
#endif
#else
  (void)pages;
  void* p = std::calloc(count, sizeof(T));
  if (!p) throw std::bad_alloc();
#endif
  return MappedArray<T>(static_cast<T*>(p), UnmapPages{bytes});
}

/// advise_huge_pages() (pds/point.h) for a vector's reserved block.
template <class Vector>
void advise_huge_pages(Vector& v) noexcept {
  advise_huge_pages(v.data(), v.capacity() * sizeof(typename Vector::value_type));
}

/// `count` copies of `value` in huge pages where offered, for the large
/// arrays that a sampler writes through at once: at 10^6 in 2D their 4 KiB
/// page faults were about half the run of the plain patterns (random, the
/// sequences, the grids) and 7% of elimination's.
template <class T>
std::vector<T> vector_in_huge_pages(std::size_t count, const T& value = T{}) {
  std::vector<T> v;
  v.reserve(count);
  advise_huge_pages(v);
  v.assign(count, value);
  return v;
}

/// `count` points (zeros), as above: the outputs filled in one pass.
template <int D>
PointSet<D> output_points(std::size_t count) {
  return vector_in_huge_pages<Point<D>>(count);
}

}  // namespace pds::detail
