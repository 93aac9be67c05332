// Large build arrays ask Linux for 2 MiB pages (madvise MADV_HUGEPAGE, as Embree's allocator
// does): with transparent huge pages in "madvise" mode a 100 MB array otherwise costs one
// page fault per 4 KiB while it is filled, and one TLB entry per 4 KiB while it is walked.
// Only where and how fast memory is mapped changes; the contents do not.
#pragma once
#include <cstddef>
#include <vector>

namespace tracer {

// Advises the 2 MiB-aligned pages inside [p, p + bytes); a no-op where unsupported.
void advise_huge_pages(void* p, size_t bytes);

// v.reserve(n), with the reserved storage advised before anything touches it.
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace tracer
