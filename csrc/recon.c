/*
 * recon.c -- missing-colour reconstruction at the Z sites of an RGB-Z frame:
 * what its entry points share (the checks of the arguments and of the plans,
 * the column map), the plan layout, and the build information.
 *
 * Paper: Rebiere et al., section 4 (eqs. 2-19, Table 1); Shi et al.'s row
 * method (eqs. 1a-1e) (docs/references.bib: rebiere_rgbz, shi_rgbz). The
 * choices made where the paper is vague are listed in
 * docs/guide/interpretation.md.
 *
 * Layout: C-contiguous row-major frames, strides in elements (= cols).
 * Borders: a tap outside the frame is moved back by whole pattern periods
 * (rgbz_extend, recon.h), so it keeps its colour.
 * Code: recon_core.template.h is the per-site arithmetic (one core for every
 * method, pattern and option) and the entry point of a precision, compiled
 * once per precision, each in its own file (recon_f32.c, recon_f64.c);
 * recon_loop.template.h the frame loop, once per precision and element type
 * (u8, u16, f32, f64); recon_mask1.h the Mask1 plans as constants.
 */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdint.h>
#include "rgbz.h"
#include "rgbz_ops.h"
#include "recon.h"
#include "recon_mask1.h"
#include "rgbz_exp.h"

/* the operation counters of the plan being run (rgbz_ops.h) */
#ifdef RGBZ_COUNT_OPS
uint64_t *rgbz_opc_cur = NULL;
#endif

int rgbz_plan_layout(int64_t *out, int n)
{
    int64_t v[RGBZ_PLAN_FIELDS + 1] = {
        (int64_t)sizeof(rgbz_plan),
        (int64_t)offsetof(rgbz_plan, method), (int64_t)offsetof(rgbz_plan, use_ab),
        (int64_t)offsetof(rgbz_plan, tap_dy), (int64_t)offsetof(rgbz_plan, tap_dx),
        (int64_t)offsetof(rgbz_plan, cand_tap), (int64_t)offsetof(rgbz_plan, cand_ori),
        (int64_t)offsetof(rgbz_plan, cand_sgmask), (int64_t)offsetof(rgbz_plan, pair_a),
        (int64_t)offsetof(rgbz_plan, pair_b), (int64_t)offsetof(rgbz_plan, pair_gmask),
        (int64_t)offsetof(rgbz_plan, target), (int64_t)offsetof(rgbz_plan, use_cd),
        (int64_t)offsetof(rgbz_plan, cd_n), (int64_t)offsetof(rgbz_plan, cd_tap),
        (int64_t)offsetof(rgbz_plan, sum_from_zero), (int64_t)offsetof(rgbz_plan, gamma_mask),
        (int64_t)offsetof(rgbz_plan, cand_alpha), (int64_t)offsetof(rgbz_plan, cand_sgscale),
        (int64_t)offsetof(rgbz_plan, group_scale), (int64_t)offsetof(rgbz_plan, cd_w),
    };
    if (!out || n < RGBZ_PLAN_FIELDS + 1) return RGBZ_EINVAL;
    for (int i = 0; i <= RGBZ_PLAN_FIELDS; i++) out[i] = v[i];
    return RGBZ_OK;
}

int rgbz_mask1_plan(int method, int sg_combined, rgbz_plan *out)
{
    const int i = rgbz_mask1_index(method, sg_combined);
    if (!out || i < 0) return RGBZ_EINVAL;
    *out = *rgbz_mask1_plans[i];
    return RGBZ_OK;
}

