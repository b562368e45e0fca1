/*
 * sim.c -- the per-pixel work of the sensor simulation (see sim.h for the API and the
 * counters of the random numbers, sim_rng.h for the generator).
 *
 * The noise chain of a sample (the module docstring of rgbz_fast.simulation._simulate and
 * its NumPy code in _noise.py, operation by operation):
 *   e = max(m (1 + prnu z0), 0) if prnu else m;  e = e + dark;  e = Poisson(e) if shot;
 *   e = max(e - suppress, 0) (ToF; drained = e < suppress);  e = e + dsnu z1 if dsnu;
 *   full = e >= full_well;
 *   e = min(e, full_well);  e = e + read_noise z;  dn = black + gain e;
 *   dn = floor(dn + 0.5) if quantise;  sat = full | drained | dn >= top | dn < 0;
 *   dn = clip(dn, 0, top)
 * Without noise no term that needs a random number or the fixed pattern runs.
 *
 * Work is split in chunks of CHUNK samples of one row (colour) or CHUNK sites (ToF): a
 * vectorised pass computes the means and the fixed pattern, a scalar pass the Poisson
 * variates, a vectorised pass the rest; threads take chunks (OpenMP), and every random
 * number is a function of its sample's position, so the result does not depend on them.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rgbz_ops.h"
#include "sim.h"
#include "sim_rng.h"

enum {
    SIM_CHUNK = 256,
};

#define SIM_TAG_FPN (1u << 24)
#define SIM_TAG_POISSON (2u << 24)
#define SIM_TAG_READ (3u << 24)

#if defined(__GNUC__) && !defined(__clang__)
#define SIM_SIMD _Pragma("GCC ivdep")
#else
#define SIM_SIMD
#endif

#ifdef _OPENMP
/* (a _Pragma string is not macro-expanded: the reduced local is nsat) */
#define SIM_PARALLEL_FOR_SUM \
    _Pragma("omp parallel for schedule(dynamic, 4) reduction(+:nsat) num_threads(nth)")
#define SIM_PARALLEL_FOR _Pragma("omp parallel for schedule(dynamic, 4) num_threads(nth)")
#else
#define SIM_PARALLEL_FOR_SUM
#define SIM_PARALLEL_FOR
#endif

/* ------------------------------------------------------------------ keys and tests */

void rgbz_sim_key(const uint64_t *words, ptrdiff_t nwords, uint64_t stream, uint32_t key[4])
{
    uint64_t h = sim_mix64(stream ^ 0x5349534D52474Aull);
    for (ptrdiff_t i = 0; i < nwords; i++) h = sim_mix64(h ^ words[i]);
    h = sim_mix64(h ^ (uint64_t)nwords);
    const uint64_t g = sim_mix64(h ^ 0x6B65792D68696768ull);
    key[0] = (uint32_t)h;
    key[1] = (uint32_t)(h >> 32);
    key[2] = (uint32_t)g;
    key[3] = (uint32_t)(g >> 32);
}

int rgbz_sim_blocks(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t c3, const uint32_t key[4],
                    ptrdiff_t n, uint32_t *out)
{
    if (!key || !out || n < 0) return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++)
        sim_block(c0 + (uint32_t)i, c1, c2, c3, key, out + 4 * i, out + 4 * i + 1,
                  out + 4 * i + 2, out + 4 * i + 3);
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ Z sites */

