/* libFuzzer target for the FMI 2.0 and FMI 3.0 interfaces of the FMU, linked statically with the
 * FMU sources (all built with AddressSanitizer + UndefinedBehaviorSanitizer).
 *
 * The input is a little program: a first byte choosing how to instantiate (co-simulation or
 * Model Exchange), then operations, each
 * an opcode byte and its arguments taken from the following bytes: fmi2Set/fmi2Get on any value
 * reference (known or not) with raw or typical values, data files written from the input and
 * named in gear_set_file / lubricant_file, SetupExperiment, Enter/Exit, DoStep with good and bad
 * times, FMU states (get, set, free, serialize, deserialize raw or mutated bytes), Reset,
 * Terminate, logging categories, input derivatives, status queries, NULL arrays, a second
 * instance, free and instantiate again; Model Exchange's modes, time, states (set from the
 * input, of the right or a wrong count), derivatives, event indicators, nominals, completed
 * integrator steps and explicit Euler steps of the host. Opcode 15 with a small argument is an
 * FMI 3.0 operation on a third instance (fmi3_op): instantiate (co-simulation or Model
 * Exchange) / free, initialization with fuzzed times, typed get and set of value references
 * (arrays, time, event indicators, unknown ones) with fuzzed nValues, DoStep, Model Exchange's
 * calls, FMU states and (mutated) serialized states, reset, terminate and the functions it does
 * not support.
 *
 * Beyond the sanitizers, two properties of the interface abort the run (and so are findings):
 * a call returning fmi2Error without a log message, and fmi2GetReal or fmi2GetDerivatives
 * returning fmi2OK with a value that is not finite. The logger formats each message as printf would, so an unescaped
 * '%' in a message is caught too.
 *
 * Input derivatives are clamped to +-1e8: a larger ramp is refused only when it leaves an input's
 * range within the step, and a long step of a legal but violent ramp is slow, not wrong.
 *
 * HG_FUZZ_WRITE_SEEDS=DIR in the environment: write a seed corpus into DIR and exit.
 * HG_FUZZ_TMPDIR=DIR: where the data files written from the input go (default /tmp). */
#define _XOPEN_SOURCE 700
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fmi2Functions.h"
#include "fmi3Functions.h"
#include "hg_vars.h"

#ifndef HG_FUZZ_RESOURCE_DIR
#error "compile with -DHG_FUZZ_RESOURCE_DIR=\"/abs/path/to/resources\""
#endif

#define MAX_STEPS 24       /* DoStep calls per input: keeps one input fast */
#define DERIVATIVE_LIMIT 1e8

/* ------------------------------------------------------------------ reading the input */

typedef struct {
    const uint8_t *p, *end;
} input;

static unsigned u8(input *in) { return in->p < in->end ? *in->p++ : 0; }

static unsigned u16(input *in) { return u8(in) | u8(in) << 8; }

static uint32_t u32(input *in) { return (uint32_t)u16(in) | (uint32_t)u16(in) << 16; }

static uint64_t raw_bits(input *in)
{
    uint64_t low = u32(in);
    return low | (uint64_t)u32(in) << 32;
}

static double raw_double(input *in)
{
    uint64_t bits = raw_bits(in);
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* Any 64-bit integer (a double's conversion would be undefined for NaN and out-of-range values) */
static int64_t raw_int64(input *in)
{
    uint64_t bits = raw_bits(in);
    int64_t i;
    memcpy(&i, &bits, sizeof i);
    return i;
}

/* A typical value most of the time, raw bits otherwise. */
static double value(input *in)
{
    static const double typical[] = {0.0, -0.0, 1.0, -1.0, 0.5, 100.0, 313.15, 209.4, 1e-9,
                                     1e-3, 2.0, 3.0, 50.0, 1e6, -1e6, 1e300, -1e300, 5e-324};
    unsigned k = u8(in);
    if (k < 200) return typical[k % (sizeof typical / sizeof *typical)];
    if (k < 230) return (double)(int8_t)u8(in);
    if (k < 240) return k == 230 ? NAN : k == 231 ? INFINITY : k == 232 ? -INFINITY : 1e-300;
    return raw_double(in);
}

static fmi2ValueReference vr_of(input *in)
{
    unsigned k = u8(in);
    if (k < 240) return (fmi2ValueReference)(k % (HG_NUM_VARS + 4)); /* + FMI 3.0's time */
    return k == 240 ? 0xFFFFFFFFu : k == 241 ? 0x80000000u : (fmi2ValueReference)u32(in);
}

/* ------------------------------------------------------------------ the host side */

static char resource_uri[4096];
static char tmp_dir[4096] = "";
static char data_path[2][4200];

typedef struct {
    long messages; /* log messages received */
} log_count;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    char text[4096];
    va_list ap;
    (void)name;
    (void)status;
    (void)category;
    va_start(ap, message);
    vsnprintf(text, sizeof text, message, ap); /* hosts format the message: '%' must be escaped */
    va_end(ap);
    if (env) ((log_count *)env)->messages++;
}

typedef struct {
    fmi2Component c;
    fmi2CallbackFunctions cb;
    log_count log;
    int has_logger;
    int error_on, all_on; /* log categories logStatusError and logAll */
    double t;
} slot;

/* A call returning fmi2Error must have said why (when there is a logger to say it to). */
static void require_message(slot *s, long before, fmi2Status status)
{
    int heard = s->has_logger && (s->error_on || s->all_on);
    if (status == fmi2Error && heard && s->log.messages == before) {
        fprintf(stderr, "fuzz_fmi2: fmi2Error without a log message\n");
        abort();
    }
    if (status == fmi2Fatal || status == fmi2Pending) {
        fprintf(stderr, "fuzz_fmi2: unexpected status %d\n", (int)status);
        abort();
    }
}

static void percent_encode(const char *path, char *out, size_t len)
{
    static const char hex[] = "0123456789ABCDEF";
    size_t n = snprintf(out, len, "file://");
    for (; *path && n + 4 < len; path++) {
        unsigned char ch = (unsigned char)*path;
        if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
            strchr("-._~/", ch)) {
            out[n++] = (char)ch;
        } else {
            out[n++] = '%';
            out[n++] = hex[ch >> 4];
            out[n++] = hex[ch & 15];
        }
    }
    out[n] = '\0';
}

