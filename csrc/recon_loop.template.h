/*
 * recon_loop.template.h -- the frame loop of the missing-colour reconstruction
 * (paper section 4, eqs. 2-19 and Shi et al.'s 1a-1e: recon_core.template.h
 * holds the arithmetic) for one input element type and one precision.
 *
 * One pass over the frame; rows are split across OpenMP threads. In a row, the
 * sites of one tile column share a plan: they are gathered in blocks of
 * RGBZ_BLK sites (v[t][j] = tap t of site j, recon_core.template.h), run
 * through the core, converted and stored.
 *
 * Memory layout: src and dst are rows x cols, C-contiguous, row stride cols
 * elements. For 2- and 4-column tiles (Mask1, Mask2) each thread converts the
 * rows its windows need once, deinterleaved by column phase into a ring
 * (rgbz_deinterleave), and the core reads the taps of a block in place there;
 * for other tiles (or without the ring's memory) a block is gathered as
 * strided streams (rgbz_sites says how taps share them). The sites within rx
 * columns of the left or right border are gathered tap by tap through the
 * column map (colmap[x + rx] = the column x moved back into the frame by
 * whole periods, so that a tap keeps its colour), in blocks of their own;
 * rows likewise through rgbz_extend.
 *
 * Mask1 (params->mask1_fast): the interior sites of the Z rows (two rows and
 * columns from the border) run the compile-time plan of recon_mask1.h, the
 * other sites the plan of _plans.py, as they always have (recon_mask1.h says
 * why the two must stay apart).
 *
 * Template parameters (rgbz_templating.h), #defined by rgbz_each_type.h, which the end of
 * recon_core.template.h includes once per precision:
 *   IN_T       the element type of the frames: uint8_t, uint16_t, float, double
 *   IS         its suffix: u8, u16, f32, f64
 *   IN_IS_INT  1 for the integer types (results rounded half up), else 0
 *   REAL, RS   the precision of the arithmetic and its suffix (recon_core.template.h's)
 */
#ifndef IN_T
#error "recon_loop.template.h: #define IN_T (the element type of the frames)"
#endif
#ifndef IS
#error "recon_loop.template.h: #define IS (the suffix of IN_T: u8, u16, f32 or f64)"
#endif
#ifndef IN_IS_INT
#error "recon_loop.template.h: #define IN_IS_INT (1 for an integer IN_T, else 0)"
#endif
#if !defined(REAL) || !defined(RS)
#error "recon_loop.template.h: #define REAL and RS (the precision) before including it"
#endif

#define LFN(name) RGBZ_CAT3(name, IS, RS)

/* where the taps of the sites x0, x0 + px, ... of one row are */
typedef struct {
    const IN_T *rowp[2 * RGBZ_MAX_RADIUS + 1];   /* row of offset dy: rowp[dy + ry] */
    const ptrdiff_t *colmap;                     /* column of x + dx: colmap[x + dx + rx] */
    /* NULL, or the rows converted to REAL and deinterleaved by column phase (px 2 or 4):
       the column x of the row of offset dy is prow[dy + ry][(x % px) * plen + x / px] */
    const REAL *prow[2 * RGBZ_MAX_RADIUS + 1];
    ptrdiff_t plen;
    int ry, rx, px;
} LFN(rgbz_row);

/* out[c * plen + i] = (REAL)row[P i + c], P = px (a compile-time 2 or 4 where it is
   called): a row converted and split into its column phases, so that the taps of the sites
   x, x + P, ... are contiguous */
RGBZ_INLINE void LFN(rgbz_deinterleave_p)(const IN_T *restrict row, ptrdiff_t cols, int P,
                                          ptrdiff_t plen, REAL *restrict out)
{
    const ptrdiff_t full = cols / P;
    for (ptrdiff_t i = 0; i < full; i++)
        for (int c = 0; c < P; c++) out[c * plen + i] = (REAL)row[(ptrdiff_t)P * i + c];
    for (ptrdiff_t x = full * P; x < cols; x++) out[(x % P) * plen + x / P] = (REAL)row[x];
}

/* the same for px = 2 or 4, vectorised for the machine (the frame loop is not cloned) */
RGBZ_CLONES_512 static void LFN(rgbz_deinterleave)(const IN_T *restrict row, ptrdiff_t cols,
                                                   int px, ptrdiff_t plen, REAL *restrict out)
{
    if (px == 2)
        LFN(rgbz_deinterleave_p)(row, cols, 2, plen, out);
    else
        LFN(rgbz_deinterleave_p)(row, cols, 4, plen, out);
}

