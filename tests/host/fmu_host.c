/* The shared parts of the C FMI hosts: see fmu_host.h. */
#define _XOPEN_SOURCE 700 /* POSIX 2008 with realpath (Windows: _wfullpath) */
#include "fmu_host.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

int host_fail(const char *what)
{
    fprintf(stderr, "FAILED: %s\n", what);
    return -1;
}

/* ------------------------------------------------------------------ the FMU's functions */

/* ------------------------------------------------------------------ the platform */

#ifdef _WIN32
#define HOST_PLATFORM "win64"
#define HOST_LIB_SUFFIX ".dll"
static void *lib_open(const char *path)
{
    return (void *)LoadLibraryA(path);
}

static void *lib_symbol(void *lib, const char *name)
{
    FARPROC f = GetProcAddress((HMODULE)lib, name);
    void *p;
    memcpy(&p, &f, sizeof p); /* a function pointer as the data pointer dlsym also returns */
    return p;
}

static void lib_close(void *lib)
{
    FreeLibrary((HMODULE)lib);
}

static const char *lib_error(void)
{
    return "Windows error (GetLastError)";
}

/* The absolute path of the directory path (in the ANSI code page, as main's argv) in UTF-8, the
 * encoding of FMI's file URIs. */
static int absolute_path(const char *path, char *out)
{
    wchar_t wide[PATH_MAX], full[PATH_MAX];
    DWORD attr;
    if (!MultiByteToWideChar(CP_ACP, 0, path, -1, wide, PATH_MAX) ||
        !_wfullpath(full, wide, PATH_MAX))
        return -1;
    attr = GetFileAttributesW(full);
    if (attr == INVALID_FILE_ATTRIBUTES || !(attr & FILE_ATTRIBUTE_DIRECTORY)) return -1;
    return WideCharToMultiByte(CP_UTF8, 0, full, -1, out, PATH_MAX, NULL, NULL) ? 0 : -1;
}
#else
#define HOST_PLATFORM "linux64"
#define HOST_LIB_SUFFIX ".so"
static void *lib_open(const char *path)
{
    return dlopen(path, RTLD_NOW | RTLD_LOCAL);
}

static void *lib_symbol(void *lib, const char *name)
{
    return dlsym(lib, name);
}

static void lib_close(void *lib)
{
    dlclose(lib);
}

static const char *lib_error(void)
{
    return dlerror();
}

static int absolute_path(const char *path, char *out)
{
    return realpath(path, out) ? 0 : -1;
}
#endif

/* ------------------------------------------------------------------ the FMU's functions */

static void *symbol(void *so, const char *name)
{
    void *p = lib_symbol(so, name);
    if (!p) fprintf(stderr, "fmu_host: %s is missing: %s\n", name, lib_error());
    return p;
}

int host_load(fmu_lib *f, const char *so_path)
{
    memset(f, 0, sizeof *f);
    if (!(f->so = lib_open(so_path))) {
        fprintf(stderr, "fmu_host: cannot load %s: %s\n", so_path, lib_error());
        return -1;
    }
#define SYM(field, name) (*(void **)&f->field = symbol(f->so, name)) != NULL
    if (SYM(instantiate, "fmi2Instantiate") && SYM(free_instance, "fmi2FreeInstance") &&
        SYM(setup, "fmi2SetupExperiment") && SYM(enter, "fmi2EnterInitializationMode") &&
        SYM(exit_init, "fmi2ExitInitializationMode") && SYM(terminate, "fmi2Terminate") &&
        SYM(reset, "fmi2Reset") && SYM(get_real, "fmi2GetReal") &&
        SYM(get_integer, "fmi2GetInteger") && SYM(set_real, "fmi2SetReal") &&
        SYM(set_integer, "fmi2SetInteger") && SYM(set_boolean, "fmi2SetBoolean") &&
        SYM(set_string, "fmi2SetString") &&
        SYM(set_real_input_derivatives, "fmi2SetRealInputDerivatives") &&
        SYM(do_step, "fmi2DoStep") && SYM(get_state, "fmi2GetFMUstate") &&
        SYM(set_state, "fmi2SetFMUstate") && SYM(free_state, "fmi2FreeFMUstate") &&
        SYM(state_size, "fmi2SerializedFMUstateSize") &&
        SYM(serialize, "fmi2SerializeFMUstate") && SYM(deserialize, "fmi2DeSerializeFMUstate")) {
#define ME_SYM(field, name) (*(void **)&f->field = lib_symbol(f->so, name))
        ME_SYM(enter_event_mode, "fmi2EnterEventMode");
        ME_SYM(new_discrete_states, "fmi2NewDiscreteStates");
        ME_SYM(enter_continuous_time_mode, "fmi2EnterContinuousTimeMode");
        ME_SYM(completed_integrator_step, "fmi2CompletedIntegratorStep");
        ME_SYM(set_time, "fmi2SetTime");
        ME_SYM(set_continuous_states, "fmi2SetContinuousStates");
        ME_SYM(get_continuous_states, "fmi2GetContinuousStates");
        ME_SYM(get_derivatives, "fmi2GetDerivatives");
        ME_SYM(get_event_indicators, "fmi2GetEventIndicators");
        ME_SYM(get_nominals, "fmi2GetNominalsOfContinuousStates");
#undef ME_SYM
        return 0;
    }
#undef SYM
    lib_close(f->so);
    return -1;
}

