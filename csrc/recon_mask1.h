/*
 * recon_mask1.h -- the plans of the Mask1 pattern as compile-time constants (data
 * only: recon_core.template.h is the one code that runs them).
 *
 * Mask1 (paper §3.2, Fig. 4) is a Bayer tile whose green on one colour row is a Z
 * pixel; around every Z site, at any of the four phases: Z pixels at (even, even)
 * offsets, one colour X at (even, odd), the other Y at (odd, even), green at
 * (odd, odd). The four candidates are the greens (-1,-1), (-1,1), (1,-1), (1,1)
 * (Fig. 11: pixels 6, 8, 16, 18 of the 5x5 kernel). The plans below are those
 * _plans.py builds for this geometry (tests/test_kernels.py compares them field by
 * field), with two differences that change no value:
 *
 *  - the order of the pairs in the EDICentral and EDILine gradients (Fig. 7, eqs. 8-11).
 *    The frames' interior sites have always been computed with the sums in the
 *    order below (the hand-written Mask1 kernels of rgbz-fast 0.1: vertical
 *    gradient rows +-2 first, EDICentral diagonals (1,1), (2,1), (1,2)), their
 *    border sites with the plans of _plans.py ((1,1), (1,2), (2,1); rows +-1
 *    first). Float addition is not associative, so each keeps its own order:
 *    results stay bit-identical to the published ones (tests/golden/);
 *  - sum_from_zero = 0 and, for BI and the EDI methods, gamma_mask = the two
 *    diagonal gammas (every Mask1 candidate is diagonal; the vertical and
 *    horizontal gradients only set sigma): the operation counts of those kernels
 *    (docs/reports/opcount.md, "fast" rows).
 *
 * The Z rows and the two border rows and columns of a frame are not interior:
 * they run the plans of _plans.py through the column map (recon_loop.template.h).
 */
#ifndef RECON_MASK1_H
#define RECON_MASK1_H

#include "rgbz.h"

/* The taps: the 16 colour pixels of the 5x5 window (dy, dx), named m2 m1 0 p1 p2 for
   -2 -1 0 +1 +2; the green candidates first (BI and bilinear gather only those). */
#define RGBZ_M1_TAPS(X)                                                                  \
    X(m1m1, -1, -1) X(m1p1, -1, 1) X(p1m1, 1, -1) X(p1p1, 1, 1)  /* green candidates */ \
    X(z0m1, 0, -1) X(z0p1, 0, 1) X(m2m1, -2, -1) X(m2p1, -2, 1) /* X: Z rows */         \
    X(p2m1, 2, -1) X(p2p1, 2, 1)                                                          \
    X(m1z0, -1, 0) X(p1z0, 1, 0) X(m1m2, -1, -2) X(m1p2, -1, 2) /* Y: Z columns */      \
    X(p1m2, 1, -2) X(p1p2, 1, 2)

#define RGBZ_M1_TAP_ENUM(name, dy, dx) M1_##name,
#define RGBZ_M1_TAP_DY(name, dy, dx) dy,
#define RGBZ_M1_TAP_DX(name, dy, dx) dx,
enum { RGBZ_M1_TAPS(RGBZ_M1_TAP_ENUM) RGBZ_M1_NTAPS };

/* groups (rgbz.h): semi-gradients 0..7 N S W E NW NE SW SE, gradients 8..11 V H D1 D2 */
#define M1G(g) (1 << (g))
#define M1_N M1G(0)
#define M1_S M1G(1)
#define M1_W M1G(2)
#define M1_E M1G(3)
#define M1_NW M1G(4)
#define M1_NE M1G(5)
#define M1_SW M1G(6)
#define M1_SE M1G(7)
#define M1_V M1G(8)
#define M1_H M1G(9)
#define M1_D1 M1G(10)   /* NW-SE (eq. 11; orientation 2) */
#define M1_D2 M1G(11)   /* NE-SW (eq. 10; orientation 3) */

/* pair lists: X(tap a, tap b, groups), in the order of the sums */
#define RGBZ_M1_CENTRAL_PAIRS(X)                                          \
    X(p1z0, m1z0, M1_V) X(z0p1, z0m1, M1_H)                                \
    X(p1p1, m1m1, M1_D1) X(p2p1, m2m1, M1_D1) X(p1p2, m1m2, M1_D1)         \
    X(p1m1, m1p1, M1_D2) X(p2m1, m2p1, M1_D2) X(p1m2, m1p2, M1_D2)

