"""Write csrc/recon_mask2.h and its sites' template: SG on Mask2 as straight-line vector code.

    python tools/gen_recon_mask2.py           # rewrite the two headers
    python tools/gen_recon_mask2.py --check   # exit 1 if they are not what it would write

The plan interpreter (csrc/recon_core.template.h) runs a block of sites one
stage at a time, each stage a pass over the block through scratch rows in L1
(the gradient sums, the gammas, beta's sums, the weights): on SG Mask2 about
half of its instructions are those passes' loads, stores and loop set-up
(docs/reports/benchmarks.md, "SG Mask2 as straight-line code"). This script
writes each SG plan that ``_plans.build_plans`` gives Mask2 at its four Bayer
phases (12 distinct plans; sg_mode "auto" = "combined", the intensity domain)
as one function whose loop body computes a vector of 16 sites from their taps to
the result: every operation of the interpreter on the same values in the same
order (the same IEEE operations: the same bits), the intermediate values in
registers. The header holds each plan's bytes too; the frame loop runs a
function only on a plan equal to them byte for byte (any other plan, a changed
``_plans.py``, float64, other exponentials: the interpreter).
tests/reconstruction/test_recon_mask2.py checks the header is this script's output and that
the results equal the interpreter's bit for bit.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "csrc" / "recon_mask2.h"
OUT_SITES = ROOT / "csrc" / "recon_mask2_sites.template.h"


def _f(x):
    """A double of the plan as the C source the core converts to float: (float)<repr>."""
    return f"(float){float(x)!r}"


def _plan_body(p, fid):
    """The C function of one plan: a vector of RGBZ_M2_W sites from its taps (tap t at
    src[t] + j0) to its results (two vectors a step, their statements interleaved, ran slower:
    26.5 against 22.8 ms a 12 MP frame on 1 thread, the registers spilled; the taps through an
    array of pointers the caller filled for each vector, src[t] = v[t] + j0, 1.10x slower on 2
    threads than the block's own pointers and an offset)."""
    nt, nc, npairs = int(p["n_taps"]), int(p["n_cand"]), int(p["n_pairs"])
    assert int(p["use_ab"]) == int(p["use_grad"]) == int(p["use_sg"]) == 1, "combined SG"
    assert int(p["use_cd"]) == 0 and int(p["sum_from_zero"]) == 1
    assert int(p["gamma_mask"]) == 0xFFF and all(p["group_scale"][g] > 0 for g in range(12))
    assert nc in (8, 11) and int(p["sg_scaled"]) == 1
    L = []

    def st(text, indent=4):
        L.append(" " * indent + text)

    L.append(f"/* Z site {fid}: {nt} taps, {nc} candidates, {npairs} pairs */")
    L.append(f"RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site{fid})(const float *const *src, "
             "int j0, rgbz_v16 floor_,")
    L.append("                                                  rgbz_v16 rel, int REL, "
             "float *restrict out)")
    L.append("{")
    for t in range(nt):
        st(f"const rgbz_v16 t{t} = rgbz_v16_load(src[{t}] + j0);")
    # the group sums: each group's differences added in the plan's pair order, the first
    # assigned (rgbz_groups_block with sum_from_zero)
    started = set()
    for i in range(npairs):
        a, b, m = int(p["pair_a"][i]), int(p["pair_b"][i]), int(p["pair_gmask"][i])
        st(f"const rgbz_v16 d{i} = rgbz_v16_abs(t{a} - t{b});")
        for g in range(12):
            if (m >> g) & 1:
                if g in started:
                    st(f"G{g} = G{g} + d{i};")
                else:
                    st(f"rgbz_v16 G{g} = d{i};")
                    started.add(g)
    assert started == set(range(12)), "every group has a difference"
    # the gammas of each family (rgbz_gammas_full)
    for g0, ng, nm in ((0, 8, "s"), (8, 4, "g")):
        for q in range(ng):
            st(f"const rgbz_v16 gm{g0 + q} = G{g0 + q} * {_f(p['group_scale'][g0 + q])};")
        st(f"rgbz_v16 {nm}min = gm{g0};")
        for q in range(1, ng):
            st(f"{nm}min = M2_MIN(gm{g0 + q}, {nm}min);")
        st(f"rgbz_v16 {nm}sg = M2_MAX({nm}min, floor_);")
        L.append("    if (REL) {")
        st(f"rgbz_v16 {nm}sum = gm{g0};", 8)
        for q in range(1, ng):
            st(f"{nm}sum = {nm}sum + gm{g0 + q};", 8)
        st(f"const rgbz_v16 {nm}rf = (rel * {nm}sum) / (float){ng};", 8)
        st(f"{nm}sg = M2_MAX({nm}rf, {nm}sg);", 8)
        L.append("    }")
        st(f"const rgbz_v16 {nm}ninv = -(1.0f / (2.0f * ({nm}sg * {nm}sg)));")
        # the family's exponentials: rgbz_exp_poly_f32's (rgbz_ops.h) operations in its
        # order, step by step across the family
        fam = range(g0, g0 + ng)
        for g in fam:
            st(f"const rgbz_v16 x{g} = (gm{g} * gm{g}) * {nm}ninv;")
        # (rgbz_exp_poly_f32 clamps x to -87 first; a lane below gets 0 from the last select
        # whatever the steps give it -- no float-to-integer conversion here --, so x itself)
        for g in fam:
            st(f"const rgbz_v16 et{g} = x{g} * 1.44269504f + 12582912.0f;")
        for g in fam:
            st(f"const rgbz_v16 en{g} = M2_RINT(x{g} * 1.44269504f, et{g});")
        # (x - en ln2_hi: the product is exact -- en an integer of at most 7 bits where the
        # result is kept, ln2_hi 9 --, so one fused operation gives the same bits: M2_XMC1)
        for g in fam:
            st(f"const rgbz_v16 ey{g} = M2_XMC1(x{g}, en{g}) - "
               f"en{g} * -2.12194440e-4f;")
        for g in fam:
            st(f"rgbz_v16 ep{g} = 1.0f / 120 + ey{g} * (1.0f / 720);")
        for c in ("1.0f / 24", "1.0f / 6", "0.5f", "1.0f", "1.0f"):
            for g in fam:
                st(f"ep{g} = {c} + ey{g} * ep{g};")
        for g in fam:
            st(f"const rgbz_v16 ga{g} = M2_EXPOUT(x{g}, ep{g}, et{g}, "
               f"en{g});")
    # beta's sums (rgbz_beta_sums): pairs (k, m), k < m, k outer
    ct = [int(p["cand_tap"][k]) for k in range(nc)]
    for k in range(nc):
        st(f"const rgbz_v16 c{k} = rgbz_v16_load(src[{ct[k]}] + j0);")
    for k in range(nc):
        st(f"rgbz_v16 S{k} = rgbz_v16_set(1.0f);")
    for k in range(nc):
        for m in range(k + 1, nc):
            # (S_k's additions through M2_ADD, S_m's plain: the two kinds of floating-point
            # pipe share the sums, the same bits)
            st(f"{{ const rgbz_v16 e = rgbz_v16_abs(c{k} - c{m}); "
               f"S{k} = M2_ADD(S{k}, e); S{m} = S{m} + e; }}")
    # the weights and the weighted mean (rgbz_weigh_sg, combined: alpha / S * gamma(ori) * sv)
    st("rgbz_v16 den, num = rgbz_v16_set(0.0f);")
    for k in range(nc):
        rows = [g for g in range(8) if (int(p["cand_sgmask"][k]) >> g) & 1]
        assert 1 <= len(rows) <= 4
        sv = f"ga{rows[0]}"
        for g in rows[1:]:
            sv = f"({sv} + ga{g})"
        ori = 8 + int(p["cand_ori"][k])
        w = f"((({_f(p['cand_alpha'][k])}) / S{k}) * ga{ori}) * ({sv} * {_f(p['cand_sgscale'][k])})"
        if k == 0:
            st(f"den = {w};")
        else:
            st(f"{{ const rgbz_v16 w = {w}; den = den + w; "
               f"num = num + w * (c{k} - c0); }}")
    st("const rgbz_v16i ok = den > 0.0f;")
    st("const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));")
    st(f"rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);")
    L.append("    if (!M2_ALLPOS(den)) {")
    L.append("        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):")
    L.append("           the plain mean of the candidates (rgbz_mean_block) */")
    st(f"rgbz_v16 s = c1 - c0;", 8)
    for k in range(2, nc):
        st(f"s = s + (c{k} - c0);", 8)
    st(f"res = rgbz_v16_sel(ok, res, c0 + s / (float){nc});", 8)
    L.append("    }")
    st("rgbz_v16_store(out, res);")
    L.append("}")
    L.append("")
    return L


HEAD = r'''/*
 * recon_mask2.h -- WRITTEN BY tools/gen_recon_mask2.py: do not edit; run the script.
 *
 * SG on Mask2 (the four Bayer phases, sg_mode "combined", the intensity domain, float32, the fast
 * exponential): each distinct Z-site plan of _plans.py (12) as straight-line code over
 * 16 sites at a time (GCC's vector extensions: 16 float lanes, split by GCC into what each
 * clone has, so every clone computes the same IEEE operations; -std=c99 implies
 * -ffp-contract=off: no FMA of them). GCC's first scheduling pass, off by default on x86, is
 * on for these functions (with register pressure): the code is long chains of dependent
 * operations, interleaved by it (SG Mask2 on 1 thread 22.8 against 28.3 ms a 12 MP
 * frame). Every value the interpreter computes (recon_core.template.h: the group sums
 * in the plan's pair order, the gammas of rgbz_gammas_full, beta's sums of rgbz_beta_sums,
 * the weights of rgbz_weigh_sg, the weighted mean and its fallback) is computed by the same
 * operations in the same order: the results are the interpreter's, bit for bit
 * (tests/test_recon_mask2.py); only where the values live changes (registers, not a block's
 * scratch rows). rgbz_m2_plan_bytes holds each plan as _plans.py builds it: the frame loop
 * runs rgbz_m2_run on a plan equal to one of them byte for byte, the interpreter on any
 * other.
 */
#ifndef RECON_MASK2_H
#define RECON_MASK2_H

#include <stdint.h>
#include <string.h>
#include "rgbz.h"
#include "rgbz_ops.h"

#if defined(__GNUC__) && !defined(RGBZ_COUNT_OPS)
#define RGBZ_HAVE_M2 1
#pragma GCC push_options
#pragma GCC optimize("schedule-insns", "sched-pressure")

/* lanes per vector: RGBZ_M2_W sites at a time (one AVX-512 register; two AVX2 or four SSE2
   registers in the other clones) */
#define RGBZ_M2_W 16
typedef float rgbz_v16 __attribute__((vector_size(4 * RGBZ_M2_W)));
typedef int32_t rgbz_v16i __attribute__((vector_size(4 * RGBZ_M2_W)));
typedef uint32_t rgbz_v16u __attribute__((vector_size(4 * RGBZ_M2_W)));

static inline rgbz_v16 rgbz_v16_load(const float *p)
{
    rgbz_v16 x;
    memcpy(&x, p, sizeof x);
    return x;
}

static inline void rgbz_v16_store(float *p, rgbz_v16 x)
{
    memcpy(p, &x, sizeof x);
}

static inline rgbz_v16 rgbz_v16_set(float c)
{
    rgbz_v16 x;
    for (int i = 0; i < RGBZ_M2_W; i++) x[i] = c;
    return x;
}

/* fabsf's bits: the sign cleared */
static inline rgbz_v16 rgbz_v16_abs(rgbz_v16 x)
{
    return (rgbz_v16)((rgbz_v16u)x & 0x7fffffffu);
}

/* m ? a : b per lane (m a comparison's result: all ones or all zeros) */
static inline rgbz_v16 rgbz_v16_sel(rgbz_v16i m, rgbz_v16 a, rgbz_v16 b)
{
    return (rgbz_v16)(((rgbz_v16i)a & m) | ((rgbz_v16i)b & ~m));
}

static inline int rgbz_v16_all(rgbz_v16i m)
{
    int32_t a = -1;
    for (int i = 0; i < RGBZ_M2_W; i++) a &= m[i];
    return a != 0;
}

'''

TEMPLATE_HEAD = r'''/*
 * recon_mask2_sites.template.h -- WRITTEN BY tools/gen_recon_mask2.py: do not edit; run the
 * script. Included twice by recon_mask2.h, once per instance:
 *   M2_FN(name)            the instance's name of a function (name_g, name_x)
 *   M2_ATTR                its target attribute (none; AVX-512F)
 *   M2_MIN(a, b)           a < b ? a : b per lane (x86's MINPS exactly)
 *   M2_MAX(a, b)           a > b ? a : b per lane (MAXPS exactly)
 *   M2_ADD(a, b)           a + b, or the same sum as a fused multiply-add a * 1 + b on the
 *                          multiplier's pipes (exact: the same bits)
 *   M2_XMC1(x, en)         x - en * 0.693359375f, or the same as one fused operation (the
 *                          product exact where it matters: the same bits)
 *   M2_ALLPOS(d)           1 if every lane of d is > 0 (a NaN is not)
 *   M2_RINT(v, et)         v rounded to an integer, ties to even: et - 1.5 * 2^23 with
 *                          et = v + 1.5 * 2^23 (rgbz_exp_poly_f32's way), or VRNDSCALEPS of v
 *                          (|v| < 2^22 where it matters: the same value)
 *   M2_EXPOUT(x, p, et, en)  the exponential's last step: x > -87 ? p * 2^en : 0, 2^en from
 *                          et's bits times p (rgbz_exp_poly_f32), or VSCALEFPS of p and en
 *                          under the comparison's mask (exact, the results normal: the same
 *                          bits)
 * and undefined again at its end.
 */
'''

TEMPLATE_TAIL = r'''
/*
 * The n sites of a block (v tap-major, recon_core.template.h) through the function of plan k
 * (an index of rgbz_m2_plan_bytes), RGBZ_M2_W at a time; the last vector of a block whose n
 * is not a multiple of it runs on a copy of its taps padded with zeros, and only its results
 * for the n sites are kept.
 */
M2_ATTR static void M2_FN(rgbz_m2_run)(int k, const float *const *v, int n, float floor_,
                                       float rel, float *restrict r)
{
    const rgbz_v16 fl = rgbz_v16_set(floor_), rl = rgbz_v16_set(rel);
    const int REL = rel > 0.0f;
    const int nt = rgbz_m2_ntaps[k];
    for (int j0 = 0; j0 < n; j0 += RGBZ_M2_W) {
        const float *pp[RGBZ_MAX_TAPS];
        float pad[RGBZ_MAX_TAPS][RGBZ_M2_W], res[RGBZ_M2_W];
        const int m = n - j0 < RGBZ_M2_W ? n - j0 : RGBZ_M2_W;
        /* a whole vector reads its taps at v[t] + j0; the last, padded, at pp[t] + 0 */
        const float *const *src = v;
        int at = j0;
        if (m < RGBZ_M2_W) {
            for (int t = 0; t < nt; t++) {
                for (int i = 0; i < RGBZ_M2_W; i++) pad[t][i] = i < m ? v[t][j0 + i] : 0.0f;
                pp[t] = pad[t];
            }
            src = pp;
            at = 0;
        }
        float *o = m == RGBZ_M2_W ? r + j0 : res;
#define RGBZ_M2_CASE_(K)                                                                  \
        case K:                                                                           \
            if (REL) M2_FN(rgbz_m2_site##K)(src, at, fl, rl, 1, o);                       \
            else M2_FN(rgbz_m2_site##K)(src, at, fl, rl, 0, o);                           \
            break;
        switch (k) {
            RGBZ_M2_CASES_
        default: break;
        }
#undef RGBZ_M2_CASE_
        if (m < RGBZ_M2_W) memcpy(r + j0, res, (size_t)m * sizeof(float));
    }
}
'''

TAIL = r'''
/* the instance every clone compiles: AVX2 and the baseline (the AVX-512F one is below) */
#define M2_FN(name) name##_g
#define M2_ATTR
#define M2_ADD(a, b) ((a) + (b))
#define M2_XMC1(x, en) ((x) - (en) * 0.693359375f)
#define M2_ALLPOS(d) rgbz_v16_all((d) > 0.0f)
#define M2_MIN(a, b) rgbz_v16_sel((a) < (b), (a), (b))
#define M2_MAX(a, b) rgbz_v16_sel((a) > (b), (a), (b))
#define M2_RINT(v, et) ((et) - 12582912.0f)
#define M2_EXPOUT(x, p, et, en)                                                         \
    rgbz_v16_sel((x) > -87.0f, (p) * (rgbz_v16)(((rgbz_v16u)(et) << 23) + (127u << 23)), \
                 rgbz_v16_set(0.0f))
#include "recon_mask2_sites.template.h"

/* with AVX-512F: the selects of sigma's minimum and maxima as VMINPS / VMAXPS, the
   exponential's rounding as VRNDSCALEPS and its 2^n and last select as a masked VSCALEFPS,
   one instruction each for two or three; x - en ln2_hi as one VFNMADD (its product exact);
   half of beta's additions as VFMADD by 1 (the adders' two pipes were the busier: 1.03x);
   the fallback's test as one mask comparison (it was 16 lane extractions); the same values
   (SG Mask2 on 1 thread 1.05x the speed of the instance without the last three,
   docs/reports/benchmarks.md) */
#if RGBZ_HAVE_CLONES      /* rgbz_ops.h: x86-64, GCC, glibc, the clones built */
#define RGBZ_M2_X 1
#include <immintrin.h>
#define M2_FN(name) name##_x
#define M2_ATTR __attribute__((target("avx512f")))
#define M2_ADD(a, b) ((rgbz_v16)_mm512_fmadd_ps((__m512)(a), _mm512_set1_ps(1.0f), (__m512)(b)))
#define M2_XMC1(x, en) \
    ((rgbz_v16)_mm512_fnmadd_ps((__m512)(en), _mm512_set1_ps(0.693359375f), (__m512)(x)))
#define M2_ALLPOS(d) \
    (_mm512_cmp_ps_mask((__m512)(d), _mm512_setzero_ps(), _CMP_GT_OQ) == (__mmask16)0xFFFF)
#define M2_MIN(a, b) ((rgbz_v16)_mm512_min_ps((__m512)(a), (__m512)(b)))
#define M2_MAX(a, b) ((rgbz_v16)_mm512_max_ps((__m512)(a), (__m512)(b)))
#define M2_RINT(v, et)                                                                   \
    ((void)(et), /* not needed here: the compiler drops it */                            \
     (rgbz_v16)_mm512_roundscale_ps((__m512)(v), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC))
#define M2_EXPOUT(x, p, et, en)                                                          \
    ((rgbz_v16)_mm512_maskz_scalef_ps(                                                    \
        _mm512_cmp_ps_mask((__m512)(x), _mm512_set1_ps(-87.0f), _CMP_GT_OQ), (__m512)(p), \
        (__m512)(en)))
#include "recon_mask2_sites.template.h"
#else
#define RGBZ_M2_X 0
#endif

/* 1: run the generic instance even where AVX-512F is (rgbz_mask2_generic, for the tests
   that compare the two instances) */
static int rgbz_m2_generic_only = 0;

/* rgbz_m2_run_x where the CPU runs AVX-512F (as the clones' resolver decides), else the
   generic instance's clone for the CPU */
static void rgbz_m2_run(int k, const float *const *v, int n, float floor_, float rel,
                        float *restrict r)
{
#if RGBZ_M2_X
    if (!rgbz_m2_generic_only && __builtin_cpu_supports("avx512f")) {
        rgbz_m2_run_x(k, v, n, floor_, rel, r);
        return;
    }
#endif
    rgbz_m2_run_g(k, v, n, floor_, rel, r);
}

/* the index of the plan in rgbz_m2_plan_bytes equal to p byte for byte, or -1 */
static inline int rgbz_m2_index(const rgbz_plan *p)
{
    for (int k = 0; k < RGBZ_M2_NPLANS; k++)
        if (!memcmp(p, rgbz_m2_plan_bytes[k], sizeof(rgbz_plan))) return k;
    return -1;
}

#pragma GCC pop_options
#else
#define RGBZ_HAVE_M2 0
#endif /* __GNUC__ && !RGBZ_COUNT_OPS */

#endif /* RECON_MASK2_H */
'''


def generate():
    from rgbz_fast._patterns import get_pattern
    from rgbz_fast.reconstruction import _plans

    # the Z-site plans of Mask2 at the four Bayer phases, each once (GRBG's first)
    # (the bytes as build_plans leaves them, its padding zeros included: the frame loop
    # compares whole structs)
    raws = []
    for phase in ("GRBG", "RGGB", "BGGR", "GBRG"):
        _, pl = _plans.build_plans(get_pattern(f"mask2_{phase.lower()}"), "sg")
        raws += [r for r in (p.tobytes() for p in pl) if r not in raws]
    plans = np.frombuffer(b"".join(raws), dtype=_plans.PLAN_DTYPE)
    tpl = [TEMPLATE_HEAD]
    for k, p in enumerate(plans):
        body = _plan_body(p, k)
        tpl.extend(line + "\n" for line in body)
    tpl.append(TEMPLATE_TAIL)
    tpl.append("\n/* the instance's parameters, for the next one */\n"
               + "".join(f"#undef {m}\n" for m in ("M2_FN", "M2_ATTR", "M2_MIN", "M2_MAX",
                                                    "M2_ADD", "M2_XMC1", "M2_ALLPOS",
                                                    "M2_RINT", "M2_EXPOUT")))
    out = [HEAD]
    out.append(f"#define RGBZ_M2_NPLANS {len(plans)}\n")
    out.append("static const int rgbz_m2_ntaps[RGBZ_M2_NPLANS] = {"
               + ", ".join(str(int(p["n_taps"])) for p in plans) + "};\n")
    out.append("#define RGBZ_M2_CASES_ " + " ".join(f"RGBZ_M2_CASE_({k})"
                                                   for k in range(len(plans))) + "\n")
    out.append(f"/* the plans as _plans.py builds them (rgbz_plan, {plans.dtype.itemsize} bytes, "
               "little-endian) */\n")
    out.append(f"static const unsigned char rgbz_m2_plan_bytes[RGBZ_M2_NPLANS][{plans.dtype.itemsize}] = {{\n")
    for p in plans:
        raw = np.ascontiguousarray(p).tobytes()
        out.append("    {")
        for i in range(0, len(raw), 24):
            out.append("\n        " + ", ".join(str(b) for b in raw[i:i + 24]) + ",")
        out.append("\n    },\n")
    out.append("};\n")
    out.append(TAIL)
    return {OUT: "".join(out), OUT_SITES: "".join(tpl)}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="exit 1 if the header differs")
    a = ap.parse_args(argv)
    files = generate()
    if a.check:
        bad = [f for f, text in files.items() if not (f.exists() and f.read_text() == text)]
        for f in files:
            print(f"{f.relative_to(ROOT)}: {'DIFFERS from the script' if f in bad else 'up to date'}")
        return 1 if bad else 0
    for f, text in files.items():
        f.write_text(text)
        print(f"wrote {f.relative_to(ROOT)} ({len(text.splitlines())} lines)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
