/* Micro-benchmark of hg_ehl_pair: ns per flank-pair evaluation with and without the T_c solve,
 * and the iteration counts of the solve. The workload mimics the ODE right-hand side: three
 * pairs walking along the path of action of gear set 1 at 2000 rpm (docs/physics.md §10.4 velocities,
 * linearly interpolated), loads 0.2-1 x 4760 N, 40 degC bath; each pair keeps its own warm start
 * from the previous call, as the FMU does. Times are medians over timed batches after a warm-up
 * (clock_gettime, CLOCK_MONOTONIC). */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "io/constants.h"
#include "tribo/ehl.h"

#define N_STATES 3000 /* per batch: 1000 steps x 3 pairs */
#define N_BATCHES 41

static hg_pair_contact states[N_STATES];

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static hg_lubricant os265962(void)
{
    hg_lubricant l;
    memset(&l, 0, sizeof l);
    strcpy(l.name, "OS265962");
    l.vogel_a = 7.560103250811039e-05, l.vogel_b = 1109.2767960557555;
    l.vogel_c = 155.39875251733173;
    l.alpha_T[0] = 313.15, l.alpha_T[1] = 373.15, l.alpha_T[2] = 413.15;
    l.alpha_star[0] = 16.09e-9, l.alpha_star[1] = 11.59e-9, l.alpha_star[2] = 9.38e-9;
    l.hn_lambda = 7.9e-8, l.hn_alpha = 0.70, l.hn_beta = 1.0;
    l.k_f = 0.18, l.c_p_f = 2090, l.rho_15 = 870;
    return l;
}

/* docs/physics.md §10.4 rows at xi = 0.02, 0.34, 0.66, 0.98 */
static void path_state(double xi, double W, hg_pair_contact *c)
{
    static const double X[4] = {0.02, 0.34, 0.66, 0.98};
    static const double U[4][4] = {{2.08, 4.38, 2.03, 1.96}, {2.46, 4.28, 1.87, 2.00},
                                   {2.83, 4.18, 1.71, 2.04}, {3.21, 4.09, 1.55, 2.08}};
    static const double RX[4] = {14.1e-3, 17.7e-3, 19.9e-3, 20.9e-3};
    int i = xi < X[1] ? 0 : xi < X[2] ? 1 : 2;
    double t = (xi - X[i]) / (X[i + 1] - X[i]);
    c->u_p[0] = U[i][0] + t * (U[i + 1][0] - U[i][0]);
    c->u_p[1] = U[i][1] + t * (U[i + 1][1] - U[i][1]);
    c->u_g[0] = U[i][2] + t * (U[i + 1][2] - U[i][2]);
    c->u_g[1] = U[i][3] + t * (U[i + 1][3] - U[i][3]);
    c->R_x = RX[i] + t * (RX[i + 1] - RX[i]);
    c->R_y = 2.25;
    c->W = W;
    c->T_bath = 313.15;
}

static void make_states(void)
{
    int step, k;
    for (step = 0; step < N_STATES / 3; step++) {
        for (k = 0; k < 3; k++) {
            double xi = fmod(0.02 + 0.96 * (step / 1000.0 + k / 3.0), 0.96) + 0.02;
            double ls = 0.2 + 0.8 * sin(HG_PI * xi) * sin(HG_PI * xi);
            path_state(xi, ls * 4760.0, &states[3 * step + k]);
        }
    }
}

/* median ns per evaluation; warm: 1 = per-pair warm start carried over, 0 = cold every call */
static double time_it(const hg_ehl_params *p, const hg_lubricant *l, int warm_mode)
{
    double t[N_BATCHES], warm[3];
    volatile double sink = 0.0;
    int b, i;
    for (b = -5; b < N_BATCHES; b++) { /* 5 warm-up batches */
        double t0, sum = 0.0;
        hg_pair_friction o;
        warm[0] = warm[1] = warm[2] = NAN;
        t0 = now_ns();
        for (i = 0; i < N_STATES; i++) {
            double *w = &warm[i % 3];
            if (!warm_mode) *w = NAN;
            hg_ehl_pair(p, l, &states[i], w, &o);
            sum += o.mu;
        }
        if (b >= 0) t[b] = (now_ns() - t0) / N_STATES;
        sink += sum;
    }
    (void)sink;
    qsort(t, N_BATCHES, sizeof t[0], cmp);
    return t[N_BATCHES / 2];
}

static void iterations(const hg_ehl_params *p, const hg_lubricant *l, int warm_mode, double *mean,
                       int *max)
{
    double warm[3] = {NAN, NAN, NAN};
    long n = 0;
    int i;
    *max = 0;
    for (i = 0; i < N_STATES; i++) {
        hg_pair_friction o;
        hg_ehl_stats s;
        if (!warm_mode) warm[i % 3] = NAN;
        hg_ehl_pair_ex(p, l, &states[i], &warm[i % 3], &o, &s);
        n += s.n_eval;
        if (s.n_eval > *max) *max = s.n_eval;
    }
    *mean = (double)n / N_STATES;
}

int main(void)
{
    hg_lubricant l = os265962();
    hg_ehl_params p;
    struct {
        const char *label;
        int thermal, z_exact, approx, warm;
    } runs[] = {
        {"thermal, warm start (FMU use)", 1, 0, 0, 1},
        {"thermal, cold start", 1, 0, 0, 0},
        {"isothermal", 0, 0, 0, 1},
        {"thermal, Hertz approximations", 1, 0, 1, 1},
        {"thermal, Z_exact, warm start", 1, 1, 0, 1},
        {"thermal, Z_exact, cold start", 1, 1, 0, 0},
        {"isothermal, Z_exact", 0, 1, 0, 1},
        {"thermal, Z_exact tabulated, warm start", 1, 2, 0, 1},
        {"thermal, Z_exact tabulated, cold start", 1, 2, 0, 0},
    };
    static hg_z_table z_table;
    size_t r;
    make_states();
    hg_z_table_build(&z_table, &l);
    printf("hg_ehl_pair, %d states (3 pairs along the path), median of %d batches\n", N_STATES,
           N_BATCHES);
    printf("%-40s %10s %14s %10s\n", "case", "ns/pair", "mean T_c iter", "max iter");
    for (r = 0; r < sizeof runs / sizeof runs[0]; r++) {
        double ns, mean;
        int max;
        hg_ehl_params_default(&p);
        p.thermal = runs[r].thermal;
        p.roelands_Z = runs[r].z_exact ? HG_Z_EXACT : HG_Z_SIMPLE;
        p.z_table = runs[r].z_exact == 2 ? &z_table : NULL; /* the FMU's */
        p.hertz = runs[r].approx ? HG_HERTZ_APPROX : HG_HERTZ_EXACT;
        ns = time_it(&p, &l, runs[r].warm);
        iterations(&p, &l, runs[r].warm, &mean, &max);
        printf("%-40s %10.0f %14.2f %10d\n", runs[r].label, ns, mean, max);
    }
    return 0;
}
