/*
 * rgbz_threads.h -- the thread count of a kernel whose work is light per value (a table
 * look-up, a colour pass): the caller's `workers` (<= 0: the OpenMP default), but one
 * thread per 2^18 values at most (MIN_PIXELS_PER_THREAD of the Python layer), so that a
 * small image does not pay the wake-up and the barrier of threads with next to nothing
 * to do. Without OpenMP, one thread.
 */
#ifndef RGBZ_THREADS_H
#define RGBZ_THREADS_H

#include <stddef.h>
#ifdef _OPENMP
#include <omp.h>
#endif

static inline int rgbz_threads_per_values(int workers, ptrdiff_t n)
{
#ifdef _OPENMP
    int t = workers > 0 ? workers : omp_get_max_threads();
    ptrdiff_t cap = n >> 18;
    if (cap < t) t = cap < 1 ? 1 : (int)cap;
    return t;
#else
    (void)workers; (void)n;
    return 1;
#endif
}

#endif
