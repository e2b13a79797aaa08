/* The integrators through the solver interface (solver/solver.h) on the linear oscillator
 *     x'' + 2 zeta w x' + w^2 x = 0,   x(0) = 1, x'(0) = 0,
 * against its closed form x(t) = exp(-zeta w t) (cos(w_d t) + zeta w / w_d sin(w_d t)),
 * w_d = w sqrt(1 - zeta^2), for each method (BDF, Adams, Newmark), with the root function g = x:
 * its zeros lie at t_k = (pi - atan(w_d / (zeta w)) + k pi) / w_d, alternately downwards and
 * upwards. Newmark (the trapezoidal rule) turns the undamped oscillator by exactly
 * 2 atan(w h / 2) per step at constant amplitude: its discrete solution is checked too. */
#include "solver/solver.h"

#include <math.h>
#include <string.h>

#include "check.h"
#include "io/constants.h"

typedef struct {
    double w, zeta; /* [rad/s], [1] */
} oscillator;

static int rhs(double t, const double *y, double *ydot, void *user)
{
    const oscillator *o = user;
    (void)t;
    ydot[0] = y[1];
    ydot[1] = -o->w * o->w * y[0] - 2.0 * o->zeta * o->w * y[1];
    return 0;
}

static int root_x(double t, const double *y, double *g, void *user)
{
    (void)t;
    (void)user;
    g[0] = y[0];
    return 0;
}

static double w_d(const oscillator *o) { return o->w * sqrt(1.0 - o->zeta * o->zeta); }

static double x_exact(const oscillator *o, double t)
{
    double wd = w_d(o);
    return exp(-o->zeta * o->w * t) * (cos(wd * t) + o->zeta * o->w / wd * sin(wd * t));
}

/* The k-th zero of x (k = 0, 1, ...). */
static double zero_exact(const oscillator *o, int k)
{
    double wd = w_d(o);
    double first = o->zeta > 0.0 ? HG_PI - atan(wd / (o->zeta * o->w)) : HG_PI / 2.0;
    return (first + k * HG_PI) / wd;
}

static hg_solver *make_order(hg_method method, oscillator *o, int n_roots, double h,
                             int max_order)
{
    static const double atol[2] = {1e-12, 1e-12};
    const double y0[2] = {1.0, 0.0};
    char err[256] = "";
    hg_solver_options opt;
    hg_solver *s;
    opt.method = method;
    opt.rtol = 1e-10;
    opt.atol = atol;
    opt.max_steps = 1000000;
    opt.max_order = max_order;
    opt.jac_every = 0;
    s = hg_solver_new(2, n_roots, rhs, n_roots ? root_x : NULL, o, &opt, err, sizeof err);
    CHECK(s != NULL);
    if (!s) {
        fprintf(stderr, "hg_solver_new: %s\n", err);
        return NULL;
    }
    CHECK(hg_solver_set_max_step(s, h, err, sizeof err) == 0);
    CHECK(hg_solver_restart(s, 0.0, y0, 0.0, err, sizeof err) == 0);
    return s;
}

static hg_solver *make(hg_method method, oscillator *o, int n_roots, double h)
{
    return make_order(method, o, n_roots, h, 0);
}

/* Two periods in communication steps of a tenth of a period: x against the closed form. */
static void check_trajectory(hg_method method, double zeta, double tol)
{
    oscillator o = {2.0 * HG_PI * 5.0, zeta};
    double T = 2.0 * HG_PI / o.w, t = 0.0, y[2];
    char err[256] = "";
    hg_solver *s = make(method, &o, 0, T / 4000.0);
    long steps = 0, evals = 0;
    int k;
    if (!s) return;
    for (k = 1; k <= 20; k++) {
        hg_advance_result r = hg_solver_advance(s, k * T / 10.0, 0, &t, y, NULL, err, sizeof err);
        CHECK(r == HG_ADVANCE_REACHED);
        CHECK(t == k * T / 10.0);
        CHECK_CLOSE(y[0], x_exact(&o, t), 0.0, tol);
    }
    hg_solver_stats(s, &steps, &evals);
    CHECK(steps > 0 && evals >= steps);
    hg_solver_free(s);
}

/* The first four zeros of x as root events, with their directions. */
static void check_roots(hg_method method, double zeta, double tol)
{
    oscillator o = {2.0 * HG_PI * 5.0, zeta};
    double T = 2.0 * HG_PI / o.w, t = 0.0, y[2];
    char err[256] = "";
    hg_solver *s = make(method, &o, 1, T / 4000.0);
    int k, dir[1];
    if (!s) return;
    for (k = 0; k < 4; k++) {
        hg_advance_result r = hg_solver_advance(s, 3.0 * T, 0, &t, y, dir, err, sizeof err);
        CHECK(r == HG_ADVANCE_ROOT);
        CHECK_CLOSE(t, zero_exact(&o, k), 0.0, tol);
        CHECK(dir[0] == (k % 2 == 0 ? -1 : 1));
        CHECK(fabs(y[0]) < 1e-6);
        /* continue from the root as the model does: a restart there */
        CHECK(hg_solver_restart(s, t, y, 0.0, err, sizeof err) == 0);
    }
    hg_solver_free(s);
}