static void remove_tmp(void)
{
    if (!tmp_dir[0]) return;
    unlink(data_path[0]);
    unlink(data_path[1]);
    rmdir(tmp_dir);
}

static void open_slot(slot *s, input *in)
{
    static const char *const uris[] = {NULL, "", "file:///nonexistent", "http://x/r",
                                       "file:///a%zz", "file://host/r"};
    unsigned how = u8(in);
    const char *uri = resource_uri;
    char name[32];
    memset(s, 0, sizeof *s);
    s->cb.logger = logger;
    s->cb.allocateMemory = calloc;
    s->cb.freeMemory = free;
    s->cb.componentEnvironment = &s->log;
    s->has_logger = (how & 1) == 0;
    s->error_on = 1;
    s->all_on = (how >> 7) & 1;
    if (!s->has_logger) s->cb.logger = NULL;
    if ((how >> 1) % 8 >= 6) uri = uris[((how >> 1) % 8 + (how >> 4)) % 6];
    snprintf(name, sizeof name, "fuzz%u", how);
    s->c = fmi2Instantiate(how == 255 ? "" : name,
                           (how >> 6) & 1 ? fmi2ModelExchange : fmi2CoSimulation, HG_GUID, uri,
                           &s->cb, fmi2False, (how >> 7) & 1);
    s->t = 0.0;
}

static void close_slot(slot *s)
{
    if (s->c) fmi2FreeInstance(s->c);
    s->c = NULL;
}

/* ------------------------------------------------------------------ FMI 3.0 */

typedef struct {
    fmi3Instance c;
    log_count log;
    fmi3FMUState state;
    double t;
} slot3;

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                    fmi3String message)
{
    (void)status;
    (void)category;
    if (strlen(message) > 4096) abort();
    ((log_count *)env)->messages++;
}

static char resource_path[4096];

static void open3(slot3 *s, input *in)
{
    unsigned how = u8(in);
    const char *token = how % 16 == 15 ? HG_GUID : HG_TOKEN_FMI3;
    const char *res = how % 16 == 14 ? "/nonexistent/" : how % 16 == 13 ? NULL : resource_path;
    if (how % 16 >= 6 && how % 16 <= 8)
        s->c = fmi3InstantiateModelExchange("fuzz3me", token, res, fmi3False, (how >> 7) & 1,
                                            &s->log, logger3);
    else
        s->c = fmi3InstantiateCoSimulation(how % 32 == 12 ? " " : "fuzz3", token, res,
                                           fmi3False, (how >> 7) & 1, (how >> 6) & 1,
                                           (how >> 5) & 1, NULL, 0, &s->log, logger3, NULL);
    s->t = 0.0;
}

static void close3(slot3 *s)
{
    if (s->state) fmi3FreeFMUState(s->c, &s->state);
    if (s->c) fmi3FreeInstance(s->c);
    s->c = NULL;
    s->state = NULL;
}

