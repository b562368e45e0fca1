/*
 * z_guided_cells.template.h -- the cell terms of z_guided (z_guided.h) in one precision:
 * what a site takes from its Z pixels alone, per tile row and target colour, in REAL, and
 * the guide weights in the layout of the fast path's dot product. Instantiated by
 * z_guided_entry.template.h (once per precision, with REAL and RS) before the frame loops.
 *
 * A cell's terms are two rows of REAL (the layout of the fast path, ZG_CVR values with
 * L lanes of 32 bytes: 8 floats or 4 doubles): [0..7] the terms c_0 .. c_7, then L values
 * c_8, -1, c_9, c_10, 0, ...; the guide weights of a bucket are three rows (ZG_GVR values)
 * g_0 .. g_7 | g_8, g_9, 0, ... | g_9, g_10, 0, ..., so that the guide term
 * base (sum_{m<9} g_m c_m - g_9) + g_9 c_9 + g_10 c_10 is the sum over the lanes of base
 * times the products of the first two rows plus the products of the third row and the
 * second row's values 2 and 3 moved to lanes 0 and 1 (zg_low2_<RS>; the weights' zeros
 * keep c_9 and c_10 out of the first sum).
 */
#if !defined(REAL) || !defined(RS)
#error "z_guided_cells.template.h: #define REAL and RS (the precision) first"
#endif

#define ZGC RGBZ_CAT
/* the lanes of a 32-byte vector, the values of a cell's two rows and of a bucket's three */
#define ZG_L ((int)(32 / sizeof(REAL)))
#define ZG_CVR (8 + ZG_L)
#define ZG_GVR (8 + 2 * ZG_L)
#define ZG_TAPS_ROW RGBZ_CAT(zg_taps_row, RS)

/* what a thread keeps of the cell terms: for each target colour t, the colour means of
   three tile rows (a ring, slot = tile row mod 3, tagged) padded by one cell on each side
   with the edge cell, and the terms of one tile row, [gx][ZG_CVR] (tagged); the noise levels
   of one tile row (tagged); the amplitude and variance rows (a ring of three tile rows,
   padded likewise, tagged) and the nu row */
typedef struct {
    ptrdiff_t gx;
    REAL *cg;                   /* [3 targets][3 slots][gx + 2] */
    ptrdiff_t cg_tag[3][3];
    REAL *cell;                 /* [3 targets][gx][ZG_CVR] */
    ptrdiff_t cell_tag[3];
    int32_t *level;             /* [gx] */
    ptrdiff_t level_tag;
    REAL *nv;                   /* [3 slots][2][gx + 2]: N and V of a tile row; then nu */
    ptrdiff_t nv_tag[3];
    int bad;                    /* a row of the taps' sites was not its Z pixels in order */
    int nbox[3];
    int ey[3][ZG_MAX_BOX], ex[3][ZG_MAX_BOX];
} ZGC(zg_cells, RS);

/* a thread's cell state (buffers, empty tags, the box offsets of each colour: the pixels of
   colour t in the box of the Z pixel and the two pixels around it, row-major, the same for
   every tile); RGBZ_ENOMEM */
static int ZGC(zg_cells_init, RS)(ZGC(zg_cells, RS) *s, const rgbz_zguided_filters *f, int py,
                                  int px)
{
    const ptrdiff_t gx = f->gx;
    s->gx = gx;
    s->cg = malloc((size_t)9 * (size_t)(gx + 2) * sizeof *s->cg);
    /* the cell vectors' padding lanes stay 0, their constant -1 (value 9) is set here */
    s->cell = calloc((size_t)3 * ZG_CVR * (size_t)gx, sizeof *s->cell);
    if (s->cell)
        for (ptrdiff_t i = 0; i < 3 * gx; i++) s->cell[i * ZG_CVR + 9] = (REAL)-1;
    s->level = malloc((size_t)gx * sizeof *s->level);
    s->nv = malloc((size_t)7 * (size_t)(gx + 2) * sizeof *s->nv);
    for (int t = 0; t < 3; t++) {
        s->cell_tag[t] = PTRDIFF_MIN;
        for (int i = 0; i < 3; i++) s->cg_tag[t][i] = PTRDIFF_MIN;
        int n = 0;
        for (int dy = -2; dy < f->block + 2; dy++)
            for (int dx = -2; dx < f->block + 2; dx++) {
                const int y = ((f->zr + dy) % py + py) % py, x = ((f->zc + dx) % px + px) % px;
                if (f->chan[y * px + x] == t) {
                    s->ey[t][n] = dy;
                    s->ex[t][n] = dx;
                    n++;
                }
            }
        s->nbox[t] = n;
    }
    s->level_tag = PTRDIFF_MIN;
    for (int i = 0; i < 3; i++) s->nv_tag[i] = PTRDIFF_MIN;
    s->bad = 0;
    return s->cg && s->cell && s->level && s->nv ? RGBZ_OK : RGBZ_ENOMEM;
}