/* tap t of the site x (one element, as stored) */
static inline IN_T LFN(rgbz_tap)(const LFN(rgbz_row) *w, const rgbz_plan *p, int t, ptrdiff_t x,
                                 int direct)
{
    const IN_T *row = w->rowp[p->tap_dy[t] + w->ry];
    const ptrdiff_t c = x + p->tap_dx[t];
    return row[direct ? c : w->colmap[c + w->rx]];
}

/* the value stream[j] = (REAL)row[x0 + j * stride], j < n */
RGBZ_INLINE void LFN(rgbz_stream)(const IN_T *restrict row, ptrdiff_t x0, ptrdiff_t stride,
                                  int n, REAL *restrict stream)
{
    const IN_T *restrict s = row + x0;
    for (int j = 0; j < n; j++) stream[j] = (REAL)s[j * stride];
}

/* The clip level as a threshold of IN_T: (double)v >= level exactly when v >= *thr (v not
   NaN); 0 when no value of IN_T reaches it. level > 0 (the Python layer checks it). */
static int LFN(rgbz_clip_threshold)(double level, IN_T *thr)
{
#if IN_IS_INT
    const double c = ceil(level);
    if (c > (double)(IN_T)-1) return 0;           /* unsigned: (IN_T)-1 is the largest */
    *thr = (IN_T)c;
#else
    IN_T f = (IN_T)level;
    if ((double)f < level) f = sizeof(IN_T) == sizeof(float) ? (IN_T)nextafterf((float)f, INFINITY)
                                                               : (IN_T)nextafter((double)f, INFINITY);
    *thr = f;
#endif
    return 1;
}

/* clipped[j] |= bit where row[c0 + j P] >= thr, j < n (P a compile-time 2 or 4 where it is
   called, so that the loop vectorises) */
RGBZ_INLINE void LFN(rgbz_clip_bits)(const IN_T *restrict row, ptrdiff_t c0, int P, int n,
                                     IN_T thr, uint64_t bit, uint64_t *restrict clipped)
{
    const IN_T *restrict s = row + c0;
    for (int j = 0; j < n; j++) clipped[j] |= s[(ptrdiff_t)j * P] >= thr ? bit : 0;
}

/* 1 if a pixel of the window's rows at a column in [a, b] (inside the frame) is at or above
   thr (rgbz_clip_threshold): the largest (a NaN is never the largest, nor clipped) */
RGBZ_CLONES_512 static int LFN(rgbz_span_reaches)(const LFN(rgbz_row) *w, ptrdiff_t a,
                                                  ptrdiff_t b, IN_T thr)
{
    for (int d = 0; d < 2 * w->ry + 1; d++) {
        const IN_T *restrict row = w->rowp[d];
#if IN_IS_INT
        IN_T m = 0;                                   /* unsigned */
#else
        IN_T m = -INFINITY;                           /* a NaN never replaces it */
#endif
        for (ptrdiff_t x = a; x <= b; x++) m = row[x] > m ? row[x] : m;
        if (m >= thr) return 1;
    }
    return 0;
}

/*
 * The sites x0, x0 + px, ... < x1 of the row, one plan: gathered, reconstructed, stored to
 * drow. m1 >= 0: the interior sites of a Mask1 Z row, run with the constant plan m1 of
 * recon_mask1.h (p is then that plan); pg: the plan _plans.py built for these sites (p
 * itself where m1 < 0). Near clipping (clip_on, clip_thr: the clip level as a threshold of
 * IN_T, rgbz_clip_threshold) every block runs the core of the unclipped frames (a site
 * without a clipped tap gives the same with either core, rgbz_core); in a
 * block whose window reaches the level, each site gets the bit mask of its clipped taps
 * (pg's), and a site with one is computed again by the clipped-pixel core on pg
 * (with the others of its block that have one, their taps gathered into a block of their
 * own); a site whose candidates (edi_rows: its ten taps) are all
 * clipped stays at or above the smallest of them: saturation is kept exactly in IN_T. So
 * the slow core runs only where a clipped pixel is (with clipped pixels in every block it
 * ran everywhere: SG Mask1 40 against 449 Mpix/s with 6 % of the pixels clipped,
 * docs/reports/benchmarks.md).
 *
 * Gathering: inside the frame, the taps of one kernel row whose columns are equal modulo
 * px are one strided stream of that row shifted by whole sites (tap (dy, dx) of site j is
 * element j + q of the stream (dy, r), dx = q px + r): each stream is converted once per
 * block and the core reads the taps as pointers into it (Mask1: 7 streams for 16 taps).
 * Near the borders each tap is gathered through the column map.
 */