/* Newmark's own closed form: the rotation by 2 atan(w h / 2) per step, amplitude kept. */
static void check_newmark_discrete(void)
{
    oscillator o = {2.0 * HG_PI * 5.0, 0.0};
    double T = 2.0 * HG_PI / o.w, h = T / 64.0, t = 0.0, y[2];
    double angle = 2.0 * atan(o.w * h / 2.0);
    char err[256] = "";
    hg_solver *s = make(HG_METHOD_NEWMARK, &o, 0, h);
    int n;
    if (!s) return;
    for (n = 1; n <= 64; n++) {
        CHECK(hg_solver_advance(s, n * h, 0, &t, y, NULL, err, sizeof err) == HG_ADVANCE_REACHED);
        CHECK_CLOSE(y[0], cos(n * angle), 0.0, 1e-9);
        CHECK_CLOSE(y[1], -o.w * sin(n * angle), 0.0, 1e-9 * o.w);
    }
    /* and not the exact solution (x' = 0 after a period): at 64 steps a period the phase lags by
     * 2 pi (w h)^2 / 12 = 5.0e-3 rad, so x' = w sin(5.0e-3) */
    CHECK_CLOSE(y[1], o.w * sin(2.0 * HG_PI * pow(2.0 * HG_PI / 64.0, 2) / 12.0), 2e-3, 0.0);
    hg_solver_free(s);
}

/* Communication points far denser than the integrator's own steps (no step limit): stopping
 * at each costs at least one step per point; passing them (pass = 1: CVODE's Nordsieck
 * interpolant, ARKODE's cubic Hermite one) interpolates, with the same accuracy against the
 * closed form and a fraction of the steps. */
static long dense_points(hg_method method, int pass, double tol)
{
    oscillator o = {2.0 * HG_PI * 5.0, 0.05};
    double T = 2.0 * HG_PI / o.w, t = 0.0, y[2];
    char err[256] = "";
    hg_solver *s = make(method, &o, 0, 0.0);
    long steps = 0, evals = 0;
    int k;
    if (!s) return 0;
    for (k = 1; k <= 2000; k++) {
        CHECK(hg_solver_advance(s, k * T / 1000.0, pass, &t, y, NULL, err, sizeof err) ==
              HG_ADVANCE_REACHED);
        CHECK(t == k * T / 1000.0);
        CHECK_CLOSE(y[0], x_exact(&o, t), 0.0, tol);
    }
    hg_solver_stats(s, &steps, &evals);
    hg_solver_free(s);
    return steps;
}

static void check_passing(hg_method method, double tol)
{
    long exact = dense_points(method, 0, tol), passing = dense_points(method, 1, tol);
    CHECK(exact >= 2000);
    CHECK(passing > 0 && passing < exact / 2);
}

/* BDF limited to order 2 (max_order): the closed form within its tolerance, in more steps than
 * at the method's own highest order on this smooth solution; an order beyond the method's is an
 * error naming the call. */
static long bdf_steps(int max_order)
{
    oscillator o = {2.0 * HG_PI * 5.0, 0.03};
    double T = 2.0 * HG_PI / o.w, t = 0.0, y[2];
    char err[256] = "";
    hg_solver *s = make_order(HG_METHOD_BDF, &o, 0, 0.0, max_order);
    long steps = 0, evals = 0;
    int k;
    if (!s) return 0;
    for (k = 1; k <= 20; k++) {
        CHECK(hg_solver_advance(s, k * T / 10.0, 1, &t, y, NULL, err, sizeof err) ==
              HG_ADVANCE_REACHED);
        CHECK_CLOSE(y[0], x_exact(&o, t), 0.0, 1e-6);
    }
    hg_solver_stats(s, &steps, &evals);
    hg_solver_free(s);
    return steps;
}

static void check_max_order(void)
{
    oscillator o = {1.0, 0.0};
    const double atol[2] = {1e-12, 1e-12};
    char err[256] = "";
    hg_solver_options opt = {HG_METHOD_BDF, 1e-10, NULL, 1000, 6, 0};
    long own = bdf_steps(0), second = bdf_steps(2);
    CHECK(own > 0 && second > 2 * own);
    opt.atol = atol;
    CHECK(hg_solver_new(2, 0, rhs, NULL, &o, &opt, err, sizeof err) == NULL);
    CHECK(strstr(err, "CVodeSetMaxOrd failed") != NULL);
}

/* A bad step names the method and the reason. */
static void check_errors(void)
{
    oscillator o = {1.0, 0.0};
    char err[256] = "";
    hg_solver *s = make(HG_METHOD_NEWMARK, &o, 0, 1e-3);
    if (!s) return;
    CHECK(hg_solver_set_max_step(s, -1.0, err, sizeof err) != 0);
    CHECK(strstr(err, "Newmark") != NULL);
    hg_solver_free(s);
    s = make(HG_METHOD_BDF, &o, 0, 1e-3);
    if (!s) return;
    CHECK(hg_solver_set_max_step(s, -1.0, err, sizeof err) != 0);
    CHECK(strstr(err, "CVodeSetMaxStep failed: CV_ILL_INPUT") != NULL);
    hg_solver_free(s);
}

int main(void)
{
    static const hg_method methods[] = {HG_METHOD_BDF, HG_METHOD_ADAMS, HG_METHOD_NEWMARK};
    /* CVODE at rtol 1e-10; Newmark at 4000 steps a period: phase error w t (w h)^2 / 12 */
    static const double tol[] = {1e-7, 1e-7, 2e-5};
    int i;
    for (i = 0; i < 3; i++) {
        check_trajectory(methods[i], 0.0, tol[i]);
        check_trajectory(methods[i], 0.05, tol[i]);
        check_roots(methods[i], 0.0, tol[i] / 100.0);
        check_roots(methods[i], 0.05, tol[i] / 100.0);
    }
    check_passing(HG_METHOD_BDF, tol[0]);
    check_max_order();
    check_passing(HG_METHOD_ADAMS, tol[1]);
    check_passing(HG_METHOD_ERK, tol[0]);
    check_newmark_discrete();
    check_errors();
    CHECK_DONE();
}