static void ZGC(zg_cells_free, RS)(ZGC(zg_cells, RS) *s)
{
    free(s->cg);
    free(s->cell);
    free(s->level);
    free(s->nv);
}

/* pads row r (gx values at r[1 ..]) with its edge values at r[0] and r[gx + 1] */
static inline void ZGC(zg_pad, RS)(REAL *r, ptrdiff_t gx)
{
    r[0] = r[1];
    r[gx + 1] = r[gx];
}

/* the amplitude and variance rows n, v (gx values at n[1 ..], padded) of tile row jy: from
   the grids (converted to REAL), or computed from the taps in REAL (ZG_TAPS_ROW: in double
   rgbz_zguided_guide_row's values, in float rgbz_zguided_guide_row_f32's; the row
   min(jy, gyc - 1), its cells past gxc taking the last complete one; its sites checked:
   s->bad when they are not the row's Z pixels in order) */
static void ZGC(zg_guide_rows, RS)(ZGC(zg_cells, RS) *s, const rgbz_zguided_filters *f,
                                   int py, int px, ptrdiff_t jy, REAL *restrict n,
                                   REAL *restrict v)
{
    const ptrdiff_t gx = f->gx;
    ptrdiff_t nc = gx;
    if (f->grid) {
        const double *restrict gr = f->grid + jy * gx, *restrict vr = f->var + jy * gx;
        RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < nc; ix++) {
            n[ix + 1] = (REAL)gr[ix];
            v[ix + 1] = (REAL)vr[ix];
        }
    } else {
        const ptrdiff_t gxc = f->gxc, jc = jy < f->gyc ? jy : f->gyc - 1;
        const int64_t *restrict sr = f->site_rows + jc * gxc;
        const int64_t *restrict sc = f->site_cols + jc * gxc;
        const int64_t r = f->zr + (int64_t)py * jc;
        s->bad |= zg_sites_bad(sr, sc, gxc, r, f->zc, px);
        ZG_TAPS_ROW(f->taps_type, f->taps, f->taps_F, f->gyc * gxc, jc * gxc, gxc, f->ratio,
                    n + 1, v + 1);
        nc = gxc;
    }
    for (ptrdiff_t ix = nc; ix < gx; ix++) {
        n[ix + 1] = n[nc];
        v[ix + 1] = v[nc];
    }
    ZGC(zg_pad, RS)(n, gx);
    ZGC(zg_pad, RS)(v, gx);
}

/* the cell terms of tile row iy: out[ix][.] (ZG_CVR values, the layout above, value 9 the
   -1 zg_cells_init set) and the relative noise nu[ix], from the padded rows N[3], V[3], C[3]
   (rows iy - 1 .. iy + 1, clamped; index ix + 1 is cell ix), in REAL: every sum in the order
   of m (as cell_terms), the means and the quotients as products with reciprocals. By chunks
   of ZG_CHUNK cells: the terms into per-term rows tm (contiguous stores), then into the cells'
   vectors, transposed in registers (terms 0 .. 7: zg_put8_<RS>; c_8, -1, c_9, c_10:
   zg_putb_<RS>) */