int rgbz_sim_z_sites(const uint8_t *tile_z, int P, int Q, ptrdiff_t rows, ptrdiff_t cols,
                     int block, int64_t *site_r, int64_t *site_c, ptrdiff_t *count,
                     int workers)
{
    if (!tile_z || !count || P < 1 || Q < 1 || rows < 1 || cols < 1 ||
        (block != 1 && block != 2))
        return RGBZ_EINVAL;
    /* the sites of a row depend on its phase y % P only: count them once per phase */
    ptrdiff_t *per_phase = (ptrdiff_t *)calloc((size_t)P, sizeof(ptrdiff_t));
    if (!per_phase) return RGBZ_ENOMEM;
    for (int py = 0; py < P; py++)
        for (ptrdiff_t x = 0; x + block <= cols; x += block)
            per_phase[py] += tile_z[py * Q + x % Q] != 0;
    const ptrdiff_t nrows = rows < block ? 0 : (rows - block) / block + 1;
    ptrdiff_t k = 0;
    for (ptrdiff_t t = 0; t < nrows; t++) k += per_phase[(t * block) % P];
    *count = k;
    if (site_r) {
        /* rows in parallel, each at the offset of the rows before it */
        /* the caller's threads (it had been every core: simulate(workers=1) started a team
           of OMP_NUM_THREADS) */
        const int nth = rgbz_threads(workers);
        (void)nth;
        SIM_PARALLEL_FOR
        for (ptrdiff_t t = 0; t < nrows; t++) {
            const ptrdiff_t y = t * block;
            ptrdiff_t o = 0;
            const ptrdiff_t full = t / P * P;        /* whole periods of rows before t */
            for (int py = 0; py < P; py++) o += per_phase[(py * block) % P] * (full / P);
            for (ptrdiff_t u = full; u < t; u++) o += per_phase[(u * block) % P];
            const uint8_t *tz = tile_z + (y % P) * Q;
            for (ptrdiff_t x = 0; x + block <= cols; x += block) {
                if (!tz[x % Q]) continue;
                site_r[o] = y;
                site_c[o] = x;
                o++;
            }
        }
    }
    free(per_phase);
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ the noise chain */

/* the mean before the shot noise: PRNU (z0 the first fixed-pattern normal), dark signal */
static inline double sim_pre(double m, double z0, double prnu, int with_prnu, double dark)
{
    double e = m;
    if (with_prnu) {
        const double g = 1.0 + prnu * z0;
        e = m * g;
        e = e > 0.0 ? e : 0.0;
    }
    return e + dark;
}

/* after the shot noise: suppression, DSNU, well, read noise, ADC; *sat set; the DN */
static inline double sim_post(double e, double suppress, int with_suppress, double offset,
                              int with_offset, double zr, int with_read,
                              const rgbz_sim_noise *nz, int *sat)
{
    /* the suppression drains at most what the tap holds: a tap of a deeply modulated pixel
       holding less than the share s of the DC charge is emptied, not made negative (it had
       held down to -300 e- unflagged and read as valid), and flagged like a clipped one */
    if (with_suppress) e = e - suppress;
    const int drained = e < 0.0;          /* never without a suppression: e >= 0 there */
    e = e > 0.0 ? e : 0.0;
    if (with_offset) e = e + offset;
    const int full = e >= nz->full_well;
    e = e < nz->full_well ? e : nz->full_well;
    if (with_read) e = e + nz->read_noise * zr;
    double dn = nz->black + nz->gain * e;
    if (nz->quantise) dn = floor(dn + 0.5);
    /* the ADC's floor clips too: a tap the ambient suppression drains below the black
       level's reach had read 0 DN unflagged, its depth biased and valid */
    *sat = full | drained | (dn >= nz->top) | (dn < 0.0);
    dn = dn < 0.0 ? 0.0 : dn;
    return dn > nz->top ? nz->top : dn;
}

/* ------------------------------------------------------------------ vectorised draws */

/* z0[i], z1[i]: the two normals of the block (c0[i], c1[i], c2, 0) */
RGBZ_CLONES_512
static void sim_bm(const uint32_t *restrict c0, const uint32_t *restrict c1, uint32_t c2,
                   const uint32_t key[4], ptrdiff_t n, double *restrict z0, double *restrict z1)
{
    const uint32_t k[4] = {key[0], key[1], key[2], key[3]};
    SIM_SIMD
    for (ptrdiff_t i = 0; i < n; i++) {
        double a, b;
        sim_normals(c0[i], c1[i], c2, 0, k, &a, &b);
        z0[i] = a;
        z1[i] = b;
    }
}

/* one attempt of PTRS for the means lam[p] >= 10 at counters (c0[p], c1[p], c2, j): the
   candidate k[p], state[p] = 1 accepted by the quick test, 2 rejected, 0 undecided, and
   for the slow test us[p] = 0.5 - |U| and v[p] = V */
RGBZ_CLONES_512
static void sim_ptrs_attempt(const double *restrict lam, const uint32_t *restrict c0,
                             const uint32_t *restrict c1, uint32_t c2, uint32_t j,
                             const uint32_t key[4], ptrdiff_t n, double *restrict k,
                             int32_t *restrict state, double *restrict us_out,
                             double *restrict v_out)
{
    const uint32_t kk4[4] = {key[0], key[1], key[2], key[3]};
    SIM_SIMD
    for (ptrdiff_t p = 0; p < n; p++) {
        uint32_t w0, w1, w2, w3;
        double b, a, invalpha, vr;
        sim_block(c0[p], c1[p], c2, j, kk4, &w0, &w1, &w2, &w3);
        sim_ptrs_consts(lam[p], &b, &a, &invalpha, &vr);
        const double U = sim_u53(w0, w1) - 0.5, V = sim_u53(w2, w3);
        const double us = 0.5 - fabs(U);
        const int32_t ok = us > 0.0;                 /* U = -0.5 would give k = -inf */
        const double uss = ok ? us : 1.0;
        const double kk = floor((2.0 * a / uss + b) * U + lam[p] + 0.43);
        const int32_t quick = ok & (us >= 0.07) & (V <= vr);
        const int32_t reject = (!ok) | (kk < 0.0) | ((us < 0.013) & (V > us));
        k[p] = kk;
        state[p] = quick | ((reject & !quick) << 1);
        us_out[p] = uss;
        v_out[p] = V;
    }
}

/* the slow test of PTRS for the undecided candidates k[p] (k >= 0, us > 0): accept[p] when
   log(V) + log(invalpha) - log(a / us^2 + b) <= -lam + k log(lam) - log(k!), the left side
   as the log of one quotient */
RGBZ_CLONES_512
static void sim_ptrs_slow(const double *restrict lam, const double *restrict k,
                          const double *restrict us, const double *restrict v, ptrdiff_t n,
                          int32_t *restrict accept)
{
    SIM_SIMD
    for (ptrdiff_t p = 0; p < n; p++) {
        double b, a, invalpha, vr;
        sim_ptrs_consts(lam[p], &b, &a, &invalpha, &vr);
        const double vs = v[p] > 0.0 ? v[p] : 1.0;   /* log(0) = -inf: always accepted */
        const double lhs = sim_log_any(vs * invalpha / (a / (us[p] * us[p]) + b));
        const double rhs = -lam[p] + k[p] * sim_log_any(lam[p]) - sim_loggam_int(k[p] + 1.0);
        accept[p] = (v[p] <= 0.0) | (lhs <= rhs);
    }
}

/* the vectorised part of the inversion of small means lam[q] (sim_inv_start) */
RGBZ_CLONES_512
static void sim_inv_fill(const double *restrict lam, const uint32_t *restrict c0,
                         const uint32_t *restrict c1, uint32_t c2, const uint32_t key[4],
                         ptrdiff_t n, double *restrict x, double *restrict u, double *restrict p,
                         double *restrict F)
{
    const uint32_t k[4] = {key[0], key[1], key[2], key[3]};
    SIM_SIMD
    for (ptrdiff_t q = 0; q < n; q++) sim_inv_start(lam[q], c0[q], c1[q], c2, k, &x[q], &u[q],
                                                    &p[q], &F[q]);
}

/* The sort of the first PTRS attempt's samples (sim_poisson_fill): e[i] the accepted
   candidate pk[i] (lam >= 10, state 1), lam (lam >= 10 or 0 < lam < 10) or 0; the indices of
   the small means (0 < lam < 10), of the open ones (lam >= 10, state 0) and of the rejected
   ones (lam >= 10, state 2) appended to their lists, in order. Returns how far it went (a
   multiple of 8; the caller sorts the rest) with the lists' lengths in len[3]. With the
   compressing stores of AVX-512 when the CPU has them (the same lists and values as the
   caller's scalar loop), else nothing. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
__attribute__((target("avx512f,avx512vl")))
static ptrdiff_t sim_sort_avx512(double *e, const int32_t *state, const double *pk,
                                 ptrdiff_t n, int32_t *small, int32_t *open_, int32_t *pend,
                                 ptrdiff_t len[3])
{
    const __m512d ten = _mm512_set1_pd(10.0), zero = _mm512_setzero_pd();
    const __m256i one = _mm256_set1_epi32(1), two = _mm256_set1_epi32(2),
                  z = _mm256_setzero_si256(), eight = _mm256_set1_epi32(8);
    __m256i idx = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    ptrdiff_t ns = len[0], no = len[1], np = len[2], i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m512d lam = _mm512_loadu_pd(e + i);
        const __m256i st = _mm256_loadu_si256((const __m256i *)(state + i));
        const __mmask8 big = _mm512_cmp_pd_mask(lam, ten, _CMP_GE_OQ);
        const __mmask8 pos = _mm512_cmp_pd_mask(lam, zero, _CMP_GT_OQ);
        const __mmask8 is_small = (__mmask8)(~big & pos);
        const __mmask8 is_open = big & _mm256_cmpeq_epi32_mask(st, z);
        const __mmask8 is_pend = big & _mm256_cmpeq_epi32_mask(st, two);
        const __mmask8 acc = big & _mm256_cmpeq_epi32_mask(st, one);
        __m512d out = _mm512_maskz_mov_pd((__mmask8)(big | is_small), lam);
        out = _mm512_mask_loadu_pd(out, acc, pk + i);
        _mm512_storeu_pd(e + i, out);
        _mm256_mask_compressstoreu_epi32(small + ns, is_small, idx);
        _mm256_mask_compressstoreu_epi32(open_ + no, is_open, idx);
        _mm256_mask_compressstoreu_epi32(pend + np, is_pend, idx);
        ns += __builtin_popcount(is_small);
        no += __builtin_popcount(is_open);
        np += __builtin_popcount(is_pend);
        idx = _mm256_add_epi32(idx, eight);
    }
    len[0] = ns;
    len[1] = no;
    len[2] = np;
    return i;
}

static ptrdiff_t sim_sort_fast(double *e, const int32_t *state, const double *pk, ptrdiff_t n,
                               int32_t *small, int32_t *open_, int32_t *pend, ptrdiff_t len[3])
{
    static int have = -1;
    if (have < 0)
        have = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
    return have ? sim_sort_avx512(e, state, pk, n, small, open_, pend, len) : 0;
}
#else
static ptrdiff_t sim_sort_fast(double *e, const int32_t *state, const double *pk, ptrdiff_t n,
                               int32_t *small, int32_t *open_, int32_t *pend, ptrdiff_t len[3])
{
    (void)e; (void)state; (void)pk; (void)n; (void)small; (void)open_; (void)pend; (void)len;
    return 0;
}
#endif

/* e[i] <- a Poisson variate of mean e[i] (i < n, n <= SIM_CHUNK), attempt j at the counter
   (c0[i], c1[i], c2, j): below a mean of 10 the inversion of the distribution function
   (one uniform, attempt 0), above it PTRS. The first attempt of PTRS runs over every sample
   in place (the small means' candidates are dropped), its slow test over those the quick
   test leaves open; the next attempts over the samples still undecided. */
static void sim_poisson_fill(double *e, const uint32_t *c0, const uint32_t *c1, uint32_t c2,
                             const uint32_t key[4], ptrdiff_t n)
{
    int32_t pend[SIM_CHUNK], state[SIM_CHUNK], open_[SIM_CHUNK], small[SIM_CHUNK];
    int32_t verdict[SIM_CHUNK];
    uint32_t pc0[SIM_CHUNK], pc1[SIM_CHUNK];
    double plam[SIM_CHUNK], pk[SIM_CHUNK], pus[SIM_CHUNK], pv[SIM_CHUNK];
    double slam[SIM_CHUNK], sk[SIM_CHUNK], sus[SIM_CHUNK], sv[SIM_CHUNK], pq[SIM_CHUNK];
    ptrdiff_t np = 0, ns = 0, nsmall = 0;
    sim_ptrs_attempt(e, c0, c1, c2, 0, key, n, pk, state, pus, pv);
    ptrdiff_t len[3] = {0, 0, 0};
    const ptrdiff_t sorted = sim_sort_fast(e, state, pk, n, small, open_, pend, len);
    nsmall = len[0];
    ns = len[1];
    np = len[2];
    /* sorted without branches (their outcome is random): each index written at the end of
       every list, the list's length advanced by its flag */
    for (ptrdiff_t i = sorted; i < n; i++) {
        const double lam = e[i];
        const int big = lam >= 10.0, st = state[i];
        const int is_small = !big & (lam > 0.0);
        const int is_open = big & (st == 0), is_pend = big & (st == 2);
        e[i] = big & (st == 1) ? pk[i] : (big | is_small ? lam : 0.0);
        small[nsmall] = (int32_t)i;
        nsmall += is_small;
        open_[ns] = (int32_t)i;
        ns += is_open;
        pend[np] = (int32_t)i;
        np += is_pend;
    }
    /* the slow test reads the first attempt's candidates (pk, pus, pv at the samples' own
       indices) before the small means' inversion takes those arrays as scratch: in the
       other order a chunk that mixed means below and above 10 gave its open samples
       another sample's candidate (shot noise of 800 for 1000 e- beside 5 e- pixels) */
    if (ns) {
        for (ptrdiff_t q = 0; q < ns; q++) {
            const int32_t i = open_[q];
            slam[q] = e[i];
            sk[q] = pk[i];
            sus[q] = pus[i];
            sv[q] = pv[i];
        }
        sim_ptrs_slow(slam, sk, sus, sv, ns, verdict);
        for (ptrdiff_t q = 0; q < ns; q++) {
            const int32_t i = open_[q];
            e[i] = verdict[q] ? sk[q] : e[i];
            pend[np] = i;
            np += !verdict[q];
        }
    }
    if (nsmall) {
        for (ptrdiff_t q = 0; q < nsmall; q++) {
            plam[q] = e[small[q]];
            pc0[q] = c0[small[q]];
            pc1[q] = c1[small[q]];
        }
        sim_inv_fill(plam, pc0, pc1, c2, key, nsmall, pk, pus, pv, pq);
        for (ptrdiff_t q = 0; q < nsmall; q++)
            e[small[q]] = pk[q] < SIM_INV_STEPS ? pk[q]
                                                : sim_inv_finish(plam[q], pus[q], pv[q], pq[q]);
    }
    for (uint32_t j = 1; np > 0; j++) {
        for (ptrdiff_t p = 0; p < np; p++) {
            plam[p] = e[pend[p]];
            pc0[p] = c0[pend[p]];
            pc1[p] = c1[pend[p]];
        }
        sim_ptrs_attempt(plam, pc0, pc1, c2, j, key, np, pk, state, pus, pv);
        ns = 0;
        for (ptrdiff_t p = 0; p < np; p++) {
            open_[ns] = (int32_t)p;
            slam[ns] = plam[p];
            sk[ns] = pk[p];
            sus[ns] = pus[p];
            sv[ns] = pv[p];
            ns += state[p] == 0;
        }
        sim_ptrs_slow(slam, sk, sus, sv, ns, verdict);
        for (ptrdiff_t q = 0; q < ns; q++) state[open_[q]] = verdict[q] ? 1 : 2;
        /* accepted: the candidate; left for the next attempt: the rest */
        ptrdiff_t left = 0;
        for (ptrdiff_t p = 0; p < np; p++) {
            const int32_t i = pend[p];
            e[i] = state[p] == 1 ? pk[p] : e[i];
            pend[left] = i;
            left += state[p] != 1;
        }
        np = left;
    }
}

/* ------------------------------------------------------------------ colour */

static inline double sim_read(int type, const void *src, ptrdiff_t i)
{
    return type == RGBZ_T_F32 ? (double)((const float *)src)[i] : ((const double *)src)[i];
}

/* the per-column tables of every row phase: source offset (col stride and channel), per-unit
   signal, Z flag; NULL on a failed allocation */
typedef struct {
    ptrdiff_t *off;
    double *pu;
    uint8_t *z;
} sim_cols;

static int sim_cols_make(sim_cols *t, ptrdiff_t cols, ptrdiff_t col_stride,
                         const ptrdiff_t chan_off[3], const int32_t *tile, const uint8_t *tile_z,
                         int P, int Q, const double per_unit[3])
{
    t->off = (ptrdiff_t *)malloc((size_t)P * (size_t)cols * sizeof(ptrdiff_t));
    t->pu = (double *)malloc((size_t)P * (size_t)cols * sizeof(double));
    t->z = (uint8_t *)malloc((size_t)P * (size_t)cols);
    if (!t->off || !t->pu || !t->z) return RGBZ_ENOMEM;
    for (int py = 0; py < P; py++) {
        for (ptrdiff_t x = 0; x < cols; x++) {
            const int32_t ch = tile[py * Q + x % Q];
            t->off[py * cols + x] = x * col_stride + chan_off[ch];
            t->pu[py * cols + x] = per_unit[ch];
            t->z[py * cols + x] = tile_z ? tile_z[py * Q + x % Q] : 0;
        }
    }
    return RGBZ_OK;
}

static void sim_cols_free(sim_cols *t)
{
    free(t->off);
    free(t->pu);
    free(t->z);
}

static int sim_check_tile(const int32_t *tile, int P, int Q)
{
    if (!tile || P < 1 || Q < 1) return 0;
    for (int i = 0; i < P * Q; i++)
        if (tile[i] < 0 || tile[i] > 2) return 0;
    return 1;
}

/* the key of a rate: its IEEE bits, -0 as +0 (rates are >= 0) */
static inline uint32_t sim_rate_key16(double r)
{
    uint64_t b;
    r = r > 0.0 ? r : 0.0;
    memcpy(&b, &r, sizeof b);
    return (uint32_t)(b >> 48);
}

int rgbz_sim_rate_hist(int type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                       ptrdiff_t row_stride, ptrdiff_t col_stride, const ptrdiff_t chan_off[3],
                       const int32_t *tile, int P, int Q, const double per_unit[3],
                       uint64_t *hist, int workers)
{
    if (!src || !hist || !chan_off || !per_unit || rows < 1 || cols < 1 ||
        !sim_check_tile(tile, P, Q) || (type != RGBZ_T_F32 && type != RGBZ_T_F64))
        return RGBZ_EINVAL;
    sim_cols t;
    int status = sim_cols_make(&t, cols, col_stride, chan_off, tile, NULL, P, Q, per_unit);
    if (status != RGBZ_OK) {
        sim_cols_free(&t);
        return status;
    }
    memset(hist, 0, 65536 * sizeof(uint64_t));
    const int nth = rgbz_threads(workers);
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
    {
        uint64_t *h = (uint64_t *)calloc(65536, sizeof(uint64_t));
        if (!h) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            bad = 1;
        }
#ifdef _OPENMP
#pragma omp for schedule(static)
#endif
        for (ptrdiff_t y = 0; y < rows; y++) {
            if (!h) continue;
            const ptrdiff_t ph = (y % P) * cols;
            const ptrdiff_t base = y * row_stride;
            for (ptrdiff_t x = 0; x < cols; x++) {
                const double v = sim_read(type, src, base + t.off[ph + x]);
                h[sim_rate_key16(v * t.pu[ph + x])]++;
            }
        }
        if (h) {
#ifdef _OPENMP
#pragma omp critical(rgbz_sim_hist)
#endif
            for (int b = 0; b < 65536; b++) hist[b] += h[b];
            free(h);
        }
    }
    sim_cols_free(&t);
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}

