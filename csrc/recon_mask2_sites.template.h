/*
 * recon_mask2_sites.template.h -- WRITTEN BY tools/gen_recon_mask2.py: do not edit; run the
 * script. Included twice by recon_mask2.h, once per instance:
 *   M2_FN(name)            the instance's name of a function (name_g, name_x)
 *   M2_ATTR                its target attribute (none; AVX-512F)
 *   M2_MIN(a, b)           a < b ? a : b per lane (x86's MINPS exactly)
 *   M2_MAX(a, b)           a > b ? a : b per lane (MAXPS exactly)
 *   M2_ADD(a, b)           a + b, or the same sum as a fused multiply-add a * 1 + b on the
 *                          multiplier's pipes (exact: the same bits)
 *   M2_XMC1(x, en)         x - en * 0.693359375f, or the same as one fused operation (the
 *                          product exact where it matters: the same bits)
 *   M2_ALLPOS(d)           1 if every lane of d is > 0 (a NaN is not)
 *   M2_RINT(v, et)         v rounded to an integer, ties to even: et - 1.5 * 2^23 with
 *                          et = v + 1.5 * 2^23 (rgbz_exp_poly_f32's way), or VRNDSCALEPS of v
 *                          (|v| < 2^22 where it matters: the same value)
 *   M2_EXPOUT(x, p, et, en)  the exponential's last step: x > -87 ? p * 2^en : 0, 2^en from
 *                          et's bits times p (rgbz_exp_poly_f32), or VSCALEFPS of p and en
 *                          under the comparison's mask (exact, the results normal: the same
 *                          bits)
 * and undefined again at its end.
 */
