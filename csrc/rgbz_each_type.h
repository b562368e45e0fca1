/*
 * rgbz_each_type.h -- includes the template RGBZ_TYPE_TEMPLATE once per element type of
 * RGBZ_ELEMENT_TYPES (rgbz_templating.h), in that order, with IN_T (the C type), IS (its
 * suffix) and IN_IS_INT (1 for an integer type) defined. The includer defines
 * RGBZ_TYPE_TEMPLATE before and undefines it after. Not include-guarded: every inclusion
 * is a new set of instances.
 *
 * One line per type below, (C type, suffix, is integer), as in RGBZ_ELEMENT_TYPES.
 */
#ifndef RGBZ_TYPE_TEMPLATE
#error "rgbz_each_type.h: #define RGBZ_TYPE_TEMPLATE (the template to instantiate) first"
#endif
#if defined(IN_T) || defined(IS) || defined(IN_IS_INT) || defined(RGBZ_TYPE_)
#error "rgbz_each_type.h: IN_T, IS and IN_IS_INT are defined here, once per type"
#endif
#include <stdint.h>
#include "rgbz_templating.h"

#define RGBZ_TYPE_T_(T, s, is_int) T
#define RGBZ_TYPE_S_(T, s, is_int) s
#define RGBZ_TYPE_INT_(T, s, is_int) is_int
#define IN_T RGBZ_APPLY(RGBZ_TYPE_T_, RGBZ_TYPE_)
#define IS RGBZ_APPLY(RGBZ_TYPE_S_, RGBZ_TYPE_)
#define IN_IS_INT RGBZ_APPLY(RGBZ_TYPE_INT_, RGBZ_TYPE_)

#define RGBZ_TYPE_ (uint8_t, u8, 1)
#include RGBZ_TYPE_TEMPLATE
#undef RGBZ_TYPE_
#define RGBZ_TYPE_ (uint16_t, u16, 1)
#include RGBZ_TYPE_TEMPLATE
#undef RGBZ_TYPE_
#define RGBZ_TYPE_ (float, f32, 0)
#include RGBZ_TYPE_TEMPLATE
#undef RGBZ_TYPE_
#define RGBZ_TYPE_ (double, f64, 0)
#include RGBZ_TYPE_TEMPLATE
#undef RGBZ_TYPE_

#undef IN_T
#undef IS
#undef IN_IS_INT
#undef RGBZ_TYPE_T_
#undef RGBZ_TYPE_S_
#undef RGBZ_TYPE_INT_
