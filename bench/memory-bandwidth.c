/*
 * One core's memory bandwidth, to judge skinning at 1M points against (docs/benchmarks.md):
 * the shapes of traffic a skinning kernel makes, each over arrays far larger than the caches,
 * best of several runs, one thread.
 *   read     sum of a 256 MB float array (loads only)
 *   copy     b[i] = a[i] (one read stream, one write stream: the write also reads the line first)
 *   skinlike read 48 bytes and write 24 bytes per element, the LBS kernel's traffic per point
 * Build and run: cc -O3 -march=native bench/memory-bandwidth.c -o /tmp/membw && /tmp/membw
 */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

int main(void) {
    const size_t n = (size_t) 64 << 20; /* 64 Mi floats = 256 MB */
    float *a = malloc(n * sizeof(float)), *b = malloc(n * sizeof(float));
    if (!a || !b) {
        return 1;
    }
    for (size_t i = 0; i < n; i++) {
        a[i] = (float) (i & 1023);
        b[i] = 0;
    }
    double best_read = 1e9, best_copy = 1e9, best_skin = 1e9;
    volatile float sink = 0;
    for (int r = 0; r < 5; r++) {
        double t0 = now();
        float s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0;
        for (size_t i = 0; i < n; i += 8) {
            s0 += a[i]; s1 += a[i + 1]; s2 += a[i + 2]; s3 += a[i + 3];
            s4 += a[i + 4]; s5 += a[i + 5]; s6 += a[i + 6]; s7 += a[i + 7];
        }
        sink += s0 + s1 + s2 + s3 + s4 + s5 + s6 + s7;
        double t1 = now();
        for (size_t i = 0; i < n; i++) {
            b[i] = a[i];
        }
        double t2 = now();
        /* 12 floats read, 6 written per element: 2/3 of a's length read, 1/3 of b's written. */
        size_t m = n / 12;
        for (size_t i = 0; i < m; i++) {
            const float *in = a + 12 * i;
            float *out = b + 6 * i;
            float x = in[0] + in[3] + in[6] + in[9], y = in[1] + in[4] + in[7] + in[10];
            float z = in[2] + in[5] + in[8] + in[11];
            out[0] = x; out[1] = y; out[2] = z; out[3] = x; out[4] = y; out[5] = z;
        }
        double t3 = now();
        if (t1 - t0 < best_read) best_read = t1 - t0;
        if (t2 - t1 < best_copy) best_copy = t2 - t1;
        if (t3 - t2 < best_skin) best_skin = t3 - t2;
    }
    double bytes = (double) n * sizeof(float);
    printf("read      %6.1f GB/s\n", bytes / best_read / 1e9);
    printf("copy      %6.1f GB/s (read + write, not counting the write-allocate read)\n", 2 * bytes / best_copy / 1e9);
    size_t m = n / 12;
    printf("skinlike  %6.1f GB/s, %.2f ns per element of 48 bytes read and 24 written\n",
           (double) m * 72 / best_skin / 1e9, best_skin / m * 1e9);
    return sink == 12345.0f;
}
