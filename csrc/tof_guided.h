/*
 * tof_guided.h -- the colour-guided ToF ISP and the guided upsampling of its depth
 * (tof_guided.c). Plain C99, no Python.h; status codes of rgbz.h. An entry point that reads
 * an array of the caller's element type (the taps, the guide) takes its rgbz_type code
 * in_type beside a void pointer (rgbz_templating.h); RGBZ_EINVAL for another code.
 *
 * Layout: the Z measurements fill a grid of R rows and C columns in row-major order
 * (N = R C; the Python layer scatters other layouts onto such a grid and marks the holes
 * unusable). Per-measurement planes are (N,) and per-frequency planes (F, N), row-major.
 */
#ifndef RGBZ_TOF_GUIDED_H
#define RGBZ_TOF_GUIDED_H

#include <stddef.h>
#include <stdint.h>

/* Taps (F, 4, N) -> phasors zr, zi (F, N) float, the variance of one component of a
   measurement's phasor averaged over the frequencies v (N,) float (2 var(A), var(A) =
   gain held / (1 - suppression) + const_var + (prnu held)^2, held = max(offset - black, 0)
   in DN), sat[n] |= 1 where a tap reaches white, and the offset (F, N) mean(A_k) when
   offset is not NULL; when phi is not NULL, phi (N,): the share of v that the taps' fixed
   pattern gives, (F fixed_var + sum_f (prnu held_f)^2) / sum_f var(A_f), at most 0.99
   (fixed_var: the per-tap variance of the fixed offsets, DSNU or a dark frame's error,
   DN^2); it is col's fourth plane for rgbz_tofg_pass and rgbz_tofg_denoise. */
int rgbz_tofg_prepare(int in_type, const void *taps, ptrdiff_t F, ptrdiff_t N, double gain,
                      double black, double supp, double const_var, double prnu, double white,
                      float *zr, float *zi, float *v, uint8_t *sat, double *offset,
                      double fixed_var, float *phi, int workers);

/* The guide (H, W, 3) at the measurements: col (3, N) the mean over the block x block
   cells of each (times scale), cells (block^2, 3, N) each cell (NULL: not stored), and
   lap (3,) the sums of |Immerkaer's Laplacian| of col over the grid's interior. With sigma
   not NULL, also the guide's noise per channel, sigma = max(sqrt(pi / 2) / (6 (R - 2)(C - 2))
   lap, floor) (floor where the interior is empty), into sigma (3,), and col and cells
   multiplied by (float)(1 / (sqrt(2) sigma)) of their channel, in float. */
int rgbz_tofg_colour(int in_type, const void *guide, ptrdiff_t H, ptrdiff_t W,
                     const int64_t *row_px, ptrdiff_t R, const int64_t *col_px, ptrdiff_t C,
                     int block, double scale, float *col, float *cells, double *lap,
                     double floor, double *sigma, int workers);

/* The guide at the pixels bordering each Z pixel: for the 4 block + 4 offsets (a, c), a and c
   in -1..block, the Z pixel's own cells left out, in row-major order, the pixel (row_px[r] +
   a, col_px[c] + c) clamped to the frame, each channel times inv[ch] in double, rounded to
   float, into ring (4 block + 4, 3, N), N = R C, measurement r C + c. */
int rgbz_tofg_ring(int in_type, const void *guide, ptrdiff_t H, ptrdiff_t W,
                   const int64_t *row_px, ptrdiff_t R, const int64_t *col_px, ptrdiff_t C,
                   int block, const double *inv, float *ring, int workers);