/* Typed access: up to 8 value references (arrays count 3), nValues exact or fuzzed. */
static fmi3Status access3(slot3 *s, input *in, int set)
{
    fmi3ValueReference vr[8];
    double r[32];
    fmi3Int32 i32[32];
    fmi3Int64 i64[32];
    fmi3Boolean b[32];
    fmi3String str[32];
    unsigned kind = u8(in) % 5, n = u8(in) % 9, k, nv = 0;
    fmi3Status st;
    for (k = 0; k < n; k++) {
        vr[k] = vr_of(in);
        nv += vr[k] < HG_NUM_VARS && hg_fmi3_vars[vr[k]].count ? hg_fmi3_vars[vr[k]].count : 1;
    }
    if (u8(in) < 32) nv = u8(in) % 32;
    if (nv > 32) nv = 32;
    for (k = 0; set && k < 32; k++) {
        r[k] = value(in);
        i32[k] = (fmi3Int32)(int8_t)u8(in);
        i64[k] = u8(in) < 250 ? (fmi3Int64)(u8(in) % 6) : (fmi3Int64)raw_int64(in);
        b[k] = u8(in) & 1;
        str[k] = u8(in) < 8 ? NULL : "";
    }
    switch (kind) {
    case 0:
        if (set) return fmi3SetFloat64(s->c, vr, n, r, nv);
        st = fmi3GetFloat64(s->c, vr, n, r, nv);
        for (k = 0; st == fmi3OK && k < nv; k++)
            if (!isfinite(r[k])) {
                fprintf(stderr, "fuzz_fmi2: fmi3GetFloat64 gave %g\n", r[k]);
                abort();
            }
        return st;
    case 1: return set ? fmi3SetInt32(s->c, vr, n, i32, nv) : fmi3GetInt32(s->c, vr, n, i32, nv);
    case 2: return set ? fmi3SetInt64(s->c, vr, n, i64, nv) : fmi3GetInt64(s->c, vr, n, i64, nv);
    case 3: return set ? fmi3SetBoolean(s->c, vr, n, b, nv) : fmi3GetBoolean(s->c, vr, n, b, nv);
    default:
        return set ? fmi3SetString(s->c, vr, n, str, nv) : fmi3GetString(s->c, vr, n, str, nv);
    }
}

static fmi3Status state3(slot3 *s, input *in)
{
    unsigned op = u8(in) % 4;
    size_t size = 0, j;
    fmi3Byte *bytes;
    fmi3Status st;
    if (op == 0) return fmi3GetFMUState(s->c, &s->state);
    if (!s->state) return fmi3OK;
    if (op == 1) return fmi3SetFMUState(s->c, s->state);
    if (op == 2) return fmi3FreeFMUState(s->c, &s->state);
    if ((st = fmi3SerializedFMUStateSize(s->c, s->state, &size)) != fmi3OK) return st;
    if (!(bytes = malloc(size ? size : 1))) return fmi3OK;
    st = fmi3SerializeFMUState(s->c, s->state, bytes, size);
    for (j = 0; st == fmi3OK && j < (size_t)(u8(in) % 4) && size; j++)
        bytes[u16(in) % size] ^= (fmi3Byte)u8(in);
    if (st == fmi3OK) st = fmi3DeserializeFMUState(s->c, bytes, size - (u8(in) < 16), &s->state);
    free(bytes);
    return st;
}

static fmi3Status step3(slot3 *s, input *in)
{
    fmi3Boolean event, terminate, early;
    fmi3Float64 last;
    double h = u8(in) < 200 ? 1e-4 * (1 + u8(in) % 8) : value(in);
    double t = u8(in) < 240 ? s->t : value(in);
    fmi3Status st = fmi3DoStep(s->c, t, h, fmi3True, &event, &terminate, &early,
                               u8(in) < 8 ? NULL : &last);
    if (st == fmi3OK) s->t = t + h;
    return st;
}

static fmi3Status unsupported3(slot3 *s, input *in)
{
    fmi3Float64 x[4];
    fmi3Float32 f[4];
    fmi3ValueReference vr = vr_of(in);
    fmi3Int32 order = 1;
    switch (u8(in) % 6) {
    case 0: return fmi3EnterEventMode(s->c);
    case 1: return fmi3GetOutputDerivatives(s->c, &vr, 1, &order, x, 1);
    case 2: return fmi3GetContinuousStates(s->c, x, 4);
    case 3: return fmi3GetFloat32(s->c, &vr, u8(in) % 2, f, 1);
    case 4: return fmi3SetDebugLogging(s->c, u8(in) & 1, 0, NULL);
    default: return fmi3EnterStepMode(s->c);
    }
}

/* Model Exchange's calls (on any instance: a co-simulation one must refuse them); the state
 * vector set from the derivatives (an explicit Euler step) or raw values, counts right or not. */
static fmi3Status me3(slot3 *s, input *in)
{
    double x[HG_NUM_STATES + 2], dx[HG_NUM_STATES + 2], z[HG_NUM_EVENT_INDICATORS + 2];
    size_t nx = u8(in) < 240 ? HG_NUM_STATES : u8(in) % (HG_NUM_STATES + 2), k;
    fmi3Boolean b[6];
    fmi3Float64 next;
    fmi3Status st;
    int raw;
    switch (u8(in) % 7) {
    case 0:
        return fmi3UpdateDiscreteStates(s->c, &b[0], &b[1], &b[2], &b[3], &b[4], &next);
    case 1: return fmi3EnterContinuousTimeMode(s->c);
    case 2: return fmi3EnterEventMode(s->c);
    case 3: return fmi3GetEventIndicators(s->c, z, u8(in) < 240 ? HG_NUM_EVENT_INDICATORS : 1);
    case 4: return fmi3GetNominalsOfContinuousStates(s->c, x, nx);
    case 5: return fmi3CompletedIntegratorStep(s->c, fmi3True, &b[0], u8(in) < 8 ? NULL : &b[1]);
    default: /* an explicit Euler step of 1 us, or states from the input */
        if ((st = fmi3GetContinuousStates(s->c, x, nx)) != fmi3OK ||
            (st = fmi3GetContinuousStateDerivatives(s->c, dx, nx)) != fmi3OK)
            return st;
        raw = u8(in) >= 250;
        for (k = 0; k < nx; k++) x[k] = raw ? value(in) : x[k] + 1e-6 * dx[k];
        s->t += 1e-6;
        if ((st = fmi3SetTime(s->c, s->t)) != fmi3OK) return st;
        return fmi3SetContinuousStates(s->c, x, nx);
    }
}

