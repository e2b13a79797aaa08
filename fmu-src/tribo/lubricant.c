/* Lubricant data: see lubricant.h; file format in docs/data-files.md. */
#include "tribo/lubricant.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/datafile.h"

#define MAGIC "hypoid-lubricant"
#define VERSION 1

/* Value ranges of the keys. */
#define A_LO 1e-10
#define A_HI 1.0
#define B_LO 1.0
#define B_HI 1e4
#define C_LO 0.0
#define C_HI 400.0
#define T_LO 200.0
#define T_HI 700.0
#define AL_LO 1e-10 /* 0.1 1/GPa */
#define AL_HI 1e-7  /* 100 1/GPa */
#define LAM_LO 0.0
#define LAM_HI 1e-3
#define HNA_LO 1e-3
#define HNA_HI 1.0
#define HNB_LO 1e-3
#define HNB_HI 10.0
#define KF_LO HG_LUBRICANT_K_F_MIN
#define KF_HI 10.0
#define CP_LO 100.0
#define CP_HI 1e5
#define RHO_LO 100.0
#define RHO_HI 5000.0

/* Checks spanning several keys; 'where' names the file (or "lubricant") in messages. */
static int cross_check(const hg_lubricant *l, const char *where, char *err, size_t errlen)
{
    const double *t = l->alpha_T, *y = l->alpha_star;
    double d1, d12, d2, s0, s2;
    int i;
    for (i = 1; i < 3; i++) {
        if (!(t[i] >= t[i - 1] + 1.0)) {
            hg_errorf(err, errlen,
                      "%s: alpha_star_T%d = %g K must exceed alpha_star_T%d = %g K by at least 1 K",
                      where, i + 1, t[i], i, t[i - 1]);
            return -1;
        }
    }
    if (!(l->vogel_c <= t[0] - 40.0)) {
        hg_errorf(err, errlen,
                  "%s: vogel_c = %g K must lie at least 40 K below alpha_star_T1 = %g K (the "
                  "Vogel law has its pole at T = c)",
                  where, l->vogel_c, t[0]);
        return -1;
    }
    /* alpha*(T) quadratic of docs/physics.md §4.2: its slope is linear in T, so non-positive slopes at
     * both ends mean non-increasing throughout */
    d1 = (y[1] - y[0]) / (t[1] - t[0]);
    d12 = (y[2] - y[1]) / (t[2] - t[1]);
    d2 = (d12 - d1) / (t[2] - t[0]);
    s0 = d1 + d2 * (t[0] - t[1]);
    s2 = d1 + d2 * ((t[2] - t[0]) + (t[2] - t[1]));
    if (s0 > 0.0 || s2 > 0.0) {
        hg_errorf(err, errlen,
                  "%s: alpha_star_1..3 = %g, %g, %g 1/Pa: the quadratic through them must not "
                  "increase with temperature on [alpha_star_T1, alpha_star_T3] (slope %g 1/(Pa K) "
                  "at T1, %g at T3)",
                  where, y[0], y[1], y[2], s0, s2);
        return -1;
    }
    if (l->hn_alpha * l->hn_beta > 1.0 + 1e-12) {
        hg_errorf(err, errlen,
                  "%s: hn_alpha * hn_beta = %g exceeds 1 (the shear stress would fall with shear "
                  "rate)",
                  where, l->hn_alpha * l->hn_beta);
        return -1;
    }
    return 0;
}

int hg_lubricant_load(const char *path, hg_lubricant *out, char *err, size_t errlen)
{
    hg_lubricant l;
    hg_datafile *f;
    char key[32];
    int i, rc = -1;
    memset(&l, 0, sizeof l);
    f = hg_datafile_load(path, MAGIC, VERSION, err, errlen);
    if (!f) return -1;
    if (hg_datafile_text(f, "name", l.name, sizeof l.name, err, errlen)) goto done;
    if (l.name[0] == '\0') {
        hg_errorf(err, errlen, "%s: key 'name' needs a text value", path);
        goto done;
    }
    if (hg_datafile_number(f, "vogel_a", A_LO, A_HI, "Pa s", &l.vogel_a, err, errlen) ||
        hg_datafile_number(f, "vogel_b", B_LO, B_HI, "K", &l.vogel_b, err, errlen) ||
        hg_datafile_number(f, "vogel_c", C_LO, C_HI, "K", &l.vogel_c, err, errlen))
        goto done;
    for (i = 0; i < 3; i++) {
        snprintf(key, sizeof key, "alpha_star_T%d", i + 1);
        if (hg_datafile_number(f, key, T_LO, T_HI, "K", &l.alpha_T[i], err, errlen)) goto done;
        snprintf(key, sizeof key, "alpha_star_%d", i + 1);
        if (hg_datafile_number(f, key, AL_LO, AL_HI, "1/Pa", &l.alpha_star[i], err, errlen))
            goto done;
    }
    if (hg_datafile_number(f, "hn_lambda", LAM_LO, LAM_HI, "s", &l.hn_lambda, err, errlen) ||
        hg_datafile_number(f, "hn_alpha", HNA_LO, HNA_HI, "", &l.hn_alpha, err, errlen) ||
        hg_datafile_number(f, "hn_beta", HNB_LO, HNB_HI, "", &l.hn_beta, err, errlen) ||
        hg_datafile_number(f, "k_f", KF_LO, KF_HI, "W/(m K)", &l.k_f, err, errlen) ||
        hg_datafile_number(f, "c_p", CP_LO, CP_HI, "J/(kg K)", &l.c_p_f, err, errlen) ||
        hg_datafile_number(f, "rho_15", RHO_LO, RHO_HI, "kg/m^3", &l.rho_15, err, errlen))
        goto done;
    if (cross_check(&l, path, err, errlen)) goto done;
    if (hg_datafile_check_all_used(f, err, errlen)) goto done;
    *out = l;
    rc = 0;
done:
    hg_datafile_free(f);
    return rc;
}

void hg_lubricant_T_range(const hg_lubricant *l, double *T_lo, double *T_hi)
{
    *T_lo = l->vogel_c + l->vogel_b / log(HG_LUBRICANT_ETA_COLD / l->vogel_a);
    *T_hi = l->alpha_T[2] + HG_LUBRICANT_T_BEYOND;
}
