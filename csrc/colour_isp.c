/*
 * colour_isp.c -- the fused colour ISP (see colour_isp.h): the defect candidates, the
 * grey-world sums and the render (white balance .. output) of rgbz_fast.isp.ColourISP.run;
 * for Menon 2007, the render's white balance and its tail (matrix .. output) as two passes
 * around that demosaic's own kernel.
 *
 * Bit for bit the NumPy stages' results (colour_isp.h lists the two exceptions): the
 * operations of each stage in its order and type, compiled with -ffp-contract=off
 * (csrc/meson.build) so that every multiply and add is rounded on its own as NumPy's are;
 * the sRGB encoding is the thresholds of isp._encode_table (found with the stages' own
 * encoding as the oracle), so the power never runs here.
 *
 * Threads: row bands (pixel bands for the tail), one per thread; one thread per 2^18 pixels
 * at most. The results do not
 * depend on the thread count (the candidates' order does; the caller does not use it).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "colour_isp.h"
#include "demosaic_bilinear.h"
#include "rgbz_templating.h"
#include "rgbz_threads.h"

/* The codes of float32 values with the gathers of AVX2, 8 at a time (float64: 4): ci_encode's lookup
   (colour_isp.template.h) lane by lane, the same codes; the caller checks the CPU. Returns
   how many of the n values it coded (a multiple of 8; the rest are the caller's). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define CI_HAVE_AVX2 1
__attribute__((target("avx2")))
static ptrdiff_t ci_encode_avx2(const float *t, const int32_t *start, uint32_t base,
                                uint32_t last, int shift, int steps, const float *v,
                                uint16_t *code, ptrdiff_t n)
{
    const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
    const __m256i vb = _mm256_set1_epi32((int32_t)base), vl = _mm256_set1_epi32((int32_t)last);
    const __m128i sh = _mm_cvtsi32_si128(shift);
    ptrdiff_t j = 0;
    for (; j + 8 <= n; j += 8) {
        /* clip: max gives +0 for -0 and NaN (its second operand), as ci_clip01 */
        const __m256 x = _mm256_min_ps(_mm256_max_ps(_mm256_loadu_ps(v + j), zero), one);
        __m256i u = _mm256_srl_epi32(_mm256_castps_si256(x), sh);
        u = _mm256_min_epu32(_mm256_max_epu32(u, vb), vl);
        __m256i c = _mm256_i32gather_epi32(start, _mm256_sub_epi32(u, vb), 4);
        for (int s = 1 << (steps - 1); s > 0; s >>= 1) {
            const __m256i step = _mm256_set1_epi32(s);
            const __m256 ts = _mm256_i32gather_ps(t, _mm256_add_epi32(c, step), 4);
            const __m256 le = _mm256_cmp_ps(ts, x, _CMP_LE_OQ);
            c = _mm256_add_epi32(c, _mm256_and_si256(_mm256_castps_si256(le), step));
        }
        const __m128i p = _mm_packus_epi32(_mm256_castsi256_si128(c),
                                           _mm256_extracti128_si256(c, 1));
        _mm_storeu_si128((__m128i *)(code + j), p);
    }
    return j;
}

/* ci_encode_avx2 for a table of one step (8 bits) from its pairs (ci_codes' `pair`): one
   8-byte gather per value gives the bucket's start code and the threshold above it, instead
   of two gathers one after the other; the same codes */
