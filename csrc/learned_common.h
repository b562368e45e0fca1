/*
 * learned_common.h -- what the learned kernel (learned.c) and the z_guided kernel
 * (z_guided.c), which hashes and filters the same windows, share outside the templates: the
 * block size, the loop and clone macros, the lane sums of the dense dot products, the border
 * rule and the test of the fast path. learned_hash.template.h holds the shared code of each
 * element type and precision. Static: each kernel's translation unit has its copy.
 */
#ifndef RGBZ_LEARNED_COMMON_H
#define RGBZ_LEARNED_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "rgbz.h"
#include "rgbz_ops.h"
#include "rgbz_templating.h"
#include "learned.h"

/* the names of the template instances (rgbz_templating.h's pasting) */
#define LRN_CAT RGBZ_CAT3

/* the fast path (learned_hash.template.h) */
#define LRN_RING 8   /* rows of a ring: the fast path's windows span at most 2 * 3 + 1 */
/* columns of a strip of the fast path, 16 KiB of REAL per ring row (4096 in float32, 2048 in
   float64): every strip costs each Z row its own set-up and halo, which outweighs the cache
   misses of longer ring rows up to about that length (40 ring rows per thread); REAL is the
   template instance's */
#define LRN_STRIP ((ptrdiff_t)(16384 / sizeof(REAL)))
#define LRN_HALO 8    /* columns the fast path reads beyond its sites: 3 + 2 (hash), 3 + 4 (dot) */

/* sites per block: a multiple of the widest vector; one in the counting build, so that
   every counted operation belongs to a real site */
#ifdef RGBZ_COUNT_OPS
#define LRN_BLK 1
#else
#define LRN_BLK 32
#endif

/* the templates' names for the shared helpers: the loops over the sites of a block
   carry no dependence (RGBZ_IVDEP, rgbz_ops.h); the hot loops are built for AVX-512, AVX2 and
   the baseline (RGBZ_CLONES_512: every vectorised loop of the template is element by
   element, no reduction across the vector, the dense dot products use 32-byte vectors
   whatever the set, and nothing is contracted (C99), so every clone gives bit-identical
   results); RGBZ_INLINE (rgbz_templating.h) compiles a helper for its caller's instruction
   set and with its constant arguments */
#define LRN_IVDEP RGBZ_IVDEP
#define LRN_CLONES RGBZ_CLONES_512
#define LRN_INLINE RGBZ_INLINE

/* keep the loops around the site loops (pairs, taps) rolled: GCC's unroll-and-jam of those
   would turn the inner loops scalar */
#if defined(__GNUC__) && !defined(__clang__)
#define LRN_NOJAM _Pragma("GCC unroll 1")
#else
#define LRN_NOJAM
#endif

/* GCC >= 9 and Clang: vector extensions for the dense dot product of the fast path */
#if (defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 9)) && !defined(RGBZ_COUNT_OPS)
#define LRN_VECTOR_EXT 1
#else
#define LRN_VECTOR_EXT 0
#endif

#if LRN_VECTOR_EXT
/* The lane sums of the dense dot products (learned.template.h): for L sites' accumulators
   a[i] (L = 8 floats or 4 doubles, one 32-byte vector each), the vector whose element i is
   a[i][0] + a[i][1] + ... + a[i][L - 1], added in lane order (into *sum): the accumulators transposed
   in registers (the unpack, pair and half shuffles of an L x L transpose), then L - 1
   vector additions. Inlined into each clone of its caller. */
typedef float lrn_v8f __attribute__((vector_size(32)));
typedef double lrn_v4d __attribute__((vector_size(32)));
#if defined(__clang__)
#define LRN_SHUF8(a, b, i0, i1, i2, i3, i4, i5, i6, i7) \
    __builtin_shufflevector(a, b, i0, i1, i2, i3, i4, i5, i6, i7)
#define LRN_SHUF4(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#else
typedef int32_t lrn_m8 __attribute__((vector_size(32)));
typedef int64_t lrn_m4 __attribute__((vector_size(32)));
#define LRN_SHUF8(a, b, i0, i1, i2, i3, i4, i5, i6, i7) \
    __builtin_shuffle(a, b, (lrn_m8){i0, i1, i2, i3, i4, i5, i6, i7})