/* One FMI 3.0 operation; a call returning fmi3Error must have said why (errors are always on). */
static void fmi3_op(slot3 *s, input *in)
{
    unsigned op = u8(in) % 12;
    long before = s->log.messages;
    fmi3Status st = fmi3OK;
    if (!s->c && op != 0) return;
    switch (op) {
    case 0: close3(s); open3(s, in); return;
    case 1: {
        double start = u8(in) < 200 ? 0.0 : value(in), stop = value(in);
        st = fmi3EnterInitializationMode(s->c, fmi3False, 0.0, start, u8(in) & 1, stop);
        if (st == fmi3OK) s->t = start;
        break;
    }
    case 2: st = fmi3ExitInitializationMode(s->c); break;
    case 3: st = access3(s, in, 1); break;
    case 4: st = access3(s, in, 0); break;
    case 5: st = step3(s, in); break;
    case 6: st = state3(s, in); break;
    case 7: st = u8(in) & 1 ? fmi3Reset(s->c) : fmi3Terminate(s->c); s->t = 0.0; break;
    case 8: case 9: st = me3(s, in); break;
    default: st = unsupported3(s, in); break;
    }
    if (st == fmi3Error && s->log.messages == before) {
        fprintf(stderr, "fuzz_fmi2: fmi3Error without a log message (op %u)\n", op);
        abort();
    }
    if (st == fmi3Fatal) abort();
}

/* ------------------------------------------------------------------ operations */

typedef struct {
    slot inst[2];
    slot3 inst3;
    int cur;
    fmi2FMUstate state[2];
    fmi2Component state_owner[2];
    char *blob;
    size_t blob_size;
    int steps;
    int euler_steps; /* of the Model Exchange host */
} session;

static fmi2Status set_one(slot *s, input *in)
{
    fmi2ValueReference vr = vr_of(in);
    unsigned kind = u8(in) % 4;
    if (kind == 0) {
        double v = value(in);
        return fmi2SetReal(s->c, &vr, 1, &v);
    }
    if (kind == 1 || kind == 2) {
        fmi2Integer v = u8(in) < 128 ? (fmi2Integer)(u8(in) % 6) : (fmi2Integer)u32(in);
        return kind == 1 ? fmi2SetInteger(s->c, &vr, 1, &v) : fmi2SetBoolean(s->c, &vr, 1, &v);
    }
    {
        char text[80];
        unsigned n = u8(in) % sizeof text, k;
        fmi2String v = text;
        for (k = 0; k < n; k++) text[k] = (char)u8(in);
        text[n] = '\0';
        if (n == 1 && text[0] == 0) v = NULL;
        return fmi2SetString(s->c, &vr, 1, &v);
    }
}

static fmi2Status get_some(slot *s, input *in)
{
    fmi2ValueReference vr[HG_NUM_VARS];
    double r[HG_NUM_VARS];
    fmi2Integer i[HG_NUM_VARS];
    fmi2String str[HG_NUM_VARS];
    unsigned kind = u8(in) % 4, n = u8(in) % 8, k;
    fmi2Status st;
    if (u8(in) < 64) { /* every variable as Real */
        for (k = n = 0; k < HG_NUM_VARS; k++)
            if (hg_var_table[k].type == HG_REAL) vr[n++] = k;
        kind = 0;
    } else {
        for (k = 0; k < n; k++) vr[k] = vr_of(in);
    }
    if (kind == 0) {
        st = fmi2GetReal(s->c, vr, n, r);
        for (k = 0; st == fmi2OK && k < n; k++)
            if (!isfinite(r[k])) {
                fprintf(stderr, "fuzz_fmi2: fmi2GetReal gave %g for vr %u\n", r[k], vr[k]);
                abort();
            }
        return st;
    }
    if (kind == 1) return fmi2GetInteger(s->c, vr, n, i);
    if (kind == 2) return fmi2GetBoolean(s->c, vr, n, i);
    st = fmi2GetString(s->c, vr, n, str);
    for (k = 0; st == fmi2OK && k < n; k++)
        if (!str[k] || strlen(str[k]) > 4095) abort();
    return st;
}

/* Writes the next bytes of the input into a data file and names it in a file parameter. */
static fmi2Status data_file(slot *s, input *in)
{
    unsigned which = u8(in) & 1, n = u16(in) % 16384;
    fmi2ValueReference vr = which ? 73 : 71;
    fmi2String path = data_path[which];
    FILE *fp = fopen(path, "wb");
    size_t k;
    const char *name = which ? "lubricant_file" : "gear_set_file";
    for (k = 0; k < HG_NUM_VARS; k++)
        if (strcmp(hg_var_table[k].name, name) == 0) vr = (fmi2ValueReference)k;
    if (!fp) return fmi2OK;
    n = n > (unsigned)(in->end - in->p) ? (unsigned)(in->end - in->p) : n;
    fwrite(in->p, 1, n, fp);
    in->p += n;
    fclose(fp);
    return fmi2SetString(s->c, &vr, 1, &path);
}