__attribute__((target("avx2")))
static ptrdiff_t ci_encode1_avx2(const uint64_t *pair, uint32_t base, uint32_t last,
                                 int shift, const float *v, uint16_t *code, ptrdiff_t n)
{
    const __m256 zero = _mm256_setzero_ps(), one = _mm256_set1_ps(1.0f);
    const __m256i vb = _mm256_set1_epi32((int32_t)base), vl = _mm256_set1_epi32((int32_t)last);
    const __m128i sh = _mm_cvtsi32_si128(shift);
    const long long *tab = (const long long *)pair;
    ptrdiff_t j = 0;
    for (; j + 8 <= n; j += 8) {
        const __m256 x = _mm256_min_ps(_mm256_max_ps(_mm256_loadu_ps(v + j), zero), one);
        __m256i u = _mm256_srl_epi32(_mm256_castps_si256(x), sh);
        u = _mm256_sub_epi32(_mm256_min_epu32(_mm256_max_epu32(u, vb), vl), vb);
        const __m256 lo = _mm256_castsi256_ps(
            _mm256_i32gather_epi64(tab, _mm256_castsi256_si128(u), 8));
        const __m256 hi = _mm256_castsi256_ps(
            _mm256_i32gather_epi64(tab, _mm256_extracti128_si256(u, 1), 8));
        /* the low halves (thresholds) and the high ones (codes) of the 8 pairs, in order */
        const __m256 t = _mm256_castpd_ps(_mm256_permute4x64_pd(
            _mm256_castps_pd(_mm256_shuffle_ps(lo, hi, 0x88)), 0xD8));
        const __m256i c = _mm256_castpd_si256(_mm256_permute4x64_pd(
            _mm256_castps_pd(_mm256_shuffle_ps(lo, hi, 0xDD)), 0xD8));
        /* t <= x: all ones, -1 */
        const __m256i k = _mm256_sub_epi32(c, _mm256_castps_si256(_mm256_cmp_ps(t, x,
                                                                            _CMP_LE_OQ)));
        const __m128i p = _mm_packus_epi32(_mm256_castsi256_si128(k),
                                           _mm256_extracti128_si256(k, 1));
        _mm_storeu_si128((__m128i *)(code + j), p);
    }
    return j;
}

/* ci_encode_avx2 for float64 values, 4 at a time: the clip, the bucket's start code from the
   value's bits, then `steps` threshold tests, lane by lane as ci_code; the same codes. The
   clipped values lie in [0, 1], so their bits and the buckets compare as signed integers. */
__attribute__((target("avx2")))
static ptrdiff_t ci_encode_f64_avx2(const double *t, const int32_t *start, uint64_t base,
                                    uint64_t last, int shift, int steps, const double *v,
                                    uint16_t *code, ptrdiff_t n)
{
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256i vb = _mm256_set1_epi64x((long long)base);
    const __m256i vl = _mm256_set1_epi64x((long long)last);
    const __m128i sh = _mm_cvtsi32_si128(shift);
    /* the low 32 bits of each 64-bit lane, into the low 128 bits */
    const __m256i lows = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    ptrdiff_t j = 0;
    for (; j + 4 <= n; j += 4) {
        const __m256d x = _mm256_min_pd(_mm256_max_pd(_mm256_loadu_pd(v + j), zero), one);
        __m256i u = _mm256_srl_epi64(_mm256_castpd_si256(x), sh);
        u = _mm256_blendv_epi8(u, vb, _mm256_cmpgt_epi64(vb, u));
        u = _mm256_blendv_epi8(u, vl, _mm256_cmpgt_epi64(u, vl));
        __m128i c = _mm256_i64gather_epi32(start, _mm256_sub_epi64(u, vb), 4);
        for (int s = 1 << (steps - 1); s > 0; s >>= 1) {
            const __m128i step = _mm_set1_epi32(s);
            const __m256d ts = _mm256_i32gather_pd(t, _mm_add_epi32(c, step), 8);
            const __m256i le = _mm256_castpd_si256(_mm256_cmp_pd(ts, x, _CMP_LE_OQ));
            const __m128i le32 = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(le, lows));
            c = _mm_add_epi32(c, _mm_and_si128(le32, step));
        }
        _mm_storel_epi64((__m128i *)(code + j), _mm_packus_epi32(c, c));
    }
    return j;
}

/* ci_encode_f64_avx2 for a table of one step (8 bits) with the buckets' next thresholds
   (ci_codes' `next`), with AVX-512, 8 values at a time: the bucket's start code and the
   threshold above it are two gathers at the same index, not one after the other, and the
   lanes the threshold passes get one code more; the same codes. (An AVX2-only CPU keeps
   ci_encode_f64_avx2.) */
