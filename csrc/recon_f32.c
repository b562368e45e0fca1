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

#define REAL float
#define RS f32
#include "recon_core.template.h"
#undef REAL
#undef RS