void host_unload(fmu_lib *f)
{
    if (f->so) lib_close(f->so);
    f->so = NULL;
}

/* ------------------------------------------------------------------ the model description */

static char *read_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    char *buf;
    long n;
    if (!fp) return NULL;
    if (fseek(fp, 0, SEEK_END) || (n = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET) ||
        !(buf = malloc((size_t)n + 1))) {
        fclose(fp);
        return NULL;
    }
    if (fread(buf, 1, (size_t)n, fp) != (size_t)n) {
        free(buf);
        buf = NULL;
    } else {
        buf[n] = '\0';
    }
    fclose(fp);
    return buf;
}

/* The text of attribute attr after position p, copied into out. */
static int attribute(const char *p, const char *attr, char *out, size_t len)
{
    char key[64];
    const char *v, *end;
    snprintf(key, sizeof key, " %s=\"", attr);
    if (!(v = strstr(p, key))) return -1;
    v += strlen(key);
    if (!(end = strchr(v, '"')) || (size_t)(end - v) >= len) return -1;
    memcpy(out, v, (size_t)(end - v));
    out[end - v] = '\0';
    return 0;
}

long host_value_reference(const fmu_info *m, const char *name)
{
    char key[160], vr[32];
    const char *p;
    snprintf(key, sizeof key, "<ScalarVariable name=\"%s\"", name);
    if (!(p = strstr(m->xml, key)) || attribute(p, "valueReference", vr, sizeof vr)) return -1;
    return strtol(vr, NULL, 10);
}

/* file:// URI of a local path, percent-encoding all but unreserved characters, '/' and ':'; a
 * Windows path "C:\\dir" becomes file:///C:/dir. */
static char *file_uri(const char *path)
{
    static const char hex[] = "0123456789ABCDEF";
    char *uri = malloc(3 * strlen(path) + 9), *o;
    if (!uri) return NULL;
    strcpy(uri, path[0] && path[1] == ':' ? "file:///" : "file://");
    for (o = uri + strlen(uri); *path; path++) {
        unsigned char ch = (unsigned char)(*path == '\\' ? '/' : *path);
        if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
            strchr("-._~/:", ch)) {
            *o++ = (char)ch;
        } else {
            *o++ = '%';
            *o++ = hex[ch >> 4];
            *o++ = hex[ch & 15];
        }
    }
    *o = '\0';
    return uri;
}

int host_read_info(fmu_info *m, const char *dir)
{
    char path[PATH_MAX], id[128], real_dir[PATH_MAX];
    const char *p;
    memset(m, 0, sizeof *m);
    snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
    if (!(m->xml = read_file(path)) || attribute(m->xml, "guid", m->guid, sizeof m->guid) ||
        !(p = strstr(m->xml, "<CoSimulation")) ||
        attribute(p, "modelIdentifier", id, sizeof id)) {
        fprintf(stderr, "fmu_host: cannot read %s\n", path);
        return -1;
    }
    snprintf(m->so_path, sizeof m->so_path, "%s/binaries/" HOST_PLATFORM "/%s" HOST_LIB_SUFFIX,
             dir, id);
    snprintf(path, sizeof path, "%s/resources", dir); /* none: a NULL resource location */
    if (!absolute_path(path, real_dir) && !(m->resource_uri = file_uri(real_dir))) {
        fprintf(stderr, "fmu_host: out of memory\n");
        return -1;
    }
    if ((p = strstr(m->xml, "<Derivatives>")) != NULL) {
        const char *end = strstr(p, "</Derivatives>");
        for (; (p = strstr(p + 1, "<Unknown ")) != NULL && end && p < end;) m->nx++;
    }
    if (!attribute(m->xml, "numberOfEventIndicators", id, sizeof id))
        m->nz = (size_t)strtoul(id, NULL, 10);
    if (m->nx > HOST_MAX_STATES || m->nz > HOST_MAX_STATES) {
        fprintf(stderr, "fmu_host: more than %d states or event indicators\n", HOST_MAX_STATES);
        return -1;
    }
    for (p = m->xml; (p = strstr(p, "<ScalarVariable ")) != NULL; p++) {
        const char *close = strstr(p, "</ScalarVariable>"), *real = strstr(p, "<Real");
        char vr[32];
        if (real && close && real < close && !attribute(p, "valueReference", vr, sizeof vr) &&
            m->n_reals < HOST_MAX_REALS)
            m->reals[m->n_reals++] = (fmi2ValueReference)strtoul(vr, NULL, 10);
    }
    return m->n_reals ? 0 : -1;
}