/* One 1-D pass of the guided cross-bilateral mean along rows (axis 1) or columns (axis 0):
   data zr, zi (F, N), v (N,); guide phasors gr, gi (F, N) with variance gv (N,); colours
   col (3, N) already divided by sqrt(2) sigma_c; use (N,) 1 = may enter a mean; nin (N,)
   the n_eff of the data (a second pass) or NULL. px: the pixel coordinate of every grid
   line along the axis; a neighbour enters within reach lines and radius_px pixels.
   Outputs mean or_, oi (F, N) (or, when or64 is not NULL, or64, oi64 in double), its
   variance ov (N,) (+inf where nothing entered) and n_eff on (N,). fixed: col holds a fourth
   plane (4, N), the share phi of each measurement's variance that the taps' fixed pattern
   gives (one DSNU offset and one PRNU gain per tap in every frequency's frame, so one error
   in every frequency), and the phasor term is the pair's Mahalanobis distance under it
   (tofg_xp in tof_guided.c; the guide's share taken as its measurement's phi); 0: col
   (3, N) and the variances taken as independent across frequencies. */
int rgbz_tofg_pass(const float *zr, const float *zi, const float *v, const float *nin,
                   const float *gr, const float *gi, const float *gv, const float *col,
                   const uint8_t *use, ptrdiff_t F, ptrdiff_t R, ptrdiff_t C, int axis,
                   const int64_t *px, ptrdiff_t reach, int64_t radius_px, double inv2h2,
                   double inv2hc2, float *or_, float *oi, double *or64, double *oi64,
                   float *ov, float *on, int fixed, int workers);

/* The validity of the fused denoise's unwrapped means (rgbz_tofg_validity's arguments but
   amp, var, depth and residual, which are the denoise's own), with the fixed-pattern
   correction delta of rgbz_tof_fixed_pattern (shared = 1) when offset (F, N) is not NULL:
   the taps' mean of the prepare stage; count is the denoise's n_eff (on64); delay_var,
   when not 0, adds delay_var / max(count, 1) to delta, as tof/_noise.py's
   fixed_pattern_delta does. Each output row's values are made while the row is in the
   cache, equal bit for bit to the two kernels run after the denoise. */
typedef struct {
    const uint8_t *sat;
    const double *sigma_scale, *refl_coef;
    double min_snr, min_amplitude, max_sigma, max_residual, min_reflectance, max_range;
    double max_reflectance;
    double *snr, *sigma, *refl;
    uint8_t *flags;
    const double *offset;
    double black, pre, var_dsnu, fix_dsnu, prnu, delay_var;
    /* usable (NULL: not made): rgbz_tofg_usable of the row's flags, depth and sigma with
       present (NULL: every one) and the bits bad, as each row's validity is made */
    uint8_t *usable;
    const uint8_t *present;
    uint8_t bad;
} tofg_valid_out;

/* The unwrapping of the fused denoise's means (rgbz_tof_depth_iq's arguments): depth,
   residual, wraps (N,), phase and amp (F, N); valid (NULL: none) the validity of the
   means as they are unwrapped (tofg_valid_out; it needs on64). */
typedef struct {
    const double *freqs, *weights;
    double max_range;
    double *depth, *residual;
    int32_t *wraps;
    double *phase, *amp;
    const tofg_valid_out *valid;
} tofg_unwrap_out;

/* The prepare stage (rgbz_tofg_prepare's arguments) made inside the guided denoise, row by row
   as its first pass reads them: the taps (F, 4, N) of in_type, and sat (N,) |= a tap at full
   scale and offset (F, N) written (each thread the rows and columns whose outputs it makes);
   zr, zi and v are then not read (NULL) and the denoise's use (N,) is taken before the taps'
   full scale (the stage's hits leave it out where they are); col's fourth plane (fixed) is
   made with them. */
typedef struct {
    int in_type;
    const void *taps;
    double gain, black, supp, const_var, prnu, white, fixed_var;
    uint8_t *sat;
    double *offset;
} tofg_prep_in;

