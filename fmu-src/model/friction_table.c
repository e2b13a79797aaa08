/* Tabulated pair friction: see friction_table.h. */
#include "model/friction_table.h"

#include <math.h>
#include <string.h>

#define TWO_PI 6.283185307179586
#define W_FLOOR 1000.0   /* smallest W_max [N] */
#define LOAD_LOW 0.0625  /* rebuild when W_t falls below this fraction of W_max */
#define FD_SPEED 2e-3    /* relative step of the speed derivatives */
#define FD_T 0.1         /* step of the temperature derivative [K] */
#define LN_W_SPAN -6.907755278982137 /* ln(1e-3): the load range is [W_max / 1000, W_max] */
#define MU_FLOOR 1e-12   /* mu of pairs the friction model leaves without friction */
#define DRIFT_HOLD 2.0   /* the drift terms are held beyond this many windows of the key */

void hg_ft_key_for(double w_p, double ratio, double T_bath, double W_t, hg_ft_key *key)
{
    key->w_p = w_p;
    key->w_g = w_p / ratio;
    key->T_bath = T_bath;
    key->W_max = fmax(2.0 * fabs(W_t), W_FLOOR);
    key->w_dir = 0.0;
}

/* The speed window of a key speed [rad/s]: relative, with an absolute floor. */
static double speed_window(double key_w)
{
    double w = fabs(key_w);
    return HG_FT_SPEED_DRIFT * (w > HG_FT_SPEED_MIN ? w : HG_FT_SPEED_MIN); /* fmax, inline */
}

static int speed_covers(double key_w_p, double w_p)
{
    return fabs(w_p - key_w_p) <= speed_window(key_w_p);
}

static int temperature_covers(double key_T, double T_bath)
{
    return fabs(T_bath - key_T) <= HG_FT_T_DRIFT;
}

static int load_covers(double W_max, double W_t)
{
    double W = fabs(W_t);
    if (W > HG_FT_LOAD_FILL * W_max) return 0;
    return W >= LOAD_LOW * W_max || W_max <= W_FLOOR;
}

int hg_ft_speed_tabulated(double w_p)
{
    return fabs(w_p) >= HG_FT_SPEED_MIN;
}

int hg_ft_key_covers(const hg_ft_key *key, double w_p, double T_bath, double W_t)
{
    return speed_covers(key->w_p, w_p) && temperature_covers(key->T_bath, T_bath) &&
           load_covers(key->W_max, W_t);
}

void hg_ft_key_next(hg_ft_key *key, int valid, double w_p, double ratio, double T_bath,
                    double W_t)
{
    hg_ft_key fresh;
    hg_ft_key_for(w_p, ratio, T_bath, W_t, &fresh);
    if (!valid) {
        *key = fresh;
        return;
    }
    if (!speed_covers(key->w_p, w_p)) {
        double dir = w_p > key->w_p ? 1.0 : -1.0, half = 0.5 * (key->w_p + w_p);
        int reversal = key->w_dir == -dir && speed_covers(half, w_p);
        key->w_p = reversal ? half : w_p;
        key->w_dir = reversal ? 0.0 : dir;
        key->w_g = key->w_p / ratio;
    }
    if (!temperature_covers(key->T_bath, T_bath)) key->T_bath = T_bath;
    if (!load_covers(key->W_max, W_t)) key->W_max = fresh.W_max;
}

/* ln mu of the friction model at one point of the path (mu floored for pairs out of contact). */
static double ln_mu(const hg_friction_config *cfg, const hg_pair_point *pt, double W, double w_p,
                    double w_g, double T_bath, double *T_c_warm)
{
    hg_pair_contact c;
    hg_pair_friction f;
    c.W = W;
    hg_gearset_entrainment(pt->up, pt->ug, pt->vc, w_p, w_g, c.u_p, c.u_g);
    c.R_x = pt->R_x;
    c.R_y = pt->R_y;
    c.T_bath = T_bath;
    hg_friction_pair(cfg, &c, T_c_warm, &f);
    return log(fmax(f.F_f / W, MU_FLOOR));
}

