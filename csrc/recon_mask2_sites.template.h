/*
 * recon_mask2_sites.template.h -- WRITTEN BY tools/gen_recon_mask2.py: do not edit; run the
 * script. Included twice by recon_mask2.h, once per instance:
 *   M2_FN(name)            the instance's name of a function (name_g, name_x)
 *   M2_ATTR                its target attribute (none; AVX-512F)
 *   M2_MIN(a, b)           a < b ? a : b per lane (x86's MINPS exactly)
 *   M2_MAX(a, b)           a > b ? a : b per lane (MAXPS exactly)
 *   M2_RINT(v, et)         v rounded to an integer, ties to even: et - 1.5 * 2^23 with
 *                          et = v + 1.5 * 2^23 (rgbz_exp_poly_f32's way), or VRNDSCALEPS of v
 *                          (|v| < 2^22 where it matters: the same value)
 *   M2_EXPOUT(x, p, et, en)  the exponential's last step: x > -87 ? p * 2^en : 0, 2^en from
 *                          et's bits times p (rgbz_exp_poly_f32), or VSCALEFPS of p and en
 *                          under the comparison's mask (exact, the results normal: the same
 *                          bits)
 */
/* Z site 0: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site0)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t5_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t11_0 - t12_0);
    G0_0 = G0_0 + d1_0;
    G4_0 = G4_0 + d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t6_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    rgbz_v16 G5_0 = d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t5_0 - t8_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t11_0 - t13_0);
    G1_0 = G1_0 + d4_0;
    G6_0 = G6_0 + d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t6_0 - t10_0);
    G1_0 = G1_0 + d5_0;
    rgbz_v16 G7_0 = d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t14_0 - t15_0);
    G2_0 = G2_0 + d7_0;
    G4_0 = G4_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t9_0 - t8_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t14_0 - t16_0);
    G3_0 = G3_0 + d10_0;
    G5_0 = G5_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t9_0 - t10_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t15_0 - t17_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t3_0 - t7_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t16_0 - t18_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t8_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t12_0 - t13_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t9_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t19_0 - t20_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t10_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t12_0 - t19_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t13_0 - t20_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t15_0 - t16_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t5_0 - t6_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t17_0 - t18_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t8_0 - t10_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t16_0 - t19_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t6_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t18_0 - t12_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t13_0 - t17_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t9_0 - t5_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t20_0 - t15_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t10_0 - t0_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t15_0 - t12_0);
    rgbz_v16 G11_0 = d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t5_0 - t1_0);
    G11_0 = G11_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t11_0 - t14_0);
    G11_0 = G11_0 + d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t17_0 - t19_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t7_0 - t4_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t8_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t13_0 - t16_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t9_0 - t6_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t20_0 - t18_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.25;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.3333333333333333;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.3333333333333333;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.5;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.14285714285714285;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.1111111111111111;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 c8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 c9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 c10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S8_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S9_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S10_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c8_0); S0_0 = S0_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c9_0); S0_0 = S0_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c10_0); S0_0 = S0_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c8_0); S1_0 = S1_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c9_0); S1_0 = S1_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c10_0); S1_0 = S1_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c8_0); S2_0 = S2_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c9_0); S2_0 = S2_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c10_0); S2_0 = S2_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c8_0); S3_0 = S3_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c9_0); S3_0 = S3_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c10_0); S3_0 = S3_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c8_0); S4_0 = S4_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c9_0); S4_0 = S4_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c10_0); S4_0 = S4_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c8_0); S5_0 = S5_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c9_0); S5_0 = S5_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c10_0); S5_0 = S5_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c8_0); S6_0 = S6_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c9_0); S6_0 = S6_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c10_0); S6_0 = S6_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c8_0); S7_0 = S7_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c9_0); S7_0 = S7_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c10_0); S7_0 = S7_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c9_0); S8_0 = S8_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c10_0); S8_0 = S8_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9_0 - c10_0); S9_0 = S9_0 + e; S10_0 = S10_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S4_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c8_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c9_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c10_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        s_0 = s_0 + (c8_0 - c0_0);
        s_0 = s_0 + (c9_0 - c0_0);
        s_0 = s_0 + (c10_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)11);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 1: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site1)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    rgbz_v16 G5_0 = d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    G5_0 = G5_0 + d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    rgbz_v16 G7_0 = d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    G7_0 = G7_0 + d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G4_0 = G4_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G5_0 = G5_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t12_0 - t14_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t13_0 - t17_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t18_0 - t9_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t20_0 - t15_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t19_0 - t10_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t13_0 - t9_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t8_0 - t11_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t16_0 - t20_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t17_0 - t18_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t19_0 - t14_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t10_0 - t12_0);
    G10_0 = G10_0 + d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t12_0 - t18_0);
    rgbz_v16 G11_0 = d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t14_0 - t9_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t19_0 - t13_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t10_0 - t17_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.3333333333333333;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.25;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.5;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.3333333333333333;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.1111111111111111;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.14285714285714285;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 2: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site2)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    G4_0 = G4_0 + d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    rgbz_v16 G5_0 = d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    G6_0 = G6_0 + d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    rgbz_v16 G7_0 = d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G6_0 = G6_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G7_0 = G7_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t14_0 - t12_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t17_0 - t13_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t9_0 - t18_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t16_0 - t20_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t10_0 - t19_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t17_0 - t18_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t11_0 - t8_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t20_0 - t15_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t13_0 - t9_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t10_0 - t12_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t19_0 - t14_0);
    G10_0 = G10_0 + d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t14_0 - t9_0);
    rgbz_v16 G11_0 = d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t12_0 - t18_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t10_0 - t17_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t19_0 - t13_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.3333333333333333;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.5;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.25;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.3333333333333333;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.1111111111111111;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.14285714285714285;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 3: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site3)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t4_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t11_0 - t12_0);
    G0_0 = G0_0 + d1_0;
    rgbz_v16 G5_0 = d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t5_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    G5_0 = G5_0 + d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t4_0 - t8_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t11_0 - t13_0);
    G1_0 = G1_0 + d4_0;
    rgbz_v16 G7_0 = d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t5_0 - t10_0);
    G1_0 = G1_0 + d5_0;
    G7_0 = G7_0 + d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t14_0 - t15_0);
    G2_0 = G2_0 + d7_0;
    G6_0 = G6_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t9_0 - t8_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t14_0 - t16_0);
    G3_0 = G3_0 + d10_0;
    G7_0 = G7_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t9_0 - t10_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t17_0 - t15_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t3_0 - t7_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t18_0 - t16_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t8_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t19_0 - t20_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t9_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t12_0 - t13_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t10_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t19_0 - t12_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t6_0 - t7_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t20_0 - t13_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t17_0 - t18_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t4_0 - t5_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t15_0 - t16_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t8_0 - t10_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t18_0 - t12_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t5_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t16_0 - t19_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t20_0 - t15_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t9_0 - t4_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t13_0 - t17_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t10_0 - t0_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t17_0 - t19_0);
    rgbz_v16 G11_0 = d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t4_0 - t1_0);
    G11_0 = G11_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t15_0 - t12_0);
    G11_0 = G11_0 + d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t6_0 - t3_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t14_0 - t11_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t8_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t20_0 - t18_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t9_0 - t5_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t13_0 - t16_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.5;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.3333333333333333;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.3333333333333333;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.25;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.14285714285714285;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.1111111111111111;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 c8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 c9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 c10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S8_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S9_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S10_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c8_0); S0_0 = S0_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c9_0); S0_0 = S0_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c10_0); S0_0 = S0_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c8_0); S1_0 = S1_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c9_0); S1_0 = S1_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c10_0); S1_0 = S1_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c8_0); S2_0 = S2_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c9_0); S2_0 = S2_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c10_0); S2_0 = S2_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c8_0); S3_0 = S3_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c9_0); S3_0 = S3_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c10_0); S3_0 = S3_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c8_0); S4_0 = S4_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c9_0); S4_0 = S4_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c10_0); S4_0 = S4_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c8_0); S5_0 = S5_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c9_0); S5_0 = S5_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c10_0); S5_0 = S5_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c8_0); S6_0 = S6_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c9_0); S6_0 = S6_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c10_0); S6_0 = S6_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c8_0); S7_0 = S7_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c9_0); S7_0 = S7_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c10_0); S7_0 = S7_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c9_0); S8_0 = S8_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c10_0); S8_0 = S8_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9_0 - c10_0); S9_0 = S9_0 + e; S10_0 = S10_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S6_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c8_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c9_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c10_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        s_0 = s_0 + (c8_0 - c0_0);
        s_0 = s_0 + (c9_0 - c0_0);
        s_0 = s_0 + (c10_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)11);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 4: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site4)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    G4_0 = G4_0 + d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    rgbz_v16 G5_0 = d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    G6_0 = G6_0 + d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    rgbz_v16 G7_0 = d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G4_0 = G4_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G5_0 = G5_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t12_0 - t14_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t13_0 - t17_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t9_0 - t18_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t15_0 - t20_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t10_0 - t19_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t13_0 - t18_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t17_0 - t9_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t10_0 - t14_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t19_0 - t12_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t12_0 - t9_0);
    rgbz_v16 G11_0 = d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t8_0 - t11_0);
    G11_0 = G11_0 + d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t14_0 - t18_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t16_0 - t20_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t10_0 - t13_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t19_0 - t17_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.25;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.3333333333333333;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.3333333333333333;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.5;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.14285714285714285;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.1111111111111111;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 5: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site5)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t5_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t11_0 - t12_0);
    G0_0 = G0_0 + d1_0;
    rgbz_v16 G5_0 = d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t6_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    G5_0 = G5_0 + d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t5_0 - t8_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t11_0 - t13_0);
    G1_0 = G1_0 + d4_0;
    rgbz_v16 G7_0 = d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t6_0 - t10_0);
    G1_0 = G1_0 + d5_0;
    G7_0 = G7_0 + d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t14_0 - t15_0);
    G2_0 = G2_0 + d7_0;
    G4_0 = G4_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t9_0 - t8_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t14_0 - t16_0);
    G3_0 = G3_0 + d10_0;
    G5_0 = G5_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t9_0 - t10_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t15_0 - t17_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t4_0 - t7_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t16_0 - t18_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t8_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t19_0 - t20_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t9_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t12_0 - t13_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t10_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t19_0 - t12_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t20_0 - t13_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t15_0 - t16_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t5_0 - t6_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t17_0 - t18_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t8_0 - t10_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t16_0 - t12_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t11_0 - t14_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t6_0 - t1_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t7_0 - t3_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t18_0 - t19_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t20_0 - t17_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t9_0 - t5_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t13_0 - t15_0);
    G10_0 = G10_0 + d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t10_0 - t0_0);
    G10_0 = G10_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t15_0 - t19_0);
    rgbz_v16 G11_0 = d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t5_0 - t1_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t17_0 - t12_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t8_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t20_0 - t16_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t9_0 - t6_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t13_0 - t18_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.3333333333333333;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.25;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.5;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.3333333333333333;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.1111111111111111;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.14285714285714285;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 c8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 c9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 c10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S8_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S9_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S10_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c8_0); S0_0 = S0_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c9_0); S0_0 = S0_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c10_0); S0_0 = S0_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c8_0); S1_0 = S1_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c9_0); S1_0 = S1_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c10_0); S1_0 = S1_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c8_0); S2_0 = S2_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c9_0); S2_0 = S2_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c10_0); S2_0 = S2_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c8_0); S3_0 = S3_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c9_0); S3_0 = S3_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c10_0); S3_0 = S3_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c8_0); S4_0 = S4_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c9_0); S4_0 = S4_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c10_0); S4_0 = S4_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c8_0); S5_0 = S5_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c9_0); S5_0 = S5_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c10_0); S5_0 = S5_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c8_0); S6_0 = S6_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c9_0); S6_0 = S6_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c10_0); S6_0 = S6_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c8_0); S7_0 = S7_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c9_0); S7_0 = S7_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c10_0); S7_0 = S7_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c9_0); S8_0 = S8_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c10_0); S8_0 = S8_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9_0 - c10_0); S9_0 = S9_0 + e; S10_0 = S10_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S4_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c8_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c9_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c10_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        s_0 = s_0 + (c8_0 - c0_0);
        s_0 = s_0 + (c9_0 - c0_0);
        s_0 = s_0 + (c10_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)11);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 6: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site6)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t4_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t11_0 - t12_0);
    G0_0 = G0_0 + d1_0;
    G4_0 = G4_0 + d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t5_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    rgbz_v16 G5_0 = d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t4_0 - t8_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t11_0 - t13_0);
    G1_0 = G1_0 + d4_0;
    G6_0 = G6_0 + d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t5_0 - t10_0);
    G1_0 = G1_0 + d5_0;
    rgbz_v16 G7_0 = d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t14_0 - t15_0);
    G2_0 = G2_0 + d7_0;
    G6_0 = G6_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t9_0 - t8_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t14_0 - t16_0);
    G3_0 = G3_0 + d10_0;
    G7_0 = G7_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t9_0 - t10_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t17_0 - t15_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t3_0 - t6_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t18_0 - t16_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t8_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t12_0 - t13_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t9_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t19_0 - t20_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t10_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t12_0 - t19_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t6_0 - t7_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t13_0 - t20_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t17_0 - t18_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t4_0 - t5_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t15_0 - t16_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t8_0 - t10_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t18_0 - t19_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t5_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t14_0 - t11_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t7_0 - t3_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t16_0 - t12_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t13_0 - t15_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t9_0 - t4_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t20_0 - t17_0);
    G10_0 = G10_0 + d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t10_0 - t0_0);
    G10_0 = G10_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t17_0 - t12_0);
    rgbz_v16 G11_0 = d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t4_0 - t1_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t15_0 - t19_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t8_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t13_0 - t18_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t9_0 - t5_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t20_0 - t16_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.3333333333333333;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.5;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.25;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.3333333333333333;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.1111111111111111;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.14285714285714285;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 c8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 c9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 c10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S8_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S9_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S10_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c8_0); S0_0 = S0_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c9_0); S0_0 = S0_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c10_0); S0_0 = S0_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c8_0); S1_0 = S1_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c9_0); S1_0 = S1_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c10_0); S1_0 = S1_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c8_0); S2_0 = S2_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c9_0); S2_0 = S2_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c10_0); S2_0 = S2_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c8_0); S3_0 = S3_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c9_0); S3_0 = S3_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c10_0); S3_0 = S3_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c8_0); S4_0 = S4_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c9_0); S4_0 = S4_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c10_0); S4_0 = S4_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c8_0); S5_0 = S5_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c9_0); S5_0 = S5_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c10_0); S5_0 = S5_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c8_0); S6_0 = S6_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c9_0); S6_0 = S6_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c10_0); S6_0 = S6_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c8_0); S7_0 = S7_0 + e; S8_0 = S8_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c9_0); S7_0 = S7_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7_0 - c10_0); S7_0 = S7_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c9_0); S8_0 = S8_0 + e; S9_0 = S9_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8_0 - c10_0); S8_0 = S8_0 + e; S10_0 = S10_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9_0 - c10_0); S9_0 = S9_0 + e; S10_0 = S10_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S6_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c8_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c9_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c10_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        s_0 = s_0 + (c8_0 - c0_0);
        s_0 = s_0 + (c9_0 - c0_0);
        s_0 = s_0 + (c10_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)11);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 7: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site7)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    rgbz_v16 G5_0 = d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    G5_0 = G5_0 + d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    rgbz_v16 G7_0 = d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    G7_0 = G7_0 + d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G6_0 = G6_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G7_0 = G7_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t14_0 - t12_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t17_0 - t13_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t18_0 - t9_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t20_0 - t16_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t19_0 - t10_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t17_0 - t9_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t13_0 - t18_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t19_0 - t12_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t10_0 - t14_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t14_0 - t18_0);
    rgbz_v16 G11_0 = d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t12_0 - t9_0);
    G11_0 = G11_0 + d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t20_0 - t15_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t11_0 - t8_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t19_0 - t17_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t10_0 - t13_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.5;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.3333333333333333;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.3333333333333333;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.25;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.14285714285714285;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.1111111111111111;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 8: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site8)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    G4_0 = G4_0 + d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    rgbz_v16 G5_0 = d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    G6_0 = G6_0 + d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    rgbz_v16 G7_0 = d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G4_0 = G4_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G5_0 = G5_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t12_0 - t14_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t13_0 - t17_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t9_0 - t18_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t15_0 - t20_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t10_0 - t19_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t13_0 - t18_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t17_0 - t9_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t10_0 - t14_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t19_0 - t12_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t12_0 - t9_0);
    rgbz_v16 G11_0 = d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t8_0 - t11_0);
    G11_0 = G11_0 + d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t14_0 - t18_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t16_0 - t20_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t10_0 - t13_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t19_0 - t17_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.25;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.3333333333333333;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.3333333333333333;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.5;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.14285714285714285;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.1111111111111111;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 9: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site9)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    rgbz_v16 G5_0 = d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    G5_0 = G5_0 + d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    rgbz_v16 G7_0 = d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    G7_0 = G7_0 + d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G6_0 = G6_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G7_0 = G7_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t14_0 - t12_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t17_0 - t13_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t18_0 - t9_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t20_0 - t16_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t19_0 - t10_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t17_0 - t9_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t13_0 - t18_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t19_0 - t12_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t10_0 - t14_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t14_0 - t18_0);
    rgbz_v16 G11_0 = d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t12_0 - t9_0);
    G11_0 = G11_0 + d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t20_0 - t15_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t11_0 - t8_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t19_0 - t17_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t10_0 - t13_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.5;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.3333333333333333;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.3333333333333333;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.25;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.14285714285714285;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.1111111111111111;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 10: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site10)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    rgbz_v16 G5_0 = d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    G5_0 = G5_0 + d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    rgbz_v16 G7_0 = d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    G7_0 = G7_0 + d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G4_0 = G4_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G5_0 = G5_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t12_0 - t14_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t13_0 - t17_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t18_0 - t9_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t20_0 - t15_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t19_0 - t10_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t13_0 - t9_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t8_0 - t11_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t16_0 - t20_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t17_0 - t18_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t19_0 - t14_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t10_0 - t12_0);
    G10_0 = G10_0 + d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t12_0 - t18_0);
    rgbz_v16 G11_0 = d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t14_0 - t9_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t19_0 - t13_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t10_0 - t17_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.3333333333333333;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.25;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.5;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.3333333333333333;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.1111111111111111;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.14285714285714285;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}

/* Z site 11: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site11)(const float *const *src, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 t1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 t2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 t3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 t4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 t5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 t6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 t7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    const rgbz_v16 t8_0 = rgbz_v16_load(src[8] + 0 * RGBZ_M2_W);
    const rgbz_v16 t9_0 = rgbz_v16_load(src[9] + 0 * RGBZ_M2_W);
    const rgbz_v16 t10_0 = rgbz_v16_load(src[10] + 0 * RGBZ_M2_W);
    const rgbz_v16 t11_0 = rgbz_v16_load(src[11] + 0 * RGBZ_M2_W);
    const rgbz_v16 t12_0 = rgbz_v16_load(src[12] + 0 * RGBZ_M2_W);
    const rgbz_v16 t13_0 = rgbz_v16_load(src[13] + 0 * RGBZ_M2_W);
    const rgbz_v16 t14_0 = rgbz_v16_load(src[14] + 0 * RGBZ_M2_W);
    const rgbz_v16 t15_0 = rgbz_v16_load(src[15] + 0 * RGBZ_M2_W);
    const rgbz_v16 t16_0 = rgbz_v16_load(src[16] + 0 * RGBZ_M2_W);
    const rgbz_v16 t17_0 = rgbz_v16_load(src[17] + 0 * RGBZ_M2_W);
    const rgbz_v16 t18_0 = rgbz_v16_load(src[18] + 0 * RGBZ_M2_W);
    const rgbz_v16 t19_0 = rgbz_v16_load(src[19] + 0 * RGBZ_M2_W);
    const rgbz_v16 t20_0 = rgbz_v16_load(src[20] + 0 * RGBZ_M2_W);
    const rgbz_v16 d0_0 = rgbz_v16_abs(t3_0 - t0_0);
    rgbz_v16 G0_0 = d0_0;
    rgbz_v16 G4_0 = d0_0;
    const rgbz_v16 d1_0 = rgbz_v16_abs(t8_0 - t9_0);
    G0_0 = G0_0 + d1_0;
    G4_0 = G4_0 + d1_0;
    const rgbz_v16 d2_0 = rgbz_v16_abs(t4_0 - t2_0);
    G0_0 = G0_0 + d2_0;
    rgbz_v16 G5_0 = d2_0;
    const rgbz_v16 d3_0 = rgbz_v16_abs(t3_0 - t5_0);
    rgbz_v16 G1_0 = d3_0;
    rgbz_v16 G6_0 = d3_0;
    const rgbz_v16 d4_0 = rgbz_v16_abs(t8_0 - t10_0);
    G1_0 = G1_0 + d4_0;
    G6_0 = G6_0 + d4_0;
    const rgbz_v16 d5_0 = rgbz_v16_abs(t4_0 - t7_0);
    G1_0 = G1_0 + d5_0;
    rgbz_v16 G7_0 = d5_0;
    const rgbz_v16 d6_0 = rgbz_v16_abs(t1_0 - t0_0);
    rgbz_v16 G2_0 = d6_0;
    G4_0 = G4_0 + d6_0;
    const rgbz_v16 d7_0 = rgbz_v16_abs(t11_0 - t12_0);
    G2_0 = G2_0 + d7_0;
    G6_0 = G6_0 + d7_0;
    const rgbz_v16 d8_0 = rgbz_v16_abs(t6_0 - t5_0);
    G2_0 = G2_0 + d8_0;
    G6_0 = G6_0 + d8_0;
    const rgbz_v16 d9_0 = rgbz_v16_abs(t1_0 - t2_0);
    rgbz_v16 G3_0 = d9_0;
    G5_0 = G5_0 + d9_0;
    const rgbz_v16 d10_0 = rgbz_v16_abs(t11_0 - t13_0);
    G3_0 = G3_0 + d10_0;
    G7_0 = G7_0 + d10_0;
    const rgbz_v16 d11_0 = rgbz_v16_abs(t6_0 - t7_0);
    G3_0 = G3_0 + d11_0;
    G7_0 = G7_0 + d11_0;
    const rgbz_v16 d12_0 = rgbz_v16_abs(t14_0 - t12_0);
    rgbz_v16 G8_0 = d12_0;
    const rgbz_v16 d13_0 = rgbz_v16_abs(t15_0 - t16_0);
    G8_0 = G8_0 + d13_0;
    const rgbz_v16 d14_0 = rgbz_v16_abs(t17_0 - t13_0);
    G8_0 = G8_0 + d14_0;
    const rgbz_v16 d15_0 = rgbz_v16_abs(t0_0 - t5_0);
    G8_0 = G8_0 + d15_0;
    const rgbz_v16 d16_0 = rgbz_v16_abs(t9_0 - t10_0);
    G8_0 = G8_0 + d16_0;
    const rgbz_v16 d17_0 = rgbz_v16_abs(t1_0 - t6_0);
    G8_0 = G8_0 + d17_0;
    const rgbz_v16 d18_0 = rgbz_v16_abs(t18_0 - t19_0);
    G8_0 = G8_0 + d18_0;
    const rgbz_v16 d19_0 = rgbz_v16_abs(t2_0 - t7_0);
    G8_0 = G8_0 + d19_0;
    const rgbz_v16 d20_0 = rgbz_v16_abs(t9_0 - t18_0);
    rgbz_v16 G9_0 = d20_0;
    const rgbz_v16 d21_0 = rgbz_v16_abs(t16_0 - t20_0);
    G9_0 = G9_0 + d21_0;
    const rgbz_v16 d22_0 = rgbz_v16_abs(t10_0 - t19_0);
    G9_0 = G9_0 + d22_0;
    const rgbz_v16 d23_0 = rgbz_v16_abs(t0_0 - t2_0);
    G9_0 = G9_0 + d23_0;
    const rgbz_v16 d24_0 = rgbz_v16_abs(t14_0 - t17_0);
    G9_0 = G9_0 + d24_0;
    const rgbz_v16 d25_0 = rgbz_v16_abs(t3_0 - t4_0);
    G9_0 = G9_0 + d25_0;
    const rgbz_v16 d26_0 = rgbz_v16_abs(t12_0 - t13_0);
    G9_0 = G9_0 + d26_0;
    const rgbz_v16 d27_0 = rgbz_v16_abs(t5_0 - t7_0);
    G9_0 = G9_0 + d27_0;
    const rgbz_v16 d28_0 = rgbz_v16_abs(t17_0 - t18_0);
    rgbz_v16 G10_0 = d28_0;
    const rgbz_v16 d29_0 = rgbz_v16_abs(t4_0 - t1_0);
    G10_0 = G10_0 + d29_0;
    const rgbz_v16 d30_0 = rgbz_v16_abs(t11_0 - t8_0);
    G10_0 = G10_0 + d30_0;
    const rgbz_v16 d31_0 = rgbz_v16_abs(t20_0 - t15_0);
    G10_0 = G10_0 + d31_0;
    const rgbz_v16 d32_0 = rgbz_v16_abs(t13_0 - t9_0);
    G10_0 = G10_0 + d32_0;
    const rgbz_v16 d33_0 = rgbz_v16_abs(t10_0 - t12_0);
    G10_0 = G10_0 + d33_0;
    const rgbz_v16 d34_0 = rgbz_v16_abs(t6_0 - t3_0);
    G10_0 = G10_0 + d34_0;
    const rgbz_v16 d35_0 = rgbz_v16_abs(t19_0 - t14_0);
    G10_0 = G10_0 + d35_0;
    const rgbz_v16 d36_0 = rgbz_v16_abs(t7_0 - t0_0);
    G10_0 = G10_0 + d36_0;
    const rgbz_v16 d37_0 = rgbz_v16_abs(t14_0 - t9_0);
    rgbz_v16 G11_0 = d37_0;
    const rgbz_v16 d38_0 = rgbz_v16_abs(t3_0 - t1_0);
    G11_0 = G11_0 + d38_0;
    const rgbz_v16 d39_0 = rgbz_v16_abs(t12_0 - t18_0);
    G11_0 = G11_0 + d39_0;
    const rgbz_v16 d40_0 = rgbz_v16_abs(t5_0 - t2_0);
    G11_0 = G11_0 + d40_0;
    const rgbz_v16 d41_0 = rgbz_v16_abs(t10_0 - t17_0);
    G11_0 = G11_0 + d41_0;
    const rgbz_v16 d42_0 = rgbz_v16_abs(t6_0 - t4_0);
    G11_0 = G11_0 + d42_0;
    const rgbz_v16 d43_0 = rgbz_v16_abs(t19_0 - t13_0);
    G11_0 = G11_0 + d43_0;
    const rgbz_v16 gm0_0 = G0_0 * (float)0.3333333333333333;
    const rgbz_v16 gm1_0 = G1_0 * (float)0.3333333333333333;
    const rgbz_v16 gm2_0 = G2_0 * (float)0.3333333333333333;
    const rgbz_v16 gm3_0 = G3_0 * (float)0.3333333333333333;
    const rgbz_v16 gm4_0 = G4_0 * (float)0.3333333333333333;
    const rgbz_v16 gm5_0 = G5_0 * (float)0.5;
    const rgbz_v16 gm6_0 = G6_0 * (float)0.25;
    const rgbz_v16 gm7_0 = G7_0 * (float)0.3333333333333333;
    rgbz_v16 smin_0 = gm0_0;
    smin_0 = M2_MIN(gm1_0, smin_0);
    smin_0 = M2_MIN(gm2_0, smin_0);
    smin_0 = M2_MIN(gm3_0, smin_0);
    smin_0 = M2_MIN(gm4_0, smin_0);
    smin_0 = M2_MIN(gm5_0, smin_0);
    smin_0 = M2_MIN(gm6_0, smin_0);
    smin_0 = M2_MIN(gm7_0, smin_0);
    rgbz_v16 ssg_0 = M2_MAX(smin_0, floor_);
    if (REL) {
        rgbz_v16 ssum_0 = gm0_0;
        ssum_0 = ssum_0 + gm1_0;
        ssum_0 = ssum_0 + gm2_0;
        ssum_0 = ssum_0 + gm3_0;
        ssum_0 = ssum_0 + gm4_0;
        ssum_0 = ssum_0 + gm5_0;
        ssum_0 = ssum_0 + gm6_0;
        ssum_0 = ssum_0 + gm7_0;
        const rgbz_v16 srf_0 = (rel * ssum_0) / (float)8;
        ssg_0 = M2_MAX(srf_0, ssg_0);
    }
    const rgbz_v16 sninv_0 = -(1.0f / (2.0f * (ssg_0 * ssg_0)));
    const rgbz_v16 x0_0 = (gm0_0 * gm0_0) * sninv_0;
    const rgbz_v16 x1_0 = (gm1_0 * gm1_0) * sninv_0;
    const rgbz_v16 x2_0 = (gm2_0 * gm2_0) * sninv_0;
    const rgbz_v16 x3_0 = (gm3_0 * gm3_0) * sninv_0;
    const rgbz_v16 x4_0 = (gm4_0 * gm4_0) * sninv_0;
    const rgbz_v16 x5_0 = (gm5_0 * gm5_0) * sninv_0;
    const rgbz_v16 x6_0 = (gm6_0 * gm6_0) * sninv_0;
    const rgbz_v16 x7_0 = (gm7_0 * gm7_0) * sninv_0;
    const rgbz_v16 xc0_0 = x0_0;
    const rgbz_v16 xc1_0 = x1_0;
    const rgbz_v16 xc2_0 = x2_0;
    const rgbz_v16 xc3_0 = x3_0;
    const rgbz_v16 xc4_0 = x4_0;
    const rgbz_v16 xc5_0 = x5_0;
    const rgbz_v16 xc6_0 = x6_0;
    const rgbz_v16 xc7_0 = x7_0;
    const rgbz_v16 et0_0 = xc0_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1_0 = xc1_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2_0 = xc2_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3_0 = xc3_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4_0 = xc4_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5_0 = xc5_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6_0 = xc6_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7_0 = xc7_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0_0 = M2_RINT(xc0_0 * 1.44269504f, et0_0);
    const rgbz_v16 en1_0 = M2_RINT(xc1_0 * 1.44269504f, et1_0);
    const rgbz_v16 en2_0 = M2_RINT(xc2_0 * 1.44269504f, et2_0);
    const rgbz_v16 en3_0 = M2_RINT(xc3_0 * 1.44269504f, et3_0);
    const rgbz_v16 en4_0 = M2_RINT(xc4_0 * 1.44269504f, et4_0);
    const rgbz_v16 en5_0 = M2_RINT(xc5_0 * 1.44269504f, et5_0);
    const rgbz_v16 en6_0 = M2_RINT(xc6_0 * 1.44269504f, et6_0);
    const rgbz_v16 en7_0 = M2_RINT(xc7_0 * 1.44269504f, et7_0);
    const rgbz_v16 ey0_0 = (xc0_0 - en0_0 * 0.693359375f) - en0_0 * -2.12194440e-4f;
    const rgbz_v16 ey1_0 = (xc1_0 - en1_0 * 0.693359375f) - en1_0 * -2.12194440e-4f;
    const rgbz_v16 ey2_0 = (xc2_0 - en2_0 * 0.693359375f) - en2_0 * -2.12194440e-4f;
    const rgbz_v16 ey3_0 = (xc3_0 - en3_0 * 0.693359375f) - en3_0 * -2.12194440e-4f;
    const rgbz_v16 ey4_0 = (xc4_0 - en4_0 * 0.693359375f) - en4_0 * -2.12194440e-4f;
    const rgbz_v16 ey5_0 = (xc5_0 - en5_0 * 0.693359375f) - en5_0 * -2.12194440e-4f;
    const rgbz_v16 ey6_0 = (xc6_0 - en6_0 * 0.693359375f) - en6_0 * -2.12194440e-4f;
    const rgbz_v16 ey7_0 = (xc7_0 - en7_0 * 0.693359375f) - en7_0 * -2.12194440e-4f;
    rgbz_v16 ep0_0 = 1.0f / 120 + ey0_0 * (1.0f / 720);
    rgbz_v16 ep1_0 = 1.0f / 120 + ey1_0 * (1.0f / 720);
    rgbz_v16 ep2_0 = 1.0f / 120 + ey2_0 * (1.0f / 720);
    rgbz_v16 ep3_0 = 1.0f / 120 + ey3_0 * (1.0f / 720);
    rgbz_v16 ep4_0 = 1.0f / 120 + ey4_0 * (1.0f / 720);
    rgbz_v16 ep5_0 = 1.0f / 120 + ey5_0 * (1.0f / 720);
    rgbz_v16 ep6_0 = 1.0f / 120 + ey6_0 * (1.0f / 720);
    rgbz_v16 ep7_0 = 1.0f / 120 + ey7_0 * (1.0f / 720);
    ep0_0 = 1.0f / 24 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 24 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 24 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 24 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 24 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 24 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 24 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 24 + ey7_0 * ep7_0;
    ep0_0 = 1.0f / 6 + ey0_0 * ep0_0;
    ep1_0 = 1.0f / 6 + ey1_0 * ep1_0;
    ep2_0 = 1.0f / 6 + ey2_0 * ep2_0;
    ep3_0 = 1.0f / 6 + ey3_0 * ep3_0;
    ep4_0 = 1.0f / 6 + ey4_0 * ep4_0;
    ep5_0 = 1.0f / 6 + ey5_0 * ep5_0;
    ep6_0 = 1.0f / 6 + ey6_0 * ep6_0;
    ep7_0 = 1.0f / 6 + ey7_0 * ep7_0;
    ep0_0 = 0.5f + ey0_0 * ep0_0;
    ep1_0 = 0.5f + ey1_0 * ep1_0;
    ep2_0 = 0.5f + ey2_0 * ep2_0;
    ep3_0 = 0.5f + ey3_0 * ep3_0;
    ep4_0 = 0.5f + ey4_0 * ep4_0;
    ep5_0 = 0.5f + ey5_0 * ep5_0;
    ep6_0 = 0.5f + ey6_0 * ep6_0;
    ep7_0 = 0.5f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    ep0_0 = 1.0f + ey0_0 * ep0_0;
    ep1_0 = 1.0f + ey1_0 * ep1_0;
    ep2_0 = 1.0f + ey2_0 * ep2_0;
    ep3_0 = 1.0f + ey3_0 * ep3_0;
    ep4_0 = 1.0f + ey4_0 * ep4_0;
    ep5_0 = 1.0f + ey5_0 * ep5_0;
    ep6_0 = 1.0f + ey6_0 * ep6_0;
    ep7_0 = 1.0f + ey7_0 * ep7_0;
    const rgbz_v16 ga0_0 = M2_EXPOUT(x0_0, ep0_0, et0_0, en0_0);
    const rgbz_v16 ga1_0 = M2_EXPOUT(x1_0, ep1_0, et1_0, en1_0);
    const rgbz_v16 ga2_0 = M2_EXPOUT(x2_0, ep2_0, et2_0, en2_0);
    const rgbz_v16 ga3_0 = M2_EXPOUT(x3_0, ep3_0, et3_0, en3_0);
    const rgbz_v16 ga4_0 = M2_EXPOUT(x4_0, ep4_0, et4_0, en4_0);
    const rgbz_v16 ga5_0 = M2_EXPOUT(x5_0, ep5_0, et5_0, en5_0);
    const rgbz_v16 ga6_0 = M2_EXPOUT(x6_0, ep6_0, et6_0, en6_0);
    const rgbz_v16 ga7_0 = M2_EXPOUT(x7_0, ep7_0, et7_0, en7_0);
    const rgbz_v16 gm8_0 = G8_0 * (float)0.125;
    const rgbz_v16 gm9_0 = G9_0 * (float)0.125;
    const rgbz_v16 gm10_0 = G10_0 * (float)0.1111111111111111;
    const rgbz_v16 gm11_0 = G11_0 * (float)0.14285714285714285;
    rgbz_v16 gmin_0 = gm8_0;
    gmin_0 = M2_MIN(gm9_0, gmin_0);
    gmin_0 = M2_MIN(gm10_0, gmin_0);
    gmin_0 = M2_MIN(gm11_0, gmin_0);
    rgbz_v16 gsg_0 = M2_MAX(gmin_0, floor_);
    if (REL) {
        rgbz_v16 gsum_0 = gm8_0;
        gsum_0 = gsum_0 + gm9_0;
        gsum_0 = gsum_0 + gm10_0;
        gsum_0 = gsum_0 + gm11_0;
        const rgbz_v16 grf_0 = (rel * gsum_0) / (float)4;
        gsg_0 = M2_MAX(grf_0, gsg_0);
    }
    const rgbz_v16 gninv_0 = -(1.0f / (2.0f * (gsg_0 * gsg_0)));
    const rgbz_v16 x8_0 = (gm8_0 * gm8_0) * gninv_0;
    const rgbz_v16 x9_0 = (gm9_0 * gm9_0) * gninv_0;
    const rgbz_v16 x10_0 = (gm10_0 * gm10_0) * gninv_0;
    const rgbz_v16 x11_0 = (gm11_0 * gm11_0) * gninv_0;
    const rgbz_v16 xc8_0 = x8_0;
    const rgbz_v16 xc9_0 = x9_0;
    const rgbz_v16 xc10_0 = x10_0;
    const rgbz_v16 xc11_0 = x11_0;
    const rgbz_v16 et8_0 = xc8_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9_0 = xc9_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10_0 = xc10_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11_0 = xc11_0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8_0 = M2_RINT(xc8_0 * 1.44269504f, et8_0);
    const rgbz_v16 en9_0 = M2_RINT(xc9_0 * 1.44269504f, et9_0);
    const rgbz_v16 en10_0 = M2_RINT(xc10_0 * 1.44269504f, et10_0);
    const rgbz_v16 en11_0 = M2_RINT(xc11_0 * 1.44269504f, et11_0);
    const rgbz_v16 ey8_0 = (xc8_0 - en8_0 * 0.693359375f) - en8_0 * -2.12194440e-4f;
    const rgbz_v16 ey9_0 = (xc9_0 - en9_0 * 0.693359375f) - en9_0 * -2.12194440e-4f;
    const rgbz_v16 ey10_0 = (xc10_0 - en10_0 * 0.693359375f) - en10_0 * -2.12194440e-4f;
    const rgbz_v16 ey11_0 = (xc11_0 - en11_0 * 0.693359375f) - en11_0 * -2.12194440e-4f;
    rgbz_v16 ep8_0 = 1.0f / 120 + ey8_0 * (1.0f / 720);
    rgbz_v16 ep9_0 = 1.0f / 120 + ey9_0 * (1.0f / 720);
    rgbz_v16 ep10_0 = 1.0f / 120 + ey10_0 * (1.0f / 720);
    rgbz_v16 ep11_0 = 1.0f / 120 + ey11_0 * (1.0f / 720);
    ep8_0 = 1.0f / 24 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 24 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 24 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 24 + ey11_0 * ep11_0;
    ep8_0 = 1.0f / 6 + ey8_0 * ep8_0;
    ep9_0 = 1.0f / 6 + ey9_0 * ep9_0;
    ep10_0 = 1.0f / 6 + ey10_0 * ep10_0;
    ep11_0 = 1.0f / 6 + ey11_0 * ep11_0;
    ep8_0 = 0.5f + ey8_0 * ep8_0;
    ep9_0 = 0.5f + ey9_0 * ep9_0;
    ep10_0 = 0.5f + ey10_0 * ep10_0;
    ep11_0 = 0.5f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    ep8_0 = 1.0f + ey8_0 * ep8_0;
    ep9_0 = 1.0f + ey9_0 * ep9_0;
    ep10_0 = 1.0f + ey10_0 * ep10_0;
    ep11_0 = 1.0f + ey11_0 * ep11_0;
    const rgbz_v16 ga8_0 = M2_EXPOUT(x8_0, ep8_0, et8_0, en8_0);
    const rgbz_v16 ga9_0 = M2_EXPOUT(x9_0, ep9_0, et9_0, en9_0);
    const rgbz_v16 ga10_0 = M2_EXPOUT(x10_0, ep10_0, et10_0, en10_0);
    const rgbz_v16 ga11_0 = M2_EXPOUT(x11_0, ep11_0, et11_0, en11_0);
    const rgbz_v16 c0_0 = rgbz_v16_load(src[0] + 0 * RGBZ_M2_W);
    const rgbz_v16 c1_0 = rgbz_v16_load(src[1] + 0 * RGBZ_M2_W);
    const rgbz_v16 c2_0 = rgbz_v16_load(src[2] + 0 * RGBZ_M2_W);
    const rgbz_v16 c3_0 = rgbz_v16_load(src[3] + 0 * RGBZ_M2_W);
    const rgbz_v16 c4_0 = rgbz_v16_load(src[4] + 0 * RGBZ_M2_W);
    const rgbz_v16 c5_0 = rgbz_v16_load(src[5] + 0 * RGBZ_M2_W);
    const rgbz_v16 c6_0 = rgbz_v16_load(src[6] + 0 * RGBZ_M2_W);
    const rgbz_v16 c7_0 = rgbz_v16_load(src[7] + 0 * RGBZ_M2_W);
    rgbz_v16 S0_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S2_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S3_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S4_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S5_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S6_0 = rgbz_v16_set(1.0f);
    rgbz_v16 S7_0 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c1_0); S0_0 = S0_0 + e; S1_0 = S1_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c2_0); S0_0 = S0_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c3_0); S0_0 = S0_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c4_0); S0_0 = S0_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c5_0); S0_0 = S0_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c6_0); S0_0 = S0_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0_0 - c7_0); S0_0 = S0_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c2_0); S1_0 = S1_0 + e; S2_0 = S2_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c3_0); S1_0 = S1_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c4_0); S1_0 = S1_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c5_0); S1_0 = S1_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c6_0); S1_0 = S1_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1_0 - c7_0); S1_0 = S1_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c3_0); S2_0 = S2_0 + e; S3_0 = S3_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c4_0); S2_0 = S2_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c5_0); S2_0 = S2_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c6_0); S2_0 = S2_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2_0 - c7_0); S2_0 = S2_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c4_0); S3_0 = S3_0 + e; S4_0 = S4_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c5_0); S3_0 = S3_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c6_0); S3_0 = S3_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3_0 - c7_0); S3_0 = S3_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c5_0); S4_0 = S4_0 + e; S5_0 = S5_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c6_0); S4_0 = S4_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4_0 - c7_0); S4_0 = S4_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c6_0); S5_0 = S5_0 + e; S6_0 = S6_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5_0 - c7_0); S5_0 = S5_0 + e; S7_0 = S7_0 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6_0 - c7_0); S6_0 = S6_0 + e; S7_0 = S7_0 + e; }
    rgbz_v16 den_0, num_0 = rgbz_v16_set(0.0f);
    den_0 = ((((float)0.01831563888873418) / S0_0) * ga10_0) * (((ga0_0 + ga2_0) + ga4_0) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1_0) * ga8_0) * (ga0_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c1_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2_0) * ga11_0) * (((ga0_0 + ga3_0) + ga5_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c2_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3_0) * ga9_0) * (ga2_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c3_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4_0) * ga9_0) * (ga3_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c4_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5_0) * ga11_0) * (((ga1_0 + ga2_0) + ga6_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c5_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6_0) * ga8_0) * (ga1_0 * (float)1.0); den_0 = den_0 + w; num_0 = num_0 + w * (c6_0 - c0_0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7_0) * ga10_0) * (((ga1_0 + ga3_0) + ga7_0) * (float)0.3333333333333333); den_0 = den_0 + w; num_0 = num_0 + w * (c7_0 - c0_0); }
    const rgbz_v16i ok_0 = den_0 > 0.0f;
    const rgbz_v16 q_0 = rgbz_v16_sel(ok_0, den_0, rgbz_v16_set(1.0f));
    rgbz_v16 res_0 = rgbz_v16_sel(ok_0, c0_0 + num_0 / q_0, c0_0);
    if (!(rgbz_v16_all(ok_0))) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s_0 = c1_0 - c0_0;
        s_0 = s_0 + (c2_0 - c0_0);
        s_0 = s_0 + (c3_0 - c0_0);
        s_0 = s_0 + (c4_0 - c0_0);
        s_0 = s_0 + (c5_0 - c0_0);
        s_0 = s_0 + (c6_0 - c0_0);
        s_0 = s_0 + (c7_0 - c0_0);
        res_0 = rgbz_v16_sel(ok_0, res_0, c0_0 + s_0 / (float)8);
    }
    rgbz_v16_store(out + 0 * RGBZ_M2_W, res_0);
}


/*
 * The n sites of a block (v tap-major, recon_core.template.h) through the function of plan k
 * (an index of rgbz_m2_plan_bytes), RGBZ_M2_STEP at a time; the last step of a block whose n
 * is not a multiple of it runs on a copy of its taps padded with zeros, and only its results
 * for the n sites are kept.
 */
