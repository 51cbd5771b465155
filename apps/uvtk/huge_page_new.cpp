// The program's operator new: glibc's malloc, each block of 2 MiB or more advised as transparent
// huge pages before it is first touched, where the kernel grants them on request (Debian's
// "madvise" mode; core/huge_pages.h advises single buffers the same way).
//
// Why the whole program: on a paravirtualised guest a 4 KiB page fault costs about 14 us, and
// `uvtk map` of a 4 M-triangle OBJ touches about a gigabyte of fresh memory (the reader's chunks
// grown by push_back, the mesh, the corners, the judgement's faces, the writer's arrays), 126 k
// faults and 2.8 to 12 s in all. glibc gives the same advice to the memory it maps only under the
// tunable GLIBC_TUNABLES=glibc.malloc.hugetlb=1, read at start-up; starting uvtk again under it
// cost 15 ms of start-up on every command (a second exec and dynamic link), advice here costs one
// madvise per large block. Advising each site instead would miss vectors grown by push_back and
// every site added later.
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePage = std::size_t(1) << 21;

}  // namespace

void* operator new(std::size_t bytes) {
  for (;;) {
    if (void* block = std::malloc(bytes == 0 ? 1 : bytes)) {
      if (bytes >= kHugePage) {
        // From the block's first page: glibc maps a large block with its header on that page, so
        // the advice covers the whole mapping and every 2 MiB-aligned stretch inside it.
        const std::uintptr_t page = std::uintptr_t(::sysconf(_SC_PAGESIZE));
        const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(block) & ~(page - 1);
        ::madvise(reinterpret_cast<void*>(start), reinterpret_cast<std::uintptr_t>(block) + bytes - start, MADV_HUGEPAGE);
      }
      return block;
    }
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

// The matching deletes, so that every tool watching malloc and free (valgrind, heaptrack) sees pairs.
void operator delete(void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
