/*
 * colour_isp_scan.template.h -- the passes of colour_isp.c over a raw frame, for one element
 * type: the defect candidates (tests 1 and 2) and the grey-world sums. Instantiated by
 * colour_isp.c once per element type through rgbz_each_type.h (rgbz_templating.h), with
 *   IN_T, IS, IN_IS_INT   the C type (uint8_t, uint16_t, float, double), its suffix (u8,
 *                         u16, f32, f64) and 1 for an integer type.
 */
#ifndef IN_T
#error "colour_isp_scan.template.h: #define IN_T, IS and IN_IS_INT first"
#endif

/* rows [y0, y1) of the defect test (rgbz_ci_defect_candidates): the candidates go to list;
   0, or RGBZ_ENOMEM when the list cannot grow */
static int RGBZ_CAT(ci_candidates, IS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols,
                                       ptrdiff_t y, int32_t P, int32_t Q, const int32_t *noff,
                                       const int32_t *offs, const ptrdiff_t *lin, float thr,
                                       float k, ci_list *list)
{
    const int32_t *prow_n = noff + (y % P) * Q;
    const int32_t *prow_o = offs + (ptrdiff_t)(y % P) * Q * 2 * RGBZ_CI_MAX_NEIGHBOURS;
    const ptrdiff_t *prow_l = lin + (ptrdiff_t)(y % P) * Q * RGBZ_CI_MAX_NEIGHBOURS;
    const int inner_y = y >= 2 && y < rows - 2;
    const IN_T *row = src + y * cols;
    int32_t xq = 0;
    for (ptrdiff_t x = 0; x < cols; x++, xq = xq + 1 == Q ? 0 : xq + 1) {
        const int32_t n = prow_n[xq];
        if (n <= 0) continue;                     /* a Z position, or no neighbour at all */
        const int32_t *o = prow_o + (ptrdiff_t)xq * 2 * RGBZ_CI_MAX_NEIGHBOURS;
        const float v = (float)row[x];
        float mx = 0, mn = 0;
        int seen = 0, out = 0;
        if (inner_y && x >= 2 && x < cols - 2) {
            /* every neighbour is inside the frame, at the offsets lin in the frame */
            const ptrdiff_t *l = prow_l + (ptrdiff_t)xq * RGBZ_CI_MAX_NEIGHBOURS;
            const IN_T *p = row + x;
            mx = mn = (float)p[l[0]];
            seen = 1;
            /* mx only grows and mn only falls: once both differences are within thr,
               test 1 fails for good */
            if (!(v - mx > thr) && !(mn - v > thr)) continue;
            for (int32_t i = 1; i < n; i++) {
                const float w = (float)p[l[i]];
                mx = w > mx ? w : mx;
                mn = w < mn ? w : mn;
                if (!(v - mx > thr) && !(mn - v > thr)) { out = 1; break; }
            }
        } else {
            for (int32_t i = 0; i < n; i++) {
                const ptrdiff_t yy = y + o[2 * i], xx = x + o[2 * i + 1];
                if (yy < 0 || yy >= rows || xx < 0 || xx >= cols) continue;
                const float w = (float)src[yy * cols + xx];
                if (!seen) { mx = mn = w; seen = 1; }
                else { mx = w > mx ? w : mx; mn = w < mn ? w : mn; }
                if (!(v - mx > thr) && !(mn - v > thr)) { out = 1; break; }
            }
        }
        if (out || !seen) continue;               /* no neighbour: NaN, no test passes */
        const float hot = v - mx, cold = mn - v, sp = mx - mn;
        const float ksp = k * sp;
        if ((hot > thr && hot > ksp) || (cold > thr && cold > ksp)) {
            if (ci_push(list, y, x, hot, cold, sp)) return RGBZ_ENOMEM;
        }
    }
    return RGBZ_OK;
}

/* grey-world sums of rows [y0, y1) into sums[4] and counts[4] (phase = 2 (y & 1) + (x & 1)) */
static void RGBZ_CAT(ci_sums, IS)(const IN_T *src, ptrdiff_t cols, ptrdiff_t y0, ptrdiff_t y1,
                                  double white, double *sums, int64_t *counts)
{
#if IN_IS_INT
    /* integers below 2^16 in at most 2^47 pixels: exact in 64 bits, and NumPy's float64 sum
       of them is exact too (every partial sum is an integer below 2^53) */
    uint64_t s[4] = {0, 0, 0, 0};
    const double lim = white;
#define CI_ACC_T uint64_t
#else
    double s[4] = {0, 0, 0, 0};
    /* NumPy compares a float32 array with a Python float in float32 */
    const IN_T lim = (IN_T)white;
#define CI_ACC_T double
#endif
    int64_t c[4] = {0, 0, 0, 0};
    for (ptrdiff_t y = y0; y < y1; y++) {
        const IN_T *row = src + y * cols;
        const int b = 2 * (int)(y & 1);
        CI_ACC_T s0 = 0, s1 = 0;
        int64_t c0 = 0, c1 = 0;
        ptrdiff_t x = 0;
        for (; x + 1 < cols; x += 2) {
            const IN_T a = row[x], d = row[x + 1];
            if (a < lim) { s0 += (CI_ACC_T)a; c0++; }
            if (d < lim) { s1 += (CI_ACC_T)d; c1++; }
        }
        if (x < cols && row[x] < lim) { s0 += (CI_ACC_T)row[x]; c0++; }
        s[b] += s0; s[b + 1] += s1;
        c[b] += c0; c[b + 1] += c1;
    }
#undef CI_ACC_T
    for (int i = 0; i < 4; i++) {
        sums[i] = (double)s[i];
        counts[i] = c[i];
    }
}
