/*
 * tof.h -- entry points of tof.c declared outside rgbz.h. Plain C99, no Python.h; status
 * codes of rgbz.h.
 */
#ifndef RGBZ_TOF_H
#define RGBZ_TOF_H

#include <stddef.h>

/* Phase in [0, 2 pi) and amplitude |I + iQ| / 2 of phasors i_comp, q_comp (F, N), no
   unwrapping; RGBZ_EDOMAIN when an I or Q is not finite (its phase is then 0). */
int rgbz_tof_phase_iq(const double *i_comp, const double *q_comp, ptrdiff_t F, ptrdiff_t N,
                      double *phase, double *amp, int workers);

#endif