static int rgbz_check_plans(const rgbz_plan *plans, int n_plans, int *ry, int *rx)
{
    *ry = 0;
    *rx = 0;
    for (int i = 0; i < n_plans; i++) {
        const rgbz_plan *p = &plans[i];
        if (p->method < RGBZ_M_BILINEAR || p->method > RGBZ_M_EDI_ROWS) return RGBZ_EINVAL;
        if (p->n_taps < 1 || p->n_taps > RGBZ_MAX_TAPS) return RGBZ_EINVAL;
        if (p->n_cand < 0 || p->n_cand > RGBZ_MAX_CAND) return RGBZ_EINVAL;
        if (p->n_pairs < 0 || p->n_pairs > RGBZ_MAX_PAIRS) return RGBZ_EINVAL;
        if (p->method == RGBZ_M_EDI_ROWS ? p->n_taps != 10 : p->n_cand < 1) return RGBZ_EINVAL;
        if (p->gamma_mask < 0 || p->gamma_mask >= (1 << RGBZ_NGROUPS)) return RGBZ_EINVAL;
        for (int t = 0; t < p->n_taps; t++) {
            int ady = abs(p->tap_dy[t]), adx = abs(p->tap_dx[t]);
            if (ady > RGBZ_MAX_RADIUS || adx > RGBZ_MAX_RADIUS) return RGBZ_EINVAL;
            if (ady > *ry) *ry = ady;
            if (adx > *rx) *rx = adx;
        }
        for (int k = 0; k < p->n_cand; k++) {
            if (p->cand_tap[k] < 0 || p->cand_tap[k] >= p->n_taps) return RGBZ_EINVAL;
            if (p->cand_ori[k] < 0 || p->cand_ori[k] > 3) return RGBZ_EINVAL;
            if (p->cand_sgmask[k] < 0 || p->cand_sgmask[k] >= (1 << 8)) return RGBZ_EINVAL;
        }
        if (p->use_cd)
            for (int k = 0; k <= p->n_cand; k++) {
                if (p->cd_n[k] < 1 || p->cd_n[k] > RGBZ_MAX_CD) return RGBZ_EINVAL;
                for (int m = 0; m < p->cd_n[k]; m++)
                    if (p->cd_tap[k][m] < 0 || p->cd_tap[k][m] >= p->n_taps) return RGBZ_EINVAL;
            }
        for (int k = 0; k < p->n_pairs; k++)
            if (p->pair_a[k] < 0 || p->pair_a[k] >= p->n_taps || p->pair_b[k] < 0 ||
                p->pair_b[k] >= p->n_taps || p->pair_gmask[k] <= 0 ||
                p->pair_gmask[k] >= (1 << RGBZ_NGROUPS) ||
                rgbz_popcount((uint32_t)p->pair_gmask[k]) > RGBZ_MAX_PAIR_GROUPS)
                return RGBZ_EINVAL;
    }
    return RGBZ_OK;
}

int rgbz_recon_setup(const void *src, const void *dst, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map, const rgbz_plan *plans, int n_plans,
                     const rgbz_params *prm, const uint64_t *opcounts, int *ry, int *rx,
                     ptrdiff_t **colmap)
{
    if (!src || !dst || !phase_map || !plans || !prm || n_plans < 1) return RGBZ_EINVAL;
    if (py < 1 || px < 1 || rows < py || cols < px) return RGBZ_EINVAL;
    for (int i = 0; i < py * px; i++)
        if (phase_map[i] < -1 || phase_map[i] >= n_plans) return RGBZ_EINVAL;
#ifdef RGBZ_COUNT_OPS
    if (!opcounts) return RGBZ_EINVAL;
#else
    (void)opcounts;
#endif
    int st = rgbz_check_plans(plans, n_plans, ry, rx);
    if (st != RGBZ_OK) return st;
    if (prm->mask1_fast) {
        /* the caller vouches for the Mask1 geometry; check what the constant plans rely
           on: the interior sites run the one of the plan's method */
        const rgbz_plan *p = &plans[0];
        int nz = 0;
        for (int i = 0; i < py * px; i++) nz += phase_map[i] >= 0;
        if (py != 2 || px != 2 || n_plans != 1 || nz != 1 || p->use_cd || p->n_cand != 4 ||
            rgbz_mask1_index(p->method, p->use_grad && p->use_sg) < 0)
            return RGBZ_EINVAL;
    }
    /* the Mask1 constant plans know nothing of clipping: the sites with a clipped tap run
       again on plans[0] (recon_loop.template.h); the counting build, whose counts would
       then hold both, keeps the two apart */
    if (prm->clip_on && !(prm->clip_level == prm->clip_level)) return RGBZ_EINVAL;
#ifdef RGBZ_COUNT_OPS
    if (prm->clip_on && prm->mask1_fast) return RGBZ_EINVAL;
#endif

    /* column map for x in [-rx, cols + rx): shared, read-only, O(cols) */
    const int r = *rx;
    ptrdiff_t *cm = (ptrdiff_t *)malloc((size_t)(cols + 2 * r) * sizeof(ptrdiff_t));
    if (!cm) return RGBZ_ENOMEM;
    for (ptrdiff_t i = 0; i < cols + 2 * r; i++) cm[i] = rgbz_extend(i - r, cols, px);
    *colmap = cm;
    return RGBZ_OK;
}

/* rgbz_exp.h's ports of glibc's exp() and expf() stand in for them only where they give
   their bits: the CPU runs AVX-512F (where fma() is an instruction and the ports' row
   functions run) and this machine's exp() / expf() agree with them on a sweep of arguments
   (eq. 7's are in [-128, 0] with the default sigma_rel, beyond with others). */
