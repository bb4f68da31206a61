/* The C reference of benchmarks/bench_kernels.py: Dormand-Prince 5(4) on a uniform power-law chain.
 *
 * The scheme of ringchain.numerics.kernels._dopri5_group, written as a plain C loop, operation for
 * operation: the same coefficients (Hairer, Norsett and Wanner, Solving ODEs I, Sec. II.5), first same
 * as last, Hairer's initial step (HINIT), the error in the max norm over the components,
 * |err_i| / (atol_i + rtol max(|y_i|, |y_new_i|)), and the same controller: h *= 0.9 err^(-1/5) within
 * [0.2, 10], no growth on the step after a rejection, a non-finite error divides h by 5.  No samples are
 * taken on the way (the benchmark compares the final state), so the continuous extension is left out.
 *
 * The chain: N sites of mass m, link k joining site k to site k + 1 (free ends, no gravity), each link
 * the unilateral contact F = K delta^n for delta = x[k+1] - x[k] > 0 and nothing otherwise
 * (ringchain's convention: extension positive, ARCHITECTURE.md), n = 3/2 (Hertz).  State
 * y = [x (N), u (N)].
 *
 * Usage: dopri5_chain INPUT OUTPUT.  INPUT holds little-endian doubles:
 *   N, K, n, m, rtol, t_end, y0 (2N values), atol (2N values);
 * OUTPUT receives: status, evaluations, accepted steps, rejected steps, seconds of the time loop,
 * then the final state (2N values).  The time loop is timed with CLOCK_MONOTONIC; reading and
 * writing the files is not.
 *
 * Build: cc -O2 -o dopri5_chain dopri5_chain.c -lm   (benchmarks/bench_kernels.py does it).
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static long N;
static double K, EXPONENT, INV_MASS;

/* dy/dt of y = [x, u]: the chain's accelerations (kernels._network_accelerations, path branch). */
static void derivative(const double *y, double *dy) {
    const double *x = y, *u = y + N;
    double *out = dy + N;
    for (long c = 0; c < N; c++) out[c] = 0.0;
    for (long k = 0; k < N - 1; k++) {
        double e = x[k + 1] - x[k];
        double force = 0.0;
        if (e > 0.0) force = EXPONENT == 1.5 ? K * e * sqrt(e) : K * pow(e, EXPONENT);
        out[k] += force;
        out[k + 1] -= force;
    }
    for (long c = 0; c < N; c++) out[c] = out[c] * INV_MASS;
    for (long c = 0; c < N; c++) dy[c] = u[c];
}

static double error_norm(const double *err, const double *y, const double *y_new, const double *atol,
                         double rtol, long size) {
    double worst = 0.0;
    for (long c = 0; c < size; c++) {
        double a = fabs(y[c]), b = fabs(y_new[c]);
        double scale = atol[c] + rtol * (a > b ? a : b);
        double ratio = fabs(err[c]) / scale;
        if (!(ratio <= worst)) worst = ratio; /* NaN too */
    }
    return worst;
}