#define LRN_SHUF4(a, b, i0, i1, i2, i3) __builtin_shuffle(a, b, (lrn_m4){i0, i1, i2, i3})
#endif

/* the 8 x 8 transpose in registers of a[0] .. a[7] into T[0] .. T[7] with the shuffle SHUF of
   lrn_transpose8_f32's indices (its 8-lane shuffles, or the same in each half of 16 lanes) */
#define LRN_TRANSPOSE8(V, SHUF, a, T)                                                         \
    do {                                                                                      \
        V t_[8], u_[8];                                                                       \
        /* t[2m], t[2m + 1]: sites 2m and 2m + 1, lanes (0, 1, 4, 5) and (2, 3, 6, 7)         \
           interleaved */                                                                     \
        for (int i_ = 0; i_ < 8; i_ += 2) {                                                   \
            t_[i_] = SHUF((a)[i_], (a)[i_ + 1], 0, 8, 1, 9, 4, 12, 5, 13);                    \
            t_[i_ + 1] = SHUF((a)[i_], (a)[i_ + 1], 2, 10, 3, 11, 6, 14, 7, 15);              \
        }                                                                                     \
        /* u[4h + l]: sites 4h .. 4h + 3, lane l in the low half, lane l + 4 in the high */   \
        for (int i_ = 0; i_ < 8; i_ += 4) {                                                   \
            u_[i_] = SHUF(t_[i_], t_[i_ + 2], 0, 1, 8, 9, 4, 5, 12, 13);                      \
            u_[i_ + 1] = SHUF(t_[i_], t_[i_ + 2], 2, 3, 10, 11, 6, 7, 14, 15);                \
            u_[i_ + 2] = SHUF(t_[i_ + 1], t_[i_ + 3], 0, 1, 8, 9, 4, 5, 12, 13);              \
            u_[i_ + 3] = SHUF(t_[i_ + 1], t_[i_ + 3], 2, 3, 10, 11, 6, 7, 14, 15);            \
        }                                                                                     \
        for (int l_ = 0; l_ < 4; l_++) {                                                      \
            (T)[l_] = SHUF(u_[l_], u_[l_ + 4], 0, 1, 2, 3, 8, 9, 10, 11);                     \
            (T)[l_ + 4] = SHUF(u_[l_], u_[l_ + 4], 4, 5, 6, 7, 12, 13, 14, 15);               \
        }                                                                                     \
    } while (0)

/* the 8 x 8 transpose in registers: T[l] holds lane l of a[0] .. a[7] (the unpack, pair and
   half shuffles); z_guided.c writes its cells' terms with it */
LRN_INLINE void lrn_transpose8_f32(const lrn_v8f *a, lrn_v8f *T)
{
    LRN_TRANSPOSE8(lrn_v8f, LRN_SHUF8, a, T);
}

/* the 4 x 4 transpose of doubles: T[l] holds lane l of a[0] .. a[3] */
LRN_INLINE void lrn_transpose4_f64(const lrn_v4d *a, lrn_v4d *T)
{
    /* t0, t1: sites 0 and 1, lanes (0, 2) and (1, 3) interleaved; t2, t3: sites 2, 3 */
    const lrn_v4d t0 = LRN_SHUF4(a[0], a[1], 0, 4, 2, 6), t1 = LRN_SHUF4(a[0], a[1], 1, 5, 3, 7);
    const lrn_v4d t2 = LRN_SHUF4(a[2], a[3], 0, 4, 2, 6), t3 = LRN_SHUF4(a[2], a[3], 1, 5, 3, 7);
    T[0] = LRN_SHUF4(t0, t2, 0, 1, 4, 5);
    T[1] = LRN_SHUF4(t1, t3, 0, 1, 4, 5);
    T[2] = LRN_SHUF4(t0, t2, 2, 3, 6, 7);
    T[3] = LRN_SHUF4(t1, t3, 2, 3, 6, 7);
}

LRN_INLINE void lrn_lane_sums_f32(const lrn_v8f *a, lrn_v8f *sum)
{
    lrn_v8f T[8];
    lrn_transpose8_f32(a, T);
    lrn_v8f s = T[0] + T[1];
    for (int l = 2; l < 8; l++) s += T[l];
    *sum = s;
}