RGBZ_CLONES_512 static void LFN(rgbz_sites)(const LFN(rgbz_row) *w, const rgbz_plan *p,
                                        const rgbz_plan *pg, int m1, int m2,
                                        ptrdiff_t cols, ptrdiff_t x0, ptrdiff_t x1,
                                        const RGBZ_CAT(rgbz_knobs, RS) *kn, REAL maxval,
                                        int clip_on, IN_T clip_thr, IN_T *drow)
{
    enum { SPAN = RGBZ_BLK + 2 * RGBZ_MAX_RADIUS + 1 };
    REAL buf[RGBZ_MAX_TAPS][SPAN];
    const REAL *v[RGBZ_MAX_TAPS];
    REAL r[RGBZ_BLK];
    /* near clipping: each site's clipped taps, and the taps, masks and places of a block's
       sites with one (zeroed once: GCC cannot tell they are written before they are read) */
    uint64_t clipped[RGBZ_BLK] = {0}, cmask[RGBZ_BLK];
    REAL cbuf[RGBZ_MAX_TAPS][RGBZ_BLK];
    int at[RGBZ_BLK] = {0};
    const int px = w->px, nt = p->n_taps;
    /* the streams of the plan: kernel row s_dy, column phase s_r, shifts [s_q0, s_q1]; only
       the strided gather reads them (rows not deinterleaved) */
    int ns = 0, s_dy[RGBZ_MAX_TAPS], s_r[RGBZ_MAX_TAPS], s_q0[RGBZ_MAX_TAPS], s_q1[RGBZ_MAX_TAPS];
    int tap_s[RGBZ_MAX_TAPS], tap_q[RGBZ_MAX_TAPS];
    for (int t = 0; t < (w->prow[0] ? 0 : nt); t++) {
        const int dx = p->tap_dx[t];
        const int q = dx >= 0 ? dx / px : -((-dx + px - 1) / px), rr = dx - q * px;
        int s = 0;
        while (s < ns && !(s_dy[s] == p->tap_dy[t] && s_r[s] == rr)) s++;
        if (s == ns) {
            s_dy[ns] = p->tap_dy[t];
            s_r[ns] = rr;
            s_q0[ns] = s_q1[ns] = q;
            ns++;
        }
        if (q < s_q0[s]) s_q0[s] = q;
        if (q > s_q1[s]) s_q1[s] = q;
        tap_s[t] = s;
        tap_q[t] = q;
    }
    /* the sites j in [jd0, jd1) are at least rx columns from either border: their taps are
       read in place (direct); the few others, through the column map. Blocks do not cross
       these bounds, so that a block near a border is only its border sites. */
    const ptrdiff_t ns_all = x1 > x0 ? (x1 - 1 - x0) / px + 1 : 0;
    ptrdiff_t jd0 = x0 >= w->rx ? 0 : (w->rx - x0 + px - 1) / px;
    ptrdiff_t jd1 = cols - w->rx - x0 > 0 ? (cols - w->rx - x0 + px - 1) / px : 0;
    if (jd0 > ns_all) jd0 = ns_all;
    if (jd1 > ns_all) jd1 = ns_all;
    if (jd1 < jd0) jd1 = jd0;
    /* rows deinterleaved: tap t of the site j is element j + tap_off[t] of its row's ring
       slot (x0 + dx = q px + phase, 0 <= phase < px: the plane of that phase, shifted by q
       sites), so that a block's pointers take no division */
    ptrdiff_t tap_off[RGBZ_MAX_TAPS];
    for (int t = 0; t < (w->prow[0] ? nt : 0); t++) {
        /* (px is 2 or 4 here: the phase a mask, the quotient a shift -- c - ph is a multiple
           of px --, not three 64-bit divisions a tap: 1 % of SG Mask2's time) */
        const ptrdiff_t c = x0 + p->tap_dx[t];
        const ptrdiff_t ph = c & (px - 1);
        tap_off[t] = ph * w->plen + (px == 4 ? (c - ph) / 4 : (c - ph) / 2);
    }
    for (ptrdiff_t jb = 0; jb < ns_all;) {
        const ptrdiff_t seg_end = jb < jd0 ? jd0 : jb < jd1 ? jd1 : ns_all;
        const int direct = jb >= jd0 && jb < jd1;
        const int n = (int)(seg_end - jb < RGBZ_BLK ? seg_end - jb : RGBZ_BLK);
        const ptrdiff_t xb = x0 + jb * px;
        if (direct && w->prow[0]) {
            /* rows deinterleaved: each tap of the block is a contiguous run of a plane */
            for (int t = 0; t < nt; t++) v[t] = w->prow[p->tap_dy[t] + w->ry] + (tap_off[t] + jb);
        } else if (direct) {
            for (int s = 0; s < ns; s++) {
                const IN_T *row = w->rowp[s_dy[s] + w->ry];
                const ptrdiff_t xs = xb + s_r[s] + (ptrdiff_t)s_q0[s] * px;
                const int len = n + s_q1[s] - s_q0[s];
                if (px == 2)        /* Mask1, Bayer-period tiles: a compile-time stride */
                    LFN(rgbz_stream)(row, xs, 2, len, buf[s]);
                else if (px == 4)   /* Mask2 */
                    LFN(rgbz_stream)(row, xs, 4, len, buf[s]);
                else
                    LFN(rgbz_stream)(row, xs, px, len, buf[s]);
            }
            for (int t = 0; t < nt; t++) v[t] = buf[tap_s[t]] + (tap_q[t] - s_q0[tap_s[t]]);
        } else {
            for (int t = 0; t < nt; t++) {
                const IN_T *restrict row = w->rowp[p->tap_dy[t] + w->ry];
                const ptrdiff_t *restrict cm = w->colmap + xb + w->rx + p->tap_dx[t];
                for (int j = 0; j < n; j++) buf[t][j] = (REAL)row[cm[(ptrdiff_t)j * px]];
                v[t] = buf[t];
            }
        }
        jb += n;
        /* near clipping: does the block's window reach the level? (the border blocks, read
           through the column map, are taken as if it did) */
        const int hit = clip_on && (!direct || LFN(rgbz_span_reaches)(
                            w, xb - w->rx, xb + (ptrdiff_t)(n - 1) * px + w->rx, clip_thr));
        if (m1 >= 0)
            RGBZ_CAT(rgbz_mask1_core, RS)[m1](v, n, kn, r);
#ifdef RGBZ_M2_RUN
        else if (m2 >= 0)
            RGBZ_M2_RUN(m2, v, n, kn, r);
#endif
        else
            RGBZ_CAT(rgbz_core_plan, RS)(p, v, n, kn, r);
        if (hit) {
            /* the sites with a clipped tap (the level as a threshold of IN_T: the comparison
               in double, exactly), their taps gathered into a block of their own */
            const int ng = pg->n_taps;
            int nc = 0;
            for (int j = 0; j < n; j++) clipped[j] = 0;
            for (int t = 0; t < ng; t++) {
                const IN_T *restrict row = w->rowp[pg->tap_dy[t] + w->ry];
                const ptrdiff_t c0 = xb + pg->tap_dx[t];
                const uint64_t bit = (uint64_t)1 << t;
                if (direct && px == 2)
                    LFN(rgbz_clip_bits)(row, c0, 2, n, clip_thr, bit, clipped);
                else if (direct && px == 4)
                    LFN(rgbz_clip_bits)(row, c0, 4, n, clip_thr, bit, clipped);
                else if (direct)
                    LFN(rgbz_clip_bits)(row, c0, px, n, clip_thr, bit, clipped);
                else
                    for (int j = 0; j < n; j++)
                        clipped[j] |= row[w->colmap[c0 + (ptrdiff_t)j * px + w->rx]] >= clip_thr
                                      ? bit : 0;
            }
            for (int j = 0; j < n; j++)
                if (clipped[j]) {
                    cmask[nc] = clipped[j];
                    at[nc++] = j;
                }
            for (int t = 0; t < ng && nc; t++)
                for (int k = 0; k < nc; k++)
                    cbuf[t][k] = (REAL)LFN(rgbz_tap)(w, pg, t, xb + (ptrdiff_t)at[k] * px, direct);
            if (nc) {
                const REAL *vc[RGBZ_MAX_TAPS];
                REAL rc[RGBZ_BLK];
                for (int t = 0; t < ng; t++) vc[t] = cbuf[t];
                RGBZ_CAT(rgbz_core_clip, RS)(pg, vc, nc, cmask, kn, rc);
                for (int k = 0; k < nc; k++) r[at[k]] = rc[k];
            }
        }
        IN_T *restrict d = drow + xb;
        for (int j = 0; j < n; j++)
            d[(ptrdiff_t)j * px] = (IN_T)RGBZ_CAT(rgbz_out, RS)(r[j], maxval, IN_IS_INT);
        if (!hit) continue;
        const int rows_m = pg->method == RGBZ_M_EDI_ROWS;
        const int nk = rows_m ? pg->n_taps : pg->n_cand;
        for (int j = 0; j < n; j++) {
            if (!clipped[j]) continue;
            int all = 1;
            IN_T lo = 0;
            for (int k = 0; k < nk && all; k++) {
                const int t = rows_m ? k : pg->cand_tap[k];
                all = (int)((clipped[j] >> t) & 1u);
                const IN_T raw = LFN(rgbz_tap)(w, pg, t, xb + (ptrdiff_t)j * px, direct);
                if (!k || raw < lo) lo = raw;
            }
            if (all && d[(ptrdiff_t)j * px] < lo) d[(ptrdiff_t)j * px] = lo;
        }
    }
}

