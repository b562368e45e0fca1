/*
 * hw_stream.h -- what the fixed-point streaming models (hw_recon.c, hw_learned.c) share:
 * the priority encoder, the border rule, and the streaming front end that turns a frame
 * into one window per output pixel through line buffers, as the chip reads it.
 *
 * Streaming: the frame is read row by row, one pixel per step, through R + A line buffers
 * (A = max(R, P - 1) rows of look-ahead, P the row period) into a window of 2 R + 1 rows by
 * R + Ax + 1 columns (Ax = max(R, Q - 1) pixels of look-ahead, Q the column period); one
 * output pixel per step, A rows and Ax pixels after its input, blanking included:
 * (rows + A) x (cols + Ax) steps. The border rule of the float cores (a tap outside the
 * frame moves back by whole periods, so it keeps its colour) needs a tap at most P - 1 rows
 * below the top row (Q - 1 columns right of the left column): the look-ahead holds it, and
 * at the bottom (right) border the buffers still hold the last R + A rows (the window its
 * last R + Ax + 1 columns).
 *
 * Header-only (static functions): each model passes its site function, which the compiler
 * can inline into its own copy of the front end.
 */
#ifndef HW_STREAM_H
#define HW_STREAM_H

#include <stddef.h>
#include <stdint.h>
#include "rgbz.h"

/* the largest kernel radius a model streams (its window rows: 2 R + 1) */
#define RGBZ_HW_STREAM_MAX_RADIUS 8

/* floor(log2 x) + 1 of x >= 0 (a priority encoder) */
static inline int64_t rgbz_hw_bitlen(int64_t x)
{
    int64_t p = 0;
    for (int s = 32; s >= 1; s >>= 1)
        if ((x >> (p + s)) > 0) p += s;
    return p + (x > 0);
}

/* i moved into [0, n) by whole periods P (n >= P): the float kernels' border rule */
static inline ptrdiff_t rgbz_hw_extend(ptrdiff_t i, ptrdiff_t n, ptrdiff_t P)
{
    return i < 0 ? i + P * ((P - 1 - i) / P) : (i >= n ? i - P * ((i - n + P) / P) : i);
}

/* the geometry of one streamed frame and its storage (the model's fixed-size arrays) */
typedef struct {
    ptrdiff_t rows, cols;
    int R, py, px;          /* kernel radius, row and column periods */
    int A, Ax;              /* rows and pixels of look-ahead */
    int NLB, WC, WR;        /* line buffers, window columns, window rows */
    uint16_t *lb;           /* NLB rows of lb_stride pixels */
    ptrdiff_t lb_stride;
    int32_t *win;           /* WR rows of win_stride registers */
    ptrdiff_t win_stride;
} rgbz_hw_stream;

/* the geometry for radius R and periods (py, px) over the given storage */
static inline rgbz_hw_stream rgbz_hw_stream_init(ptrdiff_t rows, ptrdiff_t cols, int R, int py,
                                                 int px, uint16_t *lb, ptrdiff_t lb_stride,
                                                 int32_t *win, ptrdiff_t win_stride)
{
    rgbz_hw_stream s;
    s.rows = rows;
    s.cols = cols;
    s.R = R;
    s.py = py;
    s.px = px;
    s.A = R > py - 1 ? R : py - 1;
    s.Ax = R > px - 1 ? R : px - 1;
    s.NLB = R + s.A;
    s.WC = R + s.Ax + 1;
    s.WR = 2 * R + 1;
    s.lb = lb;
    s.lb_stride = lb_stride;
    s.win = win;
    s.win_stride = win_stride;
    return s;
}

/* the window register of the tap (dy, dx) of the output pixel in column x */
static inline int32_t rgbz_hw_tap(const rgbz_hw_stream *s, int dy, int dx, ptrdiff_t x)
{
    return s->win[(ptrdiff_t)(dy + s->R) * s->win_stride +
                  rgbz_hw_extend(x + dx, s->cols, s->px) % s->WC];
}

/* the value of the Z site of phase k in column x (before clipping), read through
   rgbz_hw_tap; ctx: the model's own arguments */
typedef int64_t (*rgbz_hw_site_fn)(const void *ctx, int32_t k, const rgbz_hw_stream *s,
                                   ptrdiff_t x);

/*
 * Streams a uint8 or uint16 frame (in_type RGBZ_T_U8 / RGBZ_T_U16) into dst of the same
 * type: a pixel whose phase (phase_map[(y % py) * px + x % px]) is -1 is copied, every other
 * is site(ctx, phase, ...) clipped to [0, top]. The caller has checked the geometry
 * (py, px within the storage's period, rows >= py, cols >= px, cols <= lb_stride) and
 * every phase.
 */
static inline void rgbz_hw_stream_frame(const rgbz_hw_stream *s, int in_type, const void *src,
                                        void *dst, const int32_t *phase_map, int64_t top,
                                        rgbz_hw_site_fn site, const void *ctx)
{
    const ptrdiff_t rows = s->rows, cols = s->cols;
    const int R = s->R, A = s->A, Ax = s->Ax, NLB = s->NLB, WC = s->WC, WR = s->WR;
    const int py = s->py, px = s->px;
    const uint8_t *s8 = (const uint8_t *)src;
    const uint16_t *s16 = (const uint16_t *)src;
    uint8_t *d8 = (uint8_t *)dst;
    uint16_t *d16 = (uint16_t *)dst;

    for (ptrdiff_t in_row = 0; in_row < rows + A; in_row++) {
        const ptrdiff_t y = in_row - A;           /* the output row of these steps */
        ptrdiff_t rsel[2 * RGBZ_HW_STREAM_MAX_RADIUS + 1];  /* frame row of each window row */
        for (int d = 0; d < WR; d++) rsel[d] = y >= 0 ? rgbz_hw_extend(y + d - R, rows, py) : 0;
        for (ptrdiff_t x_in = 0; x_in < cols + Ax; x_in++) {
            /* 1. the input pixel; the column x_in of the window rows into the window (the
                  line buffers read before the incoming pixel overwrites the oldest row) */
            if (x_in < cols) {
                int32_t pix = 0;
                if (in_row < rows)
                    pix = in_type == RGBZ_T_U8 ? s8[in_row * cols + x_in]
                                               : s16[in_row * cols + x_in];
                if (y >= 0)
                    for (int d = 0; d < WR; d++)
                        s->win[d * s->win_stride + x_in % WC] =
                            rsel[d] == in_row ? pix
                                              : s->lb[(rsel[d] % NLB) * s->lb_stride + x_in];
                if (in_row < rows) s->lb[(in_row % NLB) * s->lb_stride + x_in] = (uint16_t)pix;
            }
            /* 2. the output pixel (y, x) */
            const ptrdiff_t x = x_in - Ax;
            if (y < 0 || x < 0) continue;
            const int32_t k = phase_map[(y % py) * px + x % px];
            int64_t out = s->win[(ptrdiff_t)R * s->win_stride + x % WC];  /* colour: copied */
            if (k >= 0) {
                out = site(ctx, k, s, x);
                out = out < 0 ? 0 : out > top ? top : out;
            }
            if (in_type == RGBZ_T_U8)
                d8[y * cols + x] = (uint8_t)out;
            else
                d16[y * cols + x] = (uint16_t)out;
        }
    }
}

#endif