void hg_friction_table_build(hg_friction_table *t, const hg_friction_config *cfg,
                             const hg_gearset *g, const hg_ft_key *key)
{
    double dw_p = FD_SPEED * fmax(fabs(key->w_p), HG_FT_SPEED_MIN);
    double dw_g = FD_SPEED * fmax(fabs(key->w_g), HG_FT_SPEED_MIN);
    double w_p = key->w_p, w_g = key->w_g, T = key->T_bath;
    int i, j;
    t->key = *key;
    t->usable = 1;
    for (j = 0; j < HG_FT_N_L; j++) {
        double W = key->W_max * exp(LN_W_SPAN * (1.0 - (double)j / (HG_FT_N_L - 1))), warm = NAN;
        for (i = 0; i < HG_FT_N_PSI; i++) { /* along the path: each solve warm-starts the next */
            hg_pair_point pt;
            double w0;
            hg_gearset_pair_point(g, TWO_PI * i / HG_FT_N_PSI, &pt);
            t->L[i][j] = ln_mu(cfg, &pt, W, w_p, w_g, T, &warm);
            w0 = warm;
            t->dL_wp[i][j] = (ln_mu(cfg, &pt, W, w_p + dw_p, w_g, T, &warm) -
                              ln_mu(cfg, &pt, W, w_p - dw_p, w_g, T, &warm)) / (2.0 * dw_p);
            t->dL_wg[i][j] = (ln_mu(cfg, &pt, W, w_p, w_g + dw_g, T, &warm) -
                              ln_mu(cfg, &pt, W, w_p, w_g - dw_g, T, &warm)) / (2.0 * dw_g);
            t->dL_T[i][j] = (ln_mu(cfg, &pt, W, w_p, w_g, T + FD_T, &warm) -
                             ln_mu(cfg, &pt, W, w_p, w_g, T - FD_T, &warm)) / (2.0 * FD_T);
            warm = w0;
            if (!(t->L[i][j] <= log(HG_FT_MU_MAX))) t->usable = 0;
        }
    }
    t->built = 1;
}

/* Catmull-Rom weights at t in [0, 1] for the nodes -1, 0, 1, 2. */
static void weights(double t, double w[4])
{
    double t2 = t * t, t3 = t2 * t;
    w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
    w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
    w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
}

typedef struct {
    int i[4], j[4];      /* node indices in psi and ln W */
    double wi[4], wj[4]; /* their weights */
} stencil;

static void make_stencil(double psi, double W, double W_max, stencil *st)
{
    double u = psi / TWO_PI * HG_FT_N_PSI;
    double v = (HG_FT_N_L - 1) * (1.0 + log(W / W_max) / -LN_W_SPAN);
    int i0, j0, k;
    u -= HG_FT_N_PSI * floor(u / HG_FT_N_PSI);
    if (!(u >= 0.0 && u < HG_FT_N_PSI)) u = 0.0; /* a non-finite phase: any node */
    i0 = (int)u;
    if (i0 >= HG_FT_N_PSI) i0 = HG_FT_N_PSI - 1;
    weights(u - i0, st->wi);
    v = v > 0.0 ? (v < HG_FT_N_L - 1.0 ? v : HG_FT_N_L - 1.0)
                : 0.0; /* mu held beyond the load range (and NaN) */
    j0 = (int)v;
    if (j0 > HG_FT_N_L - 2) j0 = HG_FT_N_L - 2;
    weights(v - j0, st->wj);
    for (k = 0; k < 4; k++) {
        st->i[k] = (i0 - 1 + k + HG_FT_N_PSI) % HG_FT_N_PSI;
        st->j[k] = j0 - 1 + k;
    }
    /* the end cells: ghost nodes on the line through the last two, a_-1 = 2 a_0 - a_1 */
    if (j0 == 0) {
        st->j[0] = 1;
        st->wj[1] += 2.0 * st->wj[0];
        st->wj[0] = -st->wj[0];
    }
    if (j0 == HG_FT_N_L - 2) {
        st->j[3] = HG_FT_N_L - 2;
        st->wj[2] += 2.0 * st->wj[3];
        st->wj[3] = -st->wj[3];
    }
}

static double interpolate(const double a[HG_FT_N_PSI][HG_FT_N_L], const stencil *st)
{
    double v = 0.0;
    int k, l;
    for (k = 0; k < 4; k++) {
        double row = 0.0;
        for (l = 0; l < 4; l++) row += st->wj[l] * a[st->i[k]][st->j[l]];
        v += st->wi[k] * row;
    }
    return v;
}

/* The drift d of the operating point from the key, held at +-DRIFT_HOLD windows. */
static double held(double d, double window)
{
    double lim = DRIFT_HOLD * window;
    return !(d < lim) ? lim : d < -lim ? -lim : d; /* fmax(-lim, fmin(d, lim)) without calls */
}

double hg_friction_table_F(const hg_friction_table *t, double psi, double W, double w_p,
                           double w_g, double T_bath)
{
    const hg_ft_key *k = &t->key;
    stencil st;
    if (W < HG_EHL_LOAD_MIN) return 0.0;
    make_stencil(psi, W, k->W_max, &st);
    return W * exp(interpolate(t->L, &st) +
                   interpolate(t->dL_wp, &st) * held(w_p - k->w_p, speed_window(k->w_p)) +
                   interpolate(t->dL_wg, &st) * held(w_g - k->w_g, speed_window(k->w_g)) +
                   interpolate(t->dL_T, &st) * held(T_bath - k->T_bath, HG_FT_T_DRIFT));
}
