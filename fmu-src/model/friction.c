/* Friction models behind one seam (see friction.h). */
#include "model/friction.h"

#include <math.h>
#include <string.h>

#include "hg_vars.h"

static void kinematics(const hg_pair_contact *c, hg_pair_friction *out)
{
    double ue_x = 0.5 * (c->u_p[0] + c->u_g[0]), ue_y = 0.5 * (c->u_p[1] + c->u_g[1]);
    double vs_x = c->u_p[0] - c->u_g[0], vs_y = c->u_p[1] - c->u_g[1];
    out->u_e = sqrt(ue_x * ue_x + ue_y * ue_y);
    out->V_s = sqrt(vs_x * vs_x + vs_y * vs_y);
}

static int ehl(const hg_friction_config *cfg)
{
    return cfg->model == HG_FRICTION_MODEL_EHL_ISOTHERMAL ||
           cfg->model == HG_FRICTION_MODEL_EHL_THERMAL;
}

void hg_friction_hertz(const hg_friction_config *cfg, const hg_pair_contact *c, hg_hertz *h)
{
    if (ehl(cfg))
        hg_ehl_hertz(&cfg->ehl, c, h);
    else
        memset(h, 0, sizeof *h);
}

void hg_friction_pair_hertz(const hg_friction_config *cfg, const hg_pair_contact *c,
                            const hg_hertz *h, double *T_c_warm, hg_pair_friction *out)
{
    if (ehl(cfg))
        hg_ehl_pair_hertz(&cfg->ehl, cfg->lub, c, h, T_c_warm, out);
    else
        hg_friction_pair(cfg, c, T_c_warm, out);
}

void hg_friction_pair(const hg_friction_config *cfg, const hg_pair_contact *c, double *T_c_warm,
                      hg_pair_friction *out)
{
    if (ehl(cfg)) {
        hg_ehl_pair(&cfg->ehl, cfg->lub, c, T_c_warm, out);
        return;
    }
    memset(out, 0, sizeof *out);
    kinematics(c, out);
    out->T_c = c->T_bath;
    if (cfg->model == HG_FRICTION_MODEL_COULOMB && c->W > 0.0) {
        out->mu = cfg->mu_const;
        out->F_f = cfg->mu_const * c->W;
    }
}
