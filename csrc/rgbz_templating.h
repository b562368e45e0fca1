/*
 * rgbz_templating.h -- how csrc/ writes a kernel once and compiles it per type: one name
 * pasting, one instantiation site per file, typed entry points per precision (the scheme of
 * PyWavelets' templating.h, wt.c and _dwt.pyx).
 *
 * Templates. NAME.template.h is C over the parameters
 *     IN_T, IS, IN_IS_INT   an element type of frames (uint8_t, uint16_t, float, double),
 *                           its suffix (u8, u16, f32, f64), 1 for an integer type;
 *     REAL, RS              a floating-point precision of the arithmetic (float, double)
 *                           and its suffix (f32, f64),
 * and names what it defines with those suffixes, RGBZ_CAT(name, RS) or
 * RGBZ_CAT3(name, IS, RS), so that every instance is a function of its own. What else
 * differs between precisions is looked up by suffix too (rgbz_ops.h: rgbz_out_<RS>, the
 * exponentials rgbz_exp_libm_<RS> and rgbz_exp_poly_<RS>, the counted OABSDIFF_<RS>), so
 * REAL and RS are all a template needs of a precision.
 *
 * Instances. A file instantiates a template at one place: it names the template and
 * includes the iteration header of the axis, which includes the template once per entry
 * with the parameters defined:
 *     #define RGBZ_TYPE_TEMPLATE "demosaic.template.h"
 *     #include "rgbz_each_type.h"                  (u8, u16, f32, f64)
 *     #undef RGBZ_TYPE_TEMPLATE
 * and rgbz_each_real.h likewise includes RGBZ_REAL_TEMPLATE for float and double. A
 * template over both axes is a precision template that instantiates an element-type one
 * (recon_core.template.h -> recon_loop.template.h). A file compiled for one precision
 * (recon_f32.c) defines REAL and RS itself.
 *
 * Entry points. The precision of the arithmetic is in an entry point's name and in the
 * types of its arrays of that precision (rgbz_reconstruct_f32, rgbz_fast_exp_f64, as
 * PyWavelets' float_dec_a and double_dec_a). The element type of a frame is an rgbz_type
 * code beside a void pointer, and the entry point calls its instance through
 * RGBZ_SWITCH_TYPE below: a switch of direct calls -- no table of function pointers per
 * type, no cast between function types. _kernels.pyx takes the type code from its Cython
 * fused type and selects the entry points of a precision with one explicit switch
 * (_kernels_of).
 *
 * Adding a precision (as the integer fixed-point one, `fixed`, is: hw_recon.c defines
 * rgbz_reconstruct_fixed, its settings are rgbz_params.fixed, it has no learned kernel):
 *   1. one line in RGBZ_PRECISIONS (rgbz.h): it gives the enum member RGBZ_P_FIXED and
 *      declares rgbz_reconstruct_fixed and rgbz_learned_fixed with the signatures every
 *      precision shares (rgbz_reconstruct_fn, rgbz_learned_fn; a precision's own
 *      settings travel in rgbz_params);
 *   2. its arithmetic: a kernel file that defines those entry points. (A floating-point
 *      precision instead adds one line to rgbz_each_real.h, its suffixed helpers to
 *      rgbz_ops.h and a file recon_<suffix>.c as recon_f32.c; its kernels are then the
 *      templates' instances.) An entry point it does not have yet stays undefined and
 *      unreferenced;
 *   3. in _kernels_common.pxi, the member of the cpdef enum rgbz_precision and one case in
 *      _kernels_of, the switch over the precisions (NULL for a kernel it does not have,
 *      which its caller then refuses with a ValueError naming `precision`).
 */
#ifndef RGBZ_TEMPLATING_H
#define RGBZ_TEMPLATING_H

#include "rgbz.h"

/* name pasting: the arguments are expanded first, so RGBZ_CAT(rgbz_core, RS) with RS
   standing for f32 is rgbz_core_f32 */
#define RGBZ_CAT_(a, b) a##_##b
#define RGBZ_CAT(a, b) RGBZ_CAT_(a, b)
#define RGBZ_CAT3_(a, b, c) a##_##b##_##c
#define RGBZ_CAT3(a, b, c) RGBZ_CAT3_(a, b, c)

/* f applied to the parenthesised list args: picks a field of the parameter tuples of
   rgbz_each_type.h and rgbz_each_real.h */
#define RGBZ_APPLY(f, args) f args

/* a function to inline into every caller, so that constants propagate into it (the Mask1
   plans of recon_mask1.h, the element type of a ToF tap array) and it is compiled for the
   caller's instruction set */
#if defined(__GNUC__) || defined(__clang__)
#define RGBZ_INLINE static inline __attribute__((always_inline))
#else
#define RGBZ_INLINE static inline
#endif

/*
 * The element types of frames, as X-macro lists: X(suffix, C type, rgbz_type code, A) for
 * each, A passed through unchanged. rgbz_each_type.h instantiates a template for every
 * entry of RGBZ_ELEMENT_TYPES, in this order.
 */
#define RGBZ_INT_TYPES(X, A) X(u8, uint8_t, RGBZ_T_U8, A) X(u16, uint16_t, RGBZ_T_U16, A)
#define RGBZ_FLOAT_TYPES(X, A) X(f32, float, RGBZ_T_F32, A) X(f64, double, RGBZ_T_F64, A)
#define RGBZ_ELEMENT_TYPES(X, A) RGBZ_INT_TYPES(X, A) RGBZ_FLOAT_TYPES(X, A)

/*
 * A switch over the element types of LIST: `case <code>: CALL(suffix, C type); break;` for
 * each of them, `default: OTHERWISE;`. CALL is a statement macro of the caller that calls
 * the instance of that type, e.g.
 *     #define DM_CALL_(s, T) RGBZ_CAT(rgbz_malvar, s)((const T *)src, dst, ...)
 *     RGBZ_SWITCH_TYPE(in_type, RGBZ_ELEMENT_TYPES, DM_CALL_, st = RGBZ_EINVAL)
 *     #undef DM_CALL_
 */
#define RGBZ_SWITCH_TYPE(type, LIST, CALL, OTHERWISE)                                        \
    switch (type) {                                                                          \
    LIST(RGBZ_TYPE_CASE_, CALL)                                                              \
    default: OTHERWISE;                                                                      \
    }
#define RGBZ_TYPE_CASE_(s, T, code, CALL) case code: CALL(s, T); break;

#endif /* RGBZ_TEMPLATING_H */
