/*
 * sim.h -- C API of the sensor simulation kernels (sim.c), plain C99, no Python.h.
 *
 * The per-pixel work of rgbz_fast.simulation: the colour pixels' signal and noise chain, the
 * i-ToF taps of ideal Z pixels (light, phasors, noise chain) and the noise chain of taps
 * whose mean the Python layer computed (non-ideal sensors, optics). The conventions (tap
 * phases, radiometry, the order of the noise terms) are those of the module docstring of
 * rgbz_fast.simulation._simulate; the noise-free arithmetic is that of its NumPy code, in
 * the same order, so that a noise-free frame is the same bit for bit (sim.c is compiled
 * with -ffp-contract=off and calls the C library's sin and cos, as NumPy's complex
 * exponential does).
 *
 * Random numbers (rng version 2 of the Python layer): counter-based, Threefry4x32-20
 * (sim_rng.h), each a
 * function of the stream's key and of the sample's position, so every output is the same
 * on any number of threads. Counters (word 0, word 1, word 2, word 3 = the attempt):
 *   colour pixel (y, x):          fixed pattern (x, y, FPN, 0), shot (x, y, POISSON, j),
 *                                 read noise (x / 2, y, READ, 0), the pair's normal x % 2
 *   ToF Z pixel (r, c) (its top-left cell), frequency f, tap k:
 *                                 fixed pattern (c, r, FPN + k, 0), shot (c, r, POISSON +
 *                                 4 f + k, j), read noise (c, r, READ + 2 f + k / 2, 0),
 *                                 the pair's normal k % 2
 * The fixed pattern's two normals are the PRNU's (first) and the DSNU's (second).
 *
 * Layouts: frames row-major; a source image is read as src[y * row_stride + x * col_stride +
 * chan_off[colour]] (elements); ToF taps (F, 4, n) row-major, sites by their top-left cell.
 * Status codes of rgbz.h.
 */
#ifndef RGBZ_SIM_H
#define RGBZ_SIM_H

#include <stddef.h>
#include <stdint.h>

#include "rgbz.h"

/* the noise chain of one sensor: mean electrons -> digital numbers */
typedef struct rgbz_sim_noise {
    int32_t noise;         /* 0: no random and no fixed-pattern term at all */
    int32_t shot;          /* Poisson shot noise (with noise) */
    int32_t quantise;      /* round half up to integer DN, uint16 out; 0: float64 DN out */
    int32_t pad_;
    double prnu;           /* PRNU gain rms (fraction; 0: off) */
    double dsnu;           /* DSNU offset rms (e-; 0: off) */
    double read_noise;     /* e- rms (0: off) */
    double full_well;      /* e- (may be +inf) */
    double black;          /* DN */
    double gain;           /* DN per e- */
    double top;            /* the white level, DN */
    double dark;           /* dark electrons added to every sample */
    uint32_t key_temporal[4];
    uint32_t key_fpn[4];
} rgbz_sim_noise;

/* what the ToF light model needs (rgbz_fast._sensors.ToFSensor, ideal modulation) */
typedef struct rgbz_sim_tof_light {
    double k;              /* electrons per (W/m^2 of irradiance x reflectance) */
    double power;          /* optical power, W */
    double th, tv;         /* tan of the half fields of view */
    double ambient;        /* ambient irradiance, W/m^2 */
    double duty;           /* duty cycle (1: continuous wave) */
    double c25;            /* 0.25 x the modulation contrast */
    double suppression;    /* ambient suppression share (0: off) */
    double unambiguous;    /* unambiguous range, m */
    double speed_of_light; /* m/s */
    double two_pi;
    int32_t nfreq;
    int32_t pad_;
    double four_pi_f[RGBZ_TOF_MAX_FREQS];  /* 4 pi f of every frequency */
    double shift_re[4], shift_im[4];        /* e^{i k pi / 2} of tap k */
} rgbz_sim_tof_light;

/* the 128-bit stream key (four 32-bit words) of a seed (nwords 64-bit words, least
   significant first) and a stream number */
void rgbz_sim_key(const uint64_t *words, ptrdiff_t nwords, uint64_t stream, uint32_t key[4]);

/* n blocks of Threefry4x32-20 at counters (c0 + i, c1, c2, c3) with key: out (n, 4)
   (tests) */
int rgbz_sim_blocks(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t c3, const uint32_t key[4],
                    ptrdiff_t n, uint32_t *out);
/* n standard normals (kind 0: Box-Muller pairs of blocks (i / 2, c1, c2, 0)) or Poisson
   variates of mean lam[i] (kind 1: counters (i, c1, c2, j)) (tests) */
