/* A small FMI 2.0 co-simulation host in C, for the checks that should not depend on Python:
 * it dlopens the FMU's shared library and runs one of
 *
 *   run_fmu FMU_DIR simulate [T]          simulate T s (default 0.1) with h = 1e-4; take a state
 *                                         half-way, serialize it, restore it in this and in a
 *                                         second instance; fmi2Reset; a fresh instance: every
 *                                         continuation must be bit-identical
 *   run_fmu FMU_DIR soak N [reload] [norss]
 *                                         N instantiate / simulate 2 ms / serialize / free
 *                                         cycles (reload: dlopen/dlclose every cycle); reports
 *                                         RSS and open file descriptors, fails on growth (norss:
 *                                         no RSS check, for ASan and valgrind, which hold memory)
 *   run_fmu FMU_DIR outputs T [NAME=VALUE ...]
 *                                         simulate T s with h = 1e-4 from the start values,
 *                                         NAME=VALUE set before initialisation; print every Real
 *                                         variable at T as "VR HEX DECIMAL" (the exact bits;
 *                                         tests/portability/compare.py compares platforms)
 *   run_fmu FMU_DIR threads N [T]         N instances with different parameters on N threads
 *                                         (T s each, default 0.1),
 *                                         twice, against each run alone: bit-identical; each
 *                                         thread also resets and reruns its instance
 *   ... simulate|threads|outputs ... me   the same in Model Exchange: the host integrates each
 *                                         interval of 1e-4 s by explicit Euler steps of 1 us
 *                                         (the gear's stiffest mode allows them) with an event
 *                                         iteration wherever an event indicator changes sign or
 *                                         a completed step asks for one
 *
 * FMU_DIR is an unzipped FMU (modelDescription.xml, binaries/linux64/<id>.so or, built for
 * Windows, binaries/win64/<id>.dll, resources/).
 * Errors the FMU logs are printed (everything with RUN_FMU_VERBOSE set) and fail the run.
 * Exit status 0 when every check passes. Used by scripts/sanitize.sh (ASan, valgrind) and
 * scripts/soak.sh. */
#define _XOPEN_SOURCE 700 /* POSIX 2008 */
#include <dirent.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmu_host.h"

#define H 1e-4 /* communication step [s] */
#define RSS_TOLERANCE_KIB 2048 /* soak: RSS growth allowed after the warm-up cycles */

/* ------------------------------------------------------------------ one simulation */

#define ME_H 1e-6 /* the Model Exchange host's Euler step [s] */

typedef struct {
    double T_s, w_set;
    int gear_set, friction_model, load_mode; /* 0: leave the start value */
    int model_exchange;                      /* the instance is driven as Model Exchange */
} run_spec;

static int fail(const char *what)
{
    fprintf(stderr, "run_fmu: ");
    return host_fail(what);
}

/* An integer parameter; 0 leaves its start value. */
static int set_int(instance *in, const char *name, int value)
{
    return value ? host_set_int(in, name, value) : 0;
}

/* ------------------------------------------------------------------ Model Exchange */

/* The discrete states' iteration of an event (the instance in event mode), then continuous-time
 * mode. */
static int me_iterate(instance *in)
{
    fmi2EventInfo info;
    do {
        if (in->f->new_discrete_states(in->c, &info) != fmi2OK)
            return fail("fmi2NewDiscreteStates");
    } while (info.newDiscreteStatesNeeded && !info.terminateSimulation);
    return in->f->enter_continuous_time_mode(in->c) != fmi2OK ? fail("continuous-time mode") : 0;
}

static int sign_changed(const double *a, const double *b, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++)
        if ((a[k] > 0.0) != (b[k] > 0.0)) return 1;
    return 0;
}

/* From t0 to t1 by explicit Euler steps of ME_H: the host's x, its derivatives, the time and
 * the completed step; an event wherever an indicator changed sign or the FMU asks. */
