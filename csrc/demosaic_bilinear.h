/*
 * demosaic_bilinear.h -- the bilinear demosaic of one pixel at a border, shared by
 * demosaic.c (rgbz_demosaic) and colour_isp.c (rgbz_ci_render).
 *
 * The reference, colour-demosaicing's demosaicing_CFA_Bayer_bilinear, masks each colour's
 * plane first and then convolves it with scipy.ndimage's border rule: with "reflect" a
 * mirrored tap may fall on a pixel of another colour, which the mask has set to 0, so it
 * adds nothing (a border pixel's missing colour comes from fewer taps, with the interior's
 * weights). Inside the frame, and everywhere with the period border, a tap's pixel has the
 * colour of its place and the row kernels' direct formulas hold; this function is the rule
 * itself, for the pixels the direct formulas do not cover.
 */
#ifndef RGBZ_DEMOSAIC_BILINEAR_H
#define RGBZ_DEMOSAIC_BILINEAR_H

#include <stdint.h>

/* R, G, B of a pixel from its 3x3 taps in raster order: v[k] the value of the pixel a tap
   reads and c[k] that pixel's colour (R 0, G 1, B 2). Each colour is the sum, in double from
   0.0 and in raster order, of its taps times the filter's weight (green [[0,1,0],[1,4,1],
   [0,1,0]]/4, red and blue [[1,2,1],[2,4,2],[1,2,1]]/4): scipy's sum, whose taps of the other
   colours add +-0 and change no finite sum. */
static inline void dm_bilinear_taps(const double *v, const int *c, double *rgb)
{
    static const double wg[9] = {0.0, 0.25, 0.0, 0.25, 1.0, 0.25, 0.0, 0.25, 0.0};
    static const double wrb[9] = {0.25, 0.5, 0.25, 0.5, 1.0, 0.5, 0.25, 0.5, 0.25};
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    for (int k = 0; k < 9; k++) {
        const double w = c[k] == 1 ? wg[k] : wrb[k];
        if (w != 0.0) rgb[c[k]] += v[k] * w;
    }
}

#endif /* RGBZ_DEMOSAIC_BILINEAR_H */
