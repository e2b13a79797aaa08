/* Real-time factor of the FMU in a C host (no Python in the loop): fmi2DoStep loops timed with the
 * thread's CPU clock, for every fidelity level.
 *
 *   bench_fmu FMU_DIR levels [options]        every level at one communication step (--h, 1 ms):
 *                                             real-time factor, CPU per step, solver steps and
 *                                             right-hand sides per mesh cycle, CPU per mesh cycle
 *   bench_fmu FMU_DIR steps [options]         real-time factor of every level against the
 *                                             communication step, 1 us ... 1 s
 *   bench_fmu FMU_DIR run LEVEL [options]     one timed run of one level (for perf record)
 *   bench_fmu FMU_DIR startup [options]       start of the full level's instances in this
 *                                             process: instantiate, initialise and the first
 *                                             10 ms at 1 ms steps, timed for the process's first
 *                                             instance and for --runs - 1 further instances
 *                                             (all kept alive), with the resident memory each
 *                                             further instance adds (one process: run it several
 *                                             times for a median of first instances)
 *   bench_fmu FMU_DIR replay FILE [options]   the inputs of a recorded co-simulation, one row a
 *                                             communication step (a CSV whose header names
 *                                             inputs, the first column the time), after the
 *                                             --set values: CPU, solver steps, right-hand
 *                                             sides and the energy outputs at the end (for perf
 *                                             record and callgrind on a drive cycle; with
 *                                             --ramp 1 each input ramps from where the last
 *                                             step ended to the row's value over the step, given
 *                                             as input derivatives, as bench/drive_cycle.py does)
 *
 * options: --h H (communication step [s], default 1e-3), --runs N (timed batches, default 5),
 *   --cpu S (CPU seconds per batch, default 0.2), --warm T (simulated start-up before timing,
 *   default 0.2 s, at steps of max(H, 1 ms)), --read none|few|all (outputs read after every
 *   step: few = w_p, DTE, W_t, P_loss, eta, eta_cycle, the default), --set NAME=VALUE (any
 *   parameter or input, after the level's; repeatable), --levels a,b,c (subset),
 *   --variant LABEL:NAME=VALUE,... (levels: compare settings on this FMU, applied after --set;
 *   repeatable, the first is the baseline; "LABEL:" alone is the level as it is),
 *   --vs DIR (levels: every variant also on the unzipped FMU DIR, e.g. the one before a change).
 * Variants of one level run side by side, their timed batches interleaved (A B A B ...), so that
 * a load on the machine affects them alike; each row also gives its real-time factor relative to
 * the level's first row (the same run).
 *
 * The scene is the FMU's default: gear set 1, OS265962, 2000 rpm held by the speed governor,
 * T_s = 100 N m, 40 degC. The level parameters are those of hypoid/fmu/levels.py. Each batch
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
#define MAX_VARIANTS 16
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

/* One thing to time: an FMU with settings applied after the level's and the --set ones. */
typedef struct {
    char label[128];
    const fmu_lib *f;
    const fmu_info *m;
    const char *sets; /* NAME=VALUE,..., or "" */
} variant;

