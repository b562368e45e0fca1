/*
 * learned.c -- the learned reconstruction (learned.h): 4 element types x 2 precisions
 * of learned.template.h, and the entry point that checks the arguments the Python
 * layer validated (a failure here is a bug there) and builds the column map.
 */
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "rgbz.h"
#include "rgbz_ops.h"
#include "learned.h"

/* sites per block: a multiple of the widest vector; one in the counting build, so that
   every counted operation belongs to a real site */
#ifdef RGBZ_COUNT_OPS
#define LRN_BLK 1
#else
#define LRN_BLK 32
#endif

/* the loops over the sites of a block carry no dependence (the tap, weight and result
   rows never overlap): say so, so that GCC vectorises them without a run-time check */
/* and keep the loops around them (pairs, taps) rolled: GCC's unroll-and-jam of those
   would turn the inner loops scalar */
#if defined(__GNUC__) && !defined(__clang__)
#define LRN_IVDEP _Pragma("GCC ivdep")
#define LRN_NOJAM _Pragma("GCC unroll 1")
#else
#define LRN_IVDEP
#define LRN_NOJAM
#endif

/* the instruction sets of the hot loops: rgbz_ops.h's RGBZ_CLONES (AVX2, the baseline) and
   AVX-512. Every vectorised loop of this file is element by element (no reduction across the
   vector; the dense dot products use 32-byte vectors whatever the set) and nothing is
   contracted (C99), so that every clone gives bit-identical results. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(RGBZ_COUNT_OPS) && !defined(RGBZ_NO_CLONES)
#define LRN_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define LRN_CLONES RGBZ_CLONES
#endif

/* a helper inlined into its caller whatever its size, so that it is compiled for the caller's
   instruction set (RGBZ_CLONES) and with the caller's constant arguments */
#if defined(__GNUC__) || defined(__clang__)
#define LRN_INLINE static inline __attribute__((always_inline))
#else
#define LRN_INLINE static inline
#endif

/* GCC >= 9 and Clang: vector extensions for the dense dot product of the fast path */
#if (defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 9)) && !defined(RGBZ_COUNT_OPS)
#define LRN_VECTOR_EXT 1
#else
#define LRN_VECTOR_EXT 0
#endif

/* the border rule of every kernel: an index outside [0, n) moves back inside by whole
   periods P (n >= P), so that the pixel keeps its colour */
static inline ptrdiff_t lrn_extend(ptrdiff_t i, ptrdiff_t n, ptrdiff_t P)
{
    return i < 0 ? i + P * ((P - 1 - i) / P) : (i >= n ? i - P * ((i - n + P) / P) : i);
}

/* the 8 instantiations: each element type (learned.instances.h adds both precisions) */
#define IN_T uint8_t
#define IS u8
#define IN_IS_INT 1
#include "learned.instances.h"
#define IN_T uint16_t
#define IS u16
#define IN_IS_INT 1
#include "learned.instances.h"
#define IN_T float
#define IS f32
#define IN_IS_INT 0
#include "learned.instances.h"
#define IN_T double
#define IS f64
#define IN_IS_INT 0
#include "learned.instances.h"

/* 1 when the fast path computes what the pairs say: the window fits the dense rows of 8,
   both weight tables are there, and for every phase and direction the pairs are exactly the
   known pairs of the rectangle of starts (learned.h), counted from the phase map */