__attribute__((target("avx512f,avx512vl,avx512dq,avx512bw")))
static ptrdiff_t ci_encode1_f64_avx512(const double *next, const int32_t *start, uint64_t base,
                                       uint64_t last, int shift, const double *v,
                                       uint16_t *code, ptrdiff_t n)
{
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    const __m512i vb = _mm512_set1_epi64((long long)base);
    const __m512i vl = _mm512_set1_epi64((long long)last);
    const __m128i sh = _mm_cvtsi32_si128(shift);
    const __m256i ones = _mm256_set1_epi32(1);
    ptrdiff_t j = 0;
    for (; j + 8 <= n; j += 8) {
        const __m512d x = _mm512_min_pd(_mm512_max_pd(_mm512_loadu_pd(v + j), zero), one);
        __m512i u = _mm512_srl_epi64(_mm512_castpd_si512(x), sh);
        u = _mm512_sub_epi64(_mm512_min_epu64(_mm512_max_epu64(u, vb), vl), vb);
        const __m256i c = _mm512_i64gather_epi32(u, start, 4);
        const __m512d ts = _mm512_i64gather_pd(u, next, 8);
        const __mmask8 le = _mm512_cmp_pd_mask(ts, x, _CMP_LE_OQ);
        const __m256i k = _mm256_mask_add_epi32(c, le, c, ones);
        _mm_storeu_si128((__m128i *)(code + j), _mm256_cvtepi32_epi16(k));
    }
    return j;
}

static int ci_cpu_avx512(void)
{
    static int have = -1;
    if (have < 0)
        have = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl")
               && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
    return have;
}

/* the demosaic's and the white balance's loops in 8 doubles (x86-64-v4: AVX-512) or 4 (AVX2)
   as well (the same arithmetic: -ffp-contract=off leaves every operation rounded on its own
   on every set) */
#define CI_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
/* the colour matrix's loop likewise, on sets that have FMA: the float32 dot product is
   fmaf's (CI_DOT3_f32), which the baseline set (and AVX2 alone) can only call, one value
   at a time */
#define CI_CLONES_FMA \
    __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

static int ci_cpu_avx2(void)
{
    static int have = -1;
    if (have < 0) have = __builtin_cpu_supports("avx2") ? 1 : 0;
    return have;
}
#endif
#ifndef CI_CLONES
#define CI_CLONES
#endif
#ifndef CI_CLONES_FMA
#define CI_CLONES_FMA
#endif

/* pixels per chunk of rgbz_ci_encode_rgb (its planes stay in cache) */
enum { CI_CHUNK = 4096 };

/* the calling thread's band [*lo, *hi) of n items in a parallel region: n t / nt .. n (t + 1)
   / nt (all of them without OpenMP) */
static void ci_band(ptrdiff_t n, ptrdiff_t *lo, ptrdiff_t *hi)
{
    *lo = 0;
    *hi = n;
#ifdef _OPENMP
    const ptrdiff_t t = omp_get_thread_num(), nt = omp_get_num_threads();
    *lo = n * t / nt;
    *hi = n * (t + 1) / nt;
#endif
}

/* the border rules of demosaic.c: scipy 'reflect', or a shift by whole periods */
static inline ptrdiff_t ci_extend(ptrdiff_t i, ptrdiff_t n, int mode)
{
    if (mode == RGBZ_DM_PERIOD) {
        if (i < 0) return i + 2 * ((-i + 1) / 2);
        if (i >= n) return i - 2 * ((i - n + 2) / 2);
        return i;
    }
    if (n == 1) return 0;
    ptrdiff_t period = 2 * n;
    i %= period;
    if (i < 0) i += period;
    return i < n ? i : period - 1 - i;
}

/* a Bayer quad: two greens on one diagonal, red and blue on the other */
static int ci_bayer_phase(const int32_t *phase)
{
    int greens = 0;
    for (int i = 0; i < 4; i++) {
        if (phase[i] < 0 || phase[i] > 2) return 0;
        greens += phase[i] == 1;
    }
    int main_diag = phase[0] == 1 && phase[3] == 1 && phase[1] + phase[2] == 2 && phase[1] != 1;
    int anti_diag = phase[1] == 1 && phase[2] == 1 && phase[0] + phase[3] == 2 && phase[0] != 1;
    return greens == 2 && (main_diag || anti_diag);
}

/* the defect candidates of one thread, growing */
typedef struct {
    int64_t r, c;
    float hot, cold, spread;
} ci_cand;

typedef struct {
    ci_cand *v;
    ptrdiff_t n, cap;
} ci_list;

