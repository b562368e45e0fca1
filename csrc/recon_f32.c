/*
 * recon_f32.c -- the reconstruction in float arithmetic: recon_core.template.h and its frame
 * loops for REAL = float, and the entry points rgbz_reconstruct_f32 and rgbz_fast_exp_f32
 * (rgbz.h). One file per precision, so that the two compile in parallel: they are most of
 * the build's compile time.
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
#include "recon_mask2.h"

/* SG on Mask2's plans (its four Bayer phases) as straight-line code (recon_mask2.h): float only */
#if RGBZ_HAVE_M2
#define RGBZ_M2_INDEX(p) rgbz_m2_index(p)
#define RGBZ_M2_RUN(k, v, n, kn, r) rgbz_m2_run(k, v, n, (kn)->floor_, (kn)->rel, r)
#endif

#define REAL float
#define RS f32
#include "recon_core.template.h"
#undef REAL
#undef RS

int rgbz_mask2_plan_index(const rgbz_plan *p)
{
#if RGBZ_HAVE_M2
    return p ? rgbz_m2_index(p) : -1;
#else
    (void)p;
    return -1;
#endif
}

int rgbz_mask2_generic(int on)
{
#if RGBZ_HAVE_M2
    const int was = rgbz_m2_generic_only;
    if (on >= 0) rgbz_m2_generic_only = on != 0;
    return was;
#else
    (void)on;
    return -1;
#endif
}