typedef struct {
    double h, cpu_budget, warm;
    int runs;
    int read; /* 0 none, 1 few, 2 all */
    const char *sets[MAX_SETS];
    int n_sets;
    const char *levels; /* comma-separated subset, NULL = all */
    const char *variants[MAX_VARIANTS]; /* LABEL:SETS */
    int n_variants;
    const char *vs; /* the other FMU's directory, or NULL */
    int ramp;       /* replay: inputs as ramps (input derivatives) instead of held values */
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

static int open_bench(bench *b, const variant *v, const level *lv, const options *o)
{
    const fmu_lib *f = v->f;
    const fmu_info *m = v->m;
    fmi2ValueReference vr_N_p;
    int k;
    memset(b, 0, sizeof *b);
    if (host_open(&b->in, f, m, lv->name) ||
        f->setup(b->in.c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        apply(&b->in, lv->params))
        return -1;
    for (k = 0; k < o->n_sets; k++)
        if (apply(&b->in, o->sets[k])) return -1;
    if (v->sets[0] && apply(&b->in, v->sets)) return -1;
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

/* Start-up and a calibration of the batch length to the CPU budget: *n steps per batch. */
static int prepare(bench *b, const variant *v, const level *lv, const options *o, double h,
                   int *n)
{
    double h_warm = h > 1e-3 ? h : 1e-3, t0, cpu = 0.0;
    *n = 1;
    if (open_bench(b, v, lv, o) || steps(b, (int)ceil(o->warm / h_warm - 1e-9), h_warm))
        return -1;
    for (;;) { /* double n until it costs a tenth of the budget */
        t0 = cpu_now();
        if (steps(b, *n, h)) return -1;
        cpu = cpu_now() - t0;
        if (cpu >= 0.1 * o->cpu_budget || *n > 1 << 24) break;
        *n *= 2;
    }
    *n = (int)fmax(1.0, *n * o->cpu_budget / fmax(cpu, 1e-9));
    return 0;
}

static void medians(figures fig[MAX_RUNS], int runs, figures *med)
{
    double v[MAX_RUNS];
    int k;
#define MEDIAN(field)                                           \
    for (k = 0; k < runs; k++) v[k] = fig[k].field;             \
    med->field = median(v, runs)
    MEDIAN(rtf);
    MEDIAN(us_per_step);
    MEDIAN(steps_per_cycle);
    MEDIAN(rhs_per_cycle);
    MEDIAN(us_per_cycle);
#undef MEDIAN
}

/* Every variant of one level side by side: start-up and calibration of each, then o->runs
 * rounds of one timed batch per variant; med[j] are the medians of variant j. */
static int measure(const variant *v, int nv, const level *lv, const options *o, double h,
                   figures *med)
{
    bench *b = calloc((size_t)nv, sizeof *b);
    figures(*fig)[MAX_RUNS] = calloc((size_t)nv, sizeof *fig);
    int n[MAX_VARIANTS], j, k, opened = 0, rc = -1;
    if (!b || !fig) goto done;
    for (; opened < nv; opened++)
        if (prepare(&b[opened], &v[opened], lv, o, h, &n[opened])) goto done;
    for (k = 0; k < o->runs; k++)
        for (j = 0; j < nv; j++)
            if (batch(&b[j], n[j], h, &fig[j][k])) goto done;
    for (j = 0; j < nv; j++) {
        medians(fig[j], o->runs, &med[j]);
        if (b[j].in.log.errors) goto done;
    }
    rc = 0;
done:
    for (j = 0; b && j < nv && j <= opened; j++) host_close(&b[j].in);
    free(b);
    free(fig);
    return rc ? host_fail("a run failed or the FMU logged errors") : 0;
}

/* ------------------------------------------------------------------ replay */

#define REPLAY_MAX_COLS 16
#define REPLAY_LINE 4096

/* The inputs of a recorded co-simulation: the header's names after the first (time) column. */
typedef struct {
    FILE *fp;
    int n; /* inputs */
    fmi2ValueReference vr[REPLAY_MAX_COLS];
    char names[REPLAY_MAX_COLS][64];
} replay_file;

static int replay_open(replay_file *r, const fmu_info *m, const char *path)
{
    char line[REPLAY_LINE], *tok, *save = NULL;
    int col = 0;
    memset(r, 0, sizeof *r);
    if (!(r->fp = fopen(path, "r")) || !fgets(line, sizeof line, r->fp)) return host_fail(path);
    line[strcspn(line, "\r\n")] = '\0';
    for (tok = strtok_r(line, ",", &save); tok; tok = strtok_r(NULL, ",", &save), col++) {
        if (col == 0) continue; /* the time */
        if (r->n >= REPLAY_MAX_COLS || vr_of(m, tok, &r->vr[r->n])) return -1;
        snprintf(r->names[r->n++], sizeof r->names[0], "%s", tok);
    }
    return r->n ? 0 : host_fail("replay: no inputs in the header");
}

/* The next row's inputs into u; 1 at the end of the file. */
static int replay_row(replay_file *r, double *u)
{
    char line[REPLAY_LINE], *tok, *save = NULL;
    int col = 0;
    if (!fgets(line, sizeof line, r->fp)) return 1;
    for (tok = strtok_r(line, ",", &save); tok && col <= r->n; tok = strtok_r(NULL, ",", &save))
        if (col++ > 0) u[col - 2] = strtod(tok, NULL);
    return col == r->n + 1 ? 0 : host_fail("replay: short row");
}

/* The inputs of one row for the step of h: held, or (ramp) from where the last step's ramp
 * ended (u_end, u0 + du h exactly as the FMU extrapolates it) to the row's value. */
static int replay_inputs(instance *in, const replay_file *r, const double *u, double *u_end,
                         int ramp, double h)
{
    double val[REPLAY_MAX_COLS], der[REPLAY_MAX_COLS];
    fmi2Integer order[REPLAY_MAX_COLS];
    int k;
    for (k = 0; k < r->n; k++) {
        val[k] = ramp ? u_end[k] : u[k];
        der[k] = ramp ? (u[k] - val[k]) / h : 0.0;
        order[k] = 1;
        u_end[k] = val[k] + der[k] * h;
    }
    if (in->f->set_real(in->c, r->vr, (size_t)r->n, val) != fmi2OK) return host_fail("fmi2SetReal");
    if (ramp && in->f->set_real_input_derivatives(in->c, r->vr, (size_t)r->n, order, der) != fmi2OK)
        return host_fail("fmi2SetRealInputDerivatives");
    return 0;
}

static const char *const REPLAY_OUT[] = {"E_in", "E_out", "E_friction", "E_churn", "E_bearings",
                                         "E_seals", "Q_housing", "T_oil", "w_p"};
#define N_REPLAY_OUT (int)(sizeof REPLAY_OUT / sizeof REPLAY_OUT[0])

static int replay_report(bench *b, int n, double cpu)
{
    fmi2ValueReference vr[N_REPLAY_OUT];
    double out[N_REPLAY_OUT], w = 0.0;
    long s = 0, e = 0;
    int k;
    for (k = 0; k < N_REPLAY_OUT; k++)
        if (vr_of(b->in.m, REPLAY_OUT[k], &vr[k])) return -1;
    if (b->in.f->get_real(b->in.c, vr, N_REPLAY_OUT, out) != fmi2OK || counters(b, &w, &s, &e))
        return host_fail("replay: outputs");
    printf("replay: %d steps to t = %.6g s: CPU %.4g s (real-time factor %.4g), %ld solver steps "
           "(%.4g a step), %ld rhs evaluations (%.4g a step)\n", n, b->t, cpu, b->t / cpu, s,
           (double)s / n, e, (double)e / n);
    for (k = 0; k < N_REPLAY_OUT; k++) printf("  %s = %.12g\n", REPLAY_OUT[k], out[k]);
    return 0;
}

static int mode_replay(const variant *v, const options *o, const char *path)
{
    static const level none = {"replay", ""};
    replay_file r;
    bench b;
    double u[REPLAY_MAX_COLS], u_end[REPLAY_MAX_COLS], t0, cpu = 0.0;
    int n = 0, rc = -1, end = 0, k;
    if (replay_open(&r, v->m, path)) return -1;
    t0 = cpu_now();
    if (open_bench(&b, v, &none, o)) goto done;
    for (k = 0; k < r.n; k++)
        if (b.in.f->get_real(b.in.c, &r.vr[k], 1, &u_end[k]) != fmi2OK) goto done;
    while (!(end = replay_row(&r, u))) {
        if (replay_inputs(&b.in, &r, u, u_end, o->ramp, o->h) || steps(&b, 1, o->h)) goto done;
        n++;
    }
    cpu = cpu_now() - t0;
    rc = end < 0 || b.in.log.errors ? -1 : replay_report(&b, n, cpu);
done:
    host_close(&b.in);
    fclose(r.fp);
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

static void print_settings(const options *o, const variant *v, int nv)
{
    int k;
    printf("scene: FMU defaults (2000 rpm, 100 N.m, 40 degC, speed governor); outputs read per "
           "step: %s; %d batches of ~%.2g s CPU after %.2g s start-up; medians",
           o->read == 2 ? "all Reals" : o->read ? "6" : "none", o->runs, o->cpu_budget, o->warm);
    for (k = 0; k < o->n_sets; k++) printf("%s%s", k ? ", " : "; set: ", o->sets[k]);
    printf("\n");
    for (k = 0; k < nv; k++)
        printf("variant %d: %s (%s)%s%s\n", k + 1, v[k].label, v[k].m->so_path,
               v[k].sets[0] ? ", set: " : "", v[k].sets);
    printf("\n");
}

static int mode_levels(const variant *v, int nv, const options *o)
{
    figures fig[MAX_VARIANTS];
    int k, j;
    print_settings(o, v, nv);
    printf("| level | variant | real-time factor | relative to the first row | us per fmi2DoStep | "
           "solver steps per mesh cycle | rhs evaluations per mesh cycle | us CPU per mesh "
           "cycle |\n|---|---|---|---|---|---|---|---|\n");
    for (k = 0; k < N_LEVELS; k++) {
        if (!chosen(o, LEVELS[k].name)) continue;
        if (measure(v, nv, &LEVELS[k], o, o->h, fig)) return -1;
        for (j = 0; j < nv; j++)
            printf("| %s | %s | %.4g | %.3g | %.4g | %.3g | %.3g | %.4g |\n", LEVELS[k].name,
                   v[j].label, fig[j].rtf, fig[j].rtf / fig[0].rtf, fig[j].us_per_step,
                   fig[j].steps_per_cycle, fig[j].rhs_per_cycle, fig[j].us_per_cycle);
        fflush(stdout);
    }
    return 0;
}

static int mode_steps(const variant *v, const options *o)
{
    static const double H[] = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0};
    int k, j, nh = (int)(sizeof H / sizeof H[0]);
    print_settings(o, v, 1);
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
            if (measure(v, 1, &LEVELS[k], o, H[j], &fig)) return -1;
            printf(" %.3g (%.3g) |", fig.rtf, fig.us_per_step);
            fflush(stdout);
        }
        printf("\n");
    }
    return 0;
}

/* Resident set of this process [MB] (Linux; 0 elsewhere). */
static double rss_mb(void)
{
    long pages = 0, resident = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (!f) return 0.0;
    if (fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    fclose(f);
    return (double)resident * 4096.0 / (1024.0 * 1024.0);
}

static int mode_startup(const variant *v, const options *o)
{
    static bench b[MAX_RUNS];
    double cpu[MAX_RUNS], rss0, rss1 = 0.0, t0;
    int k, j, rc = 0;
    for (k = 0; k < o->runs && !rc; k++) {
        t0 = cpu_now();
        rc = open_bench(&b[k], v, &LEVELS[0], o) || steps(&b[k], 10, 1e-3);
        cpu[k] = cpu_now() - t0;
        if (k == 0) rss1 = rss_mb();
    }
    rss0 = rss_mb();
    for (j = 0; j < k; j++) host_close(&b[j].in);
    if (rc) return -1;
    printf("full level, instantiate + initialise + 10 steps of 1 ms: first instance of the "
           "process %.2f ms CPU", 1e3 * cpu[0]);
    if (o->runs > 1)
        printf("; %d further instances: median %.2f ms CPU, %.3f MB resident each",
               o->runs - 1, 1e3 * median(cpu + 1, o->runs - 1), (rss0 - rss1) / (o->runs - 1));
    printf("\n");
    return 0;
}

static int mode_run(const variant *v, const options *o, const char *name)
{
    int k;
    for (k = 0; k < N_LEVELS; k++) {
        figures fig;
        if (strcmp(LEVELS[k].name, name)) continue;
        if (measure(v, 1, &LEVELS[k], o, o->h, &fig)) return -1;
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
    o->n_sets = 0, o->levels = NULL, o->n_variants = 0, o->vs = NULL, o->ramp = 0;
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
        else if (strcmp(a, "--variant") == 0 && strchr(v, ':') &&
                 o->n_variants < MAX_VARIANTS / 2)
            o->variants[o->n_variants++] = v;
        else if (strcmp(a, "--vs") == 0) o->vs = v;
        else if (strcmp(a, "--ramp") == 0) o->ramp = atoi(v);
        else return host_fail(a);
    }
    if (o->h <= 0.0 || o->runs < 1 || o->runs > MAX_RUNS || o->cpu_budget <= 0.0 || o->warm < 0.0)
        return host_fail("option value out of range");
    return 0;
}

/* The variants to time: the --variant ones (or the FMU as it is), then each again on the --vs
 * FMU. Returns their number. */
static int make_variants(const options *o, const fmu_lib *f, const fmu_info *m,
                         const fmu_lib *f_vs, const fmu_info *m_vs, variant *v)
{
    int k, n = o->n_variants ? o->n_variants : 1, nv = 0;
    for (k = 0; k < n; k++, nv++) {
        const char *spec = o->n_variants ? o->variants[k] : "this FMU:";
        const char *colon = strchr(spec, ':');
        int len = (int)(colon - spec);
        snprintf(v[nv].label, sizeof v[nv].label, "%.*s", len > 100 ? 100 : len, spec);
        v[nv].f = f, v[nv].m = m, v[nv].sets = colon + 1;
    }
    for (k = 0; o->vs && k < n; k++, nv++) {
        v[nv] = v[k];
        v[nv].f = f_vs, v[nv].m = m_vs;
        snprintf(v[nv].label, sizeof v[nv].label, "%.100s, --vs FMU", v[k].label);
    }
    return nv;
}

static int run_mode(int argc, char **argv, const options *o, const variant *v, int nv)
{
    if (strcmp(argv[2], "levels") == 0) return mode_levels(v, nv, o);
    if (strcmp(argv[2], "steps") == 0) return mode_steps(v, o);
    if (strcmp(argv[2], "startup") == 0) return mode_startup(v, o);
    if (argc > 3 && strcmp(argv[2], "run") == 0) return mode_run(v, o, argv[3]);
    if (argc > 3 && strcmp(argv[2], "replay") == 0) return mode_replay(v, o, argv[3]);
    return host_fail("unknown mode");
}

int main(int argc, char **argv)
{
    fmu_info m, m_vs;
    fmu_lib f, f_vs;
    options o;
    variant v[MAX_VARIANTS];
    int rc = -1, run = argc > 3 && (strcmp(argv[2], "run") == 0 || strcmp(argv[2], "replay") == 0);
    if (argc < 3 || parse(argc, argv, run ? 4 : 3, &o)) {
        fprintf(stderr, "usage: bench_fmu FMU_DIR levels|steps|startup|run LEVEL|replay FILE "
                "[--h H] [--runs N] [--cpu S] [--warm T] [--read none|few|all] [--set NAME=VALUE] "
                "[--levels a,b] [--variant LABEL:NAME=VALUE,...] [--vs FMU_DIR] [--ramp 0|1]\n");
        return 2;
    }
    if (host_read_info(&m, argv[1])) return 1;
    if (o.vs && host_read_info(&m_vs, o.vs)) {
        host_free_info(&m);
        return 1;
    }
    if (host_load(&f, m.so_path) == 0) {
        if (!o.vs || host_load(&f_vs, m_vs.so_path) == 0) {
            rc = run_mode(argc, argv, &o, v, make_variants(&o, &f, &m, &f_vs, &m_vs, v));
            if (o.vs) host_unload(&f_vs);
        }
        host_unload(&f);
    }
    if (o.vs) host_free_info(&m_vs);
    host_free_info(&m);
    return rc ? 1 : 0;
}
