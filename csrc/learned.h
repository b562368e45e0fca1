/*
 * learned.h -- the learned directional reconstruction (method "learned"):
 * hashed linear filters fitted by regularised least squares
 * (rgbz_fast/reconstruction/_learned.py fits them; docs/guide/learned.md
 * specifies the hash and the filters).
 *
 * Every Z site is one dot product: the known pixels of its window (the taps
 * of its phase) times the filter of its bucket. The bucket hashes the local
 * structure from the known pixels only: for each of four directions the
 * mean squared difference E_d of the same-colour pairs of the phase, then
 *   a = E_h - E_v, b = (E_d1 - E_d2) / 2, t = (E_h + E_v) / 2 + (E_d1 + E_d2) / 4,
 * the orientation = the octant of (a, b) rotated by 22.5 degrees (sign tests
 * and one comparison), the strength = how many thresholds t exceeds, the
 * coherence = how many squared thresholds c2 satisfy a^2 + b^2 > c2 * (t * t);
 * and for each colour c the mean squared difference E_c of its horizontal and
 * vertical pairs, the spread = how many thresholds s satisfy max_c E_c > s * min_c E_c;
 *   bucket = ((octant * n_str + strength) * n_coh + coherence) * n_spr + spread.
 */
#ifndef RGBZ_LEARNED_H
#define RGBZ_LEARNED_H

#include <stddef.h>
#include <stdint.h>
#include "rgbz.h"

#define RGBZ_LEARNED_MAX_TAPS 121     /* an 11x11 window (radius 5) */
#define RGBZ_LEARNED_MAX_RADIUS 5
#define RGBZ_LEARNED_DIRS 4           /* horizontal, vertical, main and anti-diagonal */
#define RGBZ_LEARNED_SPREAD_DIRS 2    /* the first two (horizontal, vertical) give the spread */

typedef struct {
    int32_t n_phases;     /* Z positions of the tile */
    int32_t n_buckets;    /* 8 * n_str * n_coh * n_spr */
    int32_t n_taps_max;   /* row length of tap_dy / tap_dx and of the weights' tap axis */
    int32_t n_pairs_max;  /* row length of pair_a / pair_b */
    int32_t n_str, n_coh; /* strength and coherence levels */
    int32_t n_spr;        /* channel-spread levels (1: no spread term) */
    int32_t radius;       /* largest |dy|, |dx| of a tap */
    int32_t hash_radius;  /* largest |dy|, |dx| of a pixel of a hash pair */
    const int32_t *n_taps;            /* [n_phases] */
    const int32_t *tap_dy, *tap_dx;   /* [n_phases][n_taps_max] */
    const int32_t *n_pairs;           /* [n_phases][4] */
    const int32_t *pair_a, *pair_b;   /* [n_phases][4][n_pairs_max]: tap indices */
    const int32_t *pair_col;          /* [n_phases][4][n_pairs_max]: colour of each pair, 0..2 */
    const double *inv_col;            /* [n_phases][3]: 1 / the horizontal and vertical pairs
                                         of each colour */
    const int32_t *bayer;             /* [2][2]: colour of the pixels at (row, col) mod 2 */
    const double *str_thr;            /* [n_phases][n_str - 1], increasing */
    const double *coh_thr2;           /* [n_phases][n_coh - 1]: squared coherence thresholds */
    const double *spr_thr;            /* [n_phases][n_spr - 1]: spread thresholds, >= 1 */
    const float *w_f32;               /* [n_phases][n_taps_max][n_buckets] (tap-major) */
    const double *w_f64;              /* the same weights in double */
    /* optional (NULL: not used), for radius <= 3: the weights on the dense window, zeros at
       the Z sites and in column 7, [n_phases][n_buckets][2 radius + 1][8] */
    const float *wd_f32;
    const double *wd_f64;
    /* precision FIXED only (NULL for the others): the integer hash constants, the quantised
       weights and the streaming state (hw_learned.h) */
    const struct rgbz_learned_fixed_args *fixed;
} rgbz_learned_filters;

/*
 * rgbz_learned_<precision> (one per entry of RGBZ_PRECISIONS, rgbz.h, all of this type):
 * reconstruct every Z site of a frame with learned filters, in that precision (the
 * arithmetic, and the weights w_<precision>, wd_<precision>).
 *   src, dst:  rows x cols frames of element type in_type (an rgbz_type; dst fully
 *              written: colour sites copied, Z sites clipped to [0, maxval] and, for
 *              integer types, rounded half up). src and dst must not overlap.
 *   py, px, phase_map: the pattern period and the phase (index into the filters) of
 *              each tile site, -1 for a colour site.
 *   opcounts:  counting build only: n_phases x RGBZ_NOPS counters.
 * Borders: a tap outside the frame moves back inside by whole periods.
 */
typedef int rgbz_learned_fn(int in_type, const void *src, void *dst, ptrdiff_t rows,
                            ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                            const rgbz_learned_filters *f, double maxval, int workers,
                            uint64_t *opcounts);
#define RGBZ_DECLARE_LEARNED_(s, NAME) rgbz_learned_fn rgbz_learned_##s;
RGBZ_PRECISIONS(RGBZ_DECLARE_LEARNED_)
#undef RGBZ_DECLARE_LEARNED_

#endif /* RGBZ_LEARNED_H */