#ifdef RGBZ_HAVE_EXP_VEC
/* a fixed sequence in [0, 1): xorshift64 */
static double rgbz_exp_sweep_u(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) * 0x1p-53;
}

__attribute__((target("avx512f")))
static int rgbz_exp_vec_agrees(void)
{
    static const double edges[] = {0.0, -0.0, -0x1p-54, -0x1.fffffffffffffp-1, -1.0, -0.5,
                                   -0x1.62e42fefa39efp-8, -0x1.62e42fefa39efp-9, -36.0,
                                   -127.99999999999999, -128.0, -511.99999999999994, 0x1p-54,
                                   1.0, 88.5, 511.99999999999994};
    for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++)
        if (rgbz_exp_asu64(rgbz_exp_glibc_f64(edges[i])) != rgbz_exp_asu64(exp(edges[i])))
            return 0;
    uint64_t s = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < 4096; i++) {
        const double u = rgbz_exp_sweep_u(&s);
        const double x = i % 4 == 3 ? -600.0 * u : i % 4 == 2 ? -8.0 * u : -128.0 * u;
        if (rgbz_exp_glibc_covers(x)
                && rgbz_exp_asu64(rgbz_exp_glibc_f64(x)) != rgbz_exp_asu64(exp(x)))
            return 0;
    }
    return 1;
}

__attribute__((target("avx512f")))
static int rgbz_expf_vec_agrees(void)
{
    static const float edges[] = {0.0f, -0.0f, -0x1p-60f, -0x1.fffffep-1f, -1.0f, -0.5f,
                                  -36.0f, -87.99999f, -0x1p-149f, 1.0f, 87.99999f};
    for (size_t i = 0; i < sizeof edges / sizeof edges[0]; i++) {
        const float a = rgbz_expf_glibc_f32(edges[i]), b = expf(edges[i]);
        if (memcmp(&a, &b, sizeof a)) return 0;
    }
    uint64_t s = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < 4096; i++) {
        const double u = rgbz_exp_sweep_u(&s);
        const float x = (float)(i % 2 ? -88.0 * u : -8.0 * u);
        const float a = rgbz_expf_glibc_f32(x), b = expf(x);
        if (rgbz_expf_glibc_covers(x) && memcmp(&a, &b, sizeof a)) return 0;
    }
    return 1;
}
#endif

int rgbz_exp_libm_vectorised(int single)
{
#ifdef RGBZ_HAVE_EXP_VEC
    static volatile int ready[2] = {-1, -1};     /* a race computes the same answer twice */
    const int k = single != 0;
    if (ready[k] < 0)
        ready[k] = __builtin_cpu_supports("avx512f")
                   && (k ? rgbz_expf_vec_agrees() : rgbz_exp_vec_agrees());
    return ready[k];
#else
    (void)single;
    return 0;
#endif
}

/* the ports themselves, value by value (whatever this machine's exp() / expf() gives): what
   the tests hold to a model of glibc's algorithms */
int rgbz_exp_port_f64(const double *x, double *out, ptrdiff_t n)
{
    if (!x || !out || n < 0) return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++) out[i] = rgbz_exp_glibc_f64(x[i]);
    return RGBZ_OK;
}

int rgbz_exp_port_f32(const float *x, float *out, ptrdiff_t n)
{
    if (!x || !out || n < 0) return RGBZ_EINVAL;
    for (ptrdiff_t i = 0; i < n; i++) out[i] = rgbz_expf_glibc_f32(x[i]);
    return RGBZ_OK;
}

int rgbz_have_openmp(void)
{
#ifdef _OPENMP
    return 1;
#else
    return 0;
#endif
}

int rgbz_openmp_release(void)
{
    /* the calling thread's OpenMP threads ended (they are started again at the next
       parallel region): called before a fork, so that the child, which has none of them,
       does not wait on them forever at its first parallel region (libgomp's pool does not
       survive fork) */
#if defined(_OPENMP) && (_OPENMP >= 201811 || \
                         (defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 10))
    /* OpenMP 5.0; GCC's libgomp has it from GCC 10 while its _OPENMP still says 4.5 */
    return omp_pause_resource_all(omp_pause_hard);
#else
    return 0;
#endif
}

int rgbz_max_threads(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

int rgbz_opcount_target(uint64_t *counts)
{
#ifdef RGBZ_COUNT_OPS
    if (!counts) return RGBZ_EINVAL;
    rgbz_opc_cur = counts;
#else
    (void)counts;
#endif
    return RGBZ_OK;
}

int rgbz_counting_build(void)
{
#ifdef RGBZ_COUNT_OPS
    return 1;
#else
    return 0;
#endif
}