int rgbz_sim_rate_gather(int type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                         ptrdiff_t row_stride, ptrdiff_t col_stride, const ptrdiff_t chan_off[3],
                         const int32_t *tile, int P, int Q, const double per_unit[3],
                         uint32_t lo16, uint32_t hi16, double *out, ptrdiff_t cap,
                         ptrdiff_t *count, int workers)
{
    if (!src || !out || !count || !chan_off || !per_unit || rows < 1 || cols < 1 || cap < 0 ||
        !sim_check_tile(tile, P, Q) || (type != RGBZ_T_F32 && type != RGBZ_T_F64))
        return RGBZ_EINVAL;
    sim_cols t;
    int status = sim_cols_make(&t, cols, col_stride, chan_off, tile, NULL, P, Q, per_unit);
    if (status != RGBZ_OK) {
        sim_cols_free(&t);
        return status;
    }
    /* one pass: a value in range takes the next slot (the order is the threads'; the caller
       sorts the values) */
    const int nth = rgbz_threads(workers);
    ptrdiff_t next = 0;
    (void)nth;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) num_threads(nth)
#endif
    for (ptrdiff_t y = 0; y < rows; y++) {
        const ptrdiff_t ph = (y % P) * cols, base = y * row_stride;
        for (ptrdiff_t x = 0; x < cols; x++) {
            const double r = sim_read(type, src, base + t.off[ph + x]) * t.pu[ph + x];
            const uint32_t k = sim_rate_key16(r);
            if (k >= lo16 && k <= hi16) {
                ptrdiff_t w;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
                w = next++;
                if (w < cap) out[w] = r;
            }
        }
    }
    *count = next;
    sim_cols_free(&t);
    return RGBZ_OK;
}

