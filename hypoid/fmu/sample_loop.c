/* The studies' sampling loop (hypoid.fmu.instance.FastIo.run) in C: n times fmi2SetReal of the
 * inputs (when given), fmi2DoStep and fmi2GetReal / fmi2GetInteger of fixed outputs into rows
 * of the caller's arrays, through the FMU's own function pointers. The same calls with the same
 * arguments as the Python loop, so the same results; without the interpreter and ctypes around
 * each call (about 0.6 us a call, as much as a brief read of the FMU itself).
 * A host-side helper of the Python package, not part of the FMU: a shared library of its own,
 * loaded with ctypes when the checkout's build has it. */
#include <stddef.h>

#if defined(__GNUC__)
#define HG_LOOP_EXPORT __attribute__((visibility("default"))) /* the build hides the rest */
#else
#define HG_LOOP_EXPORT
#endif

/* the FMI 2.0 signatures, with the instance as void * and the status as int */
typedef int (*hg_do_step_fn)(void *c, double t, double h, int no_set_prior);
typedef int (*hg_get_real_fn)(void *c, const unsigned *vr, size_t n, double *value);
typedef int (*hg_get_int_fn)(void *c, const unsigned *vr, size_t n, int *value);
typedef int (*hg_set_real_fn)(void *c, const unsigned *vr, size_t n, const double *value);

enum { HG_LOOP_WARNING = 1 }; /* fmi2Warning: the worst status that is not a failure */
enum { CALL_NONE, CALL_SET_REAL, CALL_DO_STEP, CALL_GET_REAL, CALL_GET_INTEGER };

/* The FMU's calls in the order of the loop. Sample i: inputs[i * n_in ...] set (inputs NULL:
 * none), a step from t_i of size h, t_{i+1} = t_i + h into times[i], the reals into
 * reals[i * real_stride ...] and the integers into ints[i * int_stride ...]. Returns the status
 * of the first call that failed (> fmi2Warning) or 0; *done is the number of samples completed,
 * *call names the failed call (CALL_*), *t_end the time reached (the failed step's start when
 * the step failed). */
HG_LOOP_EXPORT int hg_sample_loop(hg_do_step_fn do_step, hg_get_real_fn get_real,
                                  hg_get_int_fn get_int, hg_set_real_fn set_real, void *c,
                                  double t, double h, size_t n, const unsigned *vr_real,
                                  size_t n_real, double *reals, size_t real_stride,
                                  const unsigned *vr_int, size_t n_int, int *ints,
                                  size_t int_stride, const unsigned *vr_in, size_t n_in,
                                  const double *inputs, double *times, size_t *done, int *call,
                                  double *t_end)
{
    size_t i;
    int s = 0;
    *call = CALL_NONE;
    for (i = 0; i < n; i++) {
        if (inputs && (s = set_real(c, vr_in, n_in, inputs + i * n_in)) > HG_LOOP_WARNING) {
            *call = CALL_SET_REAL;
            break;
        }
        if ((s = do_step(c, t, h, 1)) > HG_LOOP_WARNING) {
            *call = CALL_DO_STEP;
            break;
        }
        t += h;
        times[i] = t;
        if ((s = get_real(c, vr_real, n_real, reals + i * real_stride)) > HG_LOOP_WARNING) {
            *call = CALL_GET_REAL;
            break;
        }
        if (n_int && (s = get_int(c, vr_int, n_int, ints + i * int_stride)) > HG_LOOP_WARNING) {
            *call = CALL_GET_INTEGER;
            break;
        }
    }
    *done = i;
    *t_end = t;
    return *call == CALL_NONE ? 0 : s;
}
