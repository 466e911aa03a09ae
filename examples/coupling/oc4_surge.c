/*
 * Drives the three fairleads of the OC4 DeepCwind mooring with a platform
 * surge through the C library, as a floating platform's solver would, and
 * prints the fairlead tensions against time: the C twin of oc4_surge.py
 * (the same numbers, to the bit).
 *
 *   cargo build --release --workspace
 *   mkdir -p target/examples
 *   cc -O1 -I crates/stancf-capi/include examples/coupling/oc4_surge.c \
 *      -L target/release -lstancf_c -Wl,-rpath,$PWD/target/release -lm -o target/examples/oc4_surge
 *   target/examples/oc4_surge examples/oc4-deepcwind-moordyn.txt 40
 *
 * The surge moves every fairlead along x by dx(t) = A/2 (1 - cos(2 pi t/T)),
 * A = 5 m, T = 20 s, from rest; the coupling interval is 0.1 s. Prints the
 * CSV t,tension_<id>,... (one row per coupling step).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "stancf.h"

static const double AMPLITUDE = 5.0, PERIOD = 20.0, INTERVAL = 0.1;
static const double PI = 3.14159265358979323846;

/* The surge dx(t) and its rate (m, m/s), as surge_offset in oc4_surge.py. */
static void surge_offset(double t, double *dx, double *vx) {
    double w = 2.0 * PI / PERIOD;
    *dx = 0.5 * AMPLITUDE * (1.0 - cos(w * t));
    *vx = 0.5 * AMPLITUDE * w * sin(w * t);
}

static int fail(const char *call) {
    fprintf(stderr, "%s: %s\n", call, stancf_error_message());
    return 1;
}

int main(int argc, char **argv) {
    const char *deck = argc > 1 ? argv[1] : "examples/oc4-deepcwind-moordyn.txt";
    double duration = argc > 2 ? atof(argv[2]) : 40.0;
    StancfSystem *s = stancf_create(deck);
    if (s == NULL) return fail("stancf_create");
    unsigned int n = 0;
    if (stancf_ncoupled_dof(s, &n) != STANCF_SUCCESS) return fail("stancf_ncoupled_dof");
    unsigned int points = n / 3;
    double *x0 = calloc(n, sizeof(double)), *x = calloc(n, sizeof(double));
    double *xd = calloc(n, sizeof(double)), *f = calloc(n, sizeof(double));
    int64_t *ids = calloc(points, sizeof(int64_t));
    if (!x0 || !x || !xd || !f || !ids) return 1;
    if (stancf_coupled_ids(s, ids) != STANCF_SUCCESS) return fail("stancf_coupled_ids");
    if (stancf_coupled_positions(s, x0) != STANCF_SUCCESS) return fail("stancf_coupled_positions");
    if (stancf_init(s, x0, xd) != STANCF_SUCCESS) return fail("stancf_init");

    printf("t");
    for (unsigned int k = 0; k < points; k++) printf(",tension_%lld", (long long)ids[k]);
    printf("\n");
    double t = 0.0, dt = INTERVAL;
    long rows = (long)floor(duration / INTERVAL + 0.5);
    for (long r = 0; r < rows; r++) {
        double dx, vx;
        surge_offset(t + dt, &dx, &vx);
        for (unsigned int i = 0; i < n; i++) {
            x[i] = x0[i];
            xd[i] = 0.0;
        }
        for (unsigned int k = 0; k < points; k++) {
            x[3 * k] = x0[3 * k] + dx;
            xd[3 * k] = vx;
        }
        /* Steps from t to t + dt and advances t, as MoorDyn_Step. */
        if (stancf_step(s, x, xd, f, &t, &dt) != STANCF_SUCCESS) return fail("stancf_step");
        printf("%.17g", t);
        for (unsigned int k = 0; k < points; k++) {
            double fx = f[3 * k], fy = f[3 * k + 1], fz = f[3 * k + 2];
            printf(",%.17g", sqrt(fx * fx + fy * fy + fz * fz));
        }
        printf("\n");
    }
    stancf_close(s);
    free(x0);
    free(x);
    free(xd);
    free(f);
    free(ids);
    return 0;
}
