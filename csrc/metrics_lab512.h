/*
 * metrics_lab512.h -- the Lab loop of metrics.c (MT_LAB over a row) in AVX-512 intrinsics,
 * software-pipelined. Included by metrics.c after MT_LAB and mt_cbrt; defines
 * MT_HAVE_LAB512 and mt_lab512 only in a build with AVX-512F and FMA (the avx512 library).
 *
 * Every value is computed by the operations of MT_LAB, mt_f and mt_cbrt, in their order, each
 * an IEEE operation rounded once (no contraction: the intrinsics name each multiply and add;
 * the FMAs are those of mt_qfma when the caller asks for it), except mt_cbrt's scaling of its
 * argument, which mt512_reduce computes exactly by other operations, equal wherever the root
 * is used; so the results are the C loop's bit for bit, for any input, NaN and infinities
 * included. What differs is the
 * schedule: the C loop computes one pixel vector's three cube roots one after the other, and
 * each root is a chain of about 130 cycles (two divisions of about 22 cycles each, waited
 * for) that the out-of-order window cannot overlap with the next vector's; here the three
 * roots advance side by side, and the second Halley step of one vector of 8 pixels is
 * interleaved with the first half (XYZ, range reduction, cubic, first Halley step) of the
 * next, so the divider and the two FMA ports have independent work.
 */
#if defined(__AVX512F__) && defined(__FMA__)
#include <immintrin.h>

#define MT_HAVE_LAB512 1
#define MT_V __m512d
#define MT_B(x) _mm512_set1_pd(x)
#define MT_AI static inline __attribute__((always_inline))

/* mt_cbrt's scaling of t into [1/8, 1) and its factor s: t 8^-k and 2^k, both exact, k the
   number of scalings by 1/8 its three selects make (-2 to 1 for the t in (MT_LAB_T3, 8) whose
   root is used; smaller or larger t, NaN and infinities take mt_f's linear branch or
   mt_lab_any, which discard it). With e = floor(log2 t) (getexp), t 8^-k in [1/8, 1) is
   e - 3 k in [-3, -1], k = ceil((e + 1) / 3), computed as ceil(fma(e, c, c)) for c = 1/3
   rounded: for e + 1 = 3 j the product is j + 3 j (c - 1/3), which rounds to j (|j| <= 1:
   below half an ulp, or the tie 2^-54 that rounds to the even j); otherwise it is at least
   1/3 - 1e-16 away from an integer. Four operations of the FMA ports where the selects
   took nine. */
MT_AI void mt512_reduce(MT_V t, MT_V *tr, MT_V *s)
{
    const MT_V k = _mm512_roundscale_pd(
        _mm512_fmadd_pd(_mm512_getexp_pd(t), MT_B(1.0 / 3.0), MT_B(1.0 / 3.0)),
        _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC);
    *tr = _mm512_scalef_pd(t, _mm512_mul_pd(k, MT_B(-3.0)));
    *s = _mm512_scalef_pd(MT_B(1.0), k);
}

/* mt_cbrt's cubic, ((a t - b) t + c) t + d */
MT_AI MT_V mt512_poly(MT_V t)
{
    MT_V y = _mm512_sub_pd(_mm512_mul_pd(MT_B(0x1.2f32bc070f5c5p-1), t),
                           MT_B(0x1.62cbdc013e649p+0));
    y = _mm512_add_pd(_mm512_mul_pd(y, t), MT_B(0x1.7546d8f3a18cep+0));
    return _mm512_add_pd(_mm512_mul_pd(y, t), MT_B(0x1.5d05ae84a1fe9p-2));
}

MT_AI MT_V mt512_cube(MT_V y) { return _mm512_mul_pd(_mm512_mul_pd(y, y), y); }

/* x / c as MT_QFMA (fma = 1) or MT_QDIV computes it */
MT_AI MT_V mt512_quot(MT_V x, double c, double rc, int fma)
{
    if (!fma) return _mm512_div_pd(x, MT_B(c));
    const MT_V q = _mm512_mul_pd(x, MT_B(rc));
    return _mm512_fmadd_pd(_mm512_fnmadd_pd(q, MT_B(c), x), MT_B(rc), q);
}

/* the state of one vector of 8 pixels between the two halves: the ratios t, the reduced t
   (u) and the scale s of each cube root, and y after the first Halley step */
typedef struct { MT_V t[3], u[3], s[3], y[3]; } mt512_half;

/* the first half of MT_LAB for the 8 pixels at lr, lg, lb: the ratios (MT_XYZ_Q), their
   maximum into *tmax (as MT_LAB's selects: vmaxpd keeps *tmax for a NaN ratio), mt_cbrt to
   its first Halley step */
