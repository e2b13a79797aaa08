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

/* SKF model constants of tapered roller bearings (bearings.h) */
#define SKF_R2 10.9
#define SKF_S2 2.0
#define SKF_K_Z 6.0   /* bearing type geometry constant, tapered roller bearings */
#define MU_BL 0.15    /* sliding friction in boundary lubrication */
#define MU_EHL 0.002  /* sliding friction in full film, tapered roller bearings */

double hg_trb_phi_rs(double K_rs, double vn, double rs)
{
    /* K_rs = 0, a flooded bearing: exp(-0) = 1 exactly, without the exp */
    return K_rs == 0.0 ? 1.0 : exp(-K_rs * vn * rs);
}

void hg_trb_geometry_of(const hg_trb *b, hg_trb_geometry *g)
{
    double d = b->d * 1e3, D = b->D * 1e3; /* mm */
    g->dm = 0.5 * (d + D);
    g->G_rr0 = b->R_1 * pow(g->dm, 2.38);
    g->G_sl0 = b->S_1 * pow(g->dm, 0.82);
    g->dm128 = pow(g->dm, 1.28);
    g->rs = (d + D) * sqrt(SKF_K_Z / (2.0 * (D - d)));
}

void hg_trb_oil_of(double nu, hg_trb_oil *o)
{
    o->v = nu * 1e6; /* mm^2/s */
    o->ln_v = log(o->v);
}

void hg_trb_speed_at(const hg_trb_oil *o, double omega, hg_trb_speed *s)
{
    double n = fabs(omega) * 30.0 / HG_PI; /* r/min */
    double ln_n = log(n), ln_v = o->ln_v;  /* n = 0: -inf, and every power of n below 0 */
    double vn04 = exp(0.4 * (ln_n + ln_v)); /* (nu n)^0.4: (nu n)^1.4 and ^0.6 from it */
    s->ln_n = ln_n;
    s->vn = o->v * n;
    s->n128v064 = exp(1.28 * ln_n + 0.64 * ln_v);
    s->vn14 = s->vn * vn04;
    s->vn06 = vn04 > 0.0 ? s->vn / vn04 : 0.0;
}

void hg_trb_speed_of(double nu, double omega, hg_trb_speed *s)
{
    hg_trb_oil o;
    hg_trb_oil_of(nu, &o);
    hg_trb_speed_at(&o, omega, s);
}

hg_trb_moment hg_trb_friction_at(const hg_trb *b, const hg_trb_geometry *g,
                                 const hg_trb_speed *s, double F_r, double F_a)
{
    hg_trb_moment m;
    double G_rr = g->G_rr0 * exp(0.31 * log(F_r + SKF_R2 * b->Y * F_a)); /* 0 at no load */
    double G_sl = g->G_sl0 * (F_r + SKF_S2 * b->Y * F_a);
    double phi_ish = 1.0 / (1.0 + 1.84e-9 * g->dm128 * s->n128v064);
    double phi_rs = hg_trb_phi_rs(b->K_rs, s->vn, g->rs);
    double phi_bl = exp(-2.6e-8 * s->vn14 * g->dm);
    double mu_sl = phi_bl * MU_BL + (1.0 - phi_bl) * MU_EHL;
    m.M_rr = 1e-3 * phi_ish * phi_rs * G_rr * s->vn06; /* N mm -> N m */
    m.M_sl = 1e-3 * mu_sl * G_sl;
    return m;
}

hg_trb_moment hg_trb_friction(const hg_trb *b, double F_r, double F_a, double nu, double omega)
{
    hg_trb_geometry g;
    hg_trb_speed s;
    hg_trb_geometry_of(b, &g);
    hg_trb_speed_of(nu, omega, &s);
    return hg_trb_friction_at(b, &g, &s, F_r, F_a);
}

double hg_trb_preload(double F_pre0, double k_ax, double d_alpha, double L, double dT)
{
    return fmax(0.0, F_pre0 - k_ax * d_alpha * L * dT);
}