static fmi2Status do_step(session *ss, slot *s, input *in)
{
    static const double hs[] = {1e-4, 1e-4, 2e-4, 5e-4, 1e-3, 0.0, -1e-4, NAN, INFINITY, 1e300,
                                1e-20, 3e-5};
    unsigned k = u8(in);
    double h = hs[k % (sizeof hs / sizeof *hs)], t = s->t;
    fmi2Status st;
    if (ss->steps++ >= MAX_STEPS) return fmi2OK;
    if (k >= 240) t = value(in);
    st = fmi2DoStep(s->c, t, h, fmi2True);
    if (st == fmi2OK) s->t = t + h;
    return st;
}

static void free_state(session *ss, int k)
{
    if (ss->state[k] && ss->state_owner[k]) fmi2FreeFMUstate(ss->state_owner[k], &ss->state[k]);
    ss->state[k] = NULL;
    ss->state_owner[k] = NULL;
}

static fmi2Status state_op(session *ss, slot *s, input *in)
{
    unsigned op = u8(in) % 6, k = u8(in) & 1;
    fmi2Status st = fmi2OK;
    switch (op) {
    case 0:
        if (ss->state[k] && ss->state_owner[k] != s->c) free_state(ss, (int)k);
        st = fmi2GetFMUstate(s->c, &ss->state[k]);
        if (st == fmi2OK) ss->state_owner[k] = s->c;
        break;
    case 1:
        if (ss->state[k]) st = fmi2SetFMUstate(s->c, ss->state[k]);
        break;
    case 2:
        free_state(ss, (int)k);
        break;
    case 3: {
        size_t size = 0;
        if (!ss->state[k]) break;
        st = fmi2SerializedFMUstateSize(s->c, ss->state[k], &size);
        if (st != fmi2OK) break;
        free(ss->blob);
        ss->blob = malloc(size ? size : 1);
        ss->blob_size = size;
        st = fmi2SerializeFMUstate(s->c, ss->state[k], (fmi2Byte *)ss->blob, size);
        break;
    }
    default: { /* deserialize: the last blob with flips, or raw bytes of the input */
        char *bytes;
        size_t n, j;
        unsigned flips = u8(in) % 4;
        if (op == 4 && ss->blob) {
            n = ss->blob_size;
            if (!(bytes = malloc(n ? n : 1))) break;
            memcpy(bytes, ss->blob, n);
            for (j = 0; j < flips && n; j++) bytes[u16(in) % n] ^= (char)u8(in);
            if (u8(in) < 16 && n) n -= u8(in) % n;
        } else {
            n = u16(in) % 4096;
            n = n > (size_t)(in->end - in->p) ? (size_t)(in->end - in->p) : n;
            if (!(bytes = malloc(n ? n : 1))) break;
            memcpy(bytes, in->p, n);
            in->p += n;
        }
        if (ss->state[k] && ss->state_owner[k] != s->c) free_state(ss, (int)k);
        st = fmi2DeSerializeFMUstate(s->c, (fmi2Byte *)bytes, n, &ss->state[k]);
        if (st == fmi2OK) ss->state_owner[k] = s->c;
        free(bytes);
        break;
    }
    }
    return st;
}

/* fmi2SetDebugLogging; follows which categories are on, as the FMU does (categories before an
 * unknown one take effect), to know when the host switched error messages off. */
static fmi2Status debug_logging(slot *s, input *in)
{
    static const char *const cats[] = {"logEvents", "logStatusWarning", "logStatusError",
                                       "logAll", "nope", "%s%n", ""};
    fmi2String c[2];
    size_t n = u8(in) % 3, k;
    fmi2Boolean on;
    c[0] = cats[u8(in) % 7];
    c[1] = u8(in) < 16 ? NULL : cats[u8(in) % 7];
    on = (fmi2Boolean)(u8(in) & 1);
    if (n == 0) {
        s->error_on = 1; /* the FMU keeps warnings and errors on */
        s->all_on = on;
    }
    for (k = 0; k < n && c[k]; k++) {
        if (!strcmp(c[k], "logStatusError"))
            s->error_on = on;
        else if (!strcmp(c[k], "logAll"))
            s->all_on = on;
        else if (strcmp(c[k], "logEvents") && strcmp(c[k], "logStatusWarning"))
            break;
    }
    return fmi2SetDebugLogging(s->c, on, n, n ? c : NULL);
}

