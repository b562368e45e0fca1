/*
 * learned.instances.h -- learned.template.h in both precisions for the element type that
 * learned.c defines (IN_T, IS, IN_IS_INT), which it undefines afterwards.
 */
#ifndef IN_T
#error "learned.instances.h: define IN_T, IS and IN_IS_INT"
#endif
#define REAL float
#define RS f32
#define RW w_f32
#define RWD wd_f32
#include "learned.template.h"
#undef REAL
#undef RS
#undef RW
#undef RWD
#define REAL double
#define RS f64
#define RW w_f64
#define RWD wd_f64
#include "learned.template.h"
#undef REAL
#undef RS
#undef RW
#undef RWD
#undef IN_T
#undef IS
#undef IN_IS_INT
