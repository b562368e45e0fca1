/*
 * sim_rng.h -- the counter-based random numbers of the sensor simulation (sim.c), internal.
 *
 * Every random number is a pure function of a 128-bit key (the seed and the stream, sim.c's
 * rgbz_sim_key) and a 128-bit counter (which pixel or tap, which variate, which attempt):
 * Threefry4x32 with 20 rounds (Salmon, Moraes, Dror and Shaw, "Parallel random numbers: as
 * easy as 1, 2, 3", SC 2011; Random123's rotations and key schedule), checked against
 * Random123's known-answer vectors (tests/simulation/test_pixels.py). So the draws of a
 * sample do not depend on which thread computes it, nor on how many there are, nor on the
 * order. Threefry rather than Philox: additions, rotations and exclusive ors vectorise in
 * plain C, 32-bit multiplications with their high halves do not (3.8 times as fast with
 * AVX-512 in a loop over blocks).
 *
 * From one block (four 32-bit words), each uniform from two words with 53 random bits:
 *   two independent standard normals (Box-Muller)                       sim_normals
 *   one uniform of the inversion of a small Poisson mean                 sim_inv_start
 *   one attempt of PTRS (a uniform U and a uniform V)                    sim.c
 * (Poisson: below a mean of 10 the inversion of the distribution function, from 10 on
 * Hormann's PTRS, the algorithm of NumPy's Generator.poisson there.)
 *
 * The transforms use their own log, exp and sine/cosine of 2 pi u (fdlibm's polynomials:
 * within about 1 ulp of the C library's), written without branches so that a loop over the
 * samples of a row vectorises; every operation is an IEEE one (sim.c is compiled with
 * -ffp-contract=off), so every instruction set gives the same bits.
 */
#ifndef RGBZ_SIM_RNG_H
#define RGBZ_SIM_RNG_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* ---- keys ---- */

