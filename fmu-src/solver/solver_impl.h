/* What each integrator implements behind hg_solver (solver.c dispatches on the method). */
#ifndef HG_SOLVER_IMPL_H
#define HG_SOLVER_IMPL_H

#include "io/errmsg.h"
#include "solver/solver.h"

/* The problem every integrator solves: n states, n_roots root functions, the caller's callbacks. */
typedef struct {
    int n, n_roots;
    hg_rhs_fn f;
    hg_root_fn g;
    void *user;
} hg_problem;

typedef struct {
    void *(*create)(const hg_problem *pb, const hg_solver_options *opt, char *err,
                    size_t errlen);
    void (*destroy)(void *impl);
    int (*restart)(void *impl, double t0, const double *y0, double h0, char *err,
                   size_t errlen);
    int (*set_max_step)(void *impl, double h_max, char *err, size_t errlen);
    hg_advance_result (*advance)(void *impl, double t_stop, int pass, double *t, double *y,
                                 int *roots, char *err, size_t errlen);
    void (*stats)(const void *impl, long *steps, long *rhs_evals);
} hg_solver_ops;

extern const hg_solver_ops hg_cvode_ops;
extern const hg_solver_ops hg_newmark_ops;
extern const hg_solver_ops hg_arkode_erk_ops;

#endif
