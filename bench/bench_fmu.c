/* Real-time factor of the FMU in a C host (no Python in the loop): fmi2DoStep loops timed with the
 * thread's CPU clock, for every fidelity level.
 *
 *   bench_fmu FMU_DIR levels [options]        every level at one communication step (--h, 1 ms):
 *                                             real-time factor, CPU per step, solver steps and
 *                                             right-hand sides per mesh cycle, CPU per mesh cycle
 *   bench_fmu FMU_DIR steps [options]         real-time factor of every level against the
 *                                             communication step, 1 us ... 1 s
 *   bench_fmu FMU_DIR run LEVEL [options]     one timed run of one level (for perf record)
 *
 * options: --h H (communication step [s], default 1e-3), --runs N (timed batches, default 5),
 *   --cpu S (CPU seconds per batch, default 0.2), --warm T (simulated start-up before timing,
 *   default 0.2 s, at steps of max(H, 1 ms)), --read none|few|all (outputs read after every
 *   step: few = w_p, DTE, W_t, P_loss, eta, eta_cycle, the default), --set NAME=VALUE (any
 *   parameter or input, after the level's; repeatable), --levels a,b,c (subset).
 *
 * The scene is the FMU's default: gear set 1, OS265962, 2000 rpm held by the speed governor,
 * T_s = 100 N m, 40 degC. The level parameters are those of hypoid/levels.py. Each batch
 * continues the same instance (steady operation after the start-up); the figures are medians
 * over the batches. Real-time factor = simulated seconds / CPU seconds of the fmi2DoStep and
 * fmi2GetReal calls. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmu_host.h"

#define MAX_SETS 32
#define MAX_RUNS 101
#define TWO_PI 6.283185307179586

typedef struct {
    const char *name;
    const char *params; /* NAME=VALUE,... */
} level;

static const level LEVELS[] = {
    {"full", "mesh_model=varying,friction_model=ehl_thermal,backlash_model=exact"},
    {"smoothed", "mesh_model=varying,friction_model=ehl_thermal,backlash_model=smoothed"},
    {"isothermal", "mesh_model=varying,friction_model=ehl_isothermal,backlash_model=exact"},
    {"mean", "mesh_model=mean,friction_model=ehl_thermal"},
    {"rigid", "mesh_model=rigid,friction_model=ehl_thermal"},
    {"map", "mesh_model=rigid,friction_model=map"},
};
#define N_LEVELS (int)(sizeof LEVELS / sizeof LEVELS[0])

static const char *const FEW[] = {"w_p", "DTE", "W_t", "P_loss", "eta", "eta_cycle"};

typedef struct {
    double h, cpu_budget, warm;
    int runs;
    int read; /* 0 none, 1 few, 2 all */
    const char *sets[MAX_SETS];
    int n_sets;
    const char *levels; /* comma-separated subset, NULL = all */
} options;

typedef struct {
    double rtf, us_per_step, steps_per_cycle, rhs_per_cycle, us_per_cycle;
} figures;

typedef struct {
    instance in;
    fmi2ValueReference read[HOST_MAX_REALS];
    size_t n_read;
    fmi2ValueReference steps, rhs, w_p;
    int N_p;
    double t;
} bench;

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Applies "NAME=VALUE" (one assignment, or a comma-separated list). */
static int apply(instance *in, const char *list)
{
    char buf[512], *tok, *save = NULL, *eq;
    snprintf(buf, sizeof buf, "%s", list);
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (!(eq = strchr(tok, '='))) return host_fail(tok);
        *eq = '\0';
        if (host_set(in, tok, eq + 1)) return -1;
    }
    return 0;
}

static int vr_of(const fmu_info *m, const char *name, fmi2ValueReference *vr)
{
    long r = host_value_reference(m, name);
    if (r < 0) return host_fail(name);
    *vr = (fmi2ValueReference)r;
    return 0;
}

static int outputs_to_read(bench *b, const options *o)
{
    size_t k;
    b->n_read = 0;
    if (o->read == 2) {
        memcpy(b->read, b->in.m->reals, b->in.m->n_reals * sizeof b->read[0]);
        b->n_read = b->in.m->n_reals;
    } else if (o->read == 1) {
        for (k = 0; k < sizeof FEW / sizeof FEW[0]; k++)
            if (vr_of(b->in.m, FEW[k], &b->read[b->n_read++])) return -1;
    }
    return 0;
}