/* one chunk [x0, x1) of colour row y (x0 even). cx and cy are written whenever a draw reads
   them (the same flags guard both); GCC cannot follow the flags and warned at every clone */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
RGBZ_CLONES_512
static void sim_colour_chunk(int type, const void *src, ptrdiff_t y, ptrdiff_t x0, ptrdiff_t x1,
                             ptrdiff_t cols, ptrdiff_t row_stride, const sim_cols *t, int P,
                             double exposure, const rgbz_sim_noise *nz, void *ref, void *data,
                             int64_t *nsat)
{
    double e[SIM_CHUNK], z0[SIM_CHUNK], z1[SIM_CHUNK], zr[SIM_CHUNK];
    uint32_t cx[SIM_CHUNK], cy[SIM_CHUNK];
    const ptrdiff_t ph = (y % P) * cols, base = y * row_stride, n = x1 - x0;
    const int noise = nz->noise != 0;
    const int with_prnu = noise && nz->prnu != 0.0, with_dsnu = noise && nz->dsnu != 0.0;
    const int with_shot = noise && nz->shot, with_read = noise && nz->read_noise > 0.0;
    const double dark = nz->dark, prnu = nz->prnu, dsnu = nz->dsnu;
    const ptrdiff_t *o = t->off + ph + x0;
    const double *pu = t->pu + ph + x0;

    if (type == RGBZ_T_F32) {
        const float *s = (const float *)src + base;
        SIM_SIMD
        for (ptrdiff_t i = 0; i < n; i++) e[i] = (double)s[o[i]] * pu[i] * exposure;
    } else {
        const double *s = (const double *)src + base;
        SIM_SIMD
        for (ptrdiff_t i = 0; i < n; i++) e[i] = s[o[i]] * pu[i] * exposure;
    }
    if (with_prnu || with_dsnu || with_shot || with_read)
        for (ptrdiff_t i = 0; i < n; i++) {
            cx[i] = (uint32_t)(x0 + i);
            cy[i] = (uint32_t)y;
        }
    if (with_prnu || with_dsnu) sim_bm(cx, cy, SIM_TAG_FPN, nz->key_fpn, n, z0, z1);
    if (with_prnu) {
        SIM_SIMD
        for (ptrdiff_t i = 0; i < n; i++) e[i] = sim_pre(e[i], z0[i], prnu, 1, dark);
    } else {
        SIM_SIMD
        for (ptrdiff_t i = 0; i < n; i++) e[i] = sim_pre(e[i], 0.0, prnu, 0, dark);
    }
    if (with_shot) sim_poisson_fill(e, cx, cy, SIM_TAG_POISSON, nz->key_temporal, n);
    if (with_read) {
        /* the pairs (x / 2): normal x % 2 of block (x / 2, y, READ, 0) */
        const ptrdiff_t npair = (n + 1) / 2;
        double r0[SIM_CHUNK / 2], r1[SIM_CHUNK / 2];
        for (ptrdiff_t i = 0; i < npair; i++) cx[i] = (uint32_t)((x0 >> 1) + i);
        sim_bm(cx, cy, SIM_TAG_READ, nz->key_temporal, npair, r0, r1);
        for (ptrdiff_t i = 0; i < n; i++) zr[i] = (i & 1) ? r1[i >> 1] : r0[i >> 1];
    }
    int64_t sat_count = 0;
    SIM_SIMD
    for (ptrdiff_t i = 0; i < n; i++) {
        int sat;
        e[i] = sim_post(e[i], 0.0, 0, with_dsnu ? dsnu * z1[i] : 0.0, with_dsnu,
                        with_read ? zr[i] : 0.0, with_read, nz, &sat);
        sat_count += sat;
    }
    const ptrdiff_t o0 = y * cols + x0;
    const uint8_t *z = t->z + ph + x0;
    if (nz->quantise) {
        uint16_t *r = (uint16_t *)ref + o0;
        SIM_SIMD
        for (ptrdiff_t i = 0; i < n; i++) r[i] = (uint16_t)(int32_t)e[i];
        if (data) {
            uint16_t *d = (uint16_t *)data + o0;
            SIM_SIMD
            for (ptrdiff_t i = 0; i < n; i++) d[i] = z[i] ? (uint16_t)0 : r[i];
        }
    } else {
        double *r = (double *)ref + o0;
        for (ptrdiff_t i = 0; i < n; i++) r[i] = e[i];
        if (data) {
            double *d = (double *)data + o0;
            for (ptrdiff_t i = 0; i < n; i++) d[i] = z[i] ? 0.0 : e[i];
        }
    }
    *nsat += sat_count;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

int rgbz_sim_colour(int type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                    ptrdiff_t row_stride, ptrdiff_t col_stride, const ptrdiff_t chan_off[3],
                    const int32_t *tile, const uint8_t *tile_z, int P, int Q,
                    const double per_unit[3], double exposure, const rgbz_sim_noise *nz,
                    void *ref, void *data, int64_t *saturated, int workers)
{
    if (!src || !ref || !nz || !saturated || !chan_off || !per_unit || rows < 1 || cols < 1 ||
        !sim_check_tile(tile, P, Q) || (type != RGBZ_T_F32 && type != RGBZ_T_F64))
        return RGBZ_EINVAL;
    sim_cols t;
    int status = sim_cols_make(&t, cols, col_stride, chan_off, tile, tile_z, P, Q, per_unit);
    if (status != RGBZ_OK) {
        sim_cols_free(&t);
        return status;
    }
    const ptrdiff_t per_row = (cols + SIM_CHUNK - 1) / SIM_CHUNK, nchunks = rows * per_row;
    const int nth = rgbz_threads(workers);
    (void)nth;
    int64_t nsat = 0;
    SIM_PARALLEL_FOR_SUM
    for (ptrdiff_t k = 0; k < nchunks; k++) {
        const ptrdiff_t y = k / per_row, x0 = (k % per_row) * SIM_CHUNK;
        const ptrdiff_t x1 = x0 + SIM_CHUNK < cols ? x0 + SIM_CHUNK : cols;
        int64_t s = 0;
        sim_colour_chunk(type, src, y, x0, x1, cols, row_stride, &t, P, exposure, nz, ref,
                         data, &s);
        nsat += s;
    }
    sim_cols_free(&t);
    *saturated = nsat;
    return RGBZ_OK;
}

/* ------------------------------------------------------------------ ToF */

/* the noise chain of the taps of sites [i0, i1): mean (F, 4, SIM_CHUNK) electrons with the
   dark signal excluded, suppress per site (local index) or NULL; writes taps (F, 4, n) and
   sat */
RGBZ_CLONES_512
static void sim_tof_chain(double *mean, const double *suppress, const int64_t *site_r,
                          const int64_t *site_c, ptrdiff_t i0, ptrdiff_t i1, ptrdiff_t n,
                          int nfreq, const rgbz_sim_noise *nz, void *taps, uint8_t *sat)
{
    const ptrdiff_t m = i1 - i0;
    const int noise = nz->noise != 0;
    const int with_prnu = noise && nz->prnu != 0.0, with_dsnu = noise && nz->dsnu != 0.0;
    const int with_shot = noise && nz->shot, with_read = noise && nz->read_noise > 0.0;
    double gz[4][SIM_CHUNK], oz[4][SIM_CHUNK], r0[SIM_CHUNK], r1[SIM_CHUNK], sup[SIM_CHUNK];
    uint32_t cc[SIM_CHUNK], cr[SIM_CHUNK];
    uint8_t s[SIM_CHUNK];
    const int with_suppress = suppress != NULL;
    /* the suppressed charge read from a local copy: a masked load from NULL (the vectorised
       form of "suppress ? suppress[i] : 0") costs a microcode assist per vector */
    for (ptrdiff_t i = 0; i < m; i++) {
        s[i] = 0;
        cc[i] = (uint32_t)site_c[i0 + i];
        cr[i] = (uint32_t)site_r[i0 + i];
        sup[i] = with_suppress ? suppress[i] : 0.0;
    }
    if (with_prnu || with_dsnu) {
        for (int k = 0; k < 4; k++) {
            sim_bm(cc, cr, SIM_TAG_FPN + (uint32_t)k, nz->key_fpn, m, gz[k], oz[k]);
            for (ptrdiff_t i = 0; i < m; i++) oz[k][i] *= nz->dsnu;
        }
    } else {
        memset(gz, 0, sizeof gz);
        memset(oz, 0, sizeof oz);
    }
    if (!with_read) {
        memset(r0, 0, sizeof r0);
        memset(r1, 0, sizeof r1);
    }
    for (int f = 0; f < nfreq; f++) {
        for (int k = 0; k < 4; k++) {
            double *e = mean + (f * 4 + k) * SIM_CHUNK;
            const double *g = gz[k];
            if (with_prnu) {
                SIM_SIMD
                for (ptrdiff_t i = 0; i < m; i++) e[i] = sim_pre(e[i], g[i], nz->prnu, 1, nz->dark);
            } else {
                SIM_SIMD
                for (ptrdiff_t i = 0; i < m; i++) e[i] = sim_pre(e[i], 0.0, nz->prnu, 0, nz->dark);
            }
            if (with_shot)
                sim_poisson_fill(e, cc, cr, SIM_TAG_POISSON + (uint32_t)(4 * f + k),
                                 nz->key_temporal, m);
            if (with_read && !(k & 1))
                sim_bm(cc, cr, SIM_TAG_READ + (uint32_t)(2 * f + k / 2), nz->key_temporal, m,
                       r0, r1);
            const double *zr = (k & 1) ? r1 : r0;
            const double *off = oz[k];
            const ptrdiff_t o = (f * 4 + k) * n + i0;
            SIM_SIMD
            for (ptrdiff_t i = 0; i < m; i++) {
                int st;
                const double dn = sim_post(e[i], sup[i], with_suppress, off[i], with_dsnu,
                                           zr[i], with_read, nz, &st);
                s[i] |= (uint8_t)st;
                e[i] = dn;
            }
            if (nz->quantise) {
                uint16_t *t = (uint16_t *)taps + o;
                SIM_SIMD
                for (ptrdiff_t i = 0; i < m; i++) t[i] = (uint16_t)(int32_t)e[i];
            } else {
                memcpy((double *)taps + o, e, (size_t)m * sizeof(double));
            }
        }
    }
    for (ptrdiff_t i = 0; i < m; i++) sat[i0 + i] = s[i];
}

/* sin and cos of the C library (those of NumPy's complex exponential): glibc's sincos
   computes both with the same code as sin and cos, in one argument reduction */
#if defined(__GLIBC__)
extern void sincos(double x, double *s, double *c);
static inline void sim_sincos(double x, double *s, double *c) { sincos(x, s, c); }
#else
static inline void sim_sincos(double x, double *s, double *c)
{
    *s = sin(x);
    *c = cos(x);
}
#endif

static inline double sim_ir(int type, const void *ir, ptrdiff_t i, int estimate)
{
    double x = sim_read(type, ir, i);
    if (!estimate) return x;
    x = x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x);
    return 0.2 + 0.6 * x;
}