/* The guided denoise, the four passes of rgbz_tofg_pass fused: a row pass of the raw
   phasors zr, zi (F, N) with variance v (N,) guided by themselves, a column pass of it guided
   by itself (the guide of the second round), a row pass of the raw phasors guided by that,
   and a column pass of it guided by the same; outputs as rgbz_tofg_pass's last (or64, oi64
   (F, N), ov, on (N,)), bit for bit. No plane of the intermediate passes is ever held for the
   whole frame: on evenly spaced grid lines (and F <= 4) each thread runs a band of output
   rows through the four passes row by row, the column passes' inputs in rings of a few padded
   rows (a band recomputes only the rows its column passes reach beyond it); otherwise strip
   by strip of grid rows, each strip recomputing the rows its column passes reach beyond it.
   row_px (R,), col_px (C,): the pixel coordinates of the grid lines; reach_r, reach_c: the
   grid lines a pass along columns and along rows reaches. With uw (not NULL) the means are
   unwrapped as they are made (rgbz_tof_depth_iq, bit for bit) into uw's arrays instead of
   being stored (or64, oi64 unused); a non-finite mean gives RGBZ_EDOMAIN after every other
   one is computed. strip: the grid rows of output per band or strip (<= 0: one band per
   thread, or strips of at most 128 rows); the outputs do not depend on it. on64 (N,), when
   not NULL, takes the n_eff of on in double (on may then be NULL). fixed: as in
   rgbz_tofg_pass. */
int rgbz_tofg_denoise(const float *zr, const float *zi, const float *v, const float *col,
                      const uint8_t *use, ptrdiff_t F, ptrdiff_t R, ptrdiff_t C,
                      const int64_t *row_px, const int64_t *col_px, ptrdiff_t reach_r,
                      ptrdiff_t reach_c, int64_t radius_px, double inv2h2, double inv2hc2,
                      double *or64, double *oi64, float *ov, float *on, double *on64,
                      const tofg_unwrap_out *uw, ptrdiff_t strip, int fixed,
                      const tofg_prep_in *prep, int workers);

/* snr, sigma, reflectance and the validity bits (1 saturated, 2 low signal, 4 inconsistent,
   16 out of range) of every measurement from amp (F, N), the component variance var (N,),
   depth, residual (N,), sat (N,). sigma_scale (F,): (w_f c / (4 pi f) / sum w)^2;
   refl_coef (F,): the reciprocal amplitude of a reflectance-1 surface at 1 m; max_sigma < 0:
   no limit. delta (N,) or NULL: rgbz_tof_fixed_pattern's correction (tof_filter.h), added to
   sigma^2 where no frequency's phase variance reached the cap and the sum stays > 0. */
int rgbz_tofg_validity(const double *amp, const float *var, const double *depth,
                       const double *residual, const uint8_t *sat, ptrdiff_t F, ptrdiff_t N,
                       const double *sigma_scale, const double *refl_coef, double min_snr,
                       double min_amplitude, double max_sigma, double max_residual,
                       double min_reflectance, double max_range, const double *delta,
                       double *snr, double *sigma, double *refl, uint8_t *flags, int workers,
                       double max_reflectance);

/* usable (N,) = 1 where the measurement may enter the flying-pixel test: none of the bits
   bad in flags, depth and sigma finite, present (NULL: every one) nonzero; else 0. */
int rgbz_tofg_usable(const uint8_t *flags, const double *depth, const double *sigma,
                     const uint8_t *present, uint8_t bad, ptrdiff_t N, uint8_t *usable,
                     int workers);

/* The candidates of the flying-pixel test (rgbz_fast.tof.flying_pixels) on the grid (R, C):
   cand (N,) = 1 where a usable (usable != 0) measurement is at a depth discontinuity along
   one of the four grid directions -- the second difference of depth exceeds
   max(step, k sqrt(s[m+e]^2 + 4 s[m]^2 + s[m-e]^2)), three usable measurements in a row --
   or is the neighbour across its larger first difference; else 0. The unusable cells' depth
   and sigma are never used (they may be NaN). 0 < k < inf. */
