/*
 * scan.c -- one pass over a float array for the argument checks: its smallest and largest
 * value and whether it holds NaN (rgbz_fast._validate.check_finite, finite_range).
 *
 * NumPy's np.all(np.isfinite(a)) writes a bool array of a's size and reads it back, and a
 * caller that needs the range reads a twice more (a.min(), a.max()); this reads it once.
 * Infinities show in the range; a NaN sets *lo = *hi = NaN, or shows as an infinity when the
 * array holds both: either way the range is not finite, which is what the checks ask.
 * Single thread (a check runs before the kernels, whose thread count the caller chose).
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include "rgbz.h"
#include "rgbz_ops.h"

/* min and max by comparisons that skip NaN (a NaN first value stays: non-finite either way),
   and s = sum of v * 0, NaN if some v is NaN or infinite: the three reductions vectorise */
#define SCAN_BODY(T)                                                                       \
    T mn = x[0], mx = x[0], s = 0;                                                         \
    _Pragma("omp simd reduction(min:mn) reduction(max:mx) reduction(+:s)")                 \
    for (ptrdiff_t i = 0; i < n; i++) {                                                    \
        const T v = x[i];                                                                  \
        mn = v < mn ? v : mn;                                                              \
        mx = v > mx ? v : mx;                                                              \
        s += v * (T)0;                                                                     \
    }                                                                                      \
    const int nan = s != s && isfinite(mn) && isfinite(mx);  /* not an infinity: a NaN */ \
    *lo = nan ? NAN : (double)mn;                                                          \
    *hi = nan ? NAN : (double)mx;

RGBZ_CLONES_512 static void scan_f32(const float *restrict x, ptrdiff_t n, double *lo,
                                     double *hi)
{
    SCAN_BODY(float)
}

RGBZ_CLONES_512 static void scan_f64(const double *restrict x, ptrdiff_t n, double *lo,
                                     double *hi)
{
    SCAN_BODY(double)
}
#undef SCAN_BODY

int rgbz_float_range(int type, const void *data, ptrdiff_t n, double *lo, double *hi)
{
    if (!data || !lo || !hi || n < 1) return RGBZ_EINVAL;
    if (type == RGBZ_T_F32) {
        scan_f32((const float *)data, n, lo, hi);
    } else if (type == RGBZ_T_F64) {
        scan_f64((const double *)data, n, lo, hi);
    } else {
        return RGBZ_EINVAL;
    }
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ measurement sites */

RGBZ_CLONES_512
static void sites_scan(const int64_t *restrict rows, const int64_t *restrict cols, ptrdiff_t n,
                       int64_t lo_hi[4], int *ordered)
{
    int64_t rlo = rows[0], rhi = rows[0], clo = cols[0], chi = cols[0];
    int bad = 0;
    _Pragma("omp simd reduction(min:rlo,clo) reduction(max:rhi,chi) reduction(|:bad)")
    for (ptrdiff_t i = 1; i < n; i++) {
        const int64_t r = rows[i], c = cols[i], pr = rows[i - 1], pc = cols[i - 1];
        rlo = r < rlo ? r : rlo;
        rhi = r > rhi ? r : rhi;
        clo = c < clo ? c : clo;
        chi = c > chi ? c : chi;
        bad |= (r < pr) | ((r == pr) & (c <= pc));
    }
    lo_hi[0] = rlo;
    lo_hi[1] = rhi;
    lo_hi[2] = clo;
    lo_hi[3] = chi;
    *ordered = !bad;
}

int rgbz_sites_range(const int64_t *rows, const int64_t *cols, ptrdiff_t n, int64_t lo_hi[4],
                     int *ordered)
{
    if (!rows || !cols || !lo_hi || !ordered || n < 1) return RGBZ_EINVAL;
    sites_scan(rows, cols, n, lo_hi, ordered);
    return RGBZ_OK;
}

/* v mod m for 0 <= v < 2^31 and 1 <= m < 2^31 without an integer division (which does not
   vectorise): the quotient through a double, off by at most one, corrected (49 / 49 gives
   0.99999...: one short) */
static inline int32_t sites_mod(int32_t v, int32_t m, double inv)
{
    int32_t r = v - (int32_t)((double)v * inv) * m;
    r = r < 0 ? r + m : r;
    return r >= m ? r - m : r;
}

/* whether the sites [i0, i1) all have their block x block cells on Z sites: the indices in
   32 bits, the tile's flags as 32-bit words (gathers of words vectorise, of bytes not) */
RGBZ_CLONES_512
static int sites_all_z(const int64_t *restrict rows, const int64_t *restrict cols, ptrdiff_t i0,
                       ptrdiff_t i1, int block, const int32_t *restrict tile_z, int P, int Q,
                       double ip, double iq)
{
    int bad = 0;
    if (block == 1) {
        _Pragma("omp simd reduction(|:bad)")
        for (ptrdiff_t i = i0; i < i1; i++) {
            const int32_t r = (int32_t)rows[i], c = (int32_t)cols[i];
            bad |= !tile_z[sites_mod(r, P, ip) * Q + sites_mod(c, Q, iq)];
        }
    } else {
        _Pragma("omp simd reduction(|:bad)")
        for (ptrdiff_t i = i0; i < i1; i++) {
            const int32_t r = (int32_t)rows[i], c = (int32_t)cols[i];
            const int32_t r0 = sites_mod(r, P, ip) * Q, r1 = sites_mod(r + 1, P, ip) * Q;
            const int32_t c0 = sites_mod(c, Q, iq), c1 = sites_mod(c + 1, Q, iq);
            bad |= !(tile_z[r0 + c0] & tile_z[r0 + c1] & tile_z[r1 + c0] & tile_z[r1 + c1]);
        }
    }
    return !bad;
}

int rgbz_sites_off_z(const int64_t *rows, const int64_t *cols, ptrdiff_t n, int block,
                     const uint8_t *tile_z, int P, int Q, ptrdiff_t *first)
{
    if (!rows || !cols || !tile_z || !first || n < 0 || P < 1 || Q < 1 ||
        (block != 1 && block != 2))
        return RGBZ_EINVAL;
    const double ip = 1.0 / P, iq = 1.0 / Q;
    int32_t *words = (int32_t *)malloc((size_t)P * (size_t)Q * sizeof(int32_t));
    if (!words) return RGBZ_ENOMEM;
    for (ptrdiff_t k = 0; k < (ptrdiff_t)P * Q; k++) words[k] = tile_z[k] != 0;
    *first = -1;
    for (ptrdiff_t i0 = 0; i0 < n && *first < 0; i0 += 4096) {
        /* a block of sites at a time, the first bad one looked for only in a bad block */
        const ptrdiff_t i1 = i0 + 4096 < n ? i0 + 4096 : n;
        if (sites_all_z(rows, cols, i0, i1, block, words, P, Q, ip, iq)) continue;
        for (ptrdiff_t i = i0; i < i1; i++)
            for (int dr = 0; dr < block; dr++)
                for (int dc = 0; dc < block; dc++)
                    if (*first < 0 && !tile_z[((rows[i] + dr) % P) * Q + (cols[i] + dc) % Q])
                        *first = i;
    }
    free(words);
    return RGBZ_OK;
}