/* s e^{i phi} with phi = 4 pi f ds / c (mod 2 pi) over the cells of a chunk, vectorised: the
   phase as a fraction of a turn, u = frac(4 pi f ds / c / (2 pi)), its sine and cosine by
   sim_sincos2pi. The C library's sincos of (4 pi f ds / c) mod 2 pi, NumPy's, was a scalar
   call per cell and frequency (a quarter of a noise-free frame's time); this differs from it
   by a few units in the last place of the phasor (tests/simulation/test_pixels.py states
   the tolerance). */
RGBZ_CLONES_512
static void sim_tof_phasors(const double *restrict s, const double *restrict ds, ptrdiff_t m,
                            double four_pi_f, double speed_of_light, double two_pi,
                            double *restrict re, double *restrict im)
{
    SIM_SIMD
    for (ptrdiff_t i = 0; i < m; i++) {
        double u = four_pi_f * ds[i] / speed_of_light / two_pi;
        u = u - floor(u);
        double sn, cs;
        sim_sincos2pi(u, &sn, &cs);
        re[i] = s[i] * cs;
        im[i] = s[i] * sn;
    }
}

/* the light of sites [i0, i1): mean (F, 4, SIM_CHUNK) and suppress (SIM_CHUNK) */
static void sim_tof_light(const double *depth, const uint8_t *depth_valid, ptrdiff_t cols,
                          int ir_type, const void *ir, ptrdiff_t ir_rs, ptrdiff_t ir_cs,
                          int ir_estimate, const int64_t *site_r, const int64_t *site_c,
                          ptrdiff_t i0, ptrdiff_t i1, int block, const rgbz_sim_tof_light *L,
                          double dark, double *mean, double *suppress, double *depth_true,
                          uint8_t *valid, uint8_t *beyond, double *dmax)
{
    const int F = L->nfreq, ncell = block * block;
    const ptrdiff_t m = i1 - i0;
    /* per cell j and site li: the signal, the depth the phase is taken of, the total */
    double sig[4][SIM_CHUNK], dsv[4][SIM_CHUNK], tot[4][SIM_CHUNK];
    double pre[4][SIM_CHUNK], pim[4][SIM_CHUNK];
    for (ptrdiff_t i = i0; i < i1; i++) {
        const ptrdiff_t li = i - i0;
        double dd[4];
        int all_valid = 1, past = 0;
        for (int j = 0; j < ncell; j++) {
            const ptrdiff_t y = site_r[i] + j / block, x = site_c[i] + j % block;
            const double d = depth[y * cols + x];
            const int cv = depth_valid[y * cols + x] != 0;
            const double rho = sim_ir(ir_type, ir, y * ir_rs + x * ir_cs, ir_estimate);
            const int surface = d > 0.0;
            const double ds = surface ? d : 1.0;
            const double irr = L->power / (4.0 * ds * ds * L->th * L->tv);
            double amb = rho * L->ambient * L->k;
            if (L->duty != 1.0) amb = amb * L->duty;
            const double s = surface ? rho * irr * L->k : 0.0;
            sig[j][li] = s;
            dsv[j][li] = ds;
            tot[j][li] = s + amb;
            dd[j] = d;
            all_valid &= cv;
            if (cv) {
                past |= d >= L->unambiguous;
                if (d > *dmax) *dmax = d;
            }
        }
        double total, dsum;
        if (ncell == 1) {
            total = tot[0][li];
            dsum = dd[0];
        } else {
            /* NumPy's sums over the cells: real ones left to right */
            total = ((tot[0][li] + tot[1][li]) + tot[2][li]) + tot[3][li];
            dsum = ((dd[0] + dd[1]) + dd[2]) + dd[3];
        }
        tot[0][li] = total;
        suppress[li] = L->suppression * (0.25 * total + dark);
        depth_true[i] = dsum / (double)ncell;
        valid[i] = (uint8_t)all_valid;
        beyond[i] = (uint8_t)past;
    }
    for (int f = 0; f < F; f++) {
        for (int j = 0; j < ncell; j++)
            sim_tof_phasors(sig[j], dsv[j], m, L->four_pi_f[f], L->speed_of_light, L->two_pi,
                            pre[j], pim[j]);
        if (ncell != 1)           /* NumPy's sums of the complex cells: pairwise */
            for (ptrdiff_t li = 0; li < m; li++) {
                pre[0][li] = (pre[0][li] + pre[1][li]) + (pre[2][li] + pre[3][li]);
                pim[0][li] = (pim[0][li] + pim[1][li]) + (pim[2][li] + pim[3][li]);
            }
        for (int k = 0; k < 4; k++) {
            const double sr = L->shift_re[k], si = L->shift_im[k];
            double *out = mean + (f * 4 + k) * SIM_CHUNK;
            SIM_SIMD
            for (ptrdiff_t li = 0; li < m; li++)
                out[li] = 0.25 * tot[0][li] + L->c25 * (pre[0][li] * sr - pim[0][li] * si);
        }
    }
}