void host_free_info(fmu_info *m)
{
    free(m->resource_uri);
    free(m->xml);
}

/* ------------------------------------------------------------------ logging */

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    char text[2048];
    log_env *e = env;
    va_list ap;
    va_start(ap, message);
    vsnprintf(text, sizeof text, message, ap); /* the message is a format string */
    va_end(ap);
    if (status >= fmi2Error && e) e->errors++;
    if (status >= fmi2Error || getenv("RUN_FMU_VERBOSE"))
        fprintf(stderr, "[%s] %s (%d): %s\n", name, category, (int)status, text);
}

/* ------------------------------------------------------------------ instances */

int host_open(instance *in, const fmu_lib *f, const fmu_info *m, const char *name)
{
    return host_open_as(in, f, m, name, 0);
}

int host_open_as(instance *in, const fmu_lib *f, const fmu_info *m, const char *name,
                 int model_exchange)
{
    memset(in, 0, sizeof *in);
    in->model_exchange = model_exchange;
    if (model_exchange && !(f->get_derivatives && m->nx)) return host_fail("no Model Exchange");
    in->f = f;
    in->m = m;
    in->cb.logger = logger;
    in->cb.allocateMemory = calloc;
    in->cb.freeMemory = free;
    in->cb.componentEnvironment = &in->log;
    in->c = f->instantiate(name, model_exchange ? fmi2ModelExchange : fmi2CoSimulation, m->guid,
                           m->resource_uri, &in->cb, fmi2False,
                           getenv("RUN_FMU_VERBOSE") ? fmi2True : fmi2False);
    return in->c ? 0 : host_fail("fmi2Instantiate");
}

void host_close(instance *in)
{
    if (!in->c) return;
    in->f->terminate(in->c);
    in->f->free_instance(in->c);
    in->c = NULL;
}

int host_set_int(instance *in, const char *name, int value)
{
    long vr = host_value_reference(in->m, name);
    fmi2ValueReference r = (fmi2ValueReference)vr;
    return vr >= 0 && in->f->set_integer(in->c, &r, 1, &value) == fmi2OK ? 0 : host_fail(name);
}

int host_set_real(instance *in, const char *name, double value)
{
    long vr = host_value_reference(in->m, name);
    fmi2ValueReference r = (fmi2ValueReference)vr;
    return vr >= 0 && in->f->set_real(in->c, &r, 1, &value) == fmi2OK ? 0 : host_fail(name);
}

/* The value of enumeration item `item` of the type the variable element `elem` declares. */
static int enum_item(const fmu_info *m, const char *elem, const char *item, int *value)
{
    char type[128], key[192], v[32];
    const char *t, *end, *q;
    if (strncmp(elem, "<Enumeration", 12) || attribute(elem, "declaredType", type, sizeof type))
        return -1;
    snprintf(key, sizeof key, "<SimpleType name=\"%s\"", type);
    if (!(t = strstr(m->xml, key)) || !(end = strstr(t, "</SimpleType>"))) return -1;
    snprintf(key, sizeof key, "<Item name=\"%s\"", item);
    if (!(q = strstr(t, key)) || q > end || attribute(q, "value", v, sizeof v)) return -1;
    *value = (int)strtol(v, NULL, 10);
    return 0;
}

int host_set(instance *in, const char *name, const char *text)
{
    char key[160], *rest;
    const char *p, *elem;
    double x;
    int i;
    snprintf(key, sizeof key, "<ScalarVariable name=\"%s\"", name);
    if (!(p = strstr(in->m->xml, key)) || !(elem = strchr(p, '>'))) return host_fail(name);
    elem += strspn(elem + 1, " \t\r\n") + 1; /* the type element */
    x = strtod(text, &rest);
    if (strncmp(elem, "<Real", 5) == 0) return *rest ? host_fail(text) : host_set_real(in, name, x);
    if (strncmp(elem, "<Boolean", 8) == 0) {
        fmi2Boolean b = strcmp(text, "true") == 0 || (!*rest && x != 0.0);
        fmi2ValueReference r = (fmi2ValueReference)host_value_reference(in->m, name);
        return in->f->set_boolean(in->c, &r, 1, &b) == fmi2OK ? 0 : host_fail(name);
    }
    if (strncmp(elem, "<String", 7) == 0) { /* a data file's name */
        fmi2ValueReference r = (fmi2ValueReference)host_value_reference(in->m, name);
        return in->f->set_string(in->c, &r, 1, &text) == fmi2OK ? 0 : host_fail(name);
    }
    if (!*rest && x == (int)x) return host_set_int(in, name, (int)x);
    return enum_item(in->m, elem, text, &i) ? host_fail(text) : host_set_int(in, name, i);
}