LRN_INLINE void lrn_lane_sums_f64(const lrn_v4d *a, lrn_v4d *sum)
{
    lrn_v4d T[4];
    lrn_transpose4_f64(a, T);
    lrn_v4d s = T[0] + T[1];
    s += T[2];
    s += T[3];
    *sum = s;
}

/* The dense dot products of 16 float sites at once, two sites an AVX-512 register of 16
   lanes: each half of a register is one site's accumulator of lrn_dense_dot_rows (lane l:
   window column l), with the same products added in the same order, and the lanes of each
   half added in lane order by the 8 x 8 transpose in each half, so the sums are bit for bit
   those of the 8-lane code. Site a's partner is site a + Q with Q px = 8 (px 2 or 4: the
   periods of Mask1 and Mask2), so that one load of 16 pixels holds both windows' row.
   AVX-512F only: with AVX2 or the baseline each 16-lane operation is two or four narrower
   ones and the shuffles are emulated (1.5x and 1.8x slower than the 8-lane code measured,
   docs/reports/benchmarks.md). GCC >= 12 and Clang (__builtin_shufflevector across vector
   sizes). */
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 12)
/* 1 where the caller runs AVX-512F code: built for it, or in the AVX-512F clone of an
   RGBZ_CLONES_512 function (the loader picks that clone wherever the CPU has AVX-512F) */
#if defined(__AVX512F__)
#define LRN_ON_AVX512() 1
#elif RGBZ_HAVE_CLONES
#define LRN_ON_AVX512() __builtin_cpu_supports("avx512f")
#else
#define LRN_ON_AVX512() 0
#endif
typedef float lrn_v16f __attribute__((vector_size(64)));
/* lane m of an 8-lane shuffle of (a, b) as lane m of each half of a 16-lane one */
#define LRN_H0_(m) ((m) < 8 ? (m) : (m) + 8)
#define LRN_H1_(m) ((m) < 8 ? (m) + 8 : (m) + 16)
#define LRN_SHUF16(a, b, i0, i1, i2, i3, i4, i5, i6, i7)                                      \
    __builtin_shufflevector(a, b, LRN_H0_(i0), LRN_H0_(i1), LRN_H0_(i2), LRN_H0_(i3),          \
                            LRN_H0_(i4), LRN_H0_(i5), LRN_H0_(i6), LRN_H0_(i7), LRN_H1_(i0),   \
                            LRN_H1_(i1), LRN_H1_(i2), LRN_H1_(i3), LRN_H1_(i4), LRN_H1_(i5),   \
                            LRN_H1_(i6), LRN_H1_(i7))

/* Sites j .. j + 15 at px PX (2 or 4; Q = 8 / PX): pair p holds site a = j + (p / Q) 2Q +
   p % Q in its low half and a + Q in its high half, its window rows starting PX ((p / Q) 2Q +
   p % Q) columns after the first pair's. lrn_pairs_store_f32: the lanes of the 8 pairs'
   accumulators added in lane order (the 8 x 8 transpose in each half), to the sites' order,
   stored at res. */
LRN_INLINE void lrn_pairs_store_f32(const lrn_v16f *acc, const int Q, float *restrict res)
{
    lrn_v16f T[8];
    LRN_TRANSPOSE8(lrn_v16f, LRN_SHUF16, acc, T);
    lrn_v16f s = T[0] + T[1];
    for (int l = 2; l < 8; l++) s += T[l];
    /* lane p: site a of pair p, lane 8 + p: its site a + Q */
    if (Q == 4)
        s = __builtin_shufflevector(s, s, 0, 1, 2, 3, 8, 9, 10, 11, 4, 5, 6, 7, 12, 13, 14, 15);
    else
        s = __builtin_shufflevector(s, s, 0, 1, 8, 9, 2, 3, 10, 11, 4, 5, 12, 13, 6, 7, 14, 15);
    memcpy(res, &s, sizeof s);
}

/* px 2: the window rows in the outer loop, the 8 accumulators side by side (each summed over
   the rows in their order). The pairs' windows start at 0, 2, 4, 6, 16, 18, 20, 22: three
   loads of 16 pixels a row (at 0, 16 and 22, none past the last window's end) and a
   two-block shuffle per pair, instead of 8 overlapping loads that each cross a cache line
   (0.68-0.74x the pair-by-pair code's time on cached data, benchmarks.md) */
