/* A pool of large, page-aligned blocks for the arrays the Python layer returns (rgbz_fast._memory).

   A call that writes a few hundred MB of results into fresh memory pays the kernel for every
   page (a fault and a zeroed page: about 10 % of the guided ToF ISP's call on a 12 MP frame,
   docs/reports/benchmarks.md); glibc gives blocks that large back to the system when they
   are freed, so a loop of calls pays it every time. The pool keeps the blocks of arrays that
   were freed, up to a limit, and hands them to the next request of the same size, their
   pages still mapped. A kept block is marked MADV_FREE (Linux): the system may take its
   pages back under memory pressure (they then read as zeros and fault again), so the pool
   never holds memory the system needs.

   Every function is thread-safe (one mutex). Blocks are 2 MiB aligned and a multiple of
   2 MiB (transparent huge pages, MADV_HUGEPAGE). Plain C, no Python.h. */
#ifndef RGBZ_POOL_H
#define RGBZ_POOL_H

#include <stddef.h>

#define RGBZ_POOL_ALIGN ((size_t)2 << 20)

/* the size of the block a request of n bytes takes (n rounded up to RGBZ_POOL_ALIGN) */
size_t rgbz_pool_size(size_t n);
/* a block of rgbz_pool_size(n) bytes, a kept one of that size when there is one; NULL when
   the system has no memory. Its contents are undefined (zeros, or a freed array's). */
void *rgbz_pool_take(size_t n);
/* give back a block of rgbz_pool_take (size: rgbz_pool_size of its request): kept when the
   limit allows (the least recently kept ones unmapped to make room), else unmapped */
void rgbz_pool_give(void *block, size_t size);
/* set the limit of the bytes kept (the kept blocks beyond it unmapped now); returns the
   previous limit. rgbz_pool_get_limit reads it. */
size_t rgbz_pool_set_limit(size_t limit);
size_t rgbz_pool_get_limit(void);
/* kept blocks and bytes; blocks handed out from the kept ones and newly mapped, since the
   process started */
void rgbz_pool_stats(size_t *kept_blocks, size_t *kept_bytes, size_t *reused, size_t *mapped);

#endif
