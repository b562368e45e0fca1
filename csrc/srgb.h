/*
 * srgb.h -- C API of the sRGB encoding kernels (srgb.c), plain C99, no Python.h.
 *
 * The colour chain's last stages (rgbz_fast.isp: clip to [0, 1], the sRGB OETF of
 * IEC 61966-2-1, quantisation to 8 or 16 bits) in two passes around the power, which the
 * caller computes with NumPy (np.power): so that the codes are those of the NumPy stages bit
 * for bit (the same operations in the same order, the same power function), without their
 * temporaries. For n values x of the precision in the name (float32: _f32, float64: _f64):
 *
 *   rgbz_oetf_prepare: p = v <= 0.0031308 ? 1 : v, with v = min(max(x, 0), 1)
 *                      (the caller then raises p to 1 / 2.4 in place)
 *   rgbz_oetf_finish:  e = v <= 0.0031308 ? v * 12.92 : p * 1.055 - 0.055,
 *                      code = floor(e * (2^bits - 1) + 0.5), into code of code_type
 *                      RGBZ_T_U8 (bits 8) or RGBZ_T_U16 (bits 16)
 *
 * Arithmetic in the type of x (constants rounded to it), as NumPy does with scalars of that
 * type; compiled with -ffp-contract=off. Contiguous arrays; status codes of rgbz.h.
 */
#ifndef RGBZ_SRGB_H
#define RGBZ_SRGB_H

#include <stddef.h>

#include "rgbz.h"

int rgbz_oetf_prepare_f32(const float *x, float *p, ptrdiff_t n, int workers);
int rgbz_oetf_prepare_f64(const double *x, double *p, ptrdiff_t n, int workers);
int rgbz_oetf_finish_f32(const float *x, const float *p, ptrdiff_t n, int code_type,
                         void *code, int workers);
int rgbz_oetf_finish_f64(const double *x, const double *p, ptrdiff_t n, int code_type,
                         void *code, int workers);

/* The decoding of 8- and 16-bit sRGB images (rgbz_fast.simulation.srgb_decode): out[i] =
   table[code[i]] for n codes of code_type (RGBZ_T_U8 or RGBZ_T_U16) and a table of size
   values, threaded (one thread per 2**18 values at most). RGBZ_EDOMAIN when a code is not
   below size (out then holds table[0] there). */
int rgbz_decode_lookup(int code_type, const void *code, ptrdiff_t n, const double *table,
                       ptrdiff_t size, double *out, int workers);

#endif /* RGBZ_SRGB_H */
