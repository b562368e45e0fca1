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

/* Tests 1 and 2 of the colour pixel x of row y (n >= 1 neighbours at offs o, or at the
   frame offsets l when `inner`: every neighbour inside the frame): its candidate entry to
   list when it passes. 0, or RGBZ_ENOMEM when the list cannot grow. */
RGBZ_INLINE int RGBZ_CAT(ci_test_pixel, IS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols,
                                            ptrdiff_t y, ptrdiff_t x, int32_t n,
                                            const int32_t *o, const ptrdiff_t *l, int inner,
                                            float thr, float k, ci_list *list)
{
    const IN_T *row = src + y * cols;
    const float v = (float)row[x];
    float mx = 0, mn = 0;
    int seen = 0;
    if (inner) {
        const IN_T *p = row + x;
        mx = mn = (float)p[l[0]];
        seen = 1;
        /* mx only grows and mn only falls: once both differences are within thr,
           test 1 fails for good */
        if (!(v - mx > thr) && !(mn - v > thr)) return RGBZ_OK;
        for (int32_t i = 1; i < n; i++) {
            const float w = (float)p[l[i]];
            mx = w > mx ? w : mx;
            mn = w < mn ? w : mn;
            if (!(v - mx > thr) && !(mn - v > thr)) return RGBZ_OK;
        }
    } else {
        for (int32_t i = 0; i < n; i++) {
            const ptrdiff_t yy = y + o[2 * i], xx = x + o[2 * i + 1];
            if (yy < 0 || yy >= rows || xx < 0 || xx >= cols) continue;
            const float w = (float)src[yy * cols + xx];
            if (!seen) { mx = mn = w; seen = 1; }
            else { mx = w > mx ? w : mx; mn = w < mn ? w : mn; }
            if (!(v - mx > thr) && !(mn - v > thr)) return RGBZ_OK;
        }
    }
    if (!seen) return RGBZ_OK;                  /* no neighbour: NaN, no test passes */
    const float hot = v - mx, cold = mn - v, sp = mx - mn;
    const float ksp = k * sp;
    if ((hot > thr && hot > ksp) || (cold > thr && cold > ksp))
        return ci_push(list, y, x, hot, cold, sp) ? RGBZ_ENOMEM : RGBZ_OK;
    return RGBZ_OK;
}

/* The pre-test of the columns [2, cols - 2) of an inner row (every neighbour inside the
   frame), without a branch: keep[x] = 0 where some neighbour w among the CI_PRE offsets of
   the plan (frame offsets pl, masks pm: 1 where the offset is one of x's neighbours) has
   |v - w| <= thr, else the colour mask pc. Such a pixel fails test 1 (v - mx <= v - w <= thr
   and mn - v <= w - v <= thr, float32 subtraction being monotonic and odd), so only the
   kept pixels need ci_test_pixel. A NaN w rejects nothing. pm NULL: every mask is pc. */
CI_CLONES static void RGBZ_CAT(ci_pretest, IS)(const IN_T *restrict row, ptrdiff_t cols,
                                               const ptrdiff_t *pl, const uint8_t *pm,
                                               const uint8_t *pc, float thr,
                                               uint8_t *restrict keep)
{
    const IN_T *r0 = row + pl[0], *r1 = row + pl[1], *r2 = row + pl[2], *r3 = row + pl[3];
    if (!pm) {                                  /* every mask is the colour mask */
        for (ptrdiff_t x = 2; x < cols - 2; x++) {
            const float v = (float)row[x];
            const int a0 = fabsf(v - (float)r0[x]) <= thr, a1 = fabsf(v - (float)r1[x]) <= thr;
            const int a2 = fabsf(v - (float)r2[x]) <= thr, a3 = fabsf(v - (float)r3[x]) <= thr;
            keep[x] = (uint8_t)(pc[x] & ((a0 | a1 | a2 | a3) ^ 1));
        }
        return;
    }
    const uint8_t *m0 = pm, *m1 = pm + cols, *m2 = pm + 2 * cols, *m3 = pm + 3 * cols;
    for (ptrdiff_t x = 2; x < cols - 2; x++) {
        const float v = (float)row[x];
        const int a0 = fabsf(v - (float)r0[x]) <= thr, a1 = fabsf(v - (float)r1[x]) <= thr;
        const int a2 = fabsf(v - (float)r2[x]) <= thr, a3 = fabsf(v - (float)r3[x]) <= thr;
        const int out = (m0[x] & a0) | (m1[x] & a1) | (m2[x] & a2) | (m3[x] & a3);
        keep[x] = (uint8_t)(pc[x] & (out ^ 1));
    }
}

/* row y of the defect test (rgbz_ci_defect_candidates): the candidates go to list; keep:
   cols bytes of scratch. 0, or RGBZ_ENOMEM when the list cannot grow */