/* SplitMix64's finaliser: a bijection of 64-bit words that mixes every input bit */
static inline uint64_t sim_mix64(uint64_t z)
{
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* ---- Threefry4x32-20 ---- */

static inline uint32_t sim_rotl(uint32_t x, int n) { return (x << n) | (x >> (32 - n)); }

#define SIM_MIX_A(r0, r1)                                                                   \
    X0 += X1; X1 = sim_rotl(X1, r0); X1 ^= X0; X2 += X3; X3 = sim_rotl(X3, r1); X3 ^= X2;
#define SIM_MIX_B(r0, r1)                                                                   \
    X0 += X3; X3 = sim_rotl(X3, r0); X3 ^= X0; X2 += X1; X1 = sim_rotl(X1, r1); X1 ^= X2;
#define SIM_INJECT(s)                                                                       \
    X0 += ks[(s) % 5]; X1 += ks[((s) + 1) % 5]; X2 += ks[((s) + 2) % 5];                    \
    X3 += ks[((s) + 3) % 5] + (uint32_t)(s);

/* the block of counter (c0, c1, c2, c3) and key k[4] into w0..w3: Threefry4x32 with 20
   rounds, Random123's rotation constants and key schedule */
static inline void sim_block(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t c3,
                             const uint32_t k[4], uint32_t *w0, uint32_t *w1, uint32_t *w2,
                             uint32_t *w3)
{
    const uint32_t ks[5] = {k[0], k[1], k[2], k[3], 0x1BD11BDAu ^ k[0] ^ k[1] ^ k[2] ^ k[3]};
    uint32_t X0 = c0 + ks[0], X1 = c1 + ks[1], X2 = c2 + ks[2], X3 = c3 + ks[3];
    SIM_MIX_A(10, 26) SIM_MIX_B(11, 21) SIM_MIX_A(13, 27) SIM_MIX_B(23, 5) SIM_INJECT(1)
    SIM_MIX_A(6, 20) SIM_MIX_B(17, 11) SIM_MIX_A(25, 10) SIM_MIX_B(18, 20) SIM_INJECT(2)
    SIM_MIX_A(10, 26) SIM_MIX_B(11, 21) SIM_MIX_A(13, 27) SIM_MIX_B(23, 5) SIM_INJECT(3)
    SIM_MIX_A(6, 20) SIM_MIX_B(17, 11) SIM_MIX_A(25, 10) SIM_MIX_B(18, 20) SIM_INJECT(4)
    SIM_MIX_A(10, 26) SIM_MIX_B(11, 21) SIM_MIX_A(13, 27) SIM_MIX_B(23, 5) SIM_INJECT(5)
    *w0 = X0;
    *w1 = X1;
    *w2 = X2;
    *w3 = X3;
}

/* a uniform in [0, 1) from two words: 27 + 26 random bits (NumPy's next_double layout) */
static inline double sim_u53(uint32_t a, uint32_t b)
{
    return ((double)(int32_t)(a >> 5) * 67108864.0 + (double)(int32_t)(b >> 6)) *
           (1.0 / 9007199254740992.0);
}

/* ---- log(x), x a positive normal double: fdlibm's e_log.c on the reduced argument, branch-free ---- */
static inline double sim_log_any(double x)
{
    static const double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10,
                        Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01,
                        Lg3 = 2.857142874366239149e-01, Lg4 = 2.222219843214978396e-01,
                        Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01,
                        Lg7 = 1.479819860511658591e-01;
    uint64_t bits, mbits, ebits;
    double m, k;
    memcpy(&bits, &x, sizeof bits);
    /* the biased exponent as a double through the 2^52 trick (no integer conversion) */
    ebits = (bits >> 52) | 0x4330000000000000ull;
    memcpy(&k, &ebits, sizeof k);
    k = k - 4503599627370496.0 - 1023.0;
    mbits = (bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull;
    memcpy(&m, &mbits, sizeof m);                        /* x = m 2^k, m in [1, 2) */
    const int big = m > 1.4142135623730951;
    m = big ? m * 0.5 : m;                               /* m in [sqrt(1/2), sqrt(2)) */
    k = big ? k + 1.0 : k;
    const double f = m - 1.0;
    const double s = f / (2.0 + f);
    const double z = s * s, w = z * z;
    const double t1 = w * (Lg2 + w * (Lg4 + w * Lg6));
    const double t2 = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
    const double R = t2 + t1;
    const double hfsq = 0.5 * f * f;
    return k * ln2_hi - ((hfsq - (s * (hfsq + R) + k * ln2_lo)) - f);
}

/* ---- sin and cos of 2 pi u, u in [0, 1): fdlibm's kernels on [0, pi/4], branch-free ---- */
static inline void sim_sincos2pi(double u, double *sn, double *cs)
{
    static const double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                        S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                        S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10,
                        C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                        C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                        C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11,
                        half_pi = 1.57079632679489661923;
    const double t = 4.0 * u;                            /* exact */
    const int32_t q = (int32_t)t;                        /* the quadrant, 0..3 (t >= 0) */
    const double r = t - (double)q;                      /* [0, 1), exact */
    const int flip = r > 0.5;
    const double x = (flip ? 1.0 - r : r) * half_pi;     /* [0, pi/4] */
    const double z = x * x;
    const double sx = x + z * x * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    const double rc = z * (C1 + z * (C2 + z * C3)) + z * z * z * z * (C4 + z * (C5 + z * C6));
    const double hz = 0.5 * z, w = 1.0 - hz;
    const double cx = w + (((1.0 - w) - hz) + z * rc);
    /* phi = r pi / 2: (sin, cos) = (sx, cx), or (cx, sx) past pi / 4 */
    const double sp = flip ? cx : sx, cp = flip ? sx : cx;
    /* turned by q quarter turns */
    const double s_even = (q & 2) ? -sp : sp, c_even = (q & 2) ? -cp : cp;
    const double s_odd = (q & 2) ? -cp : cp, c_odd = (q & 2) ? sp : -sp;
    *sn = (q & 1) ? s_odd : s_even;
    *cs = (q & 1) ? c_odd : c_even;
}

/* two independent standard normals of the block (c0, c1, c2, c3) (Box-Muller; 1 - u0 lies
   in (0, 1]) */
static inline void sim_normals(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t c3,
                               const uint32_t key[4], double *z0, double *z1)
{
    uint32_t w0, w1, w2, w3;
    double s, c;
    sim_block(c0, c1, c2, c3, key, &w0, &w1, &w2, &w3);
    const double rad = sqrt(-2.0 * sim_log_any(1.0 - sim_u53(w0, w1)));
    sim_sincos2pi(sim_u53(w2, w3), &s, &c);
    *z0 = rad * c;
    *z1 = rad * s;
}

/* ---- Poisson (PTRS) ---- */

/* log Gamma(x) of an integer x >= 1: the log of (x - 1)! below 7, Stirling's series from 7
   (NumPy's random_loggam there), branch-free */
static inline double sim_loggam_int(double x)
{
    static const double a0 = 8.333333333333333e-02, a1 = -2.777777777777778e-03,
                        a2 = 7.936507936507937e-04, a3 = -5.952380952380952e-04,
                        a4 = 8.417508417508418e-04, a5 = -1.917526917526918e-03,
                        a6 = 6.410256410256410e-03, a7 = -2.955065359477124e-02,
                        a8 = 1.796443723688307e-01, a9 = -1.39243221690590e+00,
                        half_lg2pi = 0.5 * 1.8378770664093453e+00;
    const double x0 = x < 7.0 ? 7.0 : x;
    const double r = 1.0 / x0, x2 = r * r;
    const double gl0 =
        a0 + x2 * (a1 + x2 * (a2 + x2 * (a3 + x2 * (a4 + x2 * (a5 + x2 * (a6 + x2 * (a7 +
        x2 * (a8 + x2 * a9))))))));
    const double big = gl0 / x0 + half_lg2pi + (x0 - 0.5) * sim_log_any(x0) - x0;
    /* log((x - 1)!) for x = 1..6: the factorial exactly, by selects */
    double fact = x > 2.5 ? 2.0 : 1.0;
    fact *= x > 3.5 ? 3.0 : 1.0;
    fact *= x > 4.5 ? 4.0 : 1.0;
    fact *= x > 5.5 ? 5.0 : 1.0;
    return x < 6.5 ? sim_log_any(fact) : big;
}

/* the constants of PTRS for a mean lam >= 10 */
typedef struct {
    double b, a, invalpha, vr;
} sim_ptrs;

static inline void sim_ptrs_consts(double lam, double *b, double *a, double *invalpha,
                                   double *vr)
{
    const double slam = sqrt(lam);
    *b = 0.931 + 2.53 * slam;
    *a = -0.059 + 0.02483 * *b;
    *invalpha = 1.1239 + 1.1328 / (*b - 3.4);
    *vr = 0.9277 - 3.6224 / (*b - 2.0);
}

/* e^x for x in [-745, 0]: fdlibm's e_exp.c (within 1 ulp), branch-free */
static inline double sim_exp_neg(double x)
{
    static const double P1 = 1.66666666666666019037e-01, P2 = -2.77777777770155933842e-03,
                        P3 = 6.61375632143793436117e-05, P4 = -1.65339022054652515390e-06,
                        P5 = 4.13813679705723846039e-08, ln2_hi = 6.93147180369123816490e-01,
                        ln2_lo = 1.90821492927058770002e-10, invln2 = 1.44269504088896338700e+00;
    x = x > -745.0 ? x : -745.0;
    const double k = floor(x * invln2 + 0.5);           /* -1075..0 */
    const double hi = x - k * ln2_hi, lo = k * ln2_lo;
    const double r = hi - lo, t = r * r;
    const double c = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))));
    const double y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    /* y 2^k as two factors 2^(k/2), each normal (the exponent field built from k + 1023
       through the 2^52 trick) */
    const double k1 = floor(k * 0.5), k2 = k - k1;
    double f1 = k1 + 4503599627370496.0 + 1023.0, f2 = k2 + 4503599627370496.0 + 1023.0;
    uint64_t b1, b2;
    memcpy(&b1, &f1, sizeof b1);
    memcpy(&b2, &f2, sizeof b2);
    b1 <<= 52;
    b2 <<= 52;
    memcpy(&f1, &b1, sizeof f1);
    memcpy(&f2, &b2, sizeof f2);
    return y * f1 * f2;
}

