/* A minimal FMI 3.0 co-simulation host in C for the same-bits check of linux64 and win64
 * (scripts/win64.sh): loads DIR/binaries/<platform>/HypoidGearPair.{so,dll} of an unzipped FMI 3.0
 * FMU, instantiates it with the instantiationToken of DIR/modelDescription.xml, steps T seconds
 * by h from the default start values and prints every Float64 output (arrays element by element)
 * as hexadecimal floating point (%a, exact) at each step's end. With "me": Model Exchange, explicit
 * Euler steps of h with an event where an event indicator changes sign or the FMU asks for one.
 * With "threads N": the run alone, then N instances at once on N threads, each of which must end
 * with the same bits.
 *
 *   run_fmu3 FMU_DIR T h [me] [threads N] */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"

#ifdef _WIN32
#include <windows.h>
#define PLATFORM "x86_64-windows"
#define SUFFIX ".dll"
#define SEP "\\"
static void *lib_open(const char *path) { return (void *)LoadLibraryA(path); }
static void lib_close(void *lib) { FreeLibrary((HMODULE)lib); }
static void *lib_symbol(void *lib, const char *name)
{
    FARPROC f = GetProcAddress((HMODULE)lib, name);
    void *p;
    memcpy(&p, &f, sizeof p);
    return p;
}
#else
#include <dlfcn.h>
#define PLATFORM "x86_64-linux"
#define SUFFIX ".so"
#define SEP "/"
static void *lib_open(const char *path) { return dlopen(path, RTLD_NOW | RTLD_LOCAL); }
static void lib_close(void *lib) { dlclose(lib); }
static void *lib_symbol(void *lib, const char *name) { return dlsym(lib, name); }
#endif

#define MAX_OUT 256
/* fn = the library's function name (dlsym gives a data pointer: copied, as ISO C has it) */
#define LOAD(fn, name)                                                                         \
    do {                                                                                       \
        void *sym_ = lib_symbol(lib, #name);                                                   \
        if (!sym_) return fprintf(stderr, "FAILED: no %s\n", #name), -1;                        \
        memcpy(&fn, &sym_, sizeof sym_);                                                       \
    } while (0)

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                   fmi3String message)
{
    (void)env;
    if (status >= fmi3Warning) fprintf(stderr, "[%s] %s\n", category, message);
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    long n;
    char *s;
    if (!f || fseek(f, 0, SEEK_END) || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET)) return NULL;
    if ((s = malloc((size_t)n + 1)) && fread(s, 1, (size_t)n, f) == (size_t)n) s[n] = '\0';
    fclose(f);
    return s;
}

/* The value of attribute name="..." in the tag starting at tag (within the tag only). */
static int attribute(const char *tag, const char *name, char *out, size_t n)
{
    const char *end = strchr(tag, '>'), *p = strstr(tag, name), *q;
    if (!p || (end && p > end) || !(q = strchr(p += strlen(name), '"'))) return -1;
    if ((size_t)(q - p) >= n) return -1;
    memcpy(out, p, (size_t)(q - p));
    out[q - p] = '\0';
    return 0;
}

/* The Float64 outputs: their value references and element counts. */
static size_t outputs(const char *xml, fmi3ValueReference *vr, size_t *count)
{
    const char *p = xml;
    size_t n = 0;
    char buf[64];
    while ((p = strstr(p, "<Float64 ")) && n < MAX_OUT) {
        const char *close = strchr(p, '>'), *dim = strstr(p, "<Dimension start=\"");
        p++;
        if (attribute(p, "causality=\"", buf, sizeof buf) || strcmp(buf, "output") != 0) continue;
        attribute(p, "valueReference=\"", buf, sizeof buf);
        vr[n] = (fmi3ValueReference)strtoul(buf, NULL, 10);
        count[n] = 1;
        if (close && close[-1] != '/' && dim && dim < strstr(p, "</Float64>"))
            count[n] = strtoul(dim + strlen("<Dimension start=\""), NULL, 10);
        n++;
    }
    return n;
}

