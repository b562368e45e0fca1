/*
 * srgb.c -- the sRGB encoding of the colour chain around NumPy's power (see srgb.h).
 *
 * IEC 61966-2-1 OETF: 12.92 v for v <= 0.0031308, else 1.055 v^(1/2.4) - 0.055, on values
 * clipped to [0, 1], then floor(e (2^bits - 1) + 0.5). The operations and their order are
 * those of rgbz_fast.isp's correct_colour (clip), srgb_oetf and _quantise, so that with the
 * same power the codes are the same bit for bit; -ffp-contract=off (csrc/meson.build) keeps
 * every multiply and add rounded on its own, as NumPy's are.
 *
 * Layout: n contiguous values; p has n values of the same type; code n uint8 or uint16
 * (code_type RGBZ_T_U8 or RGBZ_T_U16).
 * The floor is a conversion to int32: the value floored is e (2^bits - 1) + 0.5 >= 0.5 (v is
 * clipped to [0, 1], so e >= 0), where truncation and floor agree, and it vectorises.
 */
#include <stdint.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "srgb.h"
#include "rgbz_templating.h"
#include "rgbz_threads.h"

#define SR_PRAGMA(x) _Pragma(#x)

#ifdef _OPENMP
#define SR_FOR(nt) SR_PRAGMA(omp parallel for simd schedule(static) num_threads(nt))
#else
#define SR_FOR(nt) SR_PRAGMA(omp simd)
#endif

#define SR_CLIP(T, x) ((x) < (T)0 ? (T)0 : ((x) > (T)1 ? (T)1 : (x)))

/* srgb.template.h once per precision: the entry points rgbz_oetf_prepare_<RS> and
   rgbz_oetf_finish_<RS> (srgb.h), the finish once per integer code type within it */
#define RGBZ_REAL_TEMPLATE "srgb.template.h"
#include "rgbz_each_real.h"
#undef RGBZ_REAL_TEMPLATE

/* out[i] = table[code[i]]: the sRGB decoding's look-up (srgb.h) */
#define SR_LOOKUP(T)                                                                       \
    do {                                                                                   \
        const T *c = (const T *)code;                                                      \
        SR_FOR(nt)                                                                         \
        for (ptrdiff_t i = 0; i < n; i++) {                                                \
            const ptrdiff_t k = (ptrdiff_t)c[i];                                           \
            bad |= k >= size;                                                              \
            out[i] = table[k < size ? k : 0];                                              \
        }                                                                                  \
    } while (0)

int rgbz_decode_lookup(int code_type, const void *code, ptrdiff_t n, const double *table,
                       ptrdiff_t size, double *out, int workers)
{
    if (!code || !table || !out || n < 0 || size < 1 ||
        (code_type != RGBZ_T_U8 && code_type != RGBZ_T_U16))
        return RGBZ_EINVAL;
    const int nt = rgbz_threads_per_values(workers, n);
    (void)nt;
    int bad = 0;
#ifdef _OPENMP
#undef SR_FOR
#define SR_FOR(nt) SR_PRAGMA(omp parallel for simd schedule(static) num_threads(nt) reduction(|:bad))
#else
#undef SR_FOR
#define SR_FOR(nt) SR_PRAGMA(omp simd reduction(|:bad))
#endif
    if (code_type == RGBZ_T_U8)
        SR_LOOKUP(uint8_t);
    else
        SR_LOOKUP(uint16_t);
    return bad ? RGBZ_EDOMAIN : RGBZ_OK;
}
