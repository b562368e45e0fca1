/*
 * rgbz_ops.h -- what every kernel file shares: the counted arithmetic macros
 * (the operation counts of the paper's Table 1), the fast exponential of the
 * gamma factors (eq. 7), the helpers of each precision under its suffix (f32,
 * f64: what a template reaches as RGBZ_CAT(name, RS), rgbz_templating.h), and the
 * compiler-specific helpers, each behind a test of the compiler with a portable
 * fallback. No arrays here: the memory layouts are in the kernel files.
 *
 * Counting: in the normal build every macro is the plain operation. Built with
 * -DRGBZ_COUNT_OPS (the library of rgbz_fast._kernels_count, behind
 * `rgbz-fast opcount`), each macro also increments a counter of its category
 * in `rgbz_opc_cur`, which the kernels point at the counters of the plan being
 * run. The counting build is single-threaded. Only the per-pixel arithmetic of
 * the algorithms goes through these macros; loads, index arithmetic, the final
 * clipping and the conversion to the output type are not counted (Table 1 of
 * the paper does not count them).
 */
#ifndef RGBZ_OPS_H
#define RGBZ_OPS_H

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "rgbz.h"
#include "rgbz_templating.h"

#ifdef RGBZ_COUNT_OPS
extern uint64_t *rgbz_opc_cur;
/* a call, not an inline rgbz_opc_cur[k]++: two counted operations of one expression
   (OCMP(a) + OCMP(b)) increment the same counter, and two increments of one object
   unsequenced against each other are undefined behaviour (C11 6.5p2; GCC warned
   -Wsequence-point 192 times); the bodies of two calls are indeterminately sequenced,
   never interleaved, so each call adds its 1 */
static inline int rgbz_opc_add(int k)
{
    rgbz_opc_cur[k]++;
    return 0;
}
#define OPC_(k) ((void)rgbz_opc_add(k))
#else
#define OPC_(k) ((void)0)
#endif

#define OADD(a, b) (OPC_(RGBZ_OP_ADD), (a) + (b))
#define OSUB(a, b) (OPC_(RGBZ_OP_ADD), (a) - (b))
#define OMUL(a, b) (OPC_(RGBZ_OP_MUL), (a) * (b))
#define ODIV(a, b) (OPC_(RGBZ_OP_DIV), (a) / (b))
#define OCMP(expr) (OPC_(RGBZ_OP_CMP), (expr))

/* ---- per precision, under its suffix ---- */

/* |a - b|: one subtraction and one absolute value */
#define OABSDIFF_f32(a, b) (OPC_(RGBZ_OP_ADD), OPC_(RGBZ_OP_ABS), fabsf((a) - (b)))
#define OABSDIFF_f64(a, b) (OPC_(RGBZ_OP_ADD), OPC_(RGBZ_OP_ABS), fabs((a) - (b)))

/* the C library's exponential (exp_mode RGBZ_EXP_LIBM); rgbz_exp_poly_<suffix> below is
   the fast one (RGBZ_EXP_FAST) */
#define rgbz_exp_libm_f32 expf
#define rgbz_exp_libm_f64 exp

/* a result of the reconstruction kernels as an output element, before the cast to the
   element type: clamped to [0, maxval] (a NaN to 0), plus 0.5 for an integer type, which
   the cast then rounds half up; not counted (Table 1 does not count the conversion).
   Called as (IN_T)RGBZ_CAT(rgbz_out, RS)(r, maxval, IN_IS_INT). */
static inline float rgbz_out_f32(float r, float maxval, int is_int)
{
    r = r > 0.0f ? r : 0.0f;
    r = r > maxval ? maxval : r;
    return is_int ? r + 0.5f : r;
}

static inline double rgbz_out_f64(double r, double maxval, int is_int)
{
    r = r > 0.0 ? r : 0.0;
    r = r > maxval ? maxval : r;
    return is_int ? r + 0.5 : r;
}

/* ---- compiler-specific helpers, each with a portable fallback (RGBZ_INLINE:
   rgbz_templating.h) ---- */

/* before a loop of a compile-time trip count (at most 24) whose full unrolling lets the loop
   around it vectorise */
#if defined(__GNUC__) && !defined(__clang__)
#define RGBZ_UNROLL _Pragma("GCC unroll 24")
#else
#define RGBZ_UNROLL
#endif
/* before a loop over the sites of a block whose reads (the taps, the core's scratch rows)
   and writes (other scratch rows) never overlap, which GCC cannot always prove through the
   arrays of row pointers: it vectorises the loop without run-time overlap checks (a loop
   with more rows than --param vect-max-version-for-alias-checks is otherwise left scalar) */