static int me_advance(instance *in, double t0, double t1)
{
    const fmu_lib *f = in->f;
    size_t nx = in->m->nx, nz = in->m->nz, i;
    double x[HOST_MAX_STATES], dx[HOST_MAX_STATES], z0[HOST_MAX_STATES], z[HOST_MAX_STATES];
    int n = (int)((t1 - t0) / ME_H + 0.5), k;
    fmi2Boolean event, stop;
    if (f->get_continuous_states(in->c, x, nx) != fmi2OK ||
        f->get_event_indicators(in->c, z0, nz) != fmi2OK)
        return fail("fmi2GetContinuousStates / fmi2GetEventIndicators");
    for (k = 1; k <= n; k++) {
        if (f->get_derivatives(in->c, dx, nx) != fmi2OK) return fail("fmi2GetDerivatives");
        for (i = 0; i < nx; i++) x[i] += ME_H * dx[i];
        if (f->set_time(in->c, k == n ? t1 : t0 + k * ME_H) != fmi2OK ||
            f->set_continuous_states(in->c, x, nx) != fmi2OK ||
            f->completed_integrator_step(in->c, fmi2True, &event, &stop) != fmi2OK ||
            f->get_event_indicators(in->c, z, nz) != fmi2OK)
            return fail("a Model Exchange step");
        if (event || sign_changed(z0, z, nz)) {
            if (f->enter_event_mode(in->c) != fmi2OK || me_iterate(in) ||
                f->get_continuous_states(in->c, x, nx) != fmi2OK ||
                f->get_event_indicators(in->c, z, nz) != fmi2OK)
                return fail("a Model Exchange event");
        }
        memcpy(z0, z, nz * sizeof *z);
    }
    return 0;
}

/* ------------------------------------------------------------------ instances */

/* Parameters and start inputs of spec, then initialisation at t = 0 (Model Exchange: and the
 * initial event iteration). */