/* Z site 0: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site0)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t5 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t11 - t12);
    G0 = G0 + d1;
    G4 = G4 + d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t6 - t2);
    G0 = G0 + d2;
    rgbz_v16 G5 = d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t5 - t8);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t11 - t13);
    G1 = G1 + d4;
    G6 = G6 + d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t6 - t10);
    G1 = G1 + d5;
    rgbz_v16 G7 = d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t14 - t15);
    G2 = G2 + d7;
    G4 = G4 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t9 - t8);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t14 - t16);
    G3 = G3 + d10;
    G5 = G5 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t9 - t10);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t15 - t17);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t3 - t7);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t16 - t18);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t8);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t12 - t13);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t9);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t19 - t20);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t10);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t12 - t19);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t13 - t20);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t15 - t16);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t5 - t6);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t17 - t18);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t8 - t10);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t16 - t19);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t6 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t18 - t12);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t13 - t17);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t9 - t5);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t20 - t15);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t10 - t0);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t15 - t12);
    rgbz_v16 G11 = d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t5 - t1);
    G11 = G11 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t11 - t14);
    G11 = G11 + d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t17 - t19);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t7 - t4);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t8 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t13 - t16);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t9 - t6);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t20 - t18);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.25;
    const rgbz_v16 gm5 = G5 * (float)0.3333333333333333;
    const rgbz_v16 gm6 = G6 * (float)0.3333333333333333;
    const rgbz_v16 gm7 = G7 * (float)0.5;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.14285714285714285;
    const rgbz_v16 gm11 = G11 * (float)0.1111111111111111;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 c8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 c9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 c10 = rgbz_v16_load(src[10] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    rgbz_v16 S8 = rgbz_v16_set(1.0f);
    rgbz_v16 S9 = rgbz_v16_set(1.0f);
    rgbz_v16 S10 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c8); S0 = M2_ADD(S0, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c9); S0 = M2_ADD(S0, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c10); S0 = M2_ADD(S0, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c8); S1 = M2_ADD(S1, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c9); S1 = M2_ADD(S1, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c10); S1 = M2_ADD(S1, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c8); S2 = M2_ADD(S2, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c9); S2 = M2_ADD(S2, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c10); S2 = M2_ADD(S2, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c8); S3 = M2_ADD(S3, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c9); S3 = M2_ADD(S3, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c10); S3 = M2_ADD(S3, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c8); S4 = M2_ADD(S4, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c9); S4 = M2_ADD(S4, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c10); S4 = M2_ADD(S4, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c8); S5 = M2_ADD(S5, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c9); S5 = M2_ADD(S5, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c10); S5 = M2_ADD(S5, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c8); S6 = M2_ADD(S6, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c9); S6 = M2_ADD(S6, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c10); S6 = M2_ADD(S6, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c8); S7 = M2_ADD(S7, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c9); S7 = M2_ADD(S7, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c10); S7 = M2_ADD(S7, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c9); S8 = M2_ADD(S8, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c10); S8 = M2_ADD(S8, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9 - c10); S9 = M2_ADD(S9, e); S10 = S10 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S4) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c8 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c9 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c10 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        s = s + (c8 - c0);
        s = s + (c9 - c0);
        s = s + (c10 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)11);
    }
    rgbz_v16_store(out, res);
}

/* Z site 1: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site1)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    rgbz_v16 G5 = d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    G5 = G5 + d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    rgbz_v16 G7 = d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    G7 = G7 + d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G4 = G4 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G5 = G5 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t12 - t14);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t13 - t17);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t18 - t9);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t20 - t15);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t19 - t10);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t13 - t9);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t8 - t11);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t16 - t20);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t17 - t18);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t19 - t14);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t10 - t12);
    G10 = G10 + d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t12 - t18);
    rgbz_v16 G11 = d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t14 - t9);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t19 - t13);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t10 - t17);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.3333333333333333;
    const rgbz_v16 gm5 = G5 * (float)0.25;
    const rgbz_v16 gm6 = G6 * (float)0.5;
    const rgbz_v16 gm7 = G7 * (float)0.3333333333333333;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.1111111111111111;
    const rgbz_v16 gm11 = G11 * (float)0.14285714285714285;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 2: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site2)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    G4 = G4 + d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    rgbz_v16 G5 = d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    G6 = G6 + d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    rgbz_v16 G7 = d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G6 = G6 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G7 = G7 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t14 - t12);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t17 - t13);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t9 - t18);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t16 - t20);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t10 - t19);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t17 - t18);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t11 - t8);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t20 - t15);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t13 - t9);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t10 - t12);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t19 - t14);
    G10 = G10 + d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t14 - t9);
    rgbz_v16 G11 = d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t12 - t18);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t10 - t17);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t19 - t13);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.3333333333333333;
    const rgbz_v16 gm5 = G5 * (float)0.5;
    const rgbz_v16 gm6 = G6 * (float)0.25;
    const rgbz_v16 gm7 = G7 * (float)0.3333333333333333;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.1111111111111111;
    const rgbz_v16 gm11 = G11 * (float)0.14285714285714285;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 3: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site3)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t4 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t11 - t12);
    G0 = G0 + d1;
    rgbz_v16 G5 = d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t5 - t2);
    G0 = G0 + d2;
    G5 = G5 + d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t4 - t8);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t11 - t13);
    G1 = G1 + d4;
    rgbz_v16 G7 = d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t5 - t10);
    G1 = G1 + d5;
    G7 = G7 + d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t14 - t15);
    G2 = G2 + d7;
    G6 = G6 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t9 - t8);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t14 - t16);
    G3 = G3 + d10;
    G7 = G7 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t9 - t10);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t17 - t15);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t3 - t7);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t18 - t16);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t8);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t19 - t20);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t9);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t12 - t13);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t10);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t19 - t12);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t6 - t7);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t20 - t13);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t17 - t18);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t4 - t5);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t15 - t16);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t8 - t10);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t18 - t12);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t5 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t16 - t19);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t20 - t15);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t9 - t4);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t13 - t17);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t10 - t0);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t17 - t19);
    rgbz_v16 G11 = d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t4 - t1);
    G11 = G11 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t15 - t12);
    G11 = G11 + d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t6 - t3);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t14 - t11);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t8 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t20 - t18);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t9 - t5);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t13 - t16);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.5;
    const rgbz_v16 gm5 = G5 * (float)0.3333333333333333;
    const rgbz_v16 gm6 = G6 * (float)0.3333333333333333;
    const rgbz_v16 gm7 = G7 * (float)0.25;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.14285714285714285;
    const rgbz_v16 gm11 = G11 * (float)0.1111111111111111;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 c8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 c9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 c10 = rgbz_v16_load(src[10] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    rgbz_v16 S8 = rgbz_v16_set(1.0f);
    rgbz_v16 S9 = rgbz_v16_set(1.0f);
    rgbz_v16 S10 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c8); S0 = M2_ADD(S0, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c9); S0 = M2_ADD(S0, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c10); S0 = M2_ADD(S0, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c8); S1 = M2_ADD(S1, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c9); S1 = M2_ADD(S1, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c10); S1 = M2_ADD(S1, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c8); S2 = M2_ADD(S2, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c9); S2 = M2_ADD(S2, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c10); S2 = M2_ADD(S2, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c8); S3 = M2_ADD(S3, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c9); S3 = M2_ADD(S3, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c10); S3 = M2_ADD(S3, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c8); S4 = M2_ADD(S4, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c9); S4 = M2_ADD(S4, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c10); S4 = M2_ADD(S4, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c8); S5 = M2_ADD(S5, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c9); S5 = M2_ADD(S5, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c10); S5 = M2_ADD(S5, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c8); S6 = M2_ADD(S6, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c9); S6 = M2_ADD(S6, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c10); S6 = M2_ADD(S6, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c8); S7 = M2_ADD(S7, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c9); S7 = M2_ADD(S7, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c10); S7 = M2_ADD(S7, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c9); S8 = M2_ADD(S8, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c10); S8 = M2_ADD(S8, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9 - c10); S9 = M2_ADD(S9, e); S10 = S10 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S6) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c8 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c9 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c10 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        s = s + (c8 - c0);
        s = s + (c9 - c0);
        s = s + (c10 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)11);
    }
    rgbz_v16_store(out, res);
}

/* Z site 4: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site4)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    G4 = G4 + d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    rgbz_v16 G5 = d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    G6 = G6 + d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    rgbz_v16 G7 = d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G4 = G4 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G5 = G5 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t12 - t14);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t13 - t17);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t9 - t18);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t15 - t20);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t10 - t19);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t13 - t18);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t17 - t9);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t10 - t14);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t19 - t12);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t12 - t9);
    rgbz_v16 G11 = d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t8 - t11);
    G11 = G11 + d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t14 - t18);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t16 - t20);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t10 - t13);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t19 - t17);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.25;
    const rgbz_v16 gm5 = G5 * (float)0.3333333333333333;
    const rgbz_v16 gm6 = G6 * (float)0.3333333333333333;
    const rgbz_v16 gm7 = G7 * (float)0.5;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.14285714285714285;
    const rgbz_v16 gm11 = G11 * (float)0.1111111111111111;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 5: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site5)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t5 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t11 - t12);
    G0 = G0 + d1;
    rgbz_v16 G5 = d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t6 - t2);
    G0 = G0 + d2;
    G5 = G5 + d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t5 - t8);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t11 - t13);
    G1 = G1 + d4;
    rgbz_v16 G7 = d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t6 - t10);
    G1 = G1 + d5;
    G7 = G7 + d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t14 - t15);
    G2 = G2 + d7;
    G4 = G4 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t9 - t8);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t14 - t16);
    G3 = G3 + d10;
    G5 = G5 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t9 - t10);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t15 - t17);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t4 - t7);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t16 - t18);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t8);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t19 - t20);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t9);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t12 - t13);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t10);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t19 - t12);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t20 - t13);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t15 - t16);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t5 - t6);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t17 - t18);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t8 - t10);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t16 - t12);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t11 - t14);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t6 - t1);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t7 - t3);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t18 - t19);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t20 - t17);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t9 - t5);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t13 - t15);
    G10 = G10 + d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t10 - t0);
    G10 = G10 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t15 - t19);
    rgbz_v16 G11 = d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t5 - t1);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t17 - t12);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t8 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t20 - t16);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t9 - t6);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t13 - t18);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.3333333333333333;
    const rgbz_v16 gm5 = G5 * (float)0.25;
    const rgbz_v16 gm6 = G6 * (float)0.5;
    const rgbz_v16 gm7 = G7 * (float)0.3333333333333333;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.1111111111111111;
    const rgbz_v16 gm11 = G11 * (float)0.14285714285714285;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 c8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 c9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 c10 = rgbz_v16_load(src[10] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    rgbz_v16 S8 = rgbz_v16_set(1.0f);
    rgbz_v16 S9 = rgbz_v16_set(1.0f);
    rgbz_v16 S10 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c8); S0 = M2_ADD(S0, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c9); S0 = M2_ADD(S0, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c10); S0 = M2_ADD(S0, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c8); S1 = M2_ADD(S1, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c9); S1 = M2_ADD(S1, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c10); S1 = M2_ADD(S1, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c8); S2 = M2_ADD(S2, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c9); S2 = M2_ADD(S2, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c10); S2 = M2_ADD(S2, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c8); S3 = M2_ADD(S3, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c9); S3 = M2_ADD(S3, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c10); S3 = M2_ADD(S3, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c8); S4 = M2_ADD(S4, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c9); S4 = M2_ADD(S4, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c10); S4 = M2_ADD(S4, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c8); S5 = M2_ADD(S5, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c9); S5 = M2_ADD(S5, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c10); S5 = M2_ADD(S5, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c8); S6 = M2_ADD(S6, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c9); S6 = M2_ADD(S6, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c10); S6 = M2_ADD(S6, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c8); S7 = M2_ADD(S7, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c9); S7 = M2_ADD(S7, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c10); S7 = M2_ADD(S7, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c9); S8 = M2_ADD(S8, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c10); S8 = M2_ADD(S8, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9 - c10); S9 = M2_ADD(S9, e); S10 = S10 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S4) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c8 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c9 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c10 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        s = s + (c8 - c0);
        s = s + (c9 - c0);
        s = s + (c10 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)11);
    }
    rgbz_v16_store(out, res);
}

/* Z site 6: 21 taps, 11 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site6)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t4 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t11 - t12);
    G0 = G0 + d1;
    G4 = G4 + d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t5 - t2);
    G0 = G0 + d2;
    rgbz_v16 G5 = d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t4 - t8);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t11 - t13);
    G1 = G1 + d4;
    G6 = G6 + d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t5 - t10);
    G1 = G1 + d5;
    rgbz_v16 G7 = d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t14 - t15);
    G2 = G2 + d7;
    G6 = G6 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t9 - t8);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t14 - t16);
    G3 = G3 + d10;
    G7 = G7 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t9 - t10);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t17 - t15);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t3 - t6);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t18 - t16);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t8);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t12 - t13);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t9);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t19 - t20);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t10);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t12 - t19);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t6 - t7);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t13 - t20);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t17 - t18);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t4 - t5);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t15 - t16);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t8 - t10);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t18 - t19);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t5 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t14 - t11);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t7 - t3);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t16 - t12);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t13 - t15);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t9 - t4);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t20 - t17);
    G10 = G10 + d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t10 - t0);
    G10 = G10 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t17 - t12);
    rgbz_v16 G11 = d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t4 - t1);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t15 - t19);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t8 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t13 - t18);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t9 - t5);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t20 - t16);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.3333333333333333;
    const rgbz_v16 gm5 = G5 * (float)0.5;
    const rgbz_v16 gm6 = G6 * (float)0.25;
    const rgbz_v16 gm7 = G7 * (float)0.3333333333333333;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.1111111111111111;
    const rgbz_v16 gm11 = G11 * (float)0.14285714285714285;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 c8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 c9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 c10 = rgbz_v16_load(src[10] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    rgbz_v16 S8 = rgbz_v16_set(1.0f);
    rgbz_v16 S9 = rgbz_v16_set(1.0f);
    rgbz_v16 S10 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c8); S0 = M2_ADD(S0, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c9); S0 = M2_ADD(S0, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c10); S0 = M2_ADD(S0, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c8); S1 = M2_ADD(S1, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c9); S1 = M2_ADD(S1, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c10); S1 = M2_ADD(S1, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c8); S2 = M2_ADD(S2, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c9); S2 = M2_ADD(S2, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c10); S2 = M2_ADD(S2, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c8); S3 = M2_ADD(S3, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c9); S3 = M2_ADD(S3, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c10); S3 = M2_ADD(S3, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c8); S4 = M2_ADD(S4, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c9); S4 = M2_ADD(S4, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c10); S4 = M2_ADD(S4, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c8); S5 = M2_ADD(S5, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c9); S5 = M2_ADD(S5, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c10); S5 = M2_ADD(S5, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c8); S6 = M2_ADD(S6, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c9); S6 = M2_ADD(S6, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c10); S6 = M2_ADD(S6, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c8); S7 = M2_ADD(S7, e); S8 = S8 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c9); S7 = M2_ADD(S7, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c7 - c10); S7 = M2_ADD(S7, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c9); S8 = M2_ADD(S8, e); S9 = S9 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c8 - c10); S8 = M2_ADD(S8, e); S10 = S10 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c9 - c10); S9 = M2_ADD(S9, e); S10 = S10 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S3) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S5) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S6) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.36787944117144233) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S8) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c8 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S9) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c9 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S10) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c10 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        s = s + (c8 - c0);
        s = s + (c9 - c0);
        s = s + (c10 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)11);
    }
    rgbz_v16_store(out, res);
}

/* Z site 7: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site7)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    rgbz_v16 G5 = d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    G5 = G5 + d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    rgbz_v16 G7 = d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    G7 = G7 + d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G6 = G6 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G7 = G7 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t14 - t12);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t17 - t13);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t18 - t9);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t20 - t16);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t19 - t10);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t17 - t9);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t13 - t18);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t19 - t12);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t10 - t14);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t14 - t18);
    rgbz_v16 G11 = d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t12 - t9);
    G11 = G11 + d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t20 - t15);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t11 - t8);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t19 - t17);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t10 - t13);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.5;
    const rgbz_v16 gm5 = G5 * (float)0.3333333333333333;
    const rgbz_v16 gm6 = G6 * (float)0.3333333333333333;
    const rgbz_v16 gm7 = G7 * (float)0.25;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.14285714285714285;
    const rgbz_v16 gm11 = G11 * (float)0.1111111111111111;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 8: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site8)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    G4 = G4 + d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    rgbz_v16 G5 = d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    G6 = G6 + d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    rgbz_v16 G7 = d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G4 = G4 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G5 = G5 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t12 - t14);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t13 - t17);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t9 - t18);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t15 - t20);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t10 - t19);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t13 - t18);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t17 - t9);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t10 - t14);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t19 - t12);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t12 - t9);
    rgbz_v16 G11 = d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t8 - t11);
    G11 = G11 + d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t14 - t18);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t16 - t20);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t10 - t13);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t19 - t17);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.25;
    const rgbz_v16 gm5 = G5 * (float)0.3333333333333333;
    const rgbz_v16 gm6 = G6 * (float)0.3333333333333333;
    const rgbz_v16 gm7 = G7 * (float)0.5;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.14285714285714285;
    const rgbz_v16 gm11 = G11 * (float)0.1111111111111111;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 9: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site9)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    rgbz_v16 G5 = d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    G5 = G5 + d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    rgbz_v16 G7 = d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    G7 = G7 + d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G6 = G6 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G7 = G7 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t14 - t12);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t17 - t13);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t18 - t9);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t20 - t16);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t19 - t10);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t17 - t9);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t13 - t18);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t19 - t12);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t10 - t14);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t14 - t18);
    rgbz_v16 G11 = d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t12 - t9);
    G11 = G11 + d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t20 - t15);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t11 - t8);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t19 - t17);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t10 - t13);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.5;
    const rgbz_v16 gm5 = G5 * (float)0.3333333333333333;
    const rgbz_v16 gm6 = G6 * (float)0.3333333333333333;
    const rgbz_v16 gm7 = G7 * (float)0.25;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.14285714285714285;
    const rgbz_v16 gm11 = G11 * (float)0.1111111111111111;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 10: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site10)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    rgbz_v16 G5 = d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    G5 = G5 + d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    rgbz_v16 G7 = d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    G7 = G7 + d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G4 = G4 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G5 = G5 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t12 - t14);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t13 - t17);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t18 - t9);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t20 - t15);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t19 - t10);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t13 - t9);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t8 - t11);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t16 - t20);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t17 - t18);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t19 - t14);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t10 - t12);
    G10 = G10 + d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t12 - t18);
    rgbz_v16 G11 = d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t14 - t9);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t19 - t13);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t10 - t17);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.3333333333333333;
    const rgbz_v16 gm5 = G5 * (float)0.25;
    const rgbz_v16 gm6 = G6 * (float)0.5;
    const rgbz_v16 gm7 = G7 * (float)0.3333333333333333;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.1111111111111111;
    const rgbz_v16 gm11 = G11 * (float)0.14285714285714285;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}

/* Z site 11: 21 taps, 8 candidates, 44 pairs */
RGBZ_INLINE M2_ATTR void M2_FN(rgbz_m2_site11)(const float *const *src, int j0, rgbz_v16 floor_,
                                                  rgbz_v16 rel, int REL, float *restrict out)
{
    const rgbz_v16 t0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 t1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 t2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 t3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 t4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 t5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 t6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 t7 = rgbz_v16_load(src[7] + j0);
    const rgbz_v16 t8 = rgbz_v16_load(src[8] + j0);
    const rgbz_v16 t9 = rgbz_v16_load(src[9] + j0);
    const rgbz_v16 t10 = rgbz_v16_load(src[10] + j0);
    const rgbz_v16 t11 = rgbz_v16_load(src[11] + j0);
    const rgbz_v16 t12 = rgbz_v16_load(src[12] + j0);
    const rgbz_v16 t13 = rgbz_v16_load(src[13] + j0);
    const rgbz_v16 t14 = rgbz_v16_load(src[14] + j0);
    const rgbz_v16 t15 = rgbz_v16_load(src[15] + j0);
    const rgbz_v16 t16 = rgbz_v16_load(src[16] + j0);
    const rgbz_v16 t17 = rgbz_v16_load(src[17] + j0);
    const rgbz_v16 t18 = rgbz_v16_load(src[18] + j0);
    const rgbz_v16 t19 = rgbz_v16_load(src[19] + j0);
    const rgbz_v16 t20 = rgbz_v16_load(src[20] + j0);
    const rgbz_v16 d0 = rgbz_v16_abs(t3 - t0);
    rgbz_v16 G0 = d0;
    rgbz_v16 G4 = d0;
    const rgbz_v16 d1 = rgbz_v16_abs(t8 - t9);
    G0 = G0 + d1;
    G4 = G4 + d1;
    const rgbz_v16 d2 = rgbz_v16_abs(t4 - t2);
    G0 = G0 + d2;
    rgbz_v16 G5 = d2;
    const rgbz_v16 d3 = rgbz_v16_abs(t3 - t5);
    rgbz_v16 G1 = d3;
    rgbz_v16 G6 = d3;
    const rgbz_v16 d4 = rgbz_v16_abs(t8 - t10);
    G1 = G1 + d4;
    G6 = G6 + d4;
    const rgbz_v16 d5 = rgbz_v16_abs(t4 - t7);
    G1 = G1 + d5;
    rgbz_v16 G7 = d5;
    const rgbz_v16 d6 = rgbz_v16_abs(t1 - t0);
    rgbz_v16 G2 = d6;
    G4 = G4 + d6;
    const rgbz_v16 d7 = rgbz_v16_abs(t11 - t12);
    G2 = G2 + d7;
    G6 = G6 + d7;
    const rgbz_v16 d8 = rgbz_v16_abs(t6 - t5);
    G2 = G2 + d8;
    G6 = G6 + d8;
    const rgbz_v16 d9 = rgbz_v16_abs(t1 - t2);
    rgbz_v16 G3 = d9;
    G5 = G5 + d9;
    const rgbz_v16 d10 = rgbz_v16_abs(t11 - t13);
    G3 = G3 + d10;
    G7 = G7 + d10;
    const rgbz_v16 d11 = rgbz_v16_abs(t6 - t7);
    G3 = G3 + d11;
    G7 = G7 + d11;
    const rgbz_v16 d12 = rgbz_v16_abs(t14 - t12);
    rgbz_v16 G8 = d12;
    const rgbz_v16 d13 = rgbz_v16_abs(t15 - t16);
    G8 = G8 + d13;
    const rgbz_v16 d14 = rgbz_v16_abs(t17 - t13);
    G8 = G8 + d14;
    const rgbz_v16 d15 = rgbz_v16_abs(t0 - t5);
    G8 = G8 + d15;
    const rgbz_v16 d16 = rgbz_v16_abs(t9 - t10);
    G8 = G8 + d16;
    const rgbz_v16 d17 = rgbz_v16_abs(t1 - t6);
    G8 = G8 + d17;
    const rgbz_v16 d18 = rgbz_v16_abs(t18 - t19);
    G8 = G8 + d18;
    const rgbz_v16 d19 = rgbz_v16_abs(t2 - t7);
    G8 = G8 + d19;
    const rgbz_v16 d20 = rgbz_v16_abs(t9 - t18);
    rgbz_v16 G9 = d20;
    const rgbz_v16 d21 = rgbz_v16_abs(t16 - t20);
    G9 = G9 + d21;
    const rgbz_v16 d22 = rgbz_v16_abs(t10 - t19);
    G9 = G9 + d22;
    const rgbz_v16 d23 = rgbz_v16_abs(t0 - t2);
    G9 = G9 + d23;
    const rgbz_v16 d24 = rgbz_v16_abs(t14 - t17);
    G9 = G9 + d24;
    const rgbz_v16 d25 = rgbz_v16_abs(t3 - t4);
    G9 = G9 + d25;
    const rgbz_v16 d26 = rgbz_v16_abs(t12 - t13);
    G9 = G9 + d26;
    const rgbz_v16 d27 = rgbz_v16_abs(t5 - t7);
    G9 = G9 + d27;
    const rgbz_v16 d28 = rgbz_v16_abs(t17 - t18);
    rgbz_v16 G10 = d28;
    const rgbz_v16 d29 = rgbz_v16_abs(t4 - t1);
    G10 = G10 + d29;
    const rgbz_v16 d30 = rgbz_v16_abs(t11 - t8);
    G10 = G10 + d30;
    const rgbz_v16 d31 = rgbz_v16_abs(t20 - t15);
    G10 = G10 + d31;
    const rgbz_v16 d32 = rgbz_v16_abs(t13 - t9);
    G10 = G10 + d32;
    const rgbz_v16 d33 = rgbz_v16_abs(t10 - t12);
    G10 = G10 + d33;
    const rgbz_v16 d34 = rgbz_v16_abs(t6 - t3);
    G10 = G10 + d34;
    const rgbz_v16 d35 = rgbz_v16_abs(t19 - t14);
    G10 = G10 + d35;
    const rgbz_v16 d36 = rgbz_v16_abs(t7 - t0);
    G10 = G10 + d36;
    const rgbz_v16 d37 = rgbz_v16_abs(t14 - t9);
    rgbz_v16 G11 = d37;
    const rgbz_v16 d38 = rgbz_v16_abs(t3 - t1);
    G11 = G11 + d38;
    const rgbz_v16 d39 = rgbz_v16_abs(t12 - t18);
    G11 = G11 + d39;
    const rgbz_v16 d40 = rgbz_v16_abs(t5 - t2);
    G11 = G11 + d40;
    const rgbz_v16 d41 = rgbz_v16_abs(t10 - t17);
    G11 = G11 + d41;
    const rgbz_v16 d42 = rgbz_v16_abs(t6 - t4);
    G11 = G11 + d42;
    const rgbz_v16 d43 = rgbz_v16_abs(t19 - t13);
    G11 = G11 + d43;
    const rgbz_v16 gm0 = G0 * (float)0.3333333333333333;
    const rgbz_v16 gm1 = G1 * (float)0.3333333333333333;
    const rgbz_v16 gm2 = G2 * (float)0.3333333333333333;
    const rgbz_v16 gm3 = G3 * (float)0.3333333333333333;
    const rgbz_v16 gm4 = G4 * (float)0.3333333333333333;
    const rgbz_v16 gm5 = G5 * (float)0.5;
    const rgbz_v16 gm6 = G6 * (float)0.25;
    const rgbz_v16 gm7 = G7 * (float)0.3333333333333333;
    rgbz_v16 smin = gm0;
    smin = M2_MIN(gm1, smin);
    smin = M2_MIN(gm2, smin);
    smin = M2_MIN(gm3, smin);
    smin = M2_MIN(gm4, smin);
    smin = M2_MIN(gm5, smin);
    smin = M2_MIN(gm6, smin);
    smin = M2_MIN(gm7, smin);
    rgbz_v16 ssg = M2_MAX(smin, floor_);
    if (REL) {
        rgbz_v16 ssum = gm0;
        ssum = ssum + gm1;
        ssum = ssum + gm2;
        ssum = ssum + gm3;
        ssum = ssum + gm4;
        ssum = ssum + gm5;
        ssum = ssum + gm6;
        ssum = ssum + gm7;
        const rgbz_v16 srf = (rel * ssum) / (float)8;
        ssg = M2_MAX(srf, ssg);
    }
    const rgbz_v16 sninv = -(1.0f / (2.0f * (ssg * ssg)));
    const rgbz_v16 x0 = (gm0 * gm0) * sninv;
    const rgbz_v16 x1 = (gm1 * gm1) * sninv;
    const rgbz_v16 x2 = (gm2 * gm2) * sninv;
    const rgbz_v16 x3 = (gm3 * gm3) * sninv;
    const rgbz_v16 x4 = (gm4 * gm4) * sninv;
    const rgbz_v16 x5 = (gm5 * gm5) * sninv;
    const rgbz_v16 x6 = (gm6 * gm6) * sninv;
    const rgbz_v16 x7 = (gm7 * gm7) * sninv;
    const rgbz_v16 et0 = x0 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et1 = x1 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et2 = x2 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et3 = x3 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et4 = x4 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et5 = x5 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et6 = x6 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et7 = x7 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en0 = M2_RINT(x0 * 1.44269504f, et0);
    const rgbz_v16 en1 = M2_RINT(x1 * 1.44269504f, et1);
    const rgbz_v16 en2 = M2_RINT(x2 * 1.44269504f, et2);
    const rgbz_v16 en3 = M2_RINT(x3 * 1.44269504f, et3);
    const rgbz_v16 en4 = M2_RINT(x4 * 1.44269504f, et4);
    const rgbz_v16 en5 = M2_RINT(x5 * 1.44269504f, et5);
    const rgbz_v16 en6 = M2_RINT(x6 * 1.44269504f, et6);
    const rgbz_v16 en7 = M2_RINT(x7 * 1.44269504f, et7);
    const rgbz_v16 ey0 = M2_XMC1(x0, en0) - en0 * -2.12194440e-4f;
    const rgbz_v16 ey1 = M2_XMC1(x1, en1) - en1 * -2.12194440e-4f;
    const rgbz_v16 ey2 = M2_XMC1(x2, en2) - en2 * -2.12194440e-4f;
    const rgbz_v16 ey3 = M2_XMC1(x3, en3) - en3 * -2.12194440e-4f;
    const rgbz_v16 ey4 = M2_XMC1(x4, en4) - en4 * -2.12194440e-4f;
    const rgbz_v16 ey5 = M2_XMC1(x5, en5) - en5 * -2.12194440e-4f;
    const rgbz_v16 ey6 = M2_XMC1(x6, en6) - en6 * -2.12194440e-4f;
    const rgbz_v16 ey7 = M2_XMC1(x7, en7) - en7 * -2.12194440e-4f;
    rgbz_v16 ep0 = 1.0f / 120 + ey0 * (1.0f / 720);
    rgbz_v16 ep1 = 1.0f / 120 + ey1 * (1.0f / 720);
    rgbz_v16 ep2 = 1.0f / 120 + ey2 * (1.0f / 720);
    rgbz_v16 ep3 = 1.0f / 120 + ey3 * (1.0f / 720);
    rgbz_v16 ep4 = 1.0f / 120 + ey4 * (1.0f / 720);
    rgbz_v16 ep5 = 1.0f / 120 + ey5 * (1.0f / 720);
    rgbz_v16 ep6 = 1.0f / 120 + ey6 * (1.0f / 720);
    rgbz_v16 ep7 = 1.0f / 120 + ey7 * (1.0f / 720);
    ep0 = 1.0f / 24 + ey0 * ep0;
    ep1 = 1.0f / 24 + ey1 * ep1;
    ep2 = 1.0f / 24 + ey2 * ep2;
    ep3 = 1.0f / 24 + ey3 * ep3;
    ep4 = 1.0f / 24 + ey4 * ep4;
    ep5 = 1.0f / 24 + ey5 * ep5;
    ep6 = 1.0f / 24 + ey6 * ep6;
    ep7 = 1.0f / 24 + ey7 * ep7;
    ep0 = 1.0f / 6 + ey0 * ep0;
    ep1 = 1.0f / 6 + ey1 * ep1;
    ep2 = 1.0f / 6 + ey2 * ep2;
    ep3 = 1.0f / 6 + ey3 * ep3;
    ep4 = 1.0f / 6 + ey4 * ep4;
    ep5 = 1.0f / 6 + ey5 * ep5;
    ep6 = 1.0f / 6 + ey6 * ep6;
    ep7 = 1.0f / 6 + ey7 * ep7;
    ep0 = 0.5f + ey0 * ep0;
    ep1 = 0.5f + ey1 * ep1;
    ep2 = 0.5f + ey2 * ep2;
    ep3 = 0.5f + ey3 * ep3;
    ep4 = 0.5f + ey4 * ep4;
    ep5 = 0.5f + ey5 * ep5;
    ep6 = 0.5f + ey6 * ep6;
    ep7 = 0.5f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    ep0 = 1.0f + ey0 * ep0;
    ep1 = 1.0f + ey1 * ep1;
    ep2 = 1.0f + ey2 * ep2;
    ep3 = 1.0f + ey3 * ep3;
    ep4 = 1.0f + ey4 * ep4;
    ep5 = 1.0f + ey5 * ep5;
    ep6 = 1.0f + ey6 * ep6;
    ep7 = 1.0f + ey7 * ep7;
    const rgbz_v16 ga0 = M2_EXPOUT(x0, ep0, et0, en0);
    const rgbz_v16 ga1 = M2_EXPOUT(x1, ep1, et1, en1);
    const rgbz_v16 ga2 = M2_EXPOUT(x2, ep2, et2, en2);
    const rgbz_v16 ga3 = M2_EXPOUT(x3, ep3, et3, en3);
    const rgbz_v16 ga4 = M2_EXPOUT(x4, ep4, et4, en4);
    const rgbz_v16 ga5 = M2_EXPOUT(x5, ep5, et5, en5);
    const rgbz_v16 ga6 = M2_EXPOUT(x6, ep6, et6, en6);
    const rgbz_v16 ga7 = M2_EXPOUT(x7, ep7, et7, en7);
    const rgbz_v16 gm8 = G8 * (float)0.125;
    const rgbz_v16 gm9 = G9 * (float)0.125;
    const rgbz_v16 gm10 = G10 * (float)0.1111111111111111;
    const rgbz_v16 gm11 = G11 * (float)0.14285714285714285;
    rgbz_v16 gmin = gm8;
    gmin = M2_MIN(gm9, gmin);
    gmin = M2_MIN(gm10, gmin);
    gmin = M2_MIN(gm11, gmin);
    rgbz_v16 gsg = M2_MAX(gmin, floor_);
    if (REL) {
        rgbz_v16 gsum = gm8;
        gsum = gsum + gm9;
        gsum = gsum + gm10;
        gsum = gsum + gm11;
        const rgbz_v16 grf = (rel * gsum) / (float)4;
        gsg = M2_MAX(grf, gsg);
    }
    const rgbz_v16 gninv = -(1.0f / (2.0f * (gsg * gsg)));
    const rgbz_v16 x8 = (gm8 * gm8) * gninv;
    const rgbz_v16 x9 = (gm9 * gm9) * gninv;
    const rgbz_v16 x10 = (gm10 * gm10) * gninv;
    const rgbz_v16 x11 = (gm11 * gm11) * gninv;
    const rgbz_v16 et8 = x8 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et9 = x9 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et10 = x10 * 1.44269504f + 12582912.0f;
    const rgbz_v16 et11 = x11 * 1.44269504f + 12582912.0f;
    const rgbz_v16 en8 = M2_RINT(x8 * 1.44269504f, et8);
    const rgbz_v16 en9 = M2_RINT(x9 * 1.44269504f, et9);
    const rgbz_v16 en10 = M2_RINT(x10 * 1.44269504f, et10);
    const rgbz_v16 en11 = M2_RINT(x11 * 1.44269504f, et11);
    const rgbz_v16 ey8 = M2_XMC1(x8, en8) - en8 * -2.12194440e-4f;
    const rgbz_v16 ey9 = M2_XMC1(x9, en9) - en9 * -2.12194440e-4f;
    const rgbz_v16 ey10 = M2_XMC1(x10, en10) - en10 * -2.12194440e-4f;
    const rgbz_v16 ey11 = M2_XMC1(x11, en11) - en11 * -2.12194440e-4f;
    rgbz_v16 ep8 = 1.0f / 120 + ey8 * (1.0f / 720);
    rgbz_v16 ep9 = 1.0f / 120 + ey9 * (1.0f / 720);
    rgbz_v16 ep10 = 1.0f / 120 + ey10 * (1.0f / 720);
    rgbz_v16 ep11 = 1.0f / 120 + ey11 * (1.0f / 720);
    ep8 = 1.0f / 24 + ey8 * ep8;
    ep9 = 1.0f / 24 + ey9 * ep9;
    ep10 = 1.0f / 24 + ey10 * ep10;
    ep11 = 1.0f / 24 + ey11 * ep11;
    ep8 = 1.0f / 6 + ey8 * ep8;
    ep9 = 1.0f / 6 + ey9 * ep9;
    ep10 = 1.0f / 6 + ey10 * ep10;
    ep11 = 1.0f / 6 + ey11 * ep11;
    ep8 = 0.5f + ey8 * ep8;
    ep9 = 0.5f + ey9 * ep9;
    ep10 = 0.5f + ey10 * ep10;
    ep11 = 0.5f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    ep8 = 1.0f + ey8 * ep8;
    ep9 = 1.0f + ey9 * ep9;
    ep10 = 1.0f + ey10 * ep10;
    ep11 = 1.0f + ey11 * ep11;
    const rgbz_v16 ga8 = M2_EXPOUT(x8, ep8, et8, en8);
    const rgbz_v16 ga9 = M2_EXPOUT(x9, ep9, et9, en9);
    const rgbz_v16 ga10 = M2_EXPOUT(x10, ep10, et10, en10);
    const rgbz_v16 ga11 = M2_EXPOUT(x11, ep11, et11, en11);
    const rgbz_v16 c0 = rgbz_v16_load(src[0] + j0);
    const rgbz_v16 c1 = rgbz_v16_load(src[1] + j0);
    const rgbz_v16 c2 = rgbz_v16_load(src[2] + j0);
    const rgbz_v16 c3 = rgbz_v16_load(src[3] + j0);
    const rgbz_v16 c4 = rgbz_v16_load(src[4] + j0);
    const rgbz_v16 c5 = rgbz_v16_load(src[5] + j0);
    const rgbz_v16 c6 = rgbz_v16_load(src[6] + j0);
    const rgbz_v16 c7 = rgbz_v16_load(src[7] + j0);
    rgbz_v16 S0 = rgbz_v16_set(1.0f);
    rgbz_v16 S1 = rgbz_v16_set(1.0f);
    rgbz_v16 S2 = rgbz_v16_set(1.0f);
    rgbz_v16 S3 = rgbz_v16_set(1.0f);
    rgbz_v16 S4 = rgbz_v16_set(1.0f);
    rgbz_v16 S5 = rgbz_v16_set(1.0f);
    rgbz_v16 S6 = rgbz_v16_set(1.0f);
    rgbz_v16 S7 = rgbz_v16_set(1.0f);
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c1); S0 = M2_ADD(S0, e); S1 = S1 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c2); S0 = M2_ADD(S0, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c3); S0 = M2_ADD(S0, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c4); S0 = M2_ADD(S0, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c5); S0 = M2_ADD(S0, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c6); S0 = M2_ADD(S0, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c0 - c7); S0 = M2_ADD(S0, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c2); S1 = M2_ADD(S1, e); S2 = S2 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c3); S1 = M2_ADD(S1, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c4); S1 = M2_ADD(S1, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c5); S1 = M2_ADD(S1, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c6); S1 = M2_ADD(S1, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c1 - c7); S1 = M2_ADD(S1, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c3); S2 = M2_ADD(S2, e); S3 = S3 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c4); S2 = M2_ADD(S2, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c5); S2 = M2_ADD(S2, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c6); S2 = M2_ADD(S2, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c2 - c7); S2 = M2_ADD(S2, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c4); S3 = M2_ADD(S3, e); S4 = S4 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c5); S3 = M2_ADD(S3, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c6); S3 = M2_ADD(S3, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c3 - c7); S3 = M2_ADD(S3, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c5); S4 = M2_ADD(S4, e); S5 = S5 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c6); S4 = M2_ADD(S4, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c4 - c7); S4 = M2_ADD(S4, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c6); S5 = M2_ADD(S5, e); S6 = S6 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c5 - c7); S5 = M2_ADD(S5, e); S7 = S7 + e; }
    { const rgbz_v16 e = rgbz_v16_abs(c6 - c7); S6 = M2_ADD(S6, e); S7 = S7 + e; }
    rgbz_v16 den, num = rgbz_v16_set(0.0f);
    den = ((((float)0.01831563888873418) / S0) * ga10) * (((ga0 + ga2) + ga4) * (float)0.3333333333333333);
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S1) * ga8) * (ga0 * (float)1.0); den = den + w; num = num + w * (c1 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S2) * ga11) * (((ga0 + ga3) + ga5) * (float)0.3333333333333333); den = den + w; num = num + w * (c2 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S3) * ga9) * (ga2 * (float)1.0); den = den + w; num = num + w * (c3 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S4) * ga9) * (ga3 * (float)1.0); den = den + w; num = num + w * (c4 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S5) * ga11) * (((ga1 + ga2) + ga6) * (float)0.3333333333333333); den = den + w; num = num + w * (c5 - c0); }
    { const rgbz_v16 w = ((((float)0.1353352832366127) / S6) * ga8) * (ga1 * (float)1.0); den = den + w; num = num + w * (c6 - c0); }
    { const rgbz_v16 w = ((((float)0.01831563888873418) / S7) * ga10) * (((ga1 + ga3) + ga7) * (float)0.3333333333333333); den = den + w; num = num + w * (c7 - c0); }
    const rgbz_v16i ok = den > 0.0f;
    const rgbz_v16 q = rgbz_v16_sel(ok, den, rgbz_v16_set(1.0f));
    rgbz_v16 res = rgbz_v16_sel(ok, c0 + num / q, c0);
    if (!M2_ALLPOS(den)) {
        /* a weight sum not > 0 (every weight underflowed, or a non-finite input):
           the plain mean of the candidates (rgbz_mean_block) */
        rgbz_v16 s = c1 - c0;
        s = s + (c2 - c0);
        s = s + (c3 - c0);
        s = s + (c4 - c0);
        s = s + (c5 - c0);
        s = s + (c6 - c0);
        s = s + (c7 - c0);
        res = rgbz_v16_sel(ok, res, c0 + s / (float)8);
    }
    rgbz_v16_store(out, res);
}


