#include "mapped_pages.h"

#include <cstdint>

#if PDS_MAPPED_PAGES
#include <unistd.h>
#endif

#include "pds/point.h"

namespace pds::detail {

void advise_huge_pages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes) noexcept {
#if PDS_MAPPED_PAGES && defined(MADV_HUGEPAGE)
  // Below a huge page there is nothing to gain; madvise wants whole pages
  // of the system's size (16 or 64 KiB on some machines).
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < kHuge) return;
  static const long page = sysconf(_SC_PAGESIZE);
  if (page <= 0) return;
  const auto kPage = static_cast<std::uintptr_t>(page);
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kPage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

void release_pages([[maybe_unused]] void* p, [[maybe_unused]] std::size_t bytes) noexcept {
#if PDS_MAPPED_PAGES && defined(MADV_DONTNEED)
  // Only pages wholly inside the range: the allocator's bookkeeping around a
  // block must stay. The system's page size, not 4 KiB: madvise rounds the
  // length up to whole pages, which past the range would drop live data on
  // a machine with 16 or 64 KiB pages. Anonymous private pages read as zeros
  // once released.
  static const long page = sysconf(_SC_PAGESIZE);
  if (page <= 0) return;
  const auto kPage = static_cast<std::uintptr_t>(page);
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kPage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
#endif
}

}  // namespace pds::detail