static int RGBZ_CAT(ci_candidates, IS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols,
                                       ptrdiff_t y, int32_t P, int32_t Q, const int32_t *noff,
                                       const int32_t *offs, const ptrdiff_t *lin,
                                       const ci_pre *pre, float thr, float k, uint8_t *keep,
                                       ci_list *list)
{
    const int32_t py = (int32_t)(y % P);
    const int32_t *prow_n = noff + py * Q;
    const int32_t *prow_o = offs + (ptrdiff_t)py * Q * 2 * RGBZ_CI_MAX_NEIGHBOURS;
    const ptrdiff_t *prow_l = lin + (ptrdiff_t)py * Q * RGBZ_CI_MAX_NEIGHBOURS;
    const uint8_t *pc = pre->colour + py * cols;
    const int inner_y = y >= 2 && y < rows - 2 && cols > 4;
    if (inner_y) {
        RGBZ_CAT(ci_pretest, IS)(src + y * cols, cols, pre->lin + py * CI_PRE,
                                 pre->same[py] ? NULL : pre->mask + (ptrdiff_t)py * CI_PRE * cols,
                                 pc, thr, keep);
        keep[0] = pc[0];
        keep[1] = pc[1];
        keep[cols - 2] = pc[cols - 2];
        keep[cols - 1] = pc[cols - 1];
    } else {
        memcpy(keep, pc, (size_t)cols);
    }
    ptrdiff_t x = 0;
    while (x < cols) {
        /* 8 rejected pixels at a time */
        if (x + 8 <= cols) {
            uint64_t w;
            memcpy(&w, keep + x, 8);
            if (!w) { x += 8; continue; }
        }
        if (keep[x]) {
            const int32_t xq = (int32_t)(x % Q);
            const int inner = inner_y && x >= 2 && x < cols - 2;
            const int st = RGBZ_CAT(ci_test_pixel, IS)(
                src, rows, cols, y, x, prow_n[xq],
                prow_o + (ptrdiff_t)xq * 2 * RGBZ_CI_MAX_NEIGHBOURS,
                prow_l + (ptrdiff_t)xq * RGBZ_CI_MAX_NEIGHBOURS, inner, thr, k, list);
            if (st != RGBZ_OK) return st;
        }
        x++;
    }
    return RGBZ_OK;
}

/* grey-world sums of rows [y0, y1) into sums[4] and counts[4] (phase = 2 (y & 1) + (x & 1)) */
CI_CLONES static void RGBZ_CAT(ci_sums, IS)(const IN_T *src, ptrdiff_t cols, ptrdiff_t y0, ptrdiff_t y1,
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

/* Test 3 of the defect detection on n candidates (rgbz_ci_defect_confirm): ok[i] = 1 when
   candidate i is a defect. Every value as isp._defects._confirm computes it: the pixels as
   float32 then double, a neighbourhood's sum in np.nansum's pairwise order over its 24
   entries (missing ones 0), the trimmed mean, the high-passes' max and min (missing ones
   left out), the tests in double with k * spread a float32 product */
static void RGBZ_CAT(ci_confirm, IS)(const IN_T *src, ptrdiff_t rows, ptrdiff_t cols,
                                     int32_t P, int32_t Q, const int32_t *noff,
                                     const int32_t *offs, ptrdiff_t n, const int64_t *rr,
                                     const int64_t *cc, const float *hot, const float *cold,
                                     const float *spread, float thr, float k, double f,
                                     uint8_t *ok)
{
    for (ptrdiff_t i = 0; i < n; i++) {
        const ptrdiff_t r = (ptrdiff_t)rr[i], c = (ptrdiff_t)cc[i];
        double hi = -INFINITY, lo = INFINITY;      /* the adjacent pixels' high-passes */
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const ptrdiff_t qy = r + dy, qx = c + dx;
                if ((!dy && !dx) || qy < 0 || qy >= rows || qx < 0 || qx >= cols) continue;
                const int32_t kq = (int32_t)(qy % P) * Q + (int32_t)(qx % Q);
                const int32_t m = noff[kq];
                const double vq = (double)(float)src[qy * cols + qx];
                if (m < 0 || vq != vq) continue;          /* a Z site or NaN: no high-pass */
                const int32_t *o = offs + (ptrdiff_t)kq * 2 * RGBZ_CI_MAX_NEIGHBOURS;
                double a[RGBZ_CI_MAX_NEIGHBOURS] = {0};
                double big = -INFINITY, small = INFINITY;
                int cnt = 0;
                for (int32_t j = 0; j < m; j++) {
                    const ptrdiff_t ny = qy + o[2 * j], nx = qx + o[2 * j + 1];
                    if (ny < 0 || ny >= rows || nx < 0 || nx >= cols ||
                        noff[(int32_t)(ny % P) * Q + (int32_t)(nx % Q)] < 0)
                        continue;
                    const double w = (double)(float)src[ny * cols + nx];
                    if (w != w) continue;
                    a[j] = w;
                    cnt++;
                    big = w > big ? w : big;
                    small = w < small ? w : small;
                }
                if (!cnt) continue;
                double s[8];
                for (int t = 0; t < 8; t++) s[t] = a[t];
                for (int t = 0; t < 8; t++) s[t] += a[8 + t];
                for (int t = 0; t < 8; t++) s[t] += a[16 + t];
                const double tot = ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
                const double mean = cnt >= 3 ? (tot - big - small) / (double)(cnt - 2)
                                             : tot / (double)cnt;
                const double hp = vq - mean;
                if (hp != hp) continue;
                hi = hp > hi ? hp : hi;
                lo = hp < lo ? hp : lo;
            }
        const double eh = (double)hot[i], ec = (double)cold[i];
        const double ks = (double)(k * spread[i]);
        const int is_hot = eh > (double)thr && eh > ks && hi < f * eh;
        const int is_cold = ec > (double)thr && ec > ks && lo > -f * ec;
        ok[i] = (uint8_t)(is_hot || is_cold);
    }
}
