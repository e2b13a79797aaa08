/* Tapered roller bearings: mesh force components, reactions, pair axial loads, friction
 * (bearings.h for the sources). */
#include "axle/bearings.h"

#include <math.h>

#include "io/constants.h"

hg_mesh_force hg_mesh_force_components(const hg_member_geom *m, double F_t, double s, int driving)
{
    hg_mesh_force f;
    double k = driving ? s : -s;
    double ta = tan(m->alpha_n), sb = sin(m->beta), cb = cos(m->beta);
    double sd = sin(m->delta), cd = cos(m->delta);
    f.F_t = F_t;
    f.F_a = F_t / cb * (ta * sd + k * sb * cd);
    f.F_r = F_t / cb * (ta * cd - k * sb * sd);
    return f;
}

/* reactions R_A, R_B of a beam on supports x_A, x_B carrying a force F at x = 0 and a couple C:
 * R_A + R_B = -F and x_A R_A + x_B R_B = -C */
static void two_supports(double F, double C, double x_A, double x_B, double *R_A, double *R_B)
{
    *R_B = (x_A * F - C) / (x_B - x_A);
    *R_A = -F - *R_B;
}

void hg_shaft_reactions(const hg_mesh_force *f, double r_m, double x_A, double x_B, double *Fr_A,
                        double *Fr_B)
{
    double yA, yB, zA, zB;
    /* separating plane: contact at y = r_m, force -F_r along y, the axial force F_a along x at
     * y = r_m gives the couple M_z = -r_m F_a */
    two_supports(-f->F_r, -r_m * f->F_a, x_A, x_B, &yA, &yB);
    /* tangential plane: F_t along z at the axis position x = 0, no couple */
    two_supports(f->F_t, 0.0, x_A, x_B, &zA, &zB);
    *Fr_A = hypot(yA, zA);
    *Fr_B = hypot(yB, zB);
}

void hg_trb_pair_axial(double Fr_1, double Y_1, double Fr_2, double Y_2, double K_a, double F_pre,
                       double *Fa_1, double *Fa_2)
{
    double Fi_1 = 0.5 * Fr_1 / Y_1, Fi_2 = 0.5 * Fr_2 / Y_2;
    double a = fmax(Fi_1, fmax(Fi_2 + K_a, F_pre + 0.5 * K_a));
    *Fa_1 = a;
    *Fa_2 = a - K_a;
}

double hg_trb_torque(const hg_trb *b, double F_a, double nu, double omega)
{
    double n = fabs(omega) * 30.0 / HG_PI; /* r/min */
    double nu_mm = nu * 1e6;                /* mm^2/s */
    double dm = b->d_m * 1e3;               /* mm */
    double M_0 = 1e-7 * b->f_0 * fmax(pow(nu_mm * n, 2.0 / 3.0), 160.0) * dm * dm * dm;
    double M_1 = b->f_1 * 2.0 * b->Y * F_a * dm;
    return 1e-3 * (M_0 + M_1); /* N mm -> N m */
}