RGBZ_CLONES_512
static void ZGC(zg_cell_row, RS)(const REAL *const *N, const REAL *const *V,
                                 const REAL *const *C, ptrdiff_t gx, REAL lam,
                                 REAL *restrict out, REAL *restrict nu_out)
{
    const REAL *restrict n0 = N[0], *restrict n1 = N[1], *restrict n2 = N[2];
    const REAL *restrict v0 = V[0], *restrict v1 = V[1], *restrict v2 = V[2];
    const REAL *restrict c0 = C[0], *restrict c1 = C[1], *restrict c2 = C[2];
    const REAL ninth = (REAL)1 / (REAL)9, tiny = RGBZ_CAT(RGBZ_TINY, RS);
    REAL tm[RGBZ_ZG_FEATURES][ZG_CHUNK];
    for (ptrdiff_t i0 = 0; i0 < gx; i0 += ZG_CHUNK) {
        const int nc = (int)(gx - i0 < ZG_CHUNK ? gx - i0 : ZG_CHUNK);
        RGBZ_IVDEP for (int i = 0; i < nc; i++) {
            const ptrdiff_t ix = i0 + i;
            const REAL n_[9] = {n0[ix], n0[ix + 1], n0[ix + 2], n1[ix], n1[ix + 1], n1[ix + 2],
                                n2[ix], n2[ix + 1], n2[ix + 2]};
            const REAL v_[9] = {v0[ix], v0[ix + 1], v0[ix + 2], v1[ix], v1[ix + 1], v1[ix + 2],
                                v2[ix], v2[ix + 1], v2[ix + 2]};
            const REAL c_[9] = {c0[ix], c0[ix + 1], c0[ix + 2], c1[ix], c1[ix + 1], c1[ix + 2],
                                c2[ix], c2[ix + 1], c2[ix + 2]};
            REAL nb = 0, vb = 0, cb = 0;
            for (int m = 0; m < 9; m++) {
                nb += n_[m];
                vb += v_[m];
                cb += c_[m];
            }
            nb *= ninth;
            vb *= ninth;
            cb *= ninth;
            const int lit = nb > 0;
            const REAL inv = (REAL)1 / (lit ? nb : (REAL)1);
            REAL u[9], U = 0, ud = 0;
            for (int m = 0; m < 9; m++) {
                u[m] = lit ? n_[m] * inv - (REAL)1 : (REAL)0;
                U += u[m] * u[m];
            }
            const REAL nu = lit ? vb * inv * inv : (REAL)1;
            for (int m = 0; m < 9; m++) ud += u[m] * (c_[m] - cb);
            const REAL share = U / (U + (REAL)9 * nu + tiny);
            const REAL a = ud / (U + (REAL)9 * (lam + nu));
            const REAL au = a * u[4];
            for (int m = 0; m < 9; m++) tm[m][i] = share * u[m];
            tm[9][i] = cb + au;
            tm[10][i] = au - (c_[4] - cb);
            nu_out[ix] = nu;
        }
        REAL *restrict o = out + i0 * ZG_CVR;
        int i = 0;
#if LRN_VECTOR_EXT
        for (; i + ZG_L <= nc; i += ZG_L) {
            RGBZ_CAT(zg_put8, RS)(&tm[0][0], i, o + i * ZG_CVR, ZG_CVR);
            RGBZ_CAT(zg_putb, RS)(&tm[0][0], i, o + i * ZG_CVR, ZG_CVR);
        }
#endif
        for (; i < nc; i++) {
            for (int m = 0; m < 8; m++) o[i * ZG_CVR + m] = tm[m][i];
            o[i * ZG_CVR + 8] = tm[8][i];
            o[i * ZG_CVR + 10] = tm[9][i];
            o[i * ZG_CVR + 11] = tm[10][i];
        }
    }
}

/* the noise levels of a tile row: how many of the n_thr thresholds nu exceeds */
static void ZGC(zg_level_row, RS)(const REAL *restrict nu, ptrdiff_t gx, const double *thr,
                                  int n_thr, int32_t *restrict lvl)
{
    for (ptrdiff_t ix = 0; ix < gx; ix++) lvl[ix] = 0;
    for (int i = 0; i < n_thr; i++) {
        const REAL t = (REAL)thr[i];
        RGBZ_IVDEP for (ptrdiff_t ix = 0; ix < gx; ix++) lvl[ix] += nu[ix] > t;
    }
}

/* the guide weights g[k][b][ZG_GVR] of every phase and bucket in the layout above, from
   f->g_<RS> (malloc'ed; NULL: no memory) */
static REAL *ZGC(zg_guide_weights, RS)(const rgbz_zguided_filters *f)
{
    const ptrdiff_t n = (ptrdiff_t)f->hash->n_phases * f->n_levels * f->hash->n_buckets;
    const REAL *g = f->RGBZ_CAT(g, RS);
    REAL *out = calloc((size_t)n * ZG_GVR, sizeof *out);
    if (out)
        for (ptrdiff_t i = 0; i < n; i++) {
            const REAL *gi = g + i * RGBZ_ZG_FEATURES;
            REAL *o = out + i * ZG_GVR;
            for (int m = 0; m < 10; m++) o[m] = gi[m];
            o[8 + ZG_L] = gi[9];
            o[9 + ZG_L] = gi[10];
        }
    return out;
}

#undef ZGC
#undef ZG_TAPS_ROW
