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

#endif /* RGBZ_RECON_H */