static int init_instance(instance *in, const run_spec *s)
{
    if (in->f->setup(in->c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        set_int(in, "gear_set", s->gear_set) || set_int(in, "friction_model", s->friction_model) ||
        set_int(in, "load_mode", s->load_mode) || host_set_real(in, "T_s", s->T_s) ||
        host_set_real(in, "w_set", s->w_set) || in->f->enter(in->c) != fmi2OK ||
        in->f->exit_init(in->c) != fmi2OK || (in->model_exchange && me_iterate(in)))
        return fail("initialisation");
    return 0;
}

/* An instance of the spec's interface. */
static int open_instance(instance *in, const fmu_lib *f, const fmu_info *m, const char *name,
                         const run_spec *s)
{
    return host_open_as(in, f, m, name, s->model_exchange);
}

/* n steps from t0, every Real variable after each step into out (n * n_reals values; NULL:
 * read and drop them). */
static int run_steps(instance *in, double t0, int n, double *out)
{
    double scratch[HOST_MAX_REALS];
    int k;
    for (k = 0; k < n; k++) {
        if (in->model_exchange ? me_advance(in, t0 + k * H, t0 + (k + 1) * H)
                               : in->f->do_step(in->c, t0 + k * H, H, fmi2True) != fmi2OK)
            return fail(in->model_exchange ? "Model Exchange" : "fmi2DoStep");
        if (in->f->get_real(in->c, in->m->reals, in->m->n_reals,
                            out ? out + (size_t)k * in->m->n_reals : scratch) != fmi2OK)
            return fail("fmi2GetReal");
    }
    return 0;
}

static int same(const double *a, const double *b, size_t n, const char *what)
{
    size_t i;
    if (memcmp(a, b, n * sizeof *a) == 0) return 0;
    for (i = 0; i < n && memcmp(&a[i], &b[i], sizeof *a) == 0; i++) continue;
    fprintf(stderr, "run_fmu: value %zu differs: %.17g vs %.17g\n", i, a[i], b[i]);
    return fail(what);
}

/* ------------------------------------------------------------------ simulate */

/* Serializes state s of instance in into a new buffer; *size receives its length. */
static char *serialize(instance *in, fmi2FMUstate s, size_t *size)
{
    char *blob;
    if (in->f->state_size(in->c, s, size) != fmi2OK || !(blob = malloc(*size))) return NULL;
    if (in->f->serialize(in->c, s, blob, *size) != fmi2OK) {
        free(blob);
        return NULL;
    }
    return blob;
}

/* A plain run, then with a state taken half-way (taking a state restarts the integrator, so
 * the continuation is compared with continuations of the same state, not with the plain run). */
static int simulate(const fmu_lib *f, const fmu_info *m, double t_end, int model_exchange)
{
    run_spec spec = {150.0, 209.43951023931956, 2, 0, 0, 0};
    run_spec other = {60.0, 150.0, 3, 0, 1, 0};
    int n = (int)(t_end / H + 0.5), half = n / 2, rc = -1;
    size_t nr = m->n_reals, size = 0, size2 = 0, rest = (size_t)(n - half) * nr;
    double *plain = calloc((size_t)n * nr, sizeof *plain);
    double *cont = calloc(rest, sizeof *cont), *again = calloc((size_t)n * nr, sizeof *again);
    instance a, b;
    fmi2FMUstate s = NULL, s2 = NULL;
    char *blob = NULL, *blob2 = NULL;
    memset(&b, 0, sizeof b);
    spec.model_exchange = other.model_exchange = model_exchange;
    if (!plain || !cont || !again || open_instance(&a, f, m, "a", &spec) ||
        init_instance(&a, &spec) ||
        run_steps(&a, 0.0, n, plain))
        goto done;
    /* fmi2Reset gives a fresh instance: the first half again, then take a state */
    if (a.f->reset(a.c) != fmi2OK || init_instance(&a, &spec) || run_steps(&a, 0.0, half, again) ||
        same(plain, again, (size_t)half * nr, "reset instance reproduces the run") ||
        a.f->get_state(a.c, &s) != fmi2OK || !(blob = serialize(&a, s, &size)) ||
        run_steps(&a, half * H, n - half, cont))
        goto done;
    /* the same instance, restored */
    if (a.f->set_state(a.c, s) != fmi2OK || run_steps(&a, half * H, n - half, again) ||
        same(cont, again, rest, "restored state continues bit-identically"))
        goto done;
    /* a second instance with other parameters, from the serialized state */
    if (open_instance(&b, f, m, "b", &other) || init_instance(&b, &other) ||
        b.f->deserialize(b.c, blob, size, &s2) != fmi2OK || b.f->set_state(b.c, s2) != fmi2OK ||
        run_steps(&b, half * H, n - half, again) ||
        same(cont, again, rest, "deserialized state continues bit-identically in another "
             "instance"))
        goto done;
    if (!(blob2 = serialize(&b, s2, &size2)) || size2 != size || memcmp(blob, blob2, size)) {
        fail("a deserialized state serializes to the same bytes");
        goto done;
    }
    /* a fresh instance, while the others still exist */
    b.f->free_state(b.c, &s2);
    host_close(&b);
    if (open_instance(&b, f, m, "fresh", &spec) || init_instance(&b, &spec) ||
        run_steps(&b, 0.0, n, again) || same(plain, again, (size_t)n * nr, "a fresh instance "
                                                 "reproduces the run"))
        goto done;
    rc = a.log.errors + b.log.errors ? fail("errors were logged") : 0;
done:
    if (s) a.f->free_state(a.c, &s);
    if (s2 && b.c) b.f->free_state(b.c, &s2);
    host_close(&a);
    host_close(&b);
    free(blob);
    free(blob2);
    free(plain);
    free(cont);
    free(again);
    if (!rc) printf("run_fmu simulate%s: %d steps of %g s, %zu Real variables: reset, state "
                    "restore, deserialization in a second instance and a fresh instance all "
                    "bit-identical\n", model_exchange ? " (Model Exchange)" : "", n, H, nr);
    return rc;
}

/* ------------------------------------------------------------------ soak */

static long rss_kib(void)
{
    char line[256];
    long kib = -1;
    FILE *fp = fopen("/proc/self/status", "r");
    if (!fp) return -1;
    while (fgets(line, sizeof line, fp))
        if (strncmp(line, "VmRSS:", 6) == 0) kib = strtol(line + 6, NULL, 10);
    fclose(fp);
    return kib;
}

static int open_fds(void)
{
    int n = 0;
    DIR *d = opendir("/proc/self/fd");
    struct dirent *e;
    if (!d) return -1;
    while ((e = readdir(d)) != NULL) n += e->d_name[0] != '.';
    closedir(d);
    return n - 1; /* the directory stream's own descriptor */
}

static int soak_cycle(const fmu_lib *f, const fmu_info *m, int cycle)
{
    run_spec spec = {80.0 + cycle % 50, 209.43951023931956, 1 + cycle % 3, 0, 0, 0};
    instance in;
    fmi2FMUstate s = NULL, s2 = NULL;
    size_t size = 0;
    char *blob = NULL;
    int rc = -1;
    if (host_open(&in, f, m, "soak") || init_instance(&in, &spec) ||
        run_steps(&in, 0.0, 20, NULL) || f->get_state(in.c, &s) != fmi2OK ||
        !(blob = serialize(&in, s, &size)) || f->deserialize(in.c, blob, size, &s2) != fmi2OK ||
        f->set_state(in.c, s2) != fmi2OK)
        goto done;
    rc = in.log.errors ? fail("errors were logged") : 0;
done:
    if (s) f->free_state(in.c, &s);
    if (s2) f->free_state(in.c, &s2);
    free(blob);
    host_close(&in);
    return rc;
}

static int soak(const fmu_info *m, int cycles, int reload, int check_rss)
{
    fmu_lib f;
    long rss0 = 0, rss1, warm = cycles / 10 > 20 ? cycles / 10 : 20;
    int fd0 = 0, fd1, k;
    struct timespec t0, t1;
    if (!reload && host_load(&f, m->so_path)) return -1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    if (warm >= cycles) warm = 0;
    for (k = 0; k < cycles; k++) {
        if (k == warm) {
            rss0 = rss_kib();
            fd0 = open_fds();
        }
        if (reload && host_load(&f, m->so_path)) return -1;
        if (soak_cycle(&f, m, k)) {
            fprintf(stderr, "run_fmu soak: cycle %d failed\n", k);
            return -1;
        }
        if (reload) host_unload(&f);
    }
    if (!reload) host_unload(&f);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    rss1 = rss_kib();
    fd1 = open_fds();
    printf("run_fmu soak: %d cycles%s in %.1f s; after %ld warm-up cycles RSS %ld KiB -> %ld KiB "
           "(%+ld KiB%s), open file descriptors %d -> %d\n", cycles, reload ? " (dlopen/dlclose "
           "each)" : "", (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec -
           t0.tv_nsec), warm, rss0, rss1, rss1 - rss0, check_rss ? "" : ", not checked", fd0,
           fd1);
    if (fd1 != fd0) return fail("open file descriptors grew");
    if (check_rss && rss1 - rss0 > RSS_TOLERANCE_KIB) return fail("RSS grew beyond tolerance");
    return 0;
}

/* ------------------------------------------------------------------ threads */

typedef struct {
    const fmu_lib *f;
    const fmu_info *m;
    run_spec spec;
    int n;
    double *out, *again;
    int rc;
    pthread_barrier_t *start;
} job;

/* One instance: run, and (when again is given) reset, run again and compare. */
static void *run_job(void *arg)
{
    job *j = arg;
    instance in;
    size_t len = (size_t)j->n * j->m->n_reals;
    if (j->start) pthread_barrier_wait(j->start);
    j->rc = -1;
    if (open_instance(&in, j->f, j->m, "thread", &j->spec) || init_instance(&in, &j->spec) ||
        run_steps(&in, 0.0, j->n, j->out))
        goto done;
    if (j->again && (in.f->reset(in.c) != fmi2OK || init_instance(&in, &j->spec) ||
                     run_steps(&in, 0.0, j->n, j->again) ||
                     same(j->out, j->again, len, "reset on a thread reproduces the run")))
        goto done;
    j->rc = in.log.errors ? fail("errors were logged") : 0;
done:
    host_close(&in);
    return NULL;
}

static int threads(const fmu_lib *f, const fmu_info *m, int n_threads, double t_end,
                   int model_exchange)
{
    int n = (int)(t_end / H + 0.5), k, round, rc = 0;
    size_t len = (size_t)n * m->n_reals;
    job *jobs = calloc((size_t)n_threads, sizeof *jobs);
    double **alone = calloc((size_t)n_threads, sizeof *alone);
    pthread_t *tid = calloc((size_t)n_threads, sizeof *tid);
    pthread_barrier_t start;
    if (!jobs || !alone || !tid || pthread_barrier_init(&start, NULL, (unsigned)n_threads))
        return fail("out of memory");
    for (k = 0; k < n_threads; k++) { /* each alone, one after the other */
        run_spec s = {50.0 + 20.0 * k, 150.0 + 10.0 * k, 1 + k % 3, 1 + k % 2, 1 + (k / 3) % 2,
                      model_exchange};
        jobs[k].f = f;
        jobs[k].m = m;
        jobs[k].spec = s;
        jobs[k].n = n;
        if (!(alone[k] = calloc(len, sizeof **alone)) || !(jobs[k].out = calloc(len, sizeof
            (double))) || !(jobs[k].again = calloc(len, sizeof(double))))
            return fail("out of memory");
        run_job(&jobs[k]);
        memcpy(alone[k], jobs[k].out, len * sizeof(double));
        rc |= jobs[k].rc;
    }
    for (round = 0; round < 2 && !rc; round++) { /* all at once */
        for (k = 0; k < n_threads; k++) {
            jobs[k].start = &start;
            memset(jobs[k].out, 0, len * sizeof(double));
            if (pthread_create(&tid[k], NULL, run_job, &jobs[k])) return fail("pthread_create");
        }
        for (k = 0; k < n_threads; k++) pthread_join(tid[k], NULL);
        for (k = 0; k < n_threads; k++)
            rc |= jobs[k].rc || same(alone[k], jobs[k].out, len, "a threaded run equals the "
                                     "same run alone");
    }
    for (k = 1; k < n_threads && !rc; k++)
        if (memcmp(alone[k], alone[0], len * sizeof(double)) == 0)
            rc = fail("instances with different parameters gave the same results");
    if (!rc)
        printf("run_fmu threads%s: %d instances with different parameters, %d steps each, on %d "
               "threads twice: bit-identical to each run alone; reset on every thread "
               "reproduces its run\n", model_exchange ? " (Model Exchange)" : "", n_threads, n,
               n_threads);
    pthread_barrier_destroy(&start);
    for (k = 0; k < n_threads; k++) {
        free(alone[k]);
        free(jobs[k].out);
        free(jobs[k].again);
    }
    free(alone);
    free(jobs);
    free(tid);
    return rc;
}

/* ------------------------------------------------------------------ outputs */

static int outputs(const fmu_lib *f, const fmu_info *m, double t_end, int n_set, char **set,
                   int model_exchange)
{
    double values[HOST_MAX_REALS];
    int n = (int)(t_end / H + 0.5), k, rc = -1;
    size_t i;
    instance in;
    if (host_open_as(&in, f, m, "outputs", model_exchange) ||
        f->setup(in.c, fmi2False, 0.0, 0.0, fmi2False, 0.0))
        goto done;
    for (k = 0; k < n_set; k++) {
        char name[128], *eq = strchr(set[k], '=');
        if (!eq || (size_t)(eq - set[k]) >= sizeof name) {
            host_fail(set[k]);
            goto done;
        }
        memcpy(name, set[k], (size_t)(eq - set[k]));
        name[eq - set[k]] = '\0';
        if (host_set(&in, name, eq + 1)) goto done;
    }
    if (f->enter(in.c) != fmi2OK || f->exit_init(in.c) != fmi2OK ||
        (model_exchange && me_iterate(&in)) || run_steps(&in, 0.0, n, NULL) ||
        f->get_real(in.c, m->reals, m->n_reals, values) != fmi2OK)
        goto done;
    for (i = 0; i < m->n_reals; i++)
        printf("%u %a %.17g\n", (unsigned)m->reals[i], values[i], values[i]);
    rc = in.log.errors ? host_fail("errors were logged") : 0;
done:
    host_close(&in);
    return rc;
}

/* ------------------------------------------------------------------ main */

static int has_flag(int argc, char **argv, const char *flag)
{
    int k;
    for (k = 4; k < argc; k++)
        if (strcmp(argv[k], flag) == 0) return 1;
    return 0;
}

int main(int argc, char **argv)
{
    fmu_info m;
    fmu_lib f;
    int rc;
    if (argc < 3) {
        fprintf(stderr, "usage: run_fmu FMU_DIR simulate [T] [me] | soak N [reload] [norss] | "
                "outputs T [NAME=VALUE ...] | threads N [T] [me]\n");
        return 2;
    }
    if (host_read_info(&m, argv[1])) return 1;
    if (strcmp(argv[2], "soak") == 0) {
        rc = soak(&m, argc > 3 ? atoi(argv[3]) : 2000, has_flag(argc, argv, "reload"),
                  !has_flag(argc, argv, "norss"));
    } else if (host_load(&f, m.so_path)) {
        rc = -1;
    } else {
        int me = strcmp(argv[argc - 1], "me") == 0; /* Model Exchange */
        if (me) argc--;
        if (strcmp(argv[2], "simulate") == 0)
            rc = simulate(&f, &m, argc > 3 ? atof(argv[3]) : 0.1, me);
        else if (strcmp(argv[2], "outputs") == 0 && argc > 3)
            rc = outputs(&f, &m, atof(argv[3]), argc - 4, argv + 4, me);
        else if (strcmp(argv[2], "threads") == 0)
            rc = threads(&f, &m, argc > 3 ? atoi(argv[3]) : 4, argc > 4 ? atof(argv[4]) : 0.1,
                         me);
        else
            rc = fail("unknown mode");
        host_unload(&f);
    }
    host_free_info(&m);
    return rc ? 1 : 0;
}
