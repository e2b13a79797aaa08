/* hg_solver: one interface, several integrators (solver_impl.h). */
#include <stdio.h>
#include <stdlib.h>

#include "solver/solver_impl.h"

struct hg_solver {
    const hg_solver_ops *ops;
    void *impl;
};

hg_solver *hg_solver_new(int n, int n_roots, hg_rhs_fn f, hg_root_fn g, void *user,
                         const hg_solver_options *opt, char *err, size_t errlen)
{
    hg_solver *s = calloc(1, sizeof *s);
    hg_problem pb;
    pb.n = n;
    pb.n_roots = n_roots;
    pb.f = f;
    pb.g = g;
    pb.user = user;
    if (!s) {
        hg_errorf(err, errlen, "out of memory creating the solver");
        return NULL;
    }
    s->ops = opt->method == HG_METHOD_NEWMARK ? &hg_newmark_ops
             : opt->method == HG_METHOD_ERK   ? &hg_arkode_erk_ops
                                              : &hg_cvode_ops;
    s->impl = s->ops->create(&pb, opt, err, errlen);
    if (!s->impl) {
        free(s);
        return NULL;
    }
    return s;
}

void hg_solver_free(hg_solver *s)
{
    if (!s) return;
    s->ops->destroy(s->impl);
    free(s);
}

int hg_solver_restart(hg_solver *s, double t0, const double *y0, double h0, char *err,
                      size_t errlen)
{
    return s->ops->restart(s->impl, t0, y0, h0, err, errlen);
}

int hg_solver_set_max_step(hg_solver *s, double h_max, char *err, size_t errlen)
{
    return s->ops->set_max_step(s->impl, h_max, err, errlen);
}

hg_advance_result hg_solver_advance(hg_solver *s, double t_stop, int pass, double *t, double *y,
                                    int *roots, char *err, size_t errlen)
{
    return s->ops->advance(s->impl, t_stop, pass, t, y, roots, err, errlen);
}

void hg_solver_stats(const hg_solver *s, long *steps, long *rhs_evals)
{
    s->ops->stats(s->impl, steps, rhs_evals);
}