static int ci_push(ci_list *l, ptrdiff_t r, ptrdiff_t c, float hot, float cold, float spread)
{
    if (l->n == l->cap) {
        ptrdiff_t cap = l->cap ? 2 * l->cap : 256;
        ci_cand *v = (ci_cand *)realloc(l->v, (size_t)cap * sizeof *v);
        if (!v) return 1;
        l->v = v;
        l->cap = cap;
    }
    ci_cand *e = l->v + l->n++;
    e->r = r;
    e->c = c;
    e->hot = hot;
    e->cold = cold;
    e->spread = spread;
    return 0;
}

/* The pre-test of the defect scan (ci_pretest): per tile row, CI_PRE neighbour offsets
   (the most frequent among the row's colour positions; a position without one of them is
   kept for the full test), their frame offsets `lin` (CI_PRE per tile row), their masks
   (CI_PRE rows of cols bytes per tile row: 1 at x when the offset is a neighbour of x) and
   the colour mask (a row of cols bytes per tile row: 1 where x has neighbours to test);
   same[py]: every mask of tile row py is its colour mask. */
enum { CI_PRE = 4 };
typedef struct {
    ptrdiff_t *lin;
    uint8_t *mask, *colour, *same;
} ci_pre;

static void ci_pre_free(ci_pre *pre)
{
    free(pre->same);
    free(pre->lin);
    free(pre->mask);
    free(pre->colour);
}

static int ci_pre_build(ci_pre *pre, ptrdiff_t cols, int32_t P, int32_t Q, const int32_t *noff,
                        const int32_t *offs)
{
    pre->lin = (ptrdiff_t *)calloc((size_t)P * CI_PRE, sizeof *pre->lin);
    pre->mask = (uint8_t *)calloc((size_t)P * CI_PRE * (size_t)cols, 1);
    pre->colour = (uint8_t *)calloc((size_t)P * (size_t)cols, 1);
    pre->same = (uint8_t *)calloc((size_t)P, 1);
    if (!pre->lin || !pre->mask || !pre->colour || !pre->same) {
        ci_pre_free(pre);
        return RGBZ_ENOMEM;
    }
    for (int32_t py = 0; py < P; py++) {
        /* the offsets of the 5x5 window, dy, dx in [-2, 2]: how many positions have each */
        int count[25] = {0}, taken[25] = {0};
        for (int32_t q = 0; q < Q; q++) {
            const int32_t n = noff[py * Q + q];
            const int32_t *o = offs + (ptrdiff_t)(py * Q + q) * 2 * RGBZ_CI_MAX_NEIGHBOURS;
            for (int32_t i = 0; i < n; i++)
                if (o[2 * i] >= -2 && o[2 * i] <= 2 && o[2 * i + 1] >= -2 && o[2 * i + 1] <= 2)
                    count[(o[2 * i] + 2) * 5 + o[2 * i + 1] + 2]++;
        }
        for (int d = 0; d < CI_PRE; d++) {
            int best = -1;
            for (int i = 0; i < 25; i++)
                if (!taken[i] && count[i] > 0 && (best < 0 || count[i] > count[best])) best = i;
            if (best < 0) continue;                 /* lin 0, mask 0: tests nothing */
            taken[best] = 1;
            const int32_t dy = best / 5 - 2, dx = best % 5 - 2;
            pre->lin[py * CI_PRE + d] = (ptrdiff_t)dy * cols + dx;
            uint8_t *m = pre->mask + ((ptrdiff_t)py * CI_PRE + d) * cols;
            for (ptrdiff_t x = 0; x < cols; x++) {
                const int32_t q = (int32_t)(x % Q), n = noff[py * Q + q];
                const int32_t *o = offs + (ptrdiff_t)(py * Q + q) * 2 * RGBZ_CI_MAX_NEIGHBOURS;
                for (int32_t i = 0; i < n; i++)
                    if (o[2 * i] == dy && o[2 * i + 1] == dx) m[x] = 1;
            }
        }
        for (ptrdiff_t x = 0; x < cols; x++)
            pre->colour[py * cols + x] = noff[py * Q + (int32_t)(x % Q)] > 0;
        pre->same[py] = 1;
        for (int d = 0; d < CI_PRE; d++)
            if (memcmp(pre->mask + ((ptrdiff_t)py * CI_PRE + d) * cols,
                       pre->colour + py * cols, (size_t)cols))
                pre->same[py] = 0;
    }
    return RGBZ_OK;
}