/* the inversion of small Poisson means (lam < 10): the smallest x with u <= F(x), the
   distribution function summed term by term (p_k = p_{k-1} lam / k), u one uniform of the
   block (c0, c1, c2, 0); SIM_INV_STEPS terms in a vectorised pass, the rest (rare) after */
enum { SIM_INV_STEPS = 24 };

static inline void sim_inv_start(double lam, uint32_t c0, uint32_t c1, uint32_t c2,
                                 const uint32_t key[4], double *x, double *u, double *p,
                                 double *F)
{
    static const double inv[SIM_INV_STEPS + 1] = {
        0.0, 1.0, 1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5, 1.0 / 6, 1.0 / 7, 1.0 / 8, 1.0 / 9,
        1.0 / 10, 1.0 / 11, 1.0 / 12, 1.0 / 13, 1.0 / 14, 1.0 / 15, 1.0 / 16, 1.0 / 17,
        1.0 / 18, 1.0 / 19, 1.0 / 20, 1.0 / 21, 1.0 / 22, 1.0 / 23, 1.0 / 24};
    uint32_t w0, w1, w2, w3;
    sim_block(c0, c1, c2, 0, key, &w0, &w1, &w2, &w3);
    (void)w2;
    (void)w3;
    const double uu = sim_u53(w0, w1);
    double pp = sim_exp_neg(-lam), FF = pp, xx = 0.0;
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC unroll 24
#endif
    for (int k = 1; k <= SIM_INV_STEPS; k++) {
        xx += uu > FF ? 1.0 : 0.0;
        pp = pp * (lam * inv[k]);
        FF = FF + pp;
    }
    *x = xx;
    *u = uu;
    *p = pp;
    *F = FF;
}

/* the rest of the inversion once u > F(SIM_INV_STEPS - 1) (x = SIM_INV_STEPS, p and F the
   terms and sum up to it): term by term until u <= F, or until the terms no longer move F
   (u above the sum's largest value in floating point) */
static inline double sim_inv_finish(double lam, double u, double p, double F)
{
    double j = SIM_INV_STEPS;
    while (u > F) {
        j += 1.0;
        p = p * (lam * (1.0 / j));
        const double next = F + p;
        if (next == F) break;
        F = next;
    }
    return j;
}

#endif /* RGBZ_SIM_RNG_H */