typedef struct {
    fmi3InstantiateCoSimulationTYPE *instantiate_cs;
    fmi3InstantiateModelExchangeTYPE *instantiate_me;
    fmi3EnterInitializationModeTYPE *enter;
    fmi3ExitInitializationModeTYPE *exit_init;
    fmi3DoStepTYPE *do_step;
    fmi3GetFloat64TYPE *get;
    fmi3TerminateTYPE *terminate;
    fmi3FreeInstanceTYPE *free_instance;
    fmi3UpdateDiscreteStatesTYPE *update;
    fmi3EnterContinuousTimeModeTYPE *continuous;
    fmi3EnterEventModeTYPE *event_mode;
    fmi3CompletedIntegratorStepTYPE *completed;
    fmi3SetTimeTYPE *set_time;
    fmi3GetContinuousStatesTYPE *get_x;
    fmi3SetContinuousStatesTYPE *set_x;
    fmi3GetContinuousStateDerivativesTYPE *get_dx;
    fmi3GetEventIndicatorsTYPE *get_z;
    fmi3GetNumberOfContinuousStatesTYPE *nx;
    fmi3GetNumberOfEventIndicatorsTYPE *nz;
} fns;

static int load(fns *f, void *lib)
{
    LOAD(f->instantiate_cs, fmi3InstantiateCoSimulation);
    LOAD(f->instantiate_me, fmi3InstantiateModelExchange);
    LOAD(f->enter, fmi3EnterInitializationMode);
    LOAD(f->exit_init, fmi3ExitInitializationMode);
    LOAD(f->do_step, fmi3DoStep);
    LOAD(f->get, fmi3GetFloat64);
    LOAD(f->terminate, fmi3Terminate);
    LOAD(f->free_instance, fmi3FreeInstance);
    LOAD(f->update, fmi3UpdateDiscreteStates);
    LOAD(f->continuous, fmi3EnterContinuousTimeMode);
    LOAD(f->event_mode, fmi3EnterEventMode);
    LOAD(f->completed, fmi3CompletedIntegratorStep);
    LOAD(f->set_time, fmi3SetTime);
    LOAD(f->get_x, fmi3GetContinuousStates);
    LOAD(f->set_x, fmi3SetContinuousStates);
    LOAD(f->get_dx, fmi3GetContinuousStateDerivatives);
    LOAD(f->get_z, fmi3GetEventIndicators);
    LOAD(f->nx, fmi3GetNumberOfContinuousStates);
    LOAD(f->nz, fmi3GetNumberOfEventIndicators);
    return 0;
}

/* The event: the discrete update, then back to continuous-time mode. */
static int event(const fns *f, fmi3Instance inst, int from_continuous)
{
    fmi3Boolean b[5];
    fmi3Float64 next;
    if (from_continuous && f->event_mode(inst)) return -1;
    return f->update(inst, &b[0], &b[1], &b[2], &b[3], &b[4], &next) || f->continuous(inst) ? -1
                                                                                          : 0;
}

#define MAX_X 64

/* One explicit Euler step of h in Model Exchange, with an event where an indicator changes
 * sign or the FMU asks for one. */
static int euler(const fns *f, fmi3Instance inst, double t, double h)
{
    double x[MAX_X], dx[MAX_X], z0[MAX_X], z1[MAX_X];
    size_t nx, nz, k;
    fmi3Boolean enter, terminate;
    int crossed = 0;
    if (f->nx(inst, &nx) || f->nz(inst, &nz) || nx > MAX_X || nz > MAX_X ||
        f->get_z(inst, z0, nz) || f->get_x(inst, x, nx) || f->get_dx(inst, dx, nx))
        return -1;
    for (k = 0; k < nx; k++) x[k] += h * dx[k];
    if (f->set_time(inst, t + h) || f->set_x(inst, x, nx) || f->get_z(inst, z1, nz) ||
        f->completed(inst, fmi3True, &enter, &terminate))
        return -1;
    for (k = 0; k < nz; k++) crossed |= (z0[k] < 0.0) != (z1[k] < 0.0);
    return crossed || enter ? event(f, inst, 1) : 0;
}

/* One run: instantiate, initialise, steps of h up to t_end; prints each step's outputs (print)
 * or keeps the last ones in values. */
typedef struct {
    const fns *f;
    const char *token, *resources;
    const fmi3ValueReference *vr;
    size_t n, total;
    double t_end, h;
    int me, print, rc;
    double values[4 * MAX_OUT];
} job;