/* the scans, once per element type (rgbz_templating.h) */
#define RGBZ_TYPE_TEMPLATE "colour_isp_scan.template.h"
#include "rgbz_each_type.h"
#undef RGBZ_TYPE_TEMPLATE

int rgbz_ci_defect_candidates(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                              int32_t P, int32_t Q, const int32_t *noff, const int32_t *offs,
                              float thr, float k, ptrdiff_t capacity, int64_t *rr, int64_t *cc,
                              float *hot, float *cold, float *spread, ptrdiff_t *count,
                              int workers)
{
    if (!src || !noff || !offs || !count || rows < 0 || cols < 0 || P < 1 || Q < 1 ||
        capacity < 0 || (capacity > 0 && (!rr || !cc || !hot || !cold || !spread)))
        return RGBZ_EINVAL;
    for (int32_t i = 0; i < P * Q; i++)
        if (noff[i] > RGBZ_CI_MAX_NEIGHBOURS) return RGBZ_EINVAL;
    if (in_type < RGBZ_T_U8 || in_type > RGBZ_T_F64) return RGBZ_EINVAL;
    const int nt = rgbz_threads_per_values(workers, rows * cols);
    ci_list *lists = (ci_list *)calloc((size_t)nt, sizeof *lists);
    /* the neighbours' offsets in the frame, dy cols + dx */
    ptrdiff_t *lin = (ptrdiff_t *)malloc((size_t)P * Q * RGBZ_CI_MAX_NEIGHBOURS * sizeof *lin);
    uint8_t *keep = (uint8_t *)malloc((size_t)nt * (size_t)(cols > 0 ? cols : 1));
    ci_pre pre = {NULL, NULL, NULL, NULL};
    if (!lists || !lin || !keep || ci_pre_build(&pre, cols, P, Q, noff, offs) != RGBZ_OK) {
        free(lists);
        free(lin);
        free(keep);
        return RGBZ_ENOMEM;
    }
    for (ptrdiff_t i = 0; i < (ptrdiff_t)P * Q; i++)
        for (int32_t j = 0; j < RGBZ_CI_MAX_NEIGHBOURS; j++)
            lin[i * RGBZ_CI_MAX_NEIGHBOURS + j] =
                (ptrdiff_t)offs[(i * RGBZ_CI_MAX_NEIGHBOURS + j) * 2] * cols +
                offs[(i * RGBZ_CI_MAX_NEIGHBOURS + j) * 2 + 1];
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nt) reduction(|:bad)
#endif
    for (ptrdiff_t y = 0; y < rows; y++) {
#ifdef _OPENMP
        const int t = omp_get_thread_num();
#else
        const int t = 0;
#endif
        ci_list *l = lists + t;
        uint8_t *kp = keep + (ptrdiff_t)t * cols;
        if (bad) continue;
        int st = RGBZ_OK;
#define CI_CAND_(s, T) st = RGBZ_CAT(ci_candidates, s)((const T *)src, rows, cols, y, P, Q, \
                                                       noff, offs, lin, &pre, thr, k, kp, l)
        RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, CI_CAND_, st = RGBZ_EINVAL)
#undef CI_CAND_
        bad |= st != RGBZ_OK;
    }
    ptrdiff_t n = 0;
    for (int t = 0; t < nt; t++) {
        for (ptrdiff_t i = 0; i < lists[t].n; i++, n++) {
            if (n >= capacity) continue;
            const ci_cand *e = lists[t].v + i;
            rr[n] = e->r;
            cc[n] = e->c;
            hot[n] = e->hot;
            cold[n] = e->cold;
            spread[n] = e->spread;
        }
        free(lists[t].v);
    }
    free(lists);
    free(lin);
    free(keep);
    ci_pre_free(&pre);
    *count = n;
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}

int rgbz_ci_defect_confirm(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                           int32_t P, int32_t Q, const int32_t *noff, const int32_t *offs,
                           ptrdiff_t n, const int64_t *rr, const int64_t *cc, const float *hot,
                           const float *cold, const float *spread, float thr, float k,
                           double f, uint8_t *ok)
{
    if (!src || !noff || !offs || rows < 0 || cols < 0 || P < 1 || Q < 1 || n < 0 ||
        (n > 0 && (!rr || !cc || !hot || !cold || !spread || !ok)))
        return RGBZ_EINVAL;
    for (int32_t i = 0; i < P * Q; i++)
        if (noff[i] > RGBZ_CI_MAX_NEIGHBOURS) return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++)
        if (rr[i] < 0 || rr[i] >= rows || cc[i] < 0 || cc[i] >= cols) return RGBZ_EINVAL;
    int st = RGBZ_OK;