#if defined(__GNUC__) && !defined(__clang__)
#define RGBZ_IVDEP _Pragma("GCC ivdep")
#else
#define RGBZ_IVDEP
#endif

/* rgbz_ctz: the index of the lowest set bit of m (m != 0); rgbz_popcount: the number of
   set bits of m */
#if defined(__GNUC__) || defined(__clang__)
static inline int rgbz_ctz(uint32_t m) { return __builtin_ctz(m); }
static inline int rgbz_popcount(uint32_t m) { return __builtin_popcount(m); }
#else
static inline int rgbz_ctz(uint32_t m)
{
    int i = 0;
    for (; !(m & 1u); m >>= 1) i++;
    return i;
}
static inline int rgbz_popcount(uint32_t m)
{
    int c = 0;
    for (; m; m &= m - 1) c++;
    return c;
}
#endif

/* a hint to bring the bytes [p, p + n) into the cache, one per 64-byte line (none where the
   compiler has no prefetch builtin) */
static inline void rgbz_prefetch_span(const void *p, size_t n)
{
#if defined(__GNUC__) || defined(__clang__)
    const char *c = (const char *)p;
    for (size_t i = 0; i < n; i += 64) __builtin_prefetch(c + i, 0, 3);
#else
    (void)p;
    (void)n;
#endif
}

/*
 * Vector-width dispatch of the hottest functions: on x86-64 with GCC and glibc, a
 * function marked RGBZ_CLONES is compiled once per listed target and the loader
 * picks the widest the CPU runs (an ifunc). Only the vector width changes: the
 * C99 build (-std=c99, so -ffp-contract=off) contracts nothing into FMAs, so
 * every clone computes the same IEEE operations and the results are identical
 * bit for bit. The counting build and other compilers get one copy.
 *   RGBZ_CLONES      AVX2 and the x86-64 baseline (the learned kernel; bilinear and
 *                    BI on Mask1, slower on 1 thread with AVX-512F)
 *   RGBZ_CLONES_512  AVX-512F, AVX2 and the baseline (the reconstruction's gather and
 *                    core, the ToF blocks): the AVX-512F clone runs 16 float lanes;
 *                    SG float32 ran 1.1-1.9x as fast with it as with AVX2 on 1 thread
 *                    (docs/reports/benchmarks.md, issue 16)
 *   RGBZ_HAVE_CLONES 1 where the clones are built (then a cloned function's code runs on
 *                    the widest set the CPU has, which __builtin_cpu_supports tells), 0
 *                    for the one copy
 */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__GLIBC__) && \
    !defined(RGBZ_COUNT_OPS) && !defined(RGBZ_NO_CLONES)
#define RGBZ_CLONES __attribute__((target_clones("avx2", "default")))
#define RGBZ_CLONES_512 __attribute__((target_clones("avx512f", "avx2", "default")))
#define RGBZ_HAVE_CLONES 1
#else
#define RGBZ_CLONES
#define RGBZ_CLONES_512
#define RGBZ_HAVE_CLONES 0
#endif

/* The OpenMP loop over rows or blocks: RGBZ_PARALLEL_FOR before a `for`, on `nth` threads,
   a local the caller sets to rgbz_threads(workers) (workers <= 0: the OpenMP default).
   (A _Pragma string is not macro-expanded, so the names nth and bad are fixed.) */
#ifdef _OPENMP
#include <omp.h>
#define RGBZ_PARALLEL_FOR _Pragma("omp parallel for schedule(static) num_threads(nth)")
/* the same, or-reducing a local int `bad` over the threads */
#define RGBZ_PARALLEL_FOR_OR(bad) \
    _Pragma("omp parallel for schedule(static) reduction(|:bad) num_threads(nth)")
static inline int rgbz_threads(int workers)
{
    return workers > 0 ? workers : omp_get_max_threads();
}
/* inside a parallel region: this thread's number and the team's size (0 and 1 outside) */
static inline int rgbz_thread_num(void)
{
    return omp_get_thread_num();
}
static inline int rgbz_team_size(void)
{
    return omp_get_num_threads();
}
#else
#define RGBZ_PARALLEL_FOR
#define RGBZ_PARALLEL_FOR_OR(bad)
static inline int rgbz_threads(int workers)
{
    (void)workers;
    return 1;
}
static inline int rgbz_thread_num(void)
{
    return 0;
}
static inline int rgbz_team_size(void)
{
    return 1;
}
#endif

/* ---- the fast exponential of eq. 7 (exp_mode RGBZ_EXP_FAST) ---- */