static int open_bench(bench *b, const fmu_lib *f, const fmu_info *m, const level *lv,
                      const options *o)
{
    fmi2ValueReference vr_N_p;
    int k;
    memset(b, 0, sizeof *b);
    if (host_open(&b->in, f, m, lv->name) ||
        f->setup(b->in.c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        apply(&b->in, lv->params))
        return -1;
    for (k = 0; k < o->n_sets; k++)
        if (apply(&b->in, o->sets[k])) return -1;
    if (f->enter(b->in.c) != fmi2OK || f->exit_init(b->in.c) != fmi2OK)
        return host_fail("initialisation");
    if (vr_of(m, "solver_steps", &b->steps) || vr_of(m, "rhs_evals", &b->rhs) ||
        vr_of(m, "w_p", &b->w_p) || vr_of(m, "N_p", &vr_N_p) ||
        f->get_integer(b->in.c, &vr_N_p, 1, &b->N_p) != fmi2OK)
        return -1;
    return outputs_to_read(b, o);
}

/* n communication steps of h, reading the chosen outputs after each. */
static int steps(bench *b, int n, double h)
{
    double out[HOST_MAX_REALS];
    int k;
    for (k = 0; k < n; k++) {
        if (b->in.f->do_step(b->in.c, b->t, h, fmi2True) != fmi2OK) return host_fail("fmi2DoStep");
        b->t += h;
        if (b->n_read && b->in.f->get_real(b->in.c, b->read, b->n_read, out) != fmi2OK)
            return host_fail("fmi2GetReal");
    }
    return 0;
}

static int counters(bench *b, double *w_p, long *n_steps, long *n_rhs)
{
    fmi2Integer c[2];
    fmi2ValueReference vr[2] = {b->steps, b->rhs};
    if (b->in.f->get_integer(b->in.c, vr, 2, c) != fmi2OK ||
        b->in.f->get_real(b->in.c, &b->w_p, 1, w_p) != fmi2OK)
        return host_fail("counters");
    *n_steps = c[0];
    *n_rhs = c[1];
    return 0;
}

/* One timed batch of n steps: its figures. */
static int batch(bench *b, int n, double h, figures *fig)
{
    double w0 = 0.0, w1 = 0.0, t0, cpu, cycles;
    long s0 = 0, s1 = 0, r0 = 0, r1 = 0;
    if (counters(b, &w0, &s0, &r0)) return -1;
    t0 = cpu_now();
    if (steps(b, n, h)) return -1;
    cpu = cpu_now() - t0;
    if (counters(b, &w1, &s1, &r1)) return -1;
    cycles = 0.5 * (fabs(w0) + fabs(w1)) * b->N_p / TWO_PI * n * h;
    fig->rtf = n * h / cpu;
    fig->us_per_step = 1e6 * cpu / n;
    fig->steps_per_cycle = (double)(s1 - s0) / cycles;
    fig->rhs_per_cycle = (double)(r1 - r0) / cycles;
    fig->us_per_cycle = 1e6 * cpu / cycles;
    return 0;
}

/* Start-up, a calibration of the batch length to the CPU budget, then o->runs batches. */
static int measure(const fmu_lib *f, const fmu_info *m, const level *lv, const options *o,
                   double h, figures *med)
{
    bench b;
    figures fig[MAX_RUNS];
    double v[MAX_RUNS], h_warm = h > 1e-3 ? h : 1e-3, t0, cpu = 0.0;
    int n = 1, k, rc = -1;
    if (open_bench(&b, f, m, lv, o) || steps(&b, (int)ceil(o->warm / h_warm - 1e-9), h_warm))
        goto done;
    for (;;) { /* calibration: double n until it costs a tenth of the budget */
        t0 = cpu_now();
        if (steps(&b, n, h)) goto done;
        cpu = cpu_now() - t0;
        if (cpu >= 0.1 * o->cpu_budget || n > 1 << 24) break;
        n *= 2;
    }
    n = (int)fmax(1.0, n * o->cpu_budget / fmax(cpu, 1e-9));
    for (k = 0; k < o->runs; k++)
        if (batch(&b, n, h, &fig[k])) goto done;
#define MEDIAN(field)                                           \
    for (k = 0; k < o->runs; k++) v[k] = fig[k].field;          \
    med->field = median(v, o->runs)
    MEDIAN(rtf);
    MEDIAN(us_per_step);
    MEDIAN(steps_per_cycle);
    MEDIAN(rhs_per_cycle);
    MEDIAN(us_per_cycle);
#undef MEDIAN
    rc = b.in.log.errors ? host_fail("the FMU logged errors") : 0;
done:
    host_close(&b.in);
    return rc;
}

static int chosen(const options *o, const char *name)
{
    const char *p = o->levels;
    size_t len = strlen(name);
    if (!p) return 1;
    for (; (p = strstr(p, name)) != NULL; p += len)
        if ((p == o->levels || p[-1] == ',') && (p[len] == ',' || p[len] == '\0')) return 1;
    return 0;
}

static void print_settings(const options *o)
{
    int k;
    printf("scene: FMU defaults (2000 rpm, 100 N.m, 40 degC, speed governor); outputs read per "
           "step: %s; %d batches of ~%.2g s CPU after %.2g s start-up; medians",
           o->read == 2 ? "all Reals" : o->read ? "6" : "none", o->runs, o->cpu_budget, o->warm);
    for (k = 0; k < o->n_sets; k++) printf("%s%s", k ? ", " : "; set: ", o->sets[k]);
    printf("\n\n");
}

static int mode_levels(const fmu_lib *f, const fmu_info *m, const options *o)
{
    int k;
    print_settings(o);
    printf("| level | real-time factor | us per fmi2DoStep | solver steps per mesh cycle | "
           "rhs evaluations per mesh cycle | us CPU per mesh cycle |\n|---|---|---|---|---|---|\n");
    for (k = 0; k < N_LEVELS; k++) {
        figures fig;
        if (!chosen(o, LEVELS[k].name)) continue;
        if (measure(f, m, &LEVELS[k], o, o->h, &fig)) return -1;
        printf("| %s | %.4g | %.4g | %.3g | %.3g | %.4g |\n", LEVELS[k].name, fig.rtf,
               fig.us_per_step, fig.steps_per_cycle, fig.rhs_per_cycle, fig.us_per_cycle);
        fflush(stdout);
    }
    return 0;
}

static int mode_steps(const fmu_lib *f, const fmu_info *m, const options *o)
{
    static const double H[] = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0};
    int k, j, nh = (int)(sizeof H / sizeof H[0]);
    print_settings(o);
    printf("real-time factor (us CPU per fmi2DoStep) against the communication step\n\n| level |");
    for (j = 0; j < nh; j++) printf(" %g s |", H[j]);
    printf("\n|---|");
    for (j = 0; j < nh; j++) printf("---|");
    printf("\n");
    for (k = 0; k < N_LEVELS; k++) {
        if (!chosen(o, LEVELS[k].name)) continue;
        printf("| %s |", LEVELS[k].name);
        for (j = 0; j < nh; j++) {
            figures fig;
            if (measure(f, m, &LEVELS[k], o, H[j], &fig)) return -1;
            printf(" %.3g (%.3g) |", fig.rtf, fig.us_per_step);
            fflush(stdout);
        }
        printf("\n");
    }
    return 0;
}