/* NumPy's remainder of a float64 by b (np.mod): fmod, moved into the divisor's sign, a
   zero given the divisor's sign */
static inline double sim_np_mod(double a, double b)
{
    double m = fmod(a, b);
    if (m != 0.0) {
        if ((b < 0.0) != (m < 0.0)) m += b;
    } else {
        m = copysign(0.0, b);
    }
    return m;
}

int rgbz_sim_tof_field(const double *d, const double *s, ptrdiff_t n, double four_pi_f,
                       double speed_of_light, double two_pi, int order, double *re, double *im,
                       int workers)
{
    if (!d || !s || !re || !im || n < 0 || order < 1) return RGBZ_EINVAL;
    const int nth = rgbz_threads(workers);
    const double h = (double)order;
    (void)nth;
#ifdef _OPENMP
#pragma omp parallel for schedule(static, 16384) num_threads(nth)
#endif
    for (ptrdiff_t i = 0; i < n; i++) {
        double ph = sim_np_mod(four_pi_f * d[i] / speed_of_light, two_pi);
        if (order != 1) ph = h * ph;
        double sn, cs;
        sim_sincos(ph, &sn, &cs);
        /* (s + 0i)(cos + i sin), as NumPy multiplies a real array by a complex one */
        re[i] = s[i] * cs - 0.0 * sn;
        im[i] = s[i] * sn + 0.0 * cs;
    }
    return RGBZ_OK;
}