/*
 * exp(x) for x <= 0 by range reduction: x*log2(e) = n + f, f in [-0.5, 0.5],
 * 2^f = e^y with y = f*ln2 (ln2 split in two, Cody-Waite) from its Taylor
 * polynomial -- degree 7 in double, degree 6 in float --, 2^n by building the
 * exponent bits. Maximum relative error against libm, measured by a sweep over
 * [-87, 0] (float) and [-708, 0] (double) in tests/test_kernels.py
 * (test_fast_exp_against_libm): below 3e-7 in float, 1e-8 in double (the
 * figures ReconstructParams documents; docs/reports/tradeoff.md measures what it
 * changes in the images). x <= -708 (double) or <= -87 (float) gives 0: the
 * subnormal results and the last sliver of normal ones (exp(-708) = 3.3e-308,
 * expf(-87) = 1.6e-38) are flushed (libm returns them). Exactly 1 at 0. NaN
 * gives 0 (no NaN reaches the integer conversion, which would be undefined
 * behaviour: docs/reports/robustness.md, B10).
 */
static inline double rgbz_exp_poly_f64(double x)
{
    /* branch-free, as the float version below, so that the gamma loops vectorise (with
       floor() and an integer conversion they stayed scalar: SG Mask1 63 against 260
       Mpix/s for exp()'s vector port, docs/reports/benchmarks.md); the same operations on
       the same values as floor(x log2(e) + 0.5), so the same bits. x below the threshold,
       and NaN, take the clamp and the final 0. */
    const double xc = x > -708.0 ? x : -708.0;
    const double u = xc * 1.4426950408889634 + 0.5;    /* in [-1020.9, 0.5] for x <= 0 */
    /* floor(u): u + 1.5 * 2^52 rounds u to an integer (doubles in [2^52, 2^53) are the
       integers) and the subtraction is exact; one less where that rounded up */
    const double t = u + 6755399441055744.0;
    const double r = t - 6755399441055744.0;
    const double n = r > u ? r - 1.0 : r;
    const double y = (xc - n * 0.693147180369123816490) - n * 1.90821492927058770002e-10;
    const double p = 1.0 + y * (1.0 + y * (0.5 + y * (1.0 / 6 + y * (1.0 / 24 + y * (1.0 / 120 + y * (1.0 / 720 + y * (1.0 / 5040)))))));
    /* 2^n: the exponent field n + 1023 (in [2, 1023] for x in (-708, 0]) from the bits of
       n + 1.5 * 2^52, whose low bits are n in two's complement: shifted by 52 (which drops
       the rest) plus 1023 << 52 */
    const double tn = n + 6755399441055744.0;
    uint64_t tbits;
    memcpy(&tbits, &tn, sizeof tbits);
    const uint64_t bits = (tbits << 52) + ((uint64_t)1023 << 52);
    double scale;
    memcpy(&scale, &bits, sizeof scale);
    return x > -708.0 ? p * scale : 0.0;
}

static inline float rgbz_exp_poly_f32(float x)
{
    /* branch-free, so that loops over several gammas vectorise: clamp, evaluate,
       then zero the result below the normal range. NaN fails `x > -87` and takes the
       clamp (and the final 0). */
    const float xc = x > -87.0f ? x : -87.0f;
    /* t = 1.5 * 2^23 + n, n = x log2(e) rounded to nearest: t lies in [2^23, 2^24), where
       floats are the integers, so that the low bits of t are n */
    const float t = xc * 1.44269504f + 12582912.0f;
    const float n = t - 12582912.0f;
    /* Cody-Waite: r = x - n*ln2 with ln2 split in two, exact in float */
    const float y = (xc - n * 0.693359375f) - n * -2.12194440e-4f;
    const float p = 1.0f + y * (1.0f + y * (0.5f + y * (1.0f / 6 + y * (1.0f / 24 + y * (1.0f / 120 + y * (1.0f / 720))))));
    /* 2^n: the exponent field n + 127 (in [1, 127] for x in [-87, 0]), from the bits of t,
       bits(1.5 * 2^23) + n, shifted by 23 (the shift drops bits(1.5 * 2^23), a multiple of
       2^9): one shift and one add, no float-to-integer conversion */
    uint32_t tbits;
    memcpy(&tbits, &t, sizeof tbits);
    const uint32_t bits = (tbits << 23) + (127u << 23);
    float scale;
    memcpy(&scale, &bits, sizeof scale);
    return x > -87.0f ? p * scale : 0.0f;
}

#endif /* RGBZ_OPS_H */