static int mode_run(const fmu_lib *f, const fmu_info *m, const options *o, const char *name)
{
    int k;
    for (k = 0; k < N_LEVELS; k++) {
        figures fig;
        if (strcmp(LEVELS[k].name, name)) continue;
        if (measure(f, m, &LEVELS[k], o, o->h, &fig)) return -1;
        printf("%s at h = %g s: real-time factor %.4g, %.4g us per step, %.3g solver steps and "
               "%.3g rhs evaluations per mesh cycle, %.4g us CPU per mesh cycle\n", name, o->h,
               fig.rtf, fig.us_per_step, fig.steps_per_cycle, fig.rhs_per_cycle,
               fig.us_per_cycle);
        return 0;
    }
    return host_fail("unknown level");
}

static int parse(int argc, char **argv, int first, options *o)
{
    int k;
    o->h = 1e-3, o->cpu_budget = 0.2, o->warm = 0.2, o->runs = 5, o->read = 1;
    o->n_sets = 0, o->levels = NULL;
    for (k = first; k < argc; k++) {
        const char *a = argv[k], *v = k + 1 < argc ? argv[k + 1] : NULL;
        if (!v) return host_fail(a);
        k++;
        if (strcmp(a, "--h") == 0) o->h = atof(v);
        else if (strcmp(a, "--runs") == 0) o->runs = atoi(v);
        else if (strcmp(a, "--cpu") == 0) o->cpu_budget = atof(v);
        else if (strcmp(a, "--warm") == 0) o->warm = atof(v);
        else if (strcmp(a, "--levels") == 0) o->levels = v;
        else if (strcmp(a, "--read") == 0)
            o->read = strcmp(v, "none") == 0 ? 0 : strcmp(v, "all") == 0 ? 2 : 1;
        else if (strcmp(a, "--set") == 0 && o->n_sets < MAX_SETS) o->sets[o->n_sets++] = v;
        else return host_fail(a);
    }
    if (o->h <= 0.0 || o->runs < 1 || o->runs > MAX_RUNS || o->cpu_budget <= 0.0 || o->warm < 0.0)
        return host_fail("option value out of range");
    return 0;
}

int main(int argc, char **argv)
{
    fmu_info m;
    fmu_lib f;
    options o;
    int rc = -1, run = argc > 3 && strcmp(argv[2], "run") == 0;
    if (argc < 3 || parse(argc, argv, run ? 4 : 3, &o)) {
        fprintf(stderr, "usage: bench_fmu FMU_DIR levels|steps|run LEVEL [--h H] [--runs N] "
                "[--cpu S] [--warm T] [--read none|few|all] [--set NAME=VALUE] [--levels a,b]\n");
        return 2;
    }
    if (host_read_info(&m, argv[1])) return 1;
    if (host_load(&f, m.so_path) == 0) {
        if (strcmp(argv[2], "levels") == 0) rc = mode_levels(&f, &m, &o);
        else if (strcmp(argv[2], "steps") == 0) rc = mode_steps(&f, &m, &o);
        else if (run) rc = mode_run(&f, &m, &o, argv[3]);
        else rc = host_fail("unknown mode");
        host_unload(&f);
    }
    host_free_info(&m);
    return rc ? 1 : 0;
}
