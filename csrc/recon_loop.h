/*
 * recon_loop.h -- the frame loop of the reconstruction for one input element
 * type IN_T and one precision REAL. Included by recon.c with
 *   IN_T, IS (suffix u8|u16|f32|f64), IN_IS_INT, REAL, RS.
 * One pass over the frame; rows are split across OpenMP threads; each thread
 * uses a few hundred bytes of stack and the shared column map.
 */
#define LCAT3(a, b, c) a##_##b##_##c
#define LCAT(a, b, c) LCAT3(a, b, c)
#define SITE2(a, b) a##_##b
#define SITE(a, b) SITE2(a, b)

static int LCAT(rgbz_recon_loop, IS, RS)(const IN_T *restrict src, IN_T *restrict dst,
                                         ptrdiff_t rows, ptrdiff_t cols, int py, int px,
                                         const int32_t *phase_map, const rgbz_plan *plans,
                                         int ry, int rx, const ptrdiff_t *colmap,
                                         const rgbz_params *prm, uint64_t *opcounts)
{
    const REAL floor_ = (REAL)prm->sigma_floor;
    const REAL rel = (REAL)prm->sigma_rel;
    const REAL edge_ratio = (REAL)prm->edge_ratio;
    const REAL maxval = (REAL)prm->maxval;
    const int exp_mode = prm->exp_mode;
    const int clip_on = prm->clip_on;
    const double clip_level = prm->clip_level;
    (void)opcounts;
    /* the Mask1 fast path: interior rows and columns, constant offsets */
    int zr = -1, zc = -1;
    if (prm->mask1_fast)
        for (int i = 0; i < 4; i++)
            if (phase_map[i] >= 0) { zr = i / 2; zc = i % 2; }
    const int fast = zr >= 0;
    const int ab_method = fast && (plans[0].method == RGBZ_M_BI ||
                                   plans[0].method == RGBZ_M_EDI_CENTRAL ||
                                   plans[0].method == RGBZ_M_EDI_LINE);
    const int sg_pure = fast && plans[0].method == RGBZ_M_SG && !(plans[0].use_grad && plans[0].use_sg);
#ifdef _OPENMP
    int nth = prm->workers > 0 ? prm->workers : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(nth)
#endif
    for (ptrdiff_t y = 0; y < rows; y++) {
        const int fast_row = fast && y >= 2 && y < rows - 2 && (y & 1) == zr;
        const IN_T *rowp[2 * RGBZ_MAX_RADIUS + 1];
        for (int dy = -ry; dy <= ry; dy++)
            rowp[dy + ry] = src + rgbz_extend(y + dy, rows, py) * cols;
        memcpy(dst + y * cols, src + y * cols, (size_t)cols * sizeof(IN_T));
        const int32_t *pm = phase_map + (y % py) * px;
        int row_has_z = 0;
        for (int i = 0; i < px; i++) row_has_z |= pm[i] >= 0;
        if (!row_has_z) continue;           /* a colour-only row: the copy is the output */
        if (!clip_on && !fast_row) {
            /* the sites of one tile column share a plan: run them in blocks (rgbz_site_block),
               except edi_rows, whose sites go one by one */
            int blockable = 1;
            for (int i = 0; i < px; i++)
                if (pm[i] >= 0 && plans[pm[i]].method == RGBZ_M_EDI_ROWS) blockable = 0;
            if (blockable) {
                for (int ph0 = 0; ph0 < px && ph0 < cols; ph0++) {
                    const int pl = pm[ph0];
                    if (pl < 0) continue;
                    const rgbz_plan *p = &plans[pl];
#ifdef RGBZ_COUNT_OPS
                    rgbz_opc_cur_count = opcounts + (size_t)pl * RGBZ_NOPS;
#endif
                    REAL vb[RGBZ_MAX_TAPS][RGBZ_BLK];
                    REAL rb[RGBZ_BLK];
                    for (ptrdiff_t x0b = ph0; x0b < cols; x0b += (ptrdiff_t)px * RGBZ_BLK) {
                        ptrdiff_t left = (cols - 1 - x0b) / px + 1;
                        const int n = (int)(left < RGBZ_BLK ? left : RGBZ_BLK);
                        for (int t = 0; t < p->n_taps; t++) {
                            const IN_T *restrict row = rowp[p->tap_dy[t] + ry];
                            const ptrdiff_t *cm = colmap + x0b + rx + p->tap_dx[t];
                            for (int j = 0; j < n; j++) vb[t][j] = (REAL)row[cm[(ptrdiff_t)j * px]];
                        }
                        SITE(rgbz_site_block, RS)(vb, n, p, floor_, rel, exp_mode, rb);
                        IN_T *restrict d = dst + y * cols + x0b;
                        for (int j = 0; j < n; j++)
                            d[(ptrdiff_t)j * px] = LCAT(rgbz_to_out, IS, RS)(rb[j], maxval);
                    }
                }
                continue;
            }
        }
        /* a fast row leaves only its two border columns at each end to the interpreter */
        for (int seg = 0; seg < (fast_row ? 2 : 1); seg++) {
            const ptrdiff_t xa = fast_row ? (seg ? (cols - 2 > 2 ? cols - 2 : 2) : 0) : 0;
            const ptrdiff_t xe = fast_row ? (seg ? cols : (cols < 2 ? cols : 2)) : cols;
            int ph = (int)(xa % px);
            for (ptrdiff_t x = xa; x < xe; x++, ph = (ph + 1 == px) ? 0 : ph + 1) {
                int pl = pm[ph];
                if (pl < 0) continue;
                const rgbz_plan *p = &plans[pl];
#ifdef RGBZ_COUNT_OPS
                rgbz_opc_cur_count = opcounts + (size_t)pl * RGBZ_NOPS;
#endif
                REAL v[RGBZ_MAX_TAPS];
                const ptrdiff_t *cm = colmap + x + rx;
                IN_T raw[RGBZ_MAX_TAPS];
                uint64_t clipped = 0;               /* bit t: tap t is clipped */
                if (clip_on) {
                    /* compared in double, exact for every input type and precision */
                    for (int t = 0; t < p->n_taps; t++) {
                        raw[t] = rowp[p->tap_dy[t] + ry][cm[p->tap_dx[t]]];
                        v[t] = (REAL)raw[t];
                        if ((double)raw[t] >= clip_level) clipped |= (uint64_t)1 << t;
                    }
                } else {
                    for (int t = 0; t < p->n_taps; t++)
                        v[t] = (REAL)rowp[p->tap_dy[t] + ry][cm[p->tap_dx[t]]];
                }
                REAL r = clipped ? SITE(rgbz_site_clip, RS)(v, clipped, p, floor_, rel, edge_ratio,
                                                            exp_mode)
                                 : SITE(rgbz_site, RS)(v, p, floor_, rel, edge_ratio, exp_mode);
                IN_T out = LCAT(rgbz_to_out, IS, RS)(r, maxval);
                if (clipped) {
                    /* every candidate clipped (edi_rows: its ten taps): the output stays at or
                       above the smallest of them, so saturation is kept exactly in IN_T */
                    const int rows_m = p->method == RGBZ_M_EDI_ROWS;
                    const int n = rows_m ? p->n_taps : p->n_cand;
                    int all = 1;
                    IN_T lo = 0;
                    for (int k = 0; k < n && all; k++) {
                        int t = rows_m ? k : p->cand_tap[k];
                        all = (int)((clipped >> t) & 1u);
                        if (!k || raw[t] < lo) lo = raw[t];
                    }
                    if (all && out < lo) out = lo;
                }
                dst[y * cols + x] = out;
            }
        }
        if (fast_row) {
#ifdef RGBZ_COUNT_OPS
            rgbz_opc_cur_count = opcounts;
#endif
            if (sg_pure)
                LCAT(rgbz_mask1_sg_rows, IS, RS)(src, dst, y, cols, zc, prm, 2, cols - 2);
            else if (ab_method)
                LCAT(rgbz_mask1_ab_rows, IS, RS)(src, dst, y, cols, zc, &plans[0], prm, 2, cols - 2);
            else
                LCAT(rgbz_mask1_rows, IS, RS)(src, dst, y, cols, zr, zc, &plans[0], prm, 2, cols - 2);
        }
    }
    return RGBZ_OK;
}

#undef LCAT
#undef LCAT3
#undef SITE
#undef SITE2