int rgbz_sim_variates(int kind, const double *lam, uint32_t c1, uint32_t c2,
                      const uint32_t key[4], ptrdiff_t n, double *out, int workers);
/* the phasor field of one frequency and correlation order h over n values, re + i im =
   s e^{i h phi} with phi = (4 pi f d / c) mod 2 pi: the NumPy code of ToFSensor._returns
   (s[None] * np.exp(1j * (h * phase))) bit for bit, signed zeros included; four_pi_f = 4 pi f
   as NumPy forms it. The simulation's optics path blurs these planes. */
int rgbz_sim_tof_field(const double *d, const double *s, ptrdiff_t n, double four_pi_f,
                       double speed_of_light, double two_pi, int order, double *re, double *im,
                       int workers);
/* the log and sine/cosine of 2 pi u of the Box-Muller transform (tests) */
int rgbz_sim_math(int which, const double *x, ptrdiff_t n, double *out);

/* the sites of the Z measurements, row-major: tile_z (P x Q, 1 at a Z site); block 1: every
   Z site; block 2: the top-left cell of every 2x2 square inside the frame whose top-left
   cell is a Z site at even (row, col). With site_r NULL only *count is set. workers: the
   threads (<= 0: the OpenMP default). */
int rgbz_sim_z_sites(const uint8_t *tile_z, int P, int Q, ptrdiff_t rows, ptrdiff_t cols,
                     int block, int64_t *site_r, int64_t *site_c, ptrdiff_t *count,
                     int workers);

/* the colour signal rate value * per_unit[colour] of every site: a 65536-bin histogram of
   the top 16 bits of its IEEE representation (hist), or the rates whose top 16 bits lie in
   [lo16, hi16] (gather: *count of them, at most cap written to out) */
int rgbz_sim_rate_hist(int type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                       ptrdiff_t row_stride, ptrdiff_t col_stride, const ptrdiff_t chan_off[3],
                       const int32_t *tile, int P, int Q, const double per_unit[3],
                       uint64_t *hist, int workers);
int rgbz_sim_rate_gather(int type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                         ptrdiff_t row_stride, ptrdiff_t col_stride, const ptrdiff_t chan_off[3],
                         const int32_t *tile, int P, int Q, const double per_unit[3],
                         uint32_t lo16, uint32_t hi16, double *out, ptrdiff_t cap,
                         ptrdiff_t *count, int workers);

/* the colour pixels: mean = value * per_unit[colour] * exposure through the noise chain into
   ref (rows x cols, uint16 or float64 after nz->quantise) and, if data is not NULL, the same
   with 0 where tile_z is 1 (the RGB-Z build); *saturated counts the samples at full well
   or full scale */
int rgbz_sim_colour(int type, const void *src, ptrdiff_t rows, ptrdiff_t cols,
                    ptrdiff_t row_stride, ptrdiff_t col_stride, const ptrdiff_t chan_off[3],
                    const int32_t *tile, const uint8_t *tile_z, int P, int Q,
                    const double per_unit[3], double exposure, const rgbz_sim_noise *nz,
                    void *ref, void *data, int64_t *saturated, int workers);

/* the taps (F, 4, n) of ideal Z pixels of block x block cells: depth (rows x cols, metres),
   depth_valid, the NIR reflectance ir (float32 or float64, read as ir[y * ir_rs + x * ir_cs];
   ir_estimate: 0.2 + 0.6 clip(value, 0, 1) of it). Per site: depth_true (the mean of its
   cells' depths), valid (every cell valid), beyond (a valid cell at or past the unambiguous
   range), sat (a tap at full well or full scale); *max_depth the largest valid cell depth */
int rgbz_sim_tof(const double *depth, const uint8_t *depth_valid, ptrdiff_t rows,
                 ptrdiff_t cols, int ir_type, const void *ir, ptrdiff_t ir_rs, ptrdiff_t ir_cs,
                 int ir_estimate, const int64_t *site_r, const int64_t *site_c, ptrdiff_t n,
                 int block, const rgbz_sim_tof_light *light, const rgbz_sim_noise *nz,
                 void *taps, double *depth_true, uint8_t *valid, uint8_t *beyond, uint8_t *sat,
                 double *max_depth, int workers);

/* the noise chain of taps whose mean electrons (F, 4, n, dark signal excluded) are given,
   less suppress[i] after the shot noise when suppress is not NULL */
int rgbz_sim_tof_expose(const double *mean, const double *suppress, const int64_t *site_r,
                        const int64_t *site_c, ptrdiff_t n, int nfreq, const rgbz_sim_noise *nz,
                        void *taps, uint8_t *sat, int workers);

#endif /* RGBZ_SIM_H */
