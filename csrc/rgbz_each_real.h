/*
 * rgbz_each_real.h -- includes the template RGBZ_REAL_TEMPLATE once per floating-point
 * precision, float then double, with REAL (the C type) and RS (its suffix, f32 or f64)
 * defined. The includer defines RGBZ_REAL_TEMPLATE before and undefines it after. Not
 * include-guarded: every inclusion is a new set of instances.
 *
 * One line per precision below, (C type, suffix); each has its entry in RGBZ_PRECISIONS
 * (rgbz.h) and its suffixed helpers in rgbz_ops.h. A precision that is not floating point
 * (fixed point) has kernels of its own and no line here (rgbz_templating.h).
 */
#ifndef RGBZ_REAL_TEMPLATE
#error "rgbz_each_real.h: #define RGBZ_REAL_TEMPLATE (the template to instantiate) first"
#endif
#if defined(REAL) || defined(RS) || defined(RGBZ_REAL_)
#error "rgbz_each_real.h: REAL and RS are defined here, once per precision"
#endif
#include "rgbz_templating.h"

#define RGBZ_REAL_T_(T, s) T
#define RGBZ_REAL_S_(T, s) s
#define REAL RGBZ_APPLY(RGBZ_REAL_T_, RGBZ_REAL_)
#define RS RGBZ_APPLY(RGBZ_REAL_S_, RGBZ_REAL_)

#define RGBZ_REAL_ (float, f32)
#include RGBZ_REAL_TEMPLATE
#undef RGBZ_REAL_
#define RGBZ_REAL_ (double, f64)
#include RGBZ_REAL_TEMPLATE
#undef RGBZ_REAL_

#undef REAL
#undef RS
#undef RGBZ_REAL_T_
#undef RGBZ_REAL_S_