static fmi2Status misc_op(slot *s, input *in)
{
    unsigned op = u8(in) % 8;
    fmi2StatusKind kind;
    int null_value;
    switch (op) {
    case 0:
        return debug_logging(s, in);
    case 1: {
        fmi2ValueReference vr = vr_of(in);
        fmi2Integer order = u8(in) < 200 ? 1 : (fmi2Integer)(int8_t)u8(in);
        double v = value(in);
        if (!(fabs(v) <= DERIVATIVE_LIMIT)) v = 1.0;
        return fmi2SetRealInputDerivatives(s->c, &vr, 1, &order, &v);
    }
    case 2: case 3: case 4: {
        fmi2Status vs;
        fmi2Real vr;
        fmi2Boolean vb;
        kind = (fmi2StatusKind)(u8(in) % 5);
        null_value = u8(in) < 16;
        if (op == 2) return fmi2GetStatus(s->c, kind, null_value ? NULL : &vs);
        if (op == 3) return fmi2GetRealStatus(s->c, kind, null_value ? NULL : &vr);
        return fmi2GetBooleanStatus(s->c, kind, null_value ? NULL : &vb);
    }
    case 5: /* NULL arrays: fine with n = 0 */
        return u8(in) & 1 ? fmi2GetReal(s->c, NULL, 0, NULL) : fmi2SetInteger(s->c, NULL, 0, NULL);
    case 6:
        return fmi2CancelStep(s->c);
    default: {
        fmi2Real v;
        fmi2Integer i;
        return fmi2GetRealOutputDerivatives(s->c, NULL, u8(in) & 1, &i, &v);
    }
    }
}

/* ------------------------------------------------------------------ Model Exchange */

/* A count of the model's (n_model) most of the time, a wrong one otherwise. */
static size_t count_of(input *in, size_t n_model)
{
    unsigned k = u8(in);
    return k < 224 ? n_model : k < 240 ? k % (n_model + 2) : (size_t)u32(in);
}

static void require_finite(const char *fn, const double *a, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (!isfinite(a[k])) {
            fprintf(stderr, "fuzz_fmi2: %s gave %g at %zu\n", fn, a[k], k);
            abort();
        }
}

/* Reads one of the model's arrays (a count of the right size or not, NULL sometimes). */
static fmi2Status me_read(slot *s, input *in, unsigned which)
{
    double a[HG_NUM_STATES + 8];
    size_t n_model = which == 1 ? HG_NUM_EVENT_INDICATORS : HG_NUM_STATES;
    size_t n = count_of(in, n_model);
    double *p = u8(in) < 8 ? NULL : a;
    fmi2Status st;
    if (n > HG_NUM_STATES + 8 && p) n = HG_NUM_STATES + 8; /* the buffer's, still wrong */
    st = which == 0   ? fmi2GetDerivatives(s->c, p, n)
         : which == 1 ? fmi2GetEventIndicators(s->c, p, n)
         : which == 2 ? fmi2GetNominalsOfContinuousStates(s->c, p, n)
                      : fmi2GetContinuousStates(s->c, p, n);
    if (st == fmi2OK && p) require_finite("a Model Exchange getter", p, n);
    return st;
}

/* The current states with one of them replaced by a value of the input, set again. */
static fmi2Status me_set_states(slot *s, input *in)
{
    double x[HG_NUM_STATES + 8] = {0};
    size_t n = count_of(in, HG_NUM_STATES);
    unsigned k = u8(in) % HG_NUM_STATES;
    if (n > HG_NUM_STATES + 8) n = HG_NUM_STATES + 8;
    fmi2GetContinuousStates(s->c, x, HG_NUM_STATES); /* may fail: then zeros */
    if (u8(in) < 128) x[k] = value(in);
    return fmi2SetContinuousStates(s->c, u8(in) < 8 ? NULL : x, n);
}

/* An explicit Euler step of the host: x += h dx, t += h, and the completed step. */
static fmi2Status me_euler(session *ss, slot *s, input *in)
{
    static const double hs[] = {1e-6, 1e-6, 2e-6, 5e-7, 1e-5, 1e-4};
    double x[HG_NUM_STATES], dx[HG_NUM_STATES], h = hs[u8(in) % 6];
    fmi2Boolean event, stop;
    fmi2Status st;
    size_t k;
    if (ss->euler_steps++ >= 16 * MAX_STEPS) return fmi2OK;
    if ((st = fmi2GetContinuousStates(s->c, x, HG_NUM_STATES)) != fmi2OK ||
        (st = fmi2GetDerivatives(s->c, dx, HG_NUM_STATES)) != fmi2OK)
        return st;
    require_finite("fmi2GetDerivatives", dx, HG_NUM_STATES);
    for (k = 0; k < HG_NUM_STATES; k++) x[k] += h * dx[k];
    if ((st = fmi2SetTime(s->c, s->t + h)) != fmi2OK) return st;
    s->t += h;
    if ((st = fmi2SetContinuousStates(s->c, x, HG_NUM_STATES)) != fmi2OK) return st;
    return fmi2CompletedIntegratorStep(s->c, fmi2True, &event, &stop);
}

static fmi2Status me_op(session *ss, slot *s, input *in)
{
    unsigned op = u8(in) % 12;
    switch (op) {
    case 0: return fmi2EnterEventMode(s->c);
    case 1: {
        fmi2EventInfo info;
        return fmi2NewDiscreteStates(s->c, u8(in) < 16 ? NULL : &info);
    }
    case 2: return fmi2EnterContinuousTimeMode(s->c);
    case 3: {
        fmi2Boolean event, stop;
        int null = u8(in) < 16;
        return fmi2CompletedIntegratorStep(s->c, fmi2True, null ? NULL : &event,
                                           null ? NULL : &stop);
    }
    case 4: {
        double t = u8(in) < 200 ? s->t + 1e-6 : value(in);
        fmi2Status st = fmi2SetTime(s->c, t);
        if (st == fmi2OK) s->t = t;
        return st;
    }
    case 5: return me_set_states(s, in);
    case 6: case 7: case 8: case 9: return me_read(s, in, op - 6);
    default: return me_euler(ss, s, in);
    }
}