static int LFN(rgbz_recon_loop)(const IN_T *restrict src, IN_T *restrict dst, ptrdiff_t rows,
                                 ptrdiff_t cols, int py, int px, const int32_t *phase_map,
                                 const rgbz_plan *plans, int ry, int rx, const ptrdiff_t *colmap,
                                 const rgbz_params *prm, uint64_t *opcounts)
{
    /* exp()'s (expf()'s) bits from its vector port where this machine's function is that
       algorithm (rgbz_exp.h) */
    const int exp_mode = prm->exp_mode == RGBZ_EXP_LIBM
                         && rgbz_exp_libm_vectorised(sizeof(REAL) == sizeof(float))
                         ? RGBZ_EXP_LIBM_VEC : prm->exp_mode;
    const RGBZ_CAT(rgbz_knobs, RS) kn = {(REAL)prm->sigma_floor, (REAL)prm->sigma_rel,
                                (REAL)prm->edge_ratio, exp_mode};
    const REAL maxval = (REAL)prm->maxval;
    /* the clip level as a threshold of IN_T; a level no value of IN_T reaches clips nothing */
    IN_T clip_thr = 0;
    const int clip_on = prm->clip_on && LFN(rgbz_clip_threshold)(prm->clip_level, &clip_thr);
    (void)opcounts;
    /* Mask1: the Z row phase zr and the constant plan of its interior sites */
    int zr = -1, m1 = -1;
    if (prm->mask1_fast) {
        for (int i = 0; i < 4; i++)
            if (phase_map[i] >= 0) zr = i / 2;
        m1 = rgbz_mask1_index(plans[0].method, plans[0].use_grad && plans[0].use_sg);
    }
    /* plans equal to one of recon_mask2.h's (SG on Mask2, float32, the fast exponential): run
       as its straight-line code, the same bits (m2[pl] its index, or -1) */
    int n_pl = 0;
    for (int i = 0; i < py * px; i++) n_pl = phase_map[i] + 1 > n_pl ? phase_map[i] + 1 : n_pl;
    int *m2 = (int *)malloc((size_t)(n_pl > 0 ? n_pl : 1) * sizeof(int));
    if (!m2) return RGBZ_ENOMEM;
    for (int i = 0; i < n_pl; i++) {
        m2[i] = -1;
#ifdef RGBZ_M2_INDEX
        if (prm->mask2_fast && exp_mode == RGBZ_EXP_FAST) m2[i] = RGBZ_M2_INDEX(&plans[i]);
#endif
    }
    const int nth = rgbz_threads(prm->workers);
    (void)nth;
    /* 2- and 4-column tiles (Mask1, Mask2): each thread keeps the rows its window needs
       converted and deinterleaved (rgbz_deinterleave) in a ring of 2 ry + 1 slots, tagged
       with the frame row they hold, so that a row is converted once per thread rather than
       once per window it falls in (a thread's rows come in chunks of 32 consecutive rows;
       the chunks are handed out as threads free up, so that a thread slowed by another
       process on its core does not hold up the call: on the shared 2-core machine,
       1.04x on Mask2 and 1.19x on Mask1 over a static split, medians of paired rounds).
       Without the memory, the strided gather of rgbz_sites. */
    const int nslot = 2 * ry + 1;
    const ptrdiff_t plen = (px == 2 || px == 4) ? (cols + px - 1) / px : 0;
#ifdef _OPENMP
#pragma omp parallel num_threads(nth)
#endif
    {
        REAL *ring = plen ? (REAL *)malloc((size_t)nslot * (size_t)px * (size_t)plen * sizeof(REAL))
                          : NULL;
        ptrdiff_t tag[2 * RGBZ_MAX_RADIUS + 1];
        for (int k = 0; k < nslot; k++) tag[k] = -1;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 32)
#endif
        for (ptrdiff_t y = 0; y < rows; y++) {
            LFN(rgbz_row) w;
            w.colmap = colmap;
            w.ry = ry;
            w.rx = rx;
            w.px = px;
            w.plen = plen;
            ptrdiff_t need[2 * RGBZ_MAX_RADIUS + 1];
            for (int dy = -ry; dy <= ry; dy++) {
                need[dy + ry] = rgbz_extend(y + dy, rows, py);
                w.rowp[dy + ry] = src + need[dy + ry] * cols;
                w.prow[dy + ry] = NULL;
            }
            memcpy(dst + y * cols, src + y * cols, (size_t)cols * sizeof(IN_T));
            const int32_t *pm = phase_map + (y % py) * px;
            int row_has_z = 0;
            for (int i = 0; i < px; i++) row_has_z |= pm[i] >= 0;
            if (!row_has_z) continue;           /* a colour-only row: the copy is the output */
            if (ring) {
                /* the window's rows from the ring; a missing one into a slot no row of the
                   window holds */
                int held[2 * RGBZ_MAX_RADIUS + 1] = {0};
                for (int d = 0; d < nslot; d++)
                    for (int k = 0; k < nslot; k++)
                        if (tag[k] == need[d]) {
                            w.prow[d] = ring + (ptrdiff_t)k * px * plen;
                            held[k] = 1;
                        }
                for (int d = 0; d < nslot; d++) {
                    if (w.prow[d]) continue;
                    int k = 0;
                    while (held[k]) k++;        /* at most nslot rows are held: one is free */
                    REAL *slot = ring + (ptrdiff_t)k * px * plen;
                    LFN(rgbz_deinterleave)(w.rowp[d], cols, px, plen, slot);
                    /* the frame row below, which the next row's window converts: on its way to
                       the cache while this row's sites run (the conversion waited for memory
                       on its first read of each row: SG Mask2 1.04x the speed, benchmarks.md) */
                    if (need[d] + 1 < rows)
                        rgbz_prefetch_span(src + (need[d] + 1) * cols, (size_t)cols * sizeof(IN_T));
                    tag[k] = need[d];
                    held[k] = 1;
                    for (int e = d; e < nslot; e++)       /* the window may hold a row twice */
                        if (need[e] == need[d]) w.prow[e] = slot;
                }
            }
            /* segments [xa[s], xa[s + 1]) of the row, and their constant plan (-1: none): a
               Mask1 Z row runs its interior [2, cols - 2) on the constant plan */
            const int fast_row = m1 >= 0 && y >= 2 && y < rows - 2 && (y & 1) == zr && cols > 4;
            const ptrdiff_t xa[4] = {0, fast_row ? 2 : cols, fast_row ? cols - 2 : cols, cols};
            const int seg_m1[3] = {-1, m1, -1};
            for (int s = 0; s < 3; s++) {
                for (int ph = 0; ph < px; ph++) {
                    const int pl = pm[ph];
                    if (pl < 0 || xa[s] >= xa[s + 1]) continue;
                    const ptrdiff_t x0 = xa[s] + ((ph - xa[s] % px) + px) % px;
#ifdef RGBZ_COUNT_OPS
                    rgbz_opc_cur = opcounts + (size_t)pl * RGBZ_NOPS;
#endif
                    const int m = seg_m1[s];
                    LFN(rgbz_sites)(&w, m >= 0 ? rgbz_mask1_plans[m] : &plans[pl], &plans[pl],
                                    m, m >= 0 ? -1 : m2[pl], cols, x0,
                                    xa[s + 1], &kn, maxval, clip_on, clip_thr, dst + y * cols);
                }
            }
        }
        free(ring);
    }
    free(m2);
    return RGBZ_OK;
}

#undef LFN