#define CI_CONFIRM_(s, T) RGBZ_CAT(ci_confirm, s)((const T *)src, rows, cols, P, Q, noff, offs, \
                                                  n, rr, cc, hot, cold, spread, thr, k, f, ok)
    RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, CI_CONFIRM_, st = RGBZ_EINVAL)
#undef CI_CONFIRM_
    return st;
}

int rgbz_ci_phase_sums(int in_type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                       double white, double *sums, int64_t *counts, int workers)
{
    if (!src || !sums || !counts || rows < 0 || cols < 0) return RGBZ_EINVAL;
    if (in_type < RGBZ_T_U8 || in_type > RGBZ_T_F64) return RGBZ_EINVAL;
    const int nt = rgbz_threads_per_values(workers, rows * cols);
    double *s = (double *)calloc((size_t)nt * 4, sizeof *s);
    int64_t *c = (int64_t *)calloc((size_t)nt * 4, sizeof *c);
    if (!s || !c) {
        free(s);
        free(c);
        return RGBZ_ENOMEM;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
#endif
    {
        ptrdiff_t t = 0, n = 1;
#ifdef _OPENMP
        t = omp_get_thread_num();
        n = omp_get_num_threads();
#endif
        /* bands of even rows, so that every band starts on phase row 0 */
        const ptrdiff_t pairs = (rows + 1) / 2;
        const ptrdiff_t y0 = 2 * (pairs * t / n);
        ptrdiff_t y1 = 2 * (pairs * (t + 1) / n);
        if (y1 > rows) y1 = rows;
        int st = RGBZ_OK;
#define CI_SUMS_(sfx, T) RGBZ_CAT(ci_sums, sfx)((const T *)src, cols, y0, y1, white, s + 4 * t, \
                                                c + 4 * t)
        RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, CI_SUMS_, st = RGBZ_EINVAL)
#undef CI_SUMS_
        (void)st;
    }
    for (int i = 0; i < 4; i++) {
        /* integer sums are whole numbers below 2^53: exact in any order */
        double a = 0;
        int64_t b = 0;
        for (int t = 0; t < nt; t++) {
            a += s[4 * t + i];
            b += c[4 * t + i];
        }
        sums[i] = a;
        counts[i] = b;
    }
    free(s);
    free(c);
    return RGBZ_OK;
}

/* An output row from its codes: 6 planes of h codes (R, G, B of the even columns, then of
   the odd ones) interleaved as R, G, B per pixel, a pair of pixels per step */
CI_CLONES static void ci_interleave8(const uint16_t *code, ptrdiff_t h, ptrdiff_t cols,
                                     uint8_t *restrict o)
{
    const uint16_t *c0 = code, *c1 = code + h, *c2 = code + 2 * h, *c3 = code + 3 * h,
                   *c4 = code + 4 * h, *c5 = code + 5 * h;
    const ptrdiff_t n = cols / 2;
    for (ptrdiff_t j = 0; j < n; j++) {
        o[6 * j] = (uint8_t)c0[j];
        o[6 * j + 1] = (uint8_t)c1[j];
        o[6 * j + 2] = (uint8_t)c2[j];
        o[6 * j + 3] = (uint8_t)c3[j];
        o[6 * j + 4] = (uint8_t)c4[j];
        o[6 * j + 5] = (uint8_t)c5[j];
    }
    if (cols & 1) {
        o[6 * n] = (uint8_t)c0[n];
        o[6 * n + 1] = (uint8_t)c1[n];
        o[6 * n + 2] = (uint8_t)c2[n];
    }
}

