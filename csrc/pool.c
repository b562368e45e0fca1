/* The pool of large blocks: pool.h. */
#if !defined(_WIN32) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE        /* MAP_ANONYMOUS, MADV_* under -std=c99 */
#endif
#include "pool.h"

#include <stdint.h>
#include <stdlib.h>

#ifdef _WIN32
#include <malloc.h>
#include <windows.h>
static CRITICAL_SECTION pool_lock;
static INIT_ONCE pool_once = INIT_ONCE_STATIC_INIT;
static BOOL CALLBACK pool_init(PINIT_ONCE o, PVOID p, PVOID *c)
{
    (void)o; (void)p; (void)c;
    InitializeCriticalSection(&pool_lock);
    return TRUE;
}
static void lock(void) { InitOnceExecuteOnce(&pool_once, pool_init, NULL, NULL); EnterCriticalSection(&pool_lock); }
static void unlock(void) { LeaveCriticalSection(&pool_lock); }
static void *map_block(size_t n) { return _aligned_malloc(n, RGBZ_POOL_ALIGN); }
static void unmap_block(void *p, size_t n) { (void)n; _aligned_free(p); }
static void lazy_free(void *p, size_t n) { (void)p; (void)n; }
#else
#include <pthread.h>
#include <sys/mman.h>
static pthread_mutex_t pool_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_once_t pool_once = PTHREAD_ONCE_INIT;
static void hold(void) { pthread_mutex_lock(&pool_lock); }
static void release(void) { pthread_mutex_unlock(&pool_lock); }
/* a fork while another thread holds the lock would leave the child's copy locked for ever:
   the lock is taken around every fork (the kept blocks are the child's too, copy on write) */
static void pool_init(void) { pthread_atfork(hold, release, release); }
static void lock(void) { pthread_once(&pool_once, pool_init); hold(); }
static void unlock(void) { release(); }
#ifndef MAP_ANONYMOUS
#define MAP_ANONYMOUS MAP_ANON
#endif

static void *map_block(size_t n)
{
    /* n + one alignment, then the ends cut off: a 2 MiB aligned block of n bytes */
    size_t span = n + RGBZ_POOL_ALIGN;
    char *p = mmap(NULL, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
        return NULL;
    uintptr_t a = ((uintptr_t)p + RGBZ_POOL_ALIGN - 1) & ~(uintptr_t)(RGBZ_POOL_ALIGN - 1);
    size_t head = (size_t)(a - (uintptr_t)p), tail = span - head - n;
    if (head)
        munmap(p, head);
    if (tail)
        munmap((char *)a + n, tail);
#ifdef MADV_HUGEPAGE
    madvise((void *)a, n, MADV_HUGEPAGE);
#endif
    return (void *)a;
}

static void unmap_block(void *p, size_t n) { munmap(p, n); }

/* a kept block's pages: the system's to take back under pressure (they read as zeros then) */
static void lazy_free(void *p, size_t n)
{
#ifdef MADV_FREE
    madvise(p, n, MADV_FREE);
#else
    (void)p; (void)n;
#endif
}
#endif

#define SLOTS 64

static struct {
    void *p;
    size_t n;
    unsigned long long stamp;   /* when it was kept: the oldest goes first */
} slot[SLOTS];
static size_t nslot, kept_bytes, n_reused, n_mapped;
static unsigned long long clock_;
static size_t limit = (size_t)1 << 30;

size_t rgbz_pool_size(size_t n)
{
    if (n == 0)
        n = 1;
    if (n > SIZE_MAX - RGBZ_POOL_ALIGN)
        return 0;
    return (n + RGBZ_POOL_ALIGN - 1) & ~(RGBZ_POOL_ALIGN - 1);
}

void *rgbz_pool_take(size_t n)
{
    size_t size = rgbz_pool_size(n);
    if (size == 0)
        return NULL;
    void *p = NULL;
    lock();
    size_t best = SLOTS;
    for (size_t i = 0; i < nslot; ++i)      /* the most recently kept block of this size */
        if (slot[i].n == size && (best == SLOTS || slot[i].stamp > slot[best].stamp))
            best = i;
    if (best != SLOTS) {
        p = slot[best].p;
        kept_bytes -= size;
        slot[best] = slot[--nslot];
        ++n_reused;
    }
    unlock();
    if (p == NULL) {
        p = map_block(size);
        if (p != NULL) {
            lock();
            ++n_mapped;
            unlock();
        }
    }
    return p;
}

/* remove the oldest kept blocks until `room` more bytes and one more slot fit the limit;
   the removed blocks go to out[] (at most SLOTS), unmapped by the caller outside the lock */
static size_t evict(size_t room, void **out, size_t *out_n)
{
    size_t k = 0;
    while (nslot > 0 && (kept_bytes + room > limit || nslot >= SLOTS)) {
        size_t old = 0;
        for (size_t i = 1; i < nslot; ++i)
            if (slot[i].stamp < slot[old].stamp)
                old = i;
        out[k] = slot[old].p;
        out_n[k++] = slot[old].n;
        kept_bytes -= slot[old].n;
        slot[old] = slot[--nslot];
    }
    return k;
}

void rgbz_pool_give(void *block, size_t size)
{
    if (block == NULL)
        return;
    void *out[SLOTS + 1];
    size_t out_n[SLOTS + 1], k = 0;
    int keep = 0;
    lazy_free(block, size);
    lock();
    if (size <= limit) {
        k = evict(size, out, out_n);
        slot[nslot].p = block;
        slot[nslot].n = size;
        slot[nslot].stamp = ++clock_;
        ++nslot;
        kept_bytes += size;
        keep = 1;
    }
    unlock();
    if (!keep)
        unmap_block(block, size);
    for (size_t i = 0; i < k; ++i)
        unmap_block(out[i], out_n[i]);
}

size_t rgbz_pool_set_limit(size_t new_limit)
{
    void *out[SLOTS + 1];
    size_t out_n[SLOTS + 1];
    lock();
    size_t old = limit;
    limit = new_limit;
    size_t k = evict(0, out, out_n);
    unlock();
    for (size_t i = 0; i < k; ++i)
        unmap_block(out[i], out_n[i]);
    return old;
}

size_t rgbz_pool_get_limit(void)
{
    lock();
    size_t l = limit;
    unlock();
    return l;
}

void rgbz_pool_stats(size_t *blocks, size_t *bytes, size_t *reused, size_t *mapped)
{
    lock();
    *blocks = nslot;
    *bytes = kept_bytes;
    *reused = n_reused;
    *mapped = n_mapped;
    unlock();
}