static int lrn_fast_ok(const rgbz_learned_filters *f, int py, int px, const int32_t *phase_map)
{
#ifdef RGBZ_COUNT_OPS
    /* the counting build counts the per-site formulation (each site's pairs and taps) */
    (void)f; (void)py; (void)px; (void)phase_map;
    return 0;
#else
    static const int SY[RGBZ_LEARNED_DIRS] = {0, 2, 2, 2}, SX[RGBZ_LEARNED_DIRS] = {2, 0, 2, -2};
    const int hr = f->hash_radius;
    /* an even period along the rows: the column parity (so the colour) of a pair start is the
       same at every site of a phase */
    if (!f->wd_f32 || !f->wd_f64 || f->radius > 3 || hr < 1 || hr > f->radius || px % 2)
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

static int lrn_check(const rgbz_learned_filters *f, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map)
{
    if (!f || f->n_phases <= 0 || f->n_buckets <= 0 || f->n_str < 1 || f->n_coh < 1 ||
        f->n_spr < 1 || f->n_buckets != 8 * f->n_str * f->n_coh * f->n_spr || f->radius < 0 ||
        f->radius > RGBZ_LEARNED_MAX_RADIUS || f->n_taps_max <= 0 ||
        f->n_taps_max > RGBZ_LEARNED_MAX_TAPS || f->hash_radius > f->radius || py <= 0 || px <= 0 || rows < py || cols < px)
        return RGBZ_EINVAL;
    for (int i = 0; i < py * px; i++)
        if (phase_map[i] >= f->n_phases) return RGBZ_EINVAL;
    for (int i = 0; i < 4; i++)
        if (f->bayer[i] < 0 || f->bayer[i] > 2) return RGBZ_EINVAL;
    for (int k = 0; k < f->n_phases; k++) {
        const int nt = f->n_taps[k];
        if (nt <= 0 || nt > f->n_taps_max) return RGBZ_EINVAL;
        for (int t = 0; t < nt; t++) {
            const int dy = f->tap_dy[k * f->n_taps_max + t], dx = f->tap_dx[k * f->n_taps_max + t];
            if (dy < -f->radius || dy > f->radius || dx < -f->radius || dx > f->radius)
                return RGBZ_EINVAL;
        }
        for (int d = 0; d < RGBZ_LEARNED_DIRS; d++) {
            const int np = f->n_pairs[k * RGBZ_LEARNED_DIRS + d];
            if (np <= 0 || np > f->n_pairs_max) return RGBZ_EINVAL;
            const ptrdiff_t o = ((ptrdiff_t)k * RGBZ_LEARNED_DIRS + d) * f->n_pairs_max;
            for (int p = 0; p < np; p++)
                if (f->pair_a[o + p] < 0 || f->pair_a[o + p] >= nt || f->pair_b[o + p] < 0 ||
                    f->pair_b[o + p] >= nt || f->pair_col[o + p] < 0 || f->pair_col[o + p] > 2)
                    return RGBZ_EINVAL;
        }
    }
    return RGBZ_OK;
}

#define LRN_CALL(is, rs, T)                                                                  \
    LRN_CAT_(lrn_loop, is, rs)((const T *)src, (T *)dst, rows, cols, py, px, phase_map, f,   \
                               colmap, fast_ok, maxval, workers, opcounts)
#define LRN_CAT_(a, b, c) a##_##b##_##c

int rgbz_learned(int in_type, int precision, const void *src, void *dst,
                           ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                           const int32_t *phase_map, const rgbz_learned_filters *f,
                           double maxval, int workers, uint64_t *opcounts)
{
    int status = lrn_check(f, rows, cols, py, px, phase_map);
    if (status != RGBZ_OK) return status;
    if (precision != RGBZ_P_FLOAT32 && precision != RGBZ_P_FLOAT64) return RGBZ_EINVAL;
#ifdef RGBZ_COUNT_OPS
    if (!opcounts) return RGBZ_EINVAL;
    workers = 1;
#endif
    const int R = f->radius;
    ptrdiff_t *colmap = malloc((size_t)(cols + 2 * R) * sizeof *colmap);
    if (!colmap) return RGBZ_ENOMEM;
    for (ptrdiff_t x = -R; x < cols + R; x++) colmap[x + R] = lrn_extend(x, cols, px);
    const int f64 = precision == RGBZ_P_FLOAT64;
    const int fast_ok = lrn_fast_ok(f, py, px, phase_map);
    switch (in_type) {
    case RGBZ_T_U8:
        status = f64 ? LRN_CALL(u8, f64, uint8_t) : LRN_CALL(u8, f32, uint8_t);
        break;
    case RGBZ_T_U16:
        status = f64 ? LRN_CALL(u16, f64, uint16_t) : LRN_CALL(u16, f32, uint16_t);
        break;
    case RGBZ_T_F32:
        status = f64 ? LRN_CALL(f32, f64, float) : LRN_CALL(f32, f32, float);
        break;
    case RGBZ_T_F64:
        status = f64 ? LRN_CALL(f64, f64, double) : LRN_CALL(f64, f32, double);
        break;
    default:
        status = RGBZ_EINVAL;
    }
    free(colmap);
    return status;
}