CI_CLONES static void ci_interleave16(const uint16_t *code, ptrdiff_t h, ptrdiff_t cols,
                                      uint16_t *restrict o)
{
    const uint16_t *c0 = code, *c1 = code + h, *c2 = code + 2 * h, *c3 = code + 3 * h,
                   *c4 = code + 4 * h, *c5 = code + 5 * h;
    const ptrdiff_t n = cols / 2;
    for (ptrdiff_t j = 0; j < n; j++) {
        o[6 * j] = c0[j];
        o[6 * j + 1] = c1[j];
        o[6 * j + 2] = c2[j];
        o[6 * j + 3] = c3[j];
        o[6 * j + 4] = c4[j];
        o[6 * j + 5] = c5[j];
    }
    if (cols & 1) {
        o[6 * n] = c0[n];
        o[6 * n + 1] = c1[n];
        o[6 * n + 2] = c2[n];
    }
}

/* n pixels' codes from 3 planes of h codes (R, G, B), interleaved (rgbz_ci_encode_rgb) */
CI_CLONES static void ci_interleave3_8(const uint16_t *code, ptrdiff_t h, ptrdiff_t n,
                                       uint8_t *restrict o)
{
    const uint16_t *c0 = code, *c1 = code + h, *c2 = code + 2 * h;
    for (ptrdiff_t j = 0; j < n; j++) {
        o[3 * j] = (uint8_t)c0[j];
        o[3 * j + 1] = (uint8_t)c1[j];
        o[3 * j + 2] = (uint8_t)c2[j];
    }
}

CI_CLONES static void ci_interleave3_16(const uint16_t *code, ptrdiff_t h, ptrdiff_t n,
                                        uint16_t *restrict o)
{
    const uint16_t *c0 = code, *c1 = code + h, *c2 = code + 2 * h;
    for (ptrdiff_t j = 0; j < n; j++) {
        o[3 * j] = c0[j];
        o[3 * j + 1] = c1[j];
        o[3 * j + 2] = c2[j];
    }
}

/* ---- the render, once per precision, its rows once per element type within it ---- */
/* the vector codes of a precision, or none (0 values coded) */
#ifdef CI_HAVE_AVX2
#define CI_ENCODE_FAST_f32(tab, v, code, n)                                                \
    (!ci_cpu_avx2() ? 0 :                                                                   \
     (tab)->pair ? ci_encode1_avx2((tab)->pair, (tab)->base, (tab)->last, (tab)->shift,     \
                                   (v), (code), (n)) :                                      \
     ci_encode_avx2((tab)->t, (tab)->start, (tab)->base, (tab)->last, (tab)->shift,         \
                    (tab)->steps, (v), (code), (n)))
#else
#define CI_ENCODE_FAST_f32(tab, v, code, n) 0
#endif
#ifdef CI_HAVE_AVX2
#define CI_ENCODE_FAST_f64(tab, v, code, n)                                                \
    (!ci_cpu_avx2() ? 0 :                                                                   \
     (tab)->next && ci_cpu_avx512() ?                                                       \
     ci_encode1_f64_avx512((tab)->next, (tab)->start, (tab)->base, (tab)->last,            \
                           (tab)->shift, (v), (code), (n)) :                                \
     ci_encode_f64_avx2((tab)->t, (tab)->start, (tab)->base, (tab)->last, (tab)->shift,     \
                        (tab)->steps, (v), (code), (n)))
#else
#define CI_ENCODE_FAST_f64(tab, v, code, n) 0
#endif
typedef uint32_t ci_uint_f32;       /* the unsigned integer of a float's bits */
typedef uint64_t ci_uint_f64;
#define CI_UINT(s) RGBZ_CAT(ci_uint, s)
#define CI_MANT_f32 23              /* the bits of the mantissa */
#define CI_MANT_f64 52
#define CI_MANT(s) RGBZ_CAT(CI_MANT, s)

/* One row of the colour matrix times a pixel, as NumPy's matmul computes it with OpenBLAS
   (its sgemm kernels multiply-add in fused steps, its dgemm result is that of separate
   roundings: both checked on every pixel of tests/isp/test_fused.py). Another BLAS may round
   otherwise: a code may then differ by one. */
#define CI_DOT3_f32(a0, x0, a1, x1, a2, x2) fmaf((a2), (x2), fmaf((a1), (x1), (a0) * (x0)))
#define CI_DOT3_f64(a0, x0, a1, x1, a2, x2) ((a0) * (x0) + (a1) * (x1) + (a2) * (x2))

/* the render once per precision, its rows once per element type within it */
#define RGBZ_REAL_TEMPLATE "colour_isp.template.h"
#include "rgbz_each_real.h"
#undef RGBZ_REAL_TEMPLATE