int rgbz_sim_tof(const double *depth, const uint8_t *depth_valid, ptrdiff_t rows,
                 ptrdiff_t cols, int ir_type, const void *ir, ptrdiff_t ir_rs, ptrdiff_t ir_cs,
                 int ir_estimate, const int64_t *site_r, const int64_t *site_c, ptrdiff_t n,
                 int block, const rgbz_sim_tof_light *light, const rgbz_sim_noise *nz,
                 void *taps, double *depth_true, uint8_t *valid, uint8_t *beyond, uint8_t *sat,
                 double *max_depth, int workers)
{
    if (!depth || !depth_valid || !ir || !site_r || !site_c || !light || !nz || !taps ||
        !depth_true || !valid || !beyond || !sat || !max_depth || n < 0 || rows < 1 ||
        cols < 1 || (block != 1 && block != 2) || light->nfreq < 1 ||
        light->nfreq > RGBZ_TOF_MAX_FREQS || (ir_type != RGBZ_T_F32 && ir_type != RGBZ_T_F64))
        return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++)
        if (site_r[i] < 0 || site_c[i] < 0 || site_r[i] + block > rows ||
            site_c[i] + block > cols)
            return RGBZ_EINVAL;
    const ptrdiff_t nchunks = (n + SIM_CHUNK - 1) / SIM_CHUNK;
    const int nth = rgbz_threads(workers), F = light->nfreq;
    const int with_suppress = light->suppression != 0.0;
    double dmax = -INFINITY;
    (void)nth;
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth) reduction(max : dmax) reduction(| : bad)
#endif
    {
        double *mean = (double *)malloc((size_t)F * 4 * SIM_CHUNK * sizeof(double));
        double supp[SIM_CHUNK];
        bad |= mean == NULL;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 4)
