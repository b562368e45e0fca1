/*
 * z_guided.instances.h -- z_guided.template.h in both precisions for the element type that
 * z_guided.c defines (IN_T, IS, IN_IS_INT), which it undefines afterwards.
 */
#ifndef IN_T
#error "z_guided.instances.h: define IN_T, IS and IN_IS_INT"
#endif
#define REAL float
#define RS f32
#define RW w_f32
#define RG g_f32
#include "z_guided.template.h"
#undef REAL
#undef RS
#undef RW
#undef RG
#define REAL double
#define RS f64
#define RW w_f64
#define RG g_f64
#include "z_guided.template.h"
#undef REAL
#undef RS
#undef RW
#undef RG
#undef IN_T
#undef IS
#undef IN_IS_INT