static double seconds_now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: %s INPUT OUTPUT\n", argv[0]);
        return 2;
    }
    FILE *in = fopen(argv[1], "rb");
    if (!in) {
        perror(argv[1]);
        return 2;
    }
    double header[6];
    if (fread(header, sizeof(double), 6, in) != 6) return 2;
    N = (long)header[0];
    K = header[1];
    EXPONENT = header[2];
    INV_MASS = 1.0 / header[3];
    double rtol = header[4], t_end = header[5];
    long size = 2 * N;
    double *y = malloc(size * sizeof(double)), *tol = malloc(size * sizeof(double));
    double *k1 = malloc(size * sizeof(double)), *k2 = malloc(size * sizeof(double));
    double *k3 = malloc(size * sizeof(double)), *k4 = malloc(size * sizeof(double));
    double *k5 = malloc(size * sizeof(double)), *k6 = malloc(size * sizeof(double));
    double *k7 = malloc(size * sizeof(double)), *ys = malloc(size * sizeof(double));
    double *y_new = malloc(size * sizeof(double)), *err = malloc(size * sizeof(double));
    if (fread(y, sizeof(double), size, in) != (size_t)size || fread(tol, sizeof(double), size, in) != (size_t)size)
        return 2;
    fclose(in);

    double start = seconds_now();
    long evaluations = 1, steps = 0, rejections = 0, status = 0, max_steps = 10000000;
    derivative(y, k1);
    /* Initial step (Hairer's HINIT). */
    double d0 = 0.0, d1 = 0.0, d2 = 0.0;
    for (long c = 0; c < size; c++) {
        double scale = tol[c] + rtol * fabs(y[c]);
        d0 = fmax(d0, fabs(y[c]) / scale);
        d1 = fmax(d1, fabs(k1[c]) / scale);
    }
    double h = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 * t_end : 0.01 * d0 / d1;
    h = fmin(h, t_end);
    for (long c = 0; c < size; c++) ys[c] = y[c] + h * k1[c];
    derivative(ys, k2);
    evaluations += 1;
    for (long c = 0; c < size; c++) {
        double scale = tol[c] + rtol * fabs(y[c]);
        d2 = fmax(d2, fabs(k2[c] - k1[c]) / scale / h);
    }
    double d12 = fmax(d1, d2);
    double h1 = d12 <= 1e-15 ? fmax(1e-6 * h, 1e-3 * h) : pow(0.01 / d12, 0.2);
    h = fmin(fmin(100.0 * h, h1), t_end);

    double t = 0.0;
    int rejected_last = 0;
    while (t < t_end) {
        if (steps + rejections >= max_steps) {
            status = 1;
            break;
        }
        if (t + h > t_end) h = t_end - t;
        if (h <= 1e-14 * fmax(fabs(t), t_end)) {
            status = 3;
            break;
        }
        for (long c = 0; c < size; c++) ys[c] = y[c] + h * (0.2 * k1[c]);
        derivative(ys, k2);
        for (long c = 0; c < size; c++) ys[c] = y[c] + h * (3.0 / 40.0 * k1[c] + 9.0 / 40.0 * k2[c]);
        derivative(ys, k3);
        for (long c = 0; c < size; c++)
            ys[c] = y[c] + h * (44.0 / 45.0 * k1[c] - 56.0 / 15.0 * k2[c] + 32.0 / 9.0 * k3[c]);
        derivative(ys, k4);
        for (long c = 0; c < size; c++)
            ys[c] = y[c] + h * (19372.0 / 6561.0 * k1[c] - 25360.0 / 2187.0 * k2[c] + 64448.0 / 6561.0 * k3[c]
                                - 212.0 / 729.0 * k4[c]);
        derivative(ys, k5);
        for (long c = 0; c < size; c++)
            ys[c] = y[c] + h * (9017.0 / 3168.0 * k1[c] - 355.0 / 33.0 * k2[c] + 46732.0 / 5247.0 * k3[c]
                                + 49.0 / 176.0 * k4[c] - 5103.0 / 18656.0 * k5[c]);
        derivative(ys, k6);
        for (long c = 0; c < size; c++)
            y_new[c] = y[c] + h * (35.0 / 384.0 * k1[c] + 500.0 / 1113.0 * k3[c] + 125.0 / 192.0 * k4[c]
                                   - 2187.0 / 6784.0 * k5[c] + 11.0 / 84.0 * k6[c]);
        derivative(y_new, k7);
        evaluations += 6;
        for (long c = 0; c < size; c++)
            err[c] = h * (71.0 / 57600.0 * k1[c] - 71.0 / 16695.0 * k3[c] + 71.0 / 1920.0 * k4[c]
                          - 17253.0 / 339200.0 * k5[c] + 22.0 / 525.0 * k6[c] - 1.0 / 40.0 * k7[c]);
        double error = error_norm(err, y, y_new, tol, rtol, size);
        if (!isfinite(error)) {
            h *= 0.2;
            rejections += 1;
            rejected_last = 1;
            continue;
        }
        double factor = error > 0.0 ? 0.9 * pow(error, -0.2) : 10.0;
        if (error <= 1.0) {
            steps += 1;
            double *swap = k1;
            for (long c = 0; c < size; c++) y[c] = y_new[c];
            k1 = k7; /* first same as last */
            k7 = swap;
            t = t + h;
            if (rejected_last) factor = fmin(factor, 1.0);
            rejected_last = 0;
            h *= fmin(10.0, fmax(0.2, factor));
            int finite = 1;
            for (long c = 0; c < size; c++) finite &= isfinite(y[c]);
            if (!finite) {
                status = 2;
                break;
            }
        } else {
            rejections += 1;
            rejected_last = 1;
            h *= fmax(0.2, factor);
        }
    }
    double elapsed = seconds_now() - start;

    FILE *out = fopen(argv[2], "wb");
    if (!out) {
        perror(argv[2]);
        return 2;
    }
    double summary[5] = {(double)status, (double)evaluations, (double)steps, (double)rejections, elapsed};
    fwrite(summary, sizeof(double), 5, out);
    fwrite(y, sizeof(double), size, out);
    fclose(out);
    return status == 0 ? 0 : 1;
}