#endif
        for (ptrdiff_t k = 0; k < nchunks; k++) {
            if (!mean) continue;
            const ptrdiff_t i0 = k * SIM_CHUNK, i1 = i0 + SIM_CHUNK < n ? i0 + SIM_CHUNK : n;
            sim_tof_light(depth, depth_valid, cols, ir_type, ir, ir_rs, ir_cs, ir_estimate,
                          site_r, site_c, i0, i1, block, light, nz->dark, mean, supp,
                          depth_true, valid, beyond, &dmax);
            sim_tof_chain(mean, with_suppress ? supp : NULL, site_r, site_c, i0, i1, n, F, nz,
                          taps, sat);
        }
        free(mean);
    }
    *max_depth = dmax;
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}

int rgbz_sim_tof_expose(const double *mean, const double *suppress, const int64_t *site_r,
                        const int64_t *site_c, ptrdiff_t n, int nfreq, const rgbz_sim_noise *nz,
                        void *taps, uint8_t *sat, int workers)
{
    if (!mean || !site_r || !site_c || !nz || !taps || !sat || n < 0 || nfreq < 1 ||
        nfreq > RGBZ_TOF_MAX_FREQS)
        return RGBZ_EINVAL;
    const ptrdiff_t nchunks = (n + SIM_CHUNK - 1) / SIM_CHUNK;
    const int nth = rgbz_threads(workers);
    (void)nth;
    int bad = 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth) reduction(| : bad)
#endif
    {
        double *buf = (double *)malloc((size_t)nfreq * 4 * SIM_CHUNK * sizeof(double));
        bad |= buf == NULL;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 4)
#endif
        for (ptrdiff_t k = 0; k < nchunks; k++) {
            if (!buf) continue;
            const ptrdiff_t i0 = k * SIM_CHUNK, i1 = i0 + SIM_CHUNK < n ? i0 + SIM_CHUNK : n;
            for (int p = 0; p < nfreq * 4; p++)
                memcpy(buf + p * SIM_CHUNK, mean + p * n + i0, (size_t)(i1 - i0) * sizeof(double));
            sim_tof_chain(buf, suppress ? suppress + i0 : NULL, site_r, site_c, i0, i1, n,
                          nfreq, nz, taps, sat);
        }
        free(buf);
    }
    return bad ? RGBZ_ENOMEM : RGBZ_OK;
}

/* ------------------------------------------------------------------ tests */

int rgbz_sim_variates(int kind, const double *lam, uint32_t c1, uint32_t c2,
                      const uint32_t key[4], ptrdiff_t n, double *out, int workers)
{
    if (!key || !out || n < 0 || (kind == 1 && !lam) || (kind != 0 && kind != 1))
        return RGBZ_EINVAL;
    const ptrdiff_t nchunks = (n + SIM_CHUNK - 1) / SIM_CHUNK;
    const int nth = rgbz_threads(workers);
    (void)nth;
    SIM_PARALLEL_FOR
    for (ptrdiff_t k = 0; k < nchunks; k++) {
        const ptrdiff_t i0 = k * SIM_CHUNK, m = i0 + SIM_CHUNK < n ? SIM_CHUNK : n - i0;
        uint32_t cc[SIM_CHUNK], cr[SIM_CHUNK];
        double z0[SIM_CHUNK], z1[SIM_CHUNK];
        for (ptrdiff_t i = 0; i < m; i++) cr[i] = c1;
        if (kind == 0) {
            /* normal i is number i % 2 of the block (i / 2, c1, c2, 0) */
            const ptrdiff_t npair = (m + 1) / 2;
            for (ptrdiff_t i = 0; i < npair; i++) cc[i] = (uint32_t)(i0 / 2 + i);
            sim_bm(cc, cr, c2, key, npair, z0, z1);
            for (ptrdiff_t i = 0; i < m; i++) out[i0 + i] = (i & 1) ? z1[i / 2] : z0[i / 2];
        } else {
            for (ptrdiff_t i = 0; i < m; i++) {
                cc[i] = (uint32_t)(i0 + i);
                out[i0 + i] = lam[i0 + i];
            }
            sim_poisson_fill(out + i0, cc, cr, c2, key, m);
        }
    }
    return RGBZ_OK;
}

int rgbz_sim_math(int which, const double *x, ptrdiff_t n, double *out)
{
    if (!x || !out || n < 0 || which < 0 || which > 2) return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++) {
        double s, c;
        if (which == 0) {
            out[i] = sim_log_any(x[i]);
        } else {
            sim_sincos2pi(x[i], &s, &c);
            out[i] = which == 1 ? s : c;
        }
    }
    return RGBZ_OK;
}
