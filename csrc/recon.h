/*
 * recon.h -- internal to the reconstruction (recon.c and the files of each precision,
 * recon_f32.c and recon_f64.c): its limits, its border rule and the checks every entry
 * point runs first. Not part of the C API (rgbz.h).
 */
#ifndef RGBZ_RECON_H
#define RGBZ_RECON_H

#include <stddef.h>
#include <stdint.h>
#include "rgbz.h"

#define RGBZ_MAX_RADIUS 8

/* sites per block of the core: its scratch stays in L1. The counting build runs one site
   per block, so that a branch the core takes per block is counted per site. */
#ifdef RGBZ_COUNT_OPS
#define RGBZ_BLK 1
#else
#define RGBZ_BLK 128
#endif

/* index i moved into [0, n) by whole periods P (n >= P) */
static inline ptrdiff_t rgbz_extend(ptrdiff_t i, ptrdiff_t n, ptrdiff_t P)
{
    if (i < 0) return i + P * ((-i + P - 1) / P);
    if (i >= n) return i - P * ((i - n + P) / P);
    return i;
}

/*
 * The checks of rgbz_reconstruct_<precision>'s arguments (rgbz.h) that do not depend on
 * the precision, and what its frame loop needs: the largest tap offsets *ry, *rx of the
 * plans, and *colmap, a malloc'ed map of the columns x in [-rx, cols + rx) moved into the
 * frame by whole periods (colmap[x + rx]), which the caller frees. RGBZ_OK, or the status
 * to return (nothing then to free).
 */
int rgbz_recon_setup(const void *src, const void *dst, ptrdiff_t rows, ptrdiff_t cols, int py,
                     int px, const int32_t *phase_map, const rgbz_plan *plans, int n_plans,
                     const rgbz_params *prm, const uint64_t *opcounts, int *ry, int *rx,
                     ptrdiff_t **colmap);

/*
 * The Z pixels of Mask2 (a 2x2 Z pixel in a 4x4 tile): its four sites run together, the
 * absolute differences of their gradient pairs and of beta's candidate pairs computed once
 * per pixel pair they name (of 342 differences of an SG Z pixel, 170 are distinct) and
 * read by every site that has them (recon_loop.template.h, rgbz_quads). The result is the
 * same: each site adds the same numbers in the same order (|a - b| = |b - a|).
 */
#define RGBZ_QMAX_D 512                 /* distinct differences of one Z pixel, at most */
#define RGBZ_QBLK 128                   /* Z pixels per block */
#define RGBZ_MAX_BPAIRS (RGBZ_MAX_CAND * (RGBZ_MAX_CAND - 1) / 2)
typedef struct {
    int r0, c0;             /* the Z pixel's top-left site in the tile */
    int pl[4];              /* the plan of site s = 2 sy + sx, at (r0 + sy, c0 + sx) */
    int nd;                 /* distinct differences */
    /* difference u: |pixel (ay, ax) - pixel (by, bx)|, offsets from the top-left site */
    int16_t ay[RGBZ_QMAX_D], ax[RGBZ_QMAX_D], by[RGBZ_QMAX_D], bx[RGBZ_QMAX_D];
    /* site s: its gradient pair i is difference pidx[s][i], its beta pair i (the order of
       recon_core.template.h: (k, m), k < m, k outer) bidx[s][i]; -1 where not used */
    int16_t pidx[4][RGBZ_MAX_PAIRS], bidx[4][RGBZ_MAX_BPAIRS];
} rgbz_quad;

/*
 * 1 and *q filled when the frame loop can run the Z pixels of the pattern as rgbz_quad:
 * a 4x4 tile whose missing sites are one 2x2 block (Mask2 and its phases), no clipped-pixel
 * rule, not the counting build (its counts are per site, as the paper computes them),
 * methods with pair differences; else 0.
 */
int rgbz_quad_setup(int py, int px, const int32_t *phase_map, const rgbz_plan *plans,
                    const rgbz_params *prm, rgbz_quad *q);

#endif /* RGBZ_RECON_H */