MT_AI void mt512_first(const double *lr, const double *lg, const double *lb, int fma,
                       MT_V *tmax, mt512_half *h)
{
    const MT_V r = _mm512_loadu_pd(lr), g = _mm512_loadu_pd(lg), b = _mm512_loadu_pd(lb);
    h->t[0] = mt512_quot(_mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(MT_B(0.4124), r),
                                                     _mm512_mul_pd(MT_B(0.3576), g)),
                                       _mm512_mul_pd(MT_B(0.1805), b)),
                         MT_XN, MT_RXN, fma);
    h->t[1] = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(MT_B(0.2126), r),
                                          _mm512_mul_pd(MT_B(0.7152), g)),
                            _mm512_mul_pd(MT_B(0.0722), b));
    h->t[2] = mt512_quot(_mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(MT_B(0.0193), r),
                                                     _mm512_mul_pd(MT_B(0.1192), g)),
                                       _mm512_mul_pd(MT_B(0.9505), b)),
                         MT_ZN, MT_RZN, fma);
    for (int k = 0; k < 3; k++) *tmax = _mm512_max_pd(h->t[k], *tmax);
    MT_V y[3], c[3], n[3], d[3];
    for (int k = 0; k < 3; k++) mt512_reduce(h->t[k], &h->u[k], &h->s[k]);
    for (int k = 0; k < 3; k++) y[k] = mt512_poly(h->u[k]);
    for (int k = 0; k < 3; k++) c[k] = mt512_cube(y[k]);
    /* y (y3 + 2 t) / (2 y3 + t); 2 t and 2 y3 are exact as t + t */
    for (int k = 0; k < 3; k++)
        n[k] = _mm512_mul_pd(y[k], _mm512_add_pd(c[k], _mm512_add_pd(h->u[k], h->u[k])));
    for (int k = 0; k < 3; k++) d[k] = _mm512_add_pd(_mm512_add_pd(c[k], c[k]), h->u[k]);
    for (int k = 0; k < 3; k++) h->y[k] = _mm512_div_pd(n[k], d[k]);
}

/* the second half: the second Halley step y - y (y3 - t) / (2 y3 + t), times s, mt_f's
   select, and L, a, b to L[j os], A[j os], B[j os] for the 8 pixels j */
MT_AI void mt512_second(const mt512_half *h, double *L, double *A, double *B, ptrdiff_t os)
{
    MT_V f[3], c[3], n[3], d[3];
    for (int k = 0; k < 3; k++) c[k] = mt512_cube(h->y[k]);
    for (int k = 0; k < 3; k++) n[k] = _mm512_mul_pd(h->y[k], _mm512_sub_pd(c[k], h->u[k]));
    for (int k = 0; k < 3; k++) d[k] = _mm512_add_pd(_mm512_add_pd(c[k], c[k]), h->u[k]);
    for (int k = 0; k < 3; k++) f[k] = _mm512_sub_pd(h->y[k], _mm512_div_pd(n[k], d[k]));
    for (int k = 0; k < 3; k++) {
        const MT_V root = _mm512_mul_pd(f[k], h->s[k]);
        const MT_V lin = _mm512_add_pd(_mm512_mul_pd(MT_B(MT_LAB_K), h->t[k]), MT_B(MT_LAB_C));
        const __mmask8 above = _mm512_cmp_pd_mask(h->t[k], MT_B(MT_LAB_T3), _CMP_GT_OQ);
        f[k] = _mm512_mask_blend_pd(above, lin, root);
    }
    const MT_V vl = _mm512_sub_pd(_mm512_mul_pd(MT_B(116.0), f[1]), MT_B(16.0));
    const MT_V va = _mm512_mul_pd(MT_B(500.0), _mm512_sub_pd(f[0], f[1]));
    const MT_V vb = _mm512_mul_pd(MT_B(200.0), _mm512_sub_pd(f[1], f[2]));
    if (os == 1) {
        _mm512_storeu_pd(L, vl);
        _mm512_storeu_pd(A, va);
        _mm512_storeu_pd(B, vb);
    } else {
        double tmp[3][8];
        _mm512_storeu_pd(tmp[0], vl);
        _mm512_storeu_pd(tmp[1], va);
        _mm512_storeu_pd(tmp[2], vb);
        for (int l = 0; l < 8; l++) {
            L[l * os] = tmp[0][l];
            A[l * os] = tmp[1][l];
            B[l * os] = tmp[2][l];
        }
    }
}

/* MT_LAB of the first n - n % 8 pixels of the planar linear rows lr, lg, lb (the caller does
   the rest with MT_LAB), the white point's quotients as MT_QFMA (fma = 1) or MT_QDIV: the
   maximum ratio joins *tmax. Returns the number of pixels done. */
static ptrdiff_t mt_lab512(const double *lr, const double *lg, const double *lb, ptrdiff_t n,
                           int fma, double *L, double *A, double *B, ptrdiff_t os,
                           double *tmax)
{
    if (n < 8) return 0;
    MT_V vmax = _mm512_set1_pd(*tmax);
    mt512_half cur, next;
    if (fma) mt512_first(lr, lg, lb, 1, &vmax, &cur);
    else mt512_first(lr, lg, lb, 0, &vmax, &cur);
    ptrdiff_t j = 8;
    for (; j + 8 <= n; j += 8) {
        if (fma) mt512_first(lr + j, lg + j, lb + j, 1, &vmax, &next);
        else mt512_first(lr + j, lg + j, lb + j, 0, &vmax, &next);
        mt512_second(&cur, L + (j - 8) * os, A + (j - 8) * os, B + (j - 8) * os, os);
        cur = next;
    }
    mt512_second(&cur, L + (j - 8) * os, A + (j - 8) * os, B + (j - 8) * os, os);
    *tmax = _mm512_reduce_max_pd(vmax);
    return j;
}

#undef MT_AI
#undef MT_B
#undef MT_V
#endif