static void run(session *ss, input *in)
{
    while (in->p < in->end) {
        slot *s = &ss->inst[ss->cur];
        unsigned op = u8(in) % 19;
        long before = s->log.messages;
        fmi2Status st = fmi2OK;
        if (!s->c && op != 14) continue;
        switch (op) {
        case 0: case 1: st = set_one(s, in); break;
        case 2: st = get_some(s, in); break;
        case 3: st = data_file(s, in); break;
        case 4: {
            double stop = value(in), start = u8(in) < 200 ? 0.0 : value(in);
            fmi2Boolean stop_defined = (fmi2Boolean)(u8(in) & 1);
            st = fmi2SetupExperiment(s->c, fmi2False, 0.0, start, stop_defined, stop);
            if (st == fmi2OK) s->t = start;
            break;
        }
        case 5: st = fmi2EnterInitializationMode(s->c); break;
        case 6: st = fmi2ExitInitializationMode(s->c); break;
        case 7: case 8: st = do_step(ss, s, in); break;
        case 9: case 10: st = state_op(ss, s, in); break;
        case 11: st = fmi2Reset(s->c); s->t = 0.0; break;
        case 12: st = fmi2Terminate(s->c); break;
        case 13: st = misc_op(s, in); break;
        case 16: case 17: case 18: st = me_op(ss, s, in); break;
        case 14: /* free (forgetting its states) and instantiate again */
            if (ss->state_owner[0] == s->c) free_state(ss, 0);
            if (ss->state_owner[1] == s->c) free_state(ss, 1);
            close_slot(s);
            open_slot(s, in);
            continue;
        default:
            if (u8(in) < 96) {
                if (ss->steps++ < MAX_STEPS) fmi3_op(&ss->inst3, in);
            } else {
                ss->cur ^= 1;
            }
            continue;
        }
        require_message(s, before, st);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in = {data, data + size};
    session ss;
    int k;
    memset(&ss, 0, sizeof ss);
    open_slot(&ss.inst[0], &in);
    open_slot(&ss.inst[1], &in);
    run(&ss, &in);
    for (k = 0; k < 2; k++) free_state(&ss, k);
    for (k = 0; k < 2; k++) close_slot(&ss.inst[k]);
    close3(&ss.inst3);
    free(ss.blob);
    return 0;
}

/* ------------------------------------------------------------------ seeds */

typedef struct {
    uint8_t b[20000];
    size_t n;
} seed;

static void put(seed *s, const void *p, size_t n)
{
    if (s->n + n > sizeof s->b) n = sizeof s->b - s->n;
    memcpy(s->b + s->n, p, n);
    s->n += n;
}

static void op(seed *s, int count, ...)
{
    va_list ap;
    int k;
    va_start(ap, count);
    for (k = 0; k < count; k++) {
        uint8_t b = (uint8_t)va_arg(ap, int);
        put(s, &b, 1);
    }
    va_end(ap);
}

static void init_ops(seed *s) { op(s, 6, 4, 0, 0, 0, 5, 6); } /* setup, enter, exit */

static int write_seed(const char *dir, const char *name, const seed *s)
{
    char path[4096];
    FILE *fp;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (!(fp = fopen(path, "wb"))) return -1;
    fwrite(s->b, 1, s->n, fp);
    return fclose(fp);
}

static void file_seed(const char *dir, const char *name, const char *file, int which)
{
    char path[4096];
    seed s = {{0}, 0};
    FILE *fp;
    uint8_t buf[16384];
    size_t n;
    snprintf(path, sizeof path, "%s/%s", HG_FUZZ_RESOURCE_DIR, file);
    if (!(fp = fopen(path, "rb"))) return;
    n = fread(buf, 1, sizeof buf - 1, fp);
    fclose(fp);
    op(&s, 2, 0, 0); /* two instances with a logger and the resources */
    op(&s, 4, 3, which, (int)(n & 255), (int)(n >> 8));
    put(&s, buf, n);
    init_ops(&s);
    op(&s, 6, 7, 0, 7, 0, 2, 0);
    write_seed(dir, name, &s);
}

static int write_seeds(const char *dir)
{
    seed s = {{0}, 0};
    int k;
    op(&s, 2, 0, 0);
    init_ops(&s);
    for (k = 0; k < 5; k++) op(&s, 2, 7, 0);
    op(&s, 3, 2, 0, 0);
    write_seed(dir, "run", &s);
    /* state: get, step, serialize, deserialize with flips, set, step */
    s.n = 0;
    op(&s, 2, 0, 0);
    init_ops(&s);
    op(&s, 11, 7, 0, 9, 0, 0, 7, 0, 9, 3, 0, 9);
    op(&s, 10, 4, 0, 1, 40, 0, 1, 200, 9, 1, 0);
    op(&s, 4, 7, 0, 2, 0);
    write_seed(dir, "states", &s);
    /* parameters, then the run; values from the typical table */
    s.n = 0;
    op(&s, 2, 0, 0);
    op(&s, 4, 4, 0, 0, 0);
    for (k = 0; k < 12; k++) op(&s, 4, 0, 71 + k, 0, k);
    op(&s, 6, 0, 0, 0, 5, 5, 6);
    op(&s, 4, 7, 0, 7, 0);
    write_seed(dir, "parameters", &s);
    /* wrong order, logging, status, second instance */
    s.n = 0;
    op(&s, 2, 1, 6);
    op(&s, 14, 7, 0, 6, 12, 13, 0, 2, 3, 0, 13, 2, 0, 200, 15);
    init_ops(&s);
    op(&s, 8, 7, 0, 12, 2, 0, 0, 11, 14);
    write_seed(dir, "order", &s);
    /* Model Exchange: initial event, continuous-time mode, Euler steps, an event, states */
    s.n = 0;
    op(&s, 2, 64, 64);
    init_ops(&s);
    op(&s, 5, 16, 1, 200, 16, 2);
    for (k = 0; k < 8; k++) op(&s, 3, 16, 10, 0);
    op(&s, 4, 16, 7, 0, 200);            /* event indicators */
    op(&s, 7, 16, 0, 16, 1, 200, 16, 2); /* event mode, new discrete states, continuous */
    op(&s, 4, 16, 6, 0, 200);            /* derivatives */
    op(&s, 7, 16, 5, 0, 3, 0, 0, 200);   /* a state set */
    op(&s, 3, 9, 0, 0);                  /* FMU state get */
    op(&s, 3, 16, 10, 0);                /* Euler step */
    op(&s, 3, 9, 1, 0);                  /* FMU state set */
    op(&s, 3, 16, 10, 0);
    op(&s, 4, 2, 0, 0, 0);               /* every Real */
    write_seed(dir, "model_exchange", &s);
    /* FMI 3.0: instantiate, initialize, steps, get all, state round trip, unsupported */
    s.n = 0;
    op(&s, 2, 0, 0);
    op(&s, 4, 15, 0, 0, 0);                  /* fmi3 instantiate */
    op(&s, 6, 15, 0, 1, 0, 0, 0);            /* enter initialization */
    op(&s, 3, 15, 0, 2);                     /* exit */
    for (k = 0; k < 4; k++) op(&s, 7, 15, 0, 5, 0, 0, 0, 9); /* steps of 0.1 ms */
    op(&s, 9, 15, 0, 4, 0, 3, 4, 32, 35, 255); /* Float64: w_p .., the arrays pair.W, pair.mu */
    op(&s, 4, 15, 0, 6, 0);                    /* get the state */
    op(&s, 6, 15, 0, 6, 3, 0, 255);            /* serialize, deserialize, set */
    op(&s, 5, 15, 0, 10, 0, 1);                /* output derivatives (not provided) */
    write_seed(dir, "fmi3", &s);
    /* FMI 3.0 Model Exchange: initial event, continuous time, Euler steps, an event */
    s.n = 0;
    op(&s, 2, 0, 0);
    op(&s, 4, 15, 0, 0, 6);                    /* fmi3InstantiateModelExchange */
    op(&s, 6, 15, 0, 1, 0, 0, 0);
    op(&s, 3, 15, 0, 2);
    op(&s, 5, 15, 0, 8, 0, 0);                 /* update discrete states */
    op(&s, 5, 15, 0, 8, 0, 1);                 /* continuous-time mode */
    for (k = 0; k < 6; k++) op(&s, 6, 15, 0, 9, 0, 6, 0); /* Euler steps */
    op(&s, 5, 15, 0, 8, 0, 5);                 /* completed integrator step */
    op(&s, 5, 15, 0, 8, 0, 3);                 /* event indicators */
    op(&s, 4, 15, 0, 6, 0);                    /* FMU state */
    write_seed(dir, "fmi3_me", &s);
    file_seed(dir, "gearset_file", "gearsets/gearset1.txt", 0);
    file_seed(dir, "lubricant_file", "lubricants/OS265962.txt", 1);
    return 0;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    const char *seeds = getenv("HG_FUZZ_WRITE_SEEDS");
    (void)argc;
    (void)argv;
    percent_encode(HG_FUZZ_RESOURCE_DIR, resource_uri, sizeof resource_uri);
    snprintf(resource_path, sizeof resource_path, "%s/", HG_FUZZ_RESOURCE_DIR);
    if (seeds) exit(write_seeds(seeds) ? 1 : 0);
    snprintf(tmp_dir, sizeof tmp_dir, "%s/hg-fuzz-XXXXXX",
             getenv("HG_FUZZ_TMPDIR") ? getenv("HG_FUZZ_TMPDIR") : "/tmp");
    if (!mkdtemp(tmp_dir)) {
        perror("fuzz_fmi2: mkdtemp");
        exit(1);
    }
    snprintf(data_path[0], sizeof data_path[0], "%s/gearset.txt", tmp_dir);
    snprintf(data_path[1], sizeof data_path[1], "%s/lubricant.txt", tmp_dir);
    atexit(remove_tmp);
    return 0;
}