static int run(job *j)
{
    const fns *f = j->f;
    double t = 0.0;
    size_t k, e;
    fmi3Boolean event_needed, terminate, early;
    fmi3Float64 last;
    fmi3Instance inst =
        j->me ? f->instantiate_me("run_fmu3", j->token, j->resources, fmi3False, fmi3False, NULL,
                                  logger)
              : f->instantiate_cs("run_fmu3", j->token, j->resources, fmi3False, fmi3False,
                                  fmi3False, fmi3False, NULL, 0, NULL, logger, NULL);
    if (!inst || f->enter(inst, fmi3False, 0.0, 0.0, fmi3False, 0.0) || f->exit_init(inst) ||
        (j->me && event(f, inst, 0)))
        return fprintf(stderr, "FAILED: initialization\n"), -1;
    for (k = 0; t < j->t_end - 0.5 * j->h; k++, t = k * j->h) {
        last = (k + 1) * j->h;
        if ((j->me ? euler(f, inst, t, j->h) != 0
                   : f->do_step(inst, t, j->h, fmi3True, &event_needed, &terminate, &early,
                                &last) != fmi3OK) ||
            f->get(inst, j->vr, j->n, j->values, j->total))
            return fprintf(stderr, "FAILED: step at t = %g\n", t), -1;
        if (!j->print) continue;
        printf("%a", last);
        for (e = 0; e < j->total; e++) printf(" %a", j->values[e]);
        printf("\n");
    }
    f->terminate(inst);
    f->free_instance(inst);
    return 0;
}

static void *run_thread(void *arg)
{
    job *j = arg;
    j->rc = run(j);
    return NULL;
}

/* n_threads instances at once, each on its own thread: every one must end with the outputs of
 * the same run alone. */
static int threads(const job *alone, int n_threads)
{
    job jobs[16];
    pthread_t tid[16];
    int k, bad = 0;
    if (n_threads < 1 || n_threads > 16) return fprintf(stderr, "FAILED: 1..16 threads\n"), -1;
    for (k = 0; k < n_threads; k++) {
        jobs[k] = *alone;
        if (pthread_create(&tid[k], NULL, run_thread, &jobs[k]))
            return fprintf(stderr, "FAILED: pthread_create\n"), -1;
    }
    for (k = 0; k < n_threads; k++) pthread_join(tid[k], NULL);
    for (k = 0; k < n_threads; k++)
        bad |= jobs[k].rc ||
               memcmp(jobs[k].values, alone->values, alone->total * sizeof *alone->values);
    if (bad) return fprintf(stderr, "FAILED: a thread's outputs differ from the run alone\n"), -1;
    printf("run_fmu3 threads: %d %s instances on %d threads, outputs bit-identical to the run "
           "alone\n", n_threads, alone->me ? "Model Exchange" : "co-simulation", n_threads);
    return 0;
}

int main(int argc, char **argv)
{
    char path[4096], token[128], resources[4096];
    char *xml;
    void *lib;
    fmi3ValueReference vr[MAX_OUT];
    size_t count[MAX_OUT], n, k, total = 0;
    fns f;
    job j;
    int n_threads = 0, rc;
    memset(&j, 0, sizeof j);
    for (k = 4; k < (size_t)argc; k++) {
        if (strcmp(argv[k], "me") == 0)
            j.me = 1;
        else if (strcmp(argv[k], "threads") == 0 && k + 1 < (size_t)argc)
            n_threads = atoi(argv[++k]);
        else
            argc = 0;
    }
    if (argc < 4) return fprintf(stderr, "usage: run_fmu3 FMU_DIR T h [me] [threads N]\n"), 2;
    j.t_end = atof(argv[2]);
    j.h = atof(argv[3]);
    snprintf(path, sizeof path, "%s" SEP "modelDescription.xml", argv[1]);
    if (!(xml = read_file(path)) || attribute(strstr(xml, "<fmiModelDescription"),
                                              "instantiationToken=\"", token, sizeof token))
        return fprintf(stderr, "FAILED: %s\n", path), 1;
    n = outputs(xml, vr, count);
    for (k = 0; k < n; k++) total += count[k];
    snprintf(path, sizeof path, "%s" SEP "binaries" SEP PLATFORM SEP "HypoidGearPair" SUFFIX,
             argv[1]);
    snprintf(resources, sizeof resources, "%s" SEP "resources" SEP, argv[1]);
    if (!(lib = lib_open(path))) return fprintf(stderr, "FAILED: cannot load %s\n", path), 1;
    if (load(&f, lib)) return 1;
    j.f = &f;
    j.token = token;
    j.resources = resources;
    j.vr = vr;
    j.n = n;
    j.total = total;
    j.print = n_threads == 0;
    rc = run(&j) || (n_threads && threads(&j, n_threads));
    lib_close(lib);
    free(xml);
    return rc ? 1 : 0;
}
