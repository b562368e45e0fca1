/*
 * srgb.template.h -- the sRGB encoding of srgb.c for one float type (PyWavelets' template
 * scheme). Included by srgb.c with:
 *   REAL  the float type of the values (float, double)
 *   RS    its suffix (f32, f64), appended to every function name
 * and, for the finish, by itself once per code type (CODE_T uint8_t / uint16_t, CS u8 / u16,
 * CODE_TOP 255 / 65535).
 */
#ifndef REAL
#error "srgb.template.h: #define REAL (float or double) before including it"
#endif
#ifndef RS
#error "srgb.template.h: #define RS (the suffix of REAL: f32 or f64)"
#endif

#define SR_CAT_(a, b) a##_##b
#define SR_CAT(a, b) SR_CAT_(a, b)
#define SR_CAT3(a, b, c) SR_CAT(SR_CAT(a, b), c)

#ifndef CODE_T
/* p = 1 where the clipped x is on the OETF's linear segment, else the clipped x */
static void SR_CAT(sr_prepare, RS)(const REAL *x, REAL *p, ptrdiff_t n, int workers)
{
    const REAL knee = (REAL)0.0031308;
    int nt = sr_threads(workers, n);
    (void)nt;
    SR_FOR(nt)
    for (ptrdiff_t i = 0; i < n; i++) {
        const REAL v = SR_CLIP(REAL, x[i]);
        p[i] = v <= knee ? (REAL)1 : v;
    }
}

#define CODE_T uint8_t
#define CS u8
#define CODE_TOP 255
#include "srgb.template.h"
#undef CODE_T
#undef CS
#undef CODE_TOP
#define CODE_T uint16_t
#define CS u16
#define CODE_TOP 65535
#include "srgb.template.h"
#undef CODE_T
#undef CS
#undef CODE_TOP

#else
/* the codes of x, p holding the power 1 / 2.4 of the prepared values */
static void SR_CAT3(sr_finish, RS, CS)(const REAL *x, const REAL *p, ptrdiff_t n,
                                       CODE_T *code, int workers)
{
    const REAL knee = (REAL)0.0031308, a = (REAL)1.055, b = (REAL)0.055, s = (REAL)12.92;
    const REAL top = (REAL)CODE_TOP, half = (REAL)0.5;
    int nt = sr_threads(workers, n);
    (void)nt;
    SR_FOR(nt)
    for (ptrdiff_t i = 0; i < n; i++) {
        const REAL v = SR_CLIP(REAL, x[i]);
        REAL e = p[i] * a;
        e = e - b;
        e = v <= knee ? v * s : e;
        REAL q = e * top;
        q = q + half;
        code[i] = (CODE_T)(int32_t)q;        /* q >= 0.5: truncation = floor */
    }
}
#endif
