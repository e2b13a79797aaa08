/* A minimal FMI 3.0 co-simulation host in C for the same-bits check of linux64 and win64
 * (scripts/win64.sh): loads DIR/binaries/<platform>/HypoidGearPair.{so,dll} of an unzipped FMI 3.0
 * FMU, instantiates it with the instantiationToken of DIR/modelDescription.xml, steps T seconds
 * by h from the default start values and prints every Float64 output (arrays element by element)
 * as hexadecimal floating point (%a, exact) at each step's end.
 *
 *   run_fmu3 FMU_DIR T h */
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
        if (!sym_) return fprintf(stderr, "FAILED: no %s\n", #name), 1;                        \
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

int main(int argc, char **argv)
{
    char path[4096], token[128], resources[4096];
    char *xml;
    void *lib;
    fmi3ValueReference vr[MAX_OUT];
    size_t count[MAX_OUT], n, k, e, total = 0;
    double t = 0.0, t_end, h, values[4 * MAX_OUT];
    fmi3Instance inst;
    fmi3Boolean event, terminate, early;
    fmi3Float64 last;
    fmi3InstantiateCoSimulationTYPE *instantiate;
    fmi3EnterInitializationModeTYPE *enter;
    fmi3ExitInitializationModeTYPE *exit_init;
    fmi3DoStepTYPE *do_step;
    fmi3GetFloat64TYPE *get;
    fmi3TerminateTYPE *terminate_fn;
    fmi3FreeInstanceTYPE *free_instance;
    if (argc != 4) return fprintf(stderr, "usage: run_fmu3 FMU_DIR T h\n"), 2;
    t_end = atof(argv[2]);
    h = atof(argv[3]);
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
    LOAD(instantiate, fmi3InstantiateCoSimulation);
    LOAD(enter, fmi3EnterInitializationMode);
    LOAD(exit_init, fmi3ExitInitializationMode);
    LOAD(do_step, fmi3DoStep);
    LOAD(get, fmi3GetFloat64);
    LOAD(terminate_fn, fmi3Terminate);
    LOAD(free_instance, fmi3FreeInstance);
    inst = instantiate("run_fmu3", token, resources, fmi3False, fmi3False,
                                           fmi3False, fmi3False, NULL, 0, NULL, logger, NULL);
    if (!inst || enter(inst, fmi3False, 0.0, 0.0, fmi3False, 0.0) ||
        exit_init(inst))
        return fprintf(stderr, "FAILED: initialization\n"), 1;
    for (k = 0; t < t_end - 0.5 * h; k++, t = k * h) {
        if (do_step(inst, t, h, fmi3True, &event, &terminate, &early, &last) ||
            get(inst, vr, n, values, total))
            return fprintf(stderr, "FAILED: step at t = %g\n", t), 1;
        printf("%a", last);
        for (e = 0; e < total; e++) printf(" %a", values[e]);
        printf("\n");
    }
    terminate_fn(inst);
    free_instance(inst);
    lib_close(lib);
    free(xml);
    return 0;
}