/* eq. 8: rows -2/2 at odd columns, then rows -1/1 at every column; eq. 9 its transpose;
   eqs. 11 and 10: mirror pairs across the anti-diagonal and the main diagonal, one
   green pair and six red/blue ("inter-channel") pairs each */
#define RGBZ_M1_LINE_PAIRS(X)                                                            \
    X(m2m1, p2m1, M1_V) X(m2p1, p2p1, M1_V) X(m1m2, p1m2, M1_V) X(m1m1, p1m1, M1_V)      \
    X(m1z0, p1z0, M1_V) X(m1p1, p1p1, M1_V) X(m1p2, p1p2, M1_V)                          \
    X(m1m2, m1p2, M1_H) X(p1m2, p1p2, M1_H) X(m2m1, m2p1, M1_H) X(m1m1, m1p1, M1_H)      \
    X(z0m1, z0p1, M1_H) X(p1m1, p1p1, M1_H) X(p2m1, p2p1, M1_H)                          \
    X(m1p2, m2p1, M1_D1) X(z0p1, m1z0, M1_D1) X(p1z0, z0m1, M1_D1) X(p1p1, m1m1, M1_D1)  \
    X(p1p2, m2m1, M1_D1) X(p2m1, p1m2, M1_D1) X(p2p1, m1m2, M1_D1)                       \
    X(m1m2, m2m1, M1_D2) X(z0m1, m1z0, M1_D2) X(p1m2, m2p1, M1_D2) X(p1m1, m1p1, M1_D2)  \
    X(p1z0, z0p1, M1_D2) X(p2m1, m1p2, M1_D2) X(p2p1, p1p2, M1_D2)

/* eqs. 14-18: the two differences of each semi-gradient that touch no Z pixel; each
   difference serves two semi-gradients (two-term sums: their order is immaterial) */
#define RGBZ_M1_SG_PAIRS(X)                                                              \
    X(z0m1, m2m1, M1_N | M1_NW) X(z0p1, m2p1, M1_N | M1_NE) X(z0m1, p2m1, M1_S | M1_SW)  \
    X(z0p1, p2p1, M1_S | M1_SE) X(m1z0, m1m2, M1_W | M1_NW) X(p1z0, p1m2, M1_W | M1_SW)  \
    X(m1z0, m1p2, M1_E | M1_NE) X(p1z0, p1p2, M1_E | M1_SE)

/* SG with sg_mode "combined": the semi-gradients' pairs, then EDILine's */
#define RGBZ_M1_COMBINED_PAIRS(X) RGBZ_M1_SG_PAIRS(X) RGBZ_M1_LINE_PAIRS(X)

#define RGBZ_M1_PAIR_A(a, b, g) M1_##a,
#define RGBZ_M1_PAIR_B(a, b, g) M1_##b,
#define RGBZ_M1_PAIR_G(a, b, g) g,
#define RGBZ_M1_PAIR_N(a, b, g) +1
/* the pair fields of a plan from a pair list */
#define RGBZ_M1_PAIRS(LIST)                                                              \
    .n_pairs = 0 LIST(RGBZ_M1_PAIR_N), .pair_a = {LIST(RGBZ_M1_PAIR_A)},                  \
    .pair_b = {LIST(RGBZ_M1_PAIR_B)}, .pair_gmask = {LIST(RGBZ_M1_PAIR_G)}

/* alpha (eq. 3) of a diagonal neighbour: exp(-(1 + 1) / 2) = exp(-1), the double
   _plans.py computes with math.exp */
#define RGBZ_M1_ALPHA 0.36787944117144233

#define RGBZ_M1_COMMON                                                                   \
    .n_cand = 4, .target = 1, .cand_tap = {M1_m1m1, M1_m1p1, M1_p1m1, M1_p1p1},          \
    .cand_ori = {2, 3, 3, 2},                                                            \
    .cand_alpha = {RGBZ_M1_ALPHA, RGBZ_M1_ALPHA, RGBZ_M1_ALPHA, RGBZ_M1_ALPHA},          \
    .tap_dy = {RGBZ_M1_TAPS(RGBZ_M1_TAP_DY)}, .tap_dx = {RGBZ_M1_TAPS(RGBZ_M1_TAP_DX)}

