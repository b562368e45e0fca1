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