LRN_INLINE void lrn_dense16_px2_f32(const float *const *rowp, ptrdiff_t x0, int j,
                                    const float *restrict wd, const int R, const int rows,
                                    const int32_t *restrict bucket, float *restrict res)
{
    const float *wa[8], *wb[8];
    for (int p = 0; p < 8; p++) {
        const int ja = j + (p / 4) * 8 + p % 4;
        wa[p] = wd + (ptrdiff_t)bucket[ja] * rows * 8;
        wb[p] = wd + (ptrdiff_t)bucket[ja + 4] * rows * 8;
    }
    const ptrdiff_t base = x0 + (ptrdiff_t)j * 2 - R;
    lrn_v16f acc[8] = {{0}};
    for (int dy = 0; dy < rows; dy++) {
        lrn_v16f b0, b1, b2, w[8];
        memcpy(&b0, rowp[dy] + base, sizeof b0);
        memcpy(&b1, rowp[dy] + base + 16, sizeof b1);
        memcpy(&b2, rowp[dy] + base + 22, sizeof b2);
        w[0] = b0;
        w[1] = __builtin_shufflevector(b0, b1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
                                       16, 17);
        w[2] = __builtin_shufflevector(b0, b1, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17,
                                       18, 19);
        w[3] = __builtin_shufflevector(b0, b1, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18,
                                       19, 20, 21);
        w[4] = b1;
        /* 18 .. 33: 18 .. 31 of b1, then 32, 33 (b2's 10, 11); 20 .. 35 likewise */
        w[5] = __builtin_shufflevector(b1, b2, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
                                       26, 27);
        w[6] = __builtin_shufflevector(b1, b2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 26, 27,
                                       28, 29);
        w[7] = b2;
        for (int p = 0; p < 8; p++) {
            lrn_v8f wl, wh;
            memcpy(&wl, wa[p] + dy * 8, sizeof wl);
            memcpy(&wh, wb[p] + dy * 8, sizeof wh);
            acc[p] += __builtin_shufflevector(wl, wh, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12,
                                              13, 14, 15) * w[p];
        }
    }
    lrn_pairs_store_f32(acc, 4, res + j);
}

/* px 4: pair by pair, each window row one load (the windows overlap two by two only; rows
   outermost as for px 2 measured slower here) */
LRN_INLINE void lrn_dense16_px4_f32(const float *const *rowp, ptrdiff_t x0, int j,
                                    const float *restrict wd, const int R, const int rows,
                                    const int32_t *restrict bucket, float *restrict res)
{
    lrn_v16f acc[8];
    for (int p = 0; p < 8; p++) {
        const int ja = j + (p / 2) * 4 + p % 2;
        const ptrdiff_t xa = x0 + (ptrdiff_t)ja * 4 - R;
        const float *wa = wd + (ptrdiff_t)bucket[ja] * rows * 8;
        const float *wb = wd + (ptrdiff_t)bucket[ja + 2] * rows * 8;
        lrn_v16f s = {0};
        for (int dy = 0; dy < rows; dy++) {
            lrn_v16f xv;
            lrn_v8f wl, wh;
            memcpy(&xv, rowp[dy] + xa, sizeof xv);
            memcpy(&wl, wa + dy * 8, sizeof wl);
            memcpy(&wh, wb + dy * 8, sizeof wh);
            s += __builtin_shufflevector(wl, wh, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13,
                                         14, 15) * xv;
        }
        acc[p] = s;
    }
    lrn_pairs_store_f32(acc, 2, res + j);
}

/* the sites 0 .. 16 floor(n / 16) - 1 of lrn_dense_dot_rows through lrn_dense16_px<px>_f32 where
   it pays (AVX-512F, px 2 or 4): returns how many it did */