M2_ATTR static void M2_FN(rgbz_m2_run)(int k, const float *const *v, int n, float floor_,
                                       float rel, float *restrict r)
{
    const rgbz_v16 fl = rgbz_v16_set(floor_), rl = rgbz_v16_set(rel);
    const int REL = rel > 0.0f;
    const int nt = rgbz_m2_ntaps[k];
    for (int j0 = 0; j0 < n; j0 += RGBZ_M2_STEP) {
        const float *src[RGBZ_MAX_TAPS];
        float pad[RGBZ_MAX_TAPS][RGBZ_M2_STEP], res[RGBZ_M2_STEP];
        const int m = n - j0 < RGBZ_M2_STEP ? n - j0 : RGBZ_M2_STEP;
        if (m == RGBZ_M2_STEP) {
            for (int t = 0; t < nt; t++) src[t] = v[t] + j0;
        } else {
            for (int t = 0; t < nt; t++) {
                for (int i = 0; i < RGBZ_M2_STEP; i++) pad[t][i] = i < m ? v[t][j0 + i] : 0.0f;
                src[t] = pad[t];
            }
        }
        float *o = m == RGBZ_M2_STEP ? r + j0 : res;
#define RGBZ_M2_CASE_(K)                                                                  \
        case K:                                                                           \
            if (REL) M2_FN(rgbz_m2_site##K)(src, fl, rl, 1, o);                           \
            else M2_FN(rgbz_m2_site##K)(src, fl, rl, 0, o);                               \
            break;
        switch (k) {
            RGBZ_M2_CASES_
        default: break;
        }
#undef RGBZ_M2_CASE_
        if (m < RGBZ_M2_STEP) memcpy(r + j0, res, (size_t)m * sizeof(float));
    }
}