/*
 * The n sites of a block (v tap-major, recon_core.template.h) through the function of plan k
 * (an index of rgbz_m2_plan_bytes), RGBZ_M2_W at a time; the last vector of a block whose n
 * is not a multiple of it runs on a copy of its taps padded with zeros, and only its results
 * for the n sites are kept.
 */
M2_ATTR static void M2_FN(rgbz_m2_run)(int k, const float *const *v, int n, float floor_,
                                       float rel, float *restrict r)
{
    const rgbz_v16 fl = rgbz_v16_set(floor_), rl = rgbz_v16_set(rel);
    const int REL = rel > 0.0f;
    const int nt = rgbz_m2_ntaps[k];
    for (int j0 = 0; j0 < n; j0 += RGBZ_M2_W) {
        const float *pp[RGBZ_MAX_TAPS];
        float pad[RGBZ_MAX_TAPS][RGBZ_M2_W], res[RGBZ_M2_W];
        const int m = n - j0 < RGBZ_M2_W ? n - j0 : RGBZ_M2_W;
        /* a whole vector reads its taps at v[t] + j0; the last, padded, at pp[t] + 0 */
        const float *const *src = v;
        int at = j0;
        if (m < RGBZ_M2_W) {
            for (int t = 0; t < nt; t++) {
                for (int i = 0; i < RGBZ_M2_W; i++) pad[t][i] = i < m ? v[t][j0 + i] : 0.0f;
                pp[t] = pad[t];
            }
            src = pp;
            at = 0;
        }
        float *o = m == RGBZ_M2_W ? r + j0 : res;
#define RGBZ_M2_CASE_(K)                                                                  \
        case K:                                                                           \
            if (REL) M2_FN(rgbz_m2_site##K)(src, at, fl, rl, 1, o);                       \
            else M2_FN(rgbz_m2_site##K)(src, at, fl, rl, 0, o);                           \
            break;
        switch (k) {
            RGBZ_M2_CASES_
        default: break;
        }
#undef RGBZ_M2_CASE_
        if (m < RGBZ_M2_W) memcpy(r + j0, res, (size_t)m * sizeof(float));
    }
}

/* the instance's parameters, for the next one */
#undef M2_FN
#undef M2_ATTR
#undef M2_MIN
#undef M2_MAX
#undef M2_ADD
#undef M2_XMC1
#undef M2_ALLPOS
#undef M2_RINT
#undef M2_EXPOUT
