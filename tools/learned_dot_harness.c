/*
 * learned_dot_harness.c -- the learned kernel's dense dot product (csrc/learned_hash.template.h,
 * lrn_dense_dot) on its own: synthetic window rows and weights in the cache, the time per site
 * and a hash of the results' bits (equal hashes: the same sums bit for bit, whatever the build).
 *
 *   gcc -I csrc -DNDEBUG -std=c99 -O3 -fopenmp -fno-math-errno -fno-trapping-math \
 *       -Wno-unknown-pragmas -Wno-psabi -Wno-unused-function -o /tmp/dot tools/learned_dot_harness.c -lm
 *   /tmp/dot [PX] [COLS] [BUCKETS]      (defaults 2 4096 216: Mask1's period, a strip, the
 *                                        shipped filters' bucket count)
 *
 * The flags are the kernels' (compile_commands.json of the build); add -DRGBZ_NO_CLONES and
 * -mavx2 (or nothing, or -mavx512f) to build the function for one instruction set only.
 * Radius 3 (7 window rows), float32 arithmetic, uint16 frames' instance.
 */
#define _POSIX_C_SOURCE 199309L
#include "learned.c"
#include <stdio.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

int main(int argc, char **argv)
{
    const int px = argc > 1 ? atoi(argv[1]) : 2;
    const int cols = argc > 2 ? atoi(argv[2]) : 4096;
    const int nb = argc > 3 ? atoi(argv[3]) : 216;
    const int R = 3, rows = 2 * R + 1;
    if (px < 1 || cols < 64 || nb < 1) {
        fprintf(stderr, "usage: %s [PX >= 1] [COLS >= 64] [BUCKETS >= 1]\n", argv[0]);
        return 2;
    }
    float *buf = malloc((size_t)rows * (size_t)(cols + 64) * sizeof *buf);
    float *wd = malloc((size_t)nb * (size_t)rows * 8 * sizeof *wd);
    const int n = (cols - 16) / px;
    int32_t *bucket = malloc((size_t)n * sizeof *bucket);
    float *res = malloc((size_t)n * sizeof *res);
    if (!buf || !wd || !bucket || !res) return 1;
    for (long i = 0; i < (long)rows * (cols + 64); i++) buf[i] = (float)(i % 97);
    for (long i = 0; i < (long)nb * rows * 8; i++) wd[i] = (float)((i * 7) % 13) * 0.01f;
    const float *rp[2 * RGBZ_LEARNED_MAX_RADIUS + 1];
    for (int i = 0; i < rows; i++) rp[i] = buf + (long)i * (cols + 64) + 8;
    unsigned s = 1;
    for (int j = 0; j < n; j++) {
        s = s * 1103515245u + 12345u;
        bucket[j] = (int32_t)((s >> 8) % (unsigned)nb);
    }
    const int reps = 20000000 / n + 1;
    lrn_dense_dot_u16_f32(rp, 8, px, n, wd, R, bucket, res);   /* warm-up */
    const double t0 = now();
    for (int r = 0; r < reps; r++) lrn_dense_dot_u16_f32(rp, 8, px, n, wd, R, bucket, res);
    const double t = (now() - t0) / ((double)reps * n);
    uint64_t h = 1469598103934665603ull;
    for (int j = 0; j < n; j++) {
        uint32_t u;
        memcpy(&u, res + j, sizeof u);
        h = (h ^ u) * 1099511628211ull;
    }
    printf("px %d, %d columns, %d buckets: %.2f ns a site; results' hash %016llx\n", px, cols,
           nb, t * 1e9, (unsigned long long)h);
    free(buf);
    free(wd);
    free(bucket);
    free(res);
    return 0;
}