LRN_INLINE int lrn_dense_pairs_f32(const float *const *rowp, ptrdiff_t x0, int px, int n,
                                   const float *restrict wd, const int R,
                                   const int32_t *restrict bucket, float *restrict res)
{
    if ((px != 2 && px != 4) || !LRN_ON_AVX512()) return 0;
    const int rows = 2 * R + 1;
    int j = 0;
    for (; j + 16 <= n; j += 16) {
        if (px == 2) lrn_dense16_px2_f32(rowp, x0, j, wd, R, rows, bucket, res);
        else lrn_dense16_px4_f32(rowp, x0, j, wd, R, rows, bucket, res);
    }
    return j;
}
#else
/* no shuffles across vector sizes: every site through the 8-lane code */
#define lrn_dense_pairs_f32(rowp, x0, px, n, wd, R, bucket, res) 0
#endif
/* double precision keeps the 4-lane code for every site */
#define lrn_dense_pairs_f64(rowp, x0, px, n, wd, R, bucket, res) 0
#endif

/* the energy classes' colours of the sites of row y from column x0 (every px-th, px even, so
   the same for all): class q = 2 r + p holds the pixels of the frame's row parity (y - hr + r)
   and column parity (x0 - hr + p); cls[0] is red's class, cls[1] and cls[2] green's two,
   cls[3] blue's */
static inline void lrn_colour_classes(const rgbz_learned_filters *f, ptrdiff_t y, ptrdiff_t x0,
                                      int cls[4])
{
    const int hr = f->hash_radius;
    cls[0] = cls[1] = cls[2] = cls[3] = -1;
    for (int q = 0; q < 4; q++) {
        const int row = (int)((y - hr + (q >> 1)) & 1);
        const int col = f->bayer[row * 2 + (int)((x0 - hr + (q & 1)) & 1)];
        if (col == 1) {
            if (cls[1] < 0) cls[1] = q; else cls[2] = q;
        } else if (col == 0) {
            cls[0] = q;
        } else {
            cls[3] = q;
        }
    }
}

/* the border rule of every kernel: an index outside [0, n) moves back inside by whole
   periods P (n >= P), so that the pixel keeps its colour */
static inline ptrdiff_t lrn_extend(ptrdiff_t i, ptrdiff_t n, ptrdiff_t P)
{
    return i < 0 ? i + P * ((P - 1 - i) / P) : (i >= n ? i - P * ((i - n + P) / P) : i);
}

/* 1 when the fast path computes what the pairs say: the window fits the dense rows of 8,
   the dense weights are there (has_dense), with the spread term so is the Bayer tile, and
   for every phase and direction the pairs are exactly the known pairs of the rectangle of
   starts (learned.h), counted from the phase map */
static int lrn_fast_ok(const rgbz_learned_filters *f, int has_dense, int py, int px,
                       const int32_t *phase_map)
{
#ifdef RGBZ_COUNT_OPS
    /* the counting build counts the per-site formulation (each site's pairs and taps) */
    (void)f; (void)has_dense; (void)py; (void)px; (void)phase_map;
    return 0;
#else
    static const int SY[RGBZ_LEARNED_DIRS] = {0, 2, 2, 2}, SX[RGBZ_LEARNED_DIRS] = {2, 0, 2, -2};
    const int hr = f->hash_radius;
    /* an even period along the rows: the column parity (so the colour) of a pair start is the
       same at every site of a phase */
    if (!has_dense || f->radius > 3 || hr < 1 || hr > f->radius || px % 2 ||
        (f->n_spr > 1 && !f->bayer))
        return 0;
    for (int i = 0; i < py * px; i++) {
        const int k = phase_map[i];
        if (k < 0) continue;
        const int r = i / px, c = i % px;
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const int sy = SY[d], sx = SX[d];
            int count = 0;
            for (int dy = -hr; dy <= hr - sy; dy++)
                for (int dx = (sx < 0 ? -hr - sx : -hr); dx <= (sx > 0 ? hr - sx : hr); dx++) {
                    const int y1 = ((r + dy) % py + py) % py, x1 = ((c + dx) % px + px) % px;
                    const int y2 = ((r + dy + sy) % py + py) % py;
                    const int x2 = ((c + dx + sx) % px + px) % px;
                    count += phase_map[y1 * px + x1] < 0 && phase_map[y2 * px + x2] < 0;
                }
            if (count != f->n_pairs[k * RGBZ_LEARNED_DIRS + d]) return 0;
        }
    }
    return 1;
#endif
}

#endif /* RGBZ_LEARNED_COMMON_H */