int rgbz_tofg_flying_candidates(const double *depth, const double *sigma,
                                const uint8_t *usable, ptrdiff_t R, ptrdiff_t C, double step,
                                double k, uint8_t *cand, int workers);

/* The flying-pixel test with colour edges on the grid (R, C): usable (N,) measurements
   (not saturated, not low-signal); second differences of depth against max(step, k noise)
   mark the candidates (rgbz_fast.tof.flying_pixels); a candidate whose depth is one side's
   and whose every cell has that side's colour, and every pixel of its ring (the pixels
   bordering its Z pixel) nearer that side's colour than the other's, stays valid (unflag !=
   0, only with more than one cell), one whose cells all have one side's colour while its
   depth lies between the sides is resolved to that side (bit 32, depth_out), the others are
   flying (bit 8). col (3, N), cells (ncells, 3, N), ring (nring, 3, N) or NULL with nring 0:
   colours divided by the guide's noise. */
int rgbz_tofg_flying(const double *depth, const double *sigma, const uint8_t *usable,
                     const float *col, const float *cells, int ncells, const float *ring,
                     int nring, ptrdiff_t R, ptrdiff_t C, double step, double k,
                     double contrast, double side, int unflag, uint8_t *flags,
                     double *depth_out, double max_range, uint8_t *valid, int workers);

/* Joint bilateral upsampling of the usable measurements (depth finite) to every pixel of the
   guide (H, W, 3). First every node without a usable measurement takes the same rule over
   the usable ones within 1, else 2, else 4 (at most reach <= 4) grid lines (Gaussian
   weights exp(-d^2 inv2s2), d in spacings, its own colour), at a quarter of their
   normalised weight. Then a pixel takes
   the 4 nodes around it (grid-line centres rc (R,), cc (C,) in pixels), weighted
   bilinearly times the colour kernel exp(-max(chi - 3, 0) inv2hc2) of its colour against
   theirs (col (3, N) divided by sqrt(2) sigma_c; the pixel's is guide * scale * cscale
   (3,)): the depth of the heaviest and the weighted mean of those within max(tol_k sigma,
   tol_min) of it; confidence: the summed weight of that mean. own (N,) or NULL: a node's
   own measurement too noisy to use (NaN: none); a node with one takes only candidates
   within own_k times its sigma of it, and gets no depth, at weight 1, when none is. NaN and
   0 where no node around the pixel has a depth, where the heaviest node has none, or where
   the nodes more than max(gap, the tolerance) off the chosen depth (or without one) hold more
   than `ambiguity` of the weight. */
/* The low-signal measurements a usable neighbour confirms, for rgbz_tofg_upsample, in place on
   the grid (R, C): each node m with lone[m] != 0 (a candidate: its own measurement low[m],
   finite, sigma[m]) whose low[m] lies within max(tol_k sigma[m], tol_min) (tol_min where the
   product is NaN) of depth[n] for one
   of its 8 neighbours n with lone[n] == 0 and depth[n] finite (a usable measurement) moves
   low[m] into depth[m] (NaN there before) and sets low[m] to NaN; the others keep theirs.
   Neighbours are judged on lone and the depths they had, so the result does not depend on
   the order or the thread count. */
int rgbz_tofg_agree(double *depth, double *low, const uint8_t *lone, const double *sigma,
                    ptrdiff_t R, ptrdiff_t C, double tol_k, double tol_min, int workers);

int rgbz_tofg_upsample(int in_type, const void *guide, ptrdiff_t H, ptrdiff_t W, double scale,
                       const double *cscale, const double *depth, const double *sigma,
                       const float *col, ptrdiff_t R, ptrdiff_t C, const double *rc,
                       const double *cc, double spacing, ptrdiff_t reach, double inv2s2,
                       double inv2hc2, double tol_k, double tol_min, const double *own,
                       double own_k, double ambiguity, double gap, float *out, float *conf,
                       int workers);

#endif