/* eq. 19: the semi-gradients covering each candidate (N+W+NW, N+E+NE, S+W+SW, S+E+SE) */
#define RGBZ_M1_SG_COVER .cand_sgmask = {M1_N | M1_W | M1_NW, M1_N | M1_E | M1_NE,       \
                                         M1_S | M1_W | M1_SW, M1_S | M1_E | M1_SE}

static const rgbz_plan rgbz_mask1_bilinear = {
    RGBZ_M1_COMMON, .method = RGBZ_M_BILINEAR, .n_taps = 4,
};

static const rgbz_plan rgbz_mask1_bi = {
    RGBZ_M1_COMMON, .method = RGBZ_M_BI, .n_taps = 4, .use_ab = 1,
};

static const rgbz_plan rgbz_mask1_edi_central = {
    RGBZ_M1_COMMON, .method = RGBZ_M_EDI_CENTRAL, .n_taps = RGBZ_M1_NTAPS,
    .use_ab = 1, .use_grad = 1, .gamma_mask = M1_D1 | M1_D2,
    RGBZ_M1_PAIRS(RGBZ_M1_CENTRAL_PAIRS),
    .group_scale = {[8] = 1.0, [9] = 1.0, [10] = 1.0 / 3.0, [11] = 1.0 / 3.0},
};

static const rgbz_plan rgbz_mask1_edi_line = {
    RGBZ_M1_COMMON, .method = RGBZ_M_EDI_LINE, .n_taps = RGBZ_M1_NTAPS,
    .use_ab = 1, .use_grad = 1, .gamma_mask = M1_D1 | M1_D2,
    RGBZ_M1_PAIRS(RGBZ_M1_LINE_PAIRS),
    .group_scale = {[8] = 1.0 / 7.0, [9] = 1.0 / 7.0, [10] = 1.0 / 7.0, [11] = 1.0 / 7.0},
};

/* SG, the paper's Mask1 method (sg_mode "pure"): the semi-gradient weights alone */
static const rgbz_plan rgbz_mask1_sg = {
    RGBZ_M1_COMMON, .method = RGBZ_M_SG, .n_taps = RGBZ_M1_NTAPS, .use_sg = 1,
    .gamma_mask = 0xff, RGBZ_M1_SG_COVER,
    RGBZ_M1_PAIRS(RGBZ_M1_SG_PAIRS),
    .group_scale = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5},
};

/* SG with sg_mode "combined": EDILine's weights times the semi-gradient weights */
static const rgbz_plan rgbz_mask1_sg_combined = {
    RGBZ_M1_COMMON, .method = RGBZ_M_SG, .n_taps = RGBZ_M1_NTAPS,
    .use_ab = 1, .use_grad = 1, .use_sg = 1, .gamma_mask = 0xfff, RGBZ_M1_SG_COVER,
    RGBZ_M1_PAIRS(RGBZ_M1_COMBINED_PAIRS),
    .group_scale = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5,
                    1.0 / 7.0, 1.0 / 7.0, 1.0 / 7.0, 1.0 / 7.0},
};

/* the constant plans, indexed by rgbz_mask1_index */
enum { RGBZ_M1_BILINEAR, RGBZ_M1_BI, RGBZ_M1_EDI_CENTRAL, RGBZ_M1_EDI_LINE, RGBZ_M1_SG,
       RGBZ_M1_SG_COMBINED, RGBZ_M1_NPLANS };
static const rgbz_plan *const rgbz_mask1_plans[RGBZ_M1_NPLANS] = {
    &rgbz_mask1_bilinear, &rgbz_mask1_bi, &rgbz_mask1_edi_central, &rgbz_mask1_edi_line,
    &rgbz_mask1_sg, &rgbz_mask1_sg_combined,
};

/* the constant plan of a method (SG: sg_combined = its plan has use_grad), or -1 */
static inline int rgbz_mask1_index(int method, int sg_combined)
{
    switch (method) {
    case RGBZ_M_BILINEAR: return RGBZ_M1_BILINEAR;
    case RGBZ_M_BI: return RGBZ_M1_BI;
    case RGBZ_M_EDI_CENTRAL: return RGBZ_M1_EDI_CENTRAL;
    case RGBZ_M_EDI_LINE: return RGBZ_M1_EDI_LINE;
    case RGBZ_M_SG: return sg_combined ? RGBZ_M1_SG_COMBINED : RGBZ_M1_SG;
    default: return -1;
    }
}

#endif /* RECON_MASK1_H */
