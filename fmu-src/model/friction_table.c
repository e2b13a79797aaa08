/* Tabulated pair friction: see friction_table.h. */
#include "model/friction_table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/constants.h"
#include "model/table_store.h"

#define W_FLOOR 1000.0   /* smallest W_max [N] */
#define LOAD_LOW 0.0625  /* rebuild when W_t falls below this fraction of W_max */
#define FD_SPEED 5e-4    /* relative step of the speed derivatives (forward) */
#define FD_T 0.025       /* step of the temperature derivative (forward) [K] */
#define LN_W_SPAN -6.931471805599453 /* ln(2^-10): the load range is [W_max / 1024, W_max] */
#define SQRT_HALF 0.70710678118654752440
#define MU_FLOOR 1e-12   /* mu of pairs the friction model leaves without friction */
#define DRIFT_HOLD 2.0   /* the drift terms are held beyond this many windows of the key */

typedef char psi_nodes_in_thirds[HG_FT_N_PSI % 3 == 0 ? 1 : -1]; /* hg_friction_table_pairs */

void hg_ft_key_for(double w_p, double ratio, double T_bath, double W_t, hg_ft_key *key)
{
    key->w_p = w_p;
    key->w_g = w_p / ratio;
    key->T_bath = T_bath;
    key->W_max = fmax(2.0 * fabs(W_t), W_FLOOR);
    key->w_dir = 0.0;
}

double hg_ft_load_range_on_lattice(double W_max)
{
    double W = W_FLOOR; /* powers of 4 by multiplication: exact, the same on every platform */
    while (W < W_max && W < 1e300) W *= 4.0;
    return W;
}

double hg_ft_temperature_on_lattice(double T_bath)
{
    return 2.0 * HG_FT_T_DRIFT * floor(T_bath * (0.5 / HG_FT_T_DRIFT) + 0.5);
}

int hg_ft_temperature_nodes(double T_bath, double *T_lo, double *T_hi)
{
    double lo = HG_FT_T_NODE_STEP * floor(T_bath / HG_FT_T_NODE_STEP);
    if (hg_ft_temperature_on_lattice(T_bath) != T_bath || lo == T_bath) return 0;
    *T_lo = lo;
    *T_hi = lo + HG_FT_T_NODE_STEP;
    return 1;
}

void hg_ft_node_keys(const hg_ft_key *key, double ratio, hg_ft_key *lo, hg_ft_key *hi)
{
    double x = log(fabs(key->w_p) > HG_FT_SPEED_MIN ? fabs(key->w_p) : HG_FT_SPEED_MIN);
    double n = floor(x * (1.0 / HG_FT_NODE_STEP));
    *lo = *hi = *key;
    lo->w_p = copysign(exp(n * HG_FT_NODE_STEP), key->w_p);
    hi->w_p = copysign(exp((n + 1.0) * HG_FT_NODE_STEP), key->w_p);
    lo->w_g = lo->w_p / ratio;
    hi->w_g = hi->w_p / ratio;
    lo->w_dir = hi->w_dir = 0.0;
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

/* One point of the path under one load, evaluated at several speeds and temperatures: its
 * Hertz ellipse depends on neither, so it is solved once (hg_friction_hertz). */
typedef struct {
    const hg_pair_point *pt;
    double W;
    hg_hertz hertz;
} table_point;

static void contact_at(const table_point *q, double w_p, double w_g, double T_bath,
                       hg_pair_contact *c)
{
    c->W = q->W;
    hg_gearset_entrainment(q->pt->up, q->pt->ug, q->pt->vc, w_p, w_g, c->u_p, c->u_g);
    c->R_x = q->pt->R_x;
    c->R_y = q->pt->R_y;
    c->T_bath = T_bath;
}

static void point_at(const hg_friction_config *cfg, const hg_pair_point *pt, double W,
                     const hg_ft_key *k, table_point *q)
{
    hg_pair_contact c;
    q->pt = pt;
    q->W = W;
    contact_at(q, k->w_p, k->w_g, k->T_bath, &c);
    hg_friction_hertz(cfg, &c, &q->hertz);
}

/* ln mu of the friction model at one point of the path (mu floored for pairs out of contact). */
static double ln_mu(const hg_friction_config *cfg, const table_point *q, double w_p, double w_g,
                    double T_bath, double *T_c_warm)
{
    hg_pair_contact c;
    hg_pair_friction f;
    contact_at(q, w_p, w_g, T_bath, &c);
    hg_friction_pair_hertz(cfg, &c, &q->hertz, T_c_warm, &f);
    return log(fmax(f.F_f / q->W, MU_FLOOR));
}

/* The ghost nodes around the table (friction_table.h). */
static void fill_ghosts(hg_friction_table *t)
{
    int i, ch;
    for (i = 1; i <= HG_FT_N_PSI; i++)
        for (ch = 0; ch < HG_FT_N_CH; ch++) {
            double(*row)[HG_FT_N_CH] = t->c[i];
            row[0][ch] = 2.0 * row[1][ch] - row[2][ch];
            row[HG_FT_N_L + 1][ch] = 2.0 * row[HG_FT_N_L][ch] - row[HG_FT_N_L - 1][ch];
        }
    memcpy(t->c[0], t->c[HG_FT_N_PSI], sizeof t->c[0]);
    memcpy(t->c[HG_FT_N_PSI + 1], t->c[1], sizeof t->c[0]);
    memcpy(t->c[HG_FT_N_PSI + 2], t->c[2], sizeof t->c[0]);
}

/* ln mu at a drift d (0: w_p, 1: w_g, 2: T) of the point, its T_c solve warm-started from the
 * key's T_c there plus the shift the drift gave at the previous point of the path (shift[d],
 * updated): a step along the path changes that shift by a few per cent, so the solve starts
 * within about 1e-3 K of its root. */
static double ln_mu_drift(const hg_friction_config *cfg, const table_point *q, double w_p,
                          double w_g, double T_bath, double T_c, double *shift)
{
    double warm = T_c + *shift, L = ln_mu(cfg, q, w_p, w_g, T_bath, &warm);
    *shift = warm - T_c;
    return L;
}

/* The drift derivatives of ln mu at one node e (its channels) by forward differences from
 * e[HG_FT_CH_L] (steps small enough that their one-sided error, half a step's curvature, stays
 * a few per cent of the window's own): per rad/s of w_p and of w_g, or, when the gear speed
 * follows the pinion's (gear_follows: w_g = w_p w_g / w_p), one derivative along that line in
 * the w_p channel and none in w_g; per K of T. T_c: the key's conjunction temperature there;
 * shift: as ln_mu_drift's, per drift. */
static void drift_slopes(double *e, const hg_ft_key *k, const hg_friction_config *cfg,
                         const table_point *q, int gear_follows, double T_c, double shift[3])
{
    double L0 = e[HG_FT_CH_L], T = k->T_bath;
    double dw_p = FD_SPEED * fmax(fabs(k->w_p), HG_FT_SPEED_MIN);
    double dw_g = FD_SPEED * fmax(fabs(k->w_g), HG_FT_SPEED_MIN);
    double along = k->w_p != 0.0 ? dw_p * k->w_g / k->w_p : 0.0;
    if (gear_follows) {
        e[HG_FT_CH_WP] =
            (ln_mu_drift(cfg, q, k->w_p + dw_p, k->w_g + along, T, T_c, &shift[0]) - L0) / dw_p;
        e[HG_FT_CH_WG] = 0.0;
    } else {
        e[HG_FT_CH_WP] =
            (ln_mu_drift(cfg, q, k->w_p + dw_p, k->w_g, T, T_c, &shift[0]) - L0) / dw_p;
        e[HG_FT_CH_WG] =
            (ln_mu_drift(cfg, q, k->w_p, k->w_g + dw_g, T, T_c, &shift[1]) - L0) / dw_g;
    }
    e[HG_FT_CH_T] = (ln_mu_drift(cfg, q, k->w_p, k->w_g, T + FD_T, T_c, &shift[2]) - L0) / FD_T;
}

double hg_ft_column_load(double W_max, int j)
{
    int down = HG_FT_N_L - 1 - j; /* half powers of 2 below W_max */
    double W = ldexp(W_max, -(down / 2));
    return down % 2 ? W * SQRT_HALF : W;
}

void hg_ft_column_build(hg_ft_column *col, const hg_friction_config *cfg, const hg_gearset *g,
                        int flank, int level, const hg_ft_key *key, int gear_follows)
{
    double warm = NAN, shift[3] = {0.0, 0.0, 0.0}, step = 0.0;
    int i;
    col->key = *key;
    col->usable = 1;
    for (i = 0; i < HG_FT_N_PSI; i++) { /* along the path: each solve warm-starts the next */
        hg_pair_point pt;
        table_point q;
        double *e = col->c[i], before = warm;
        hg_gearset_pair_point(g, flank, level, HG_TWO_PI * i / HG_FT_N_PSI, &pt);
        point_at(cfg, &pt, key->W_max, key, &q);
        warm += step; /* the last step along the path continued */
        e[HG_FT_CH_L] = ln_mu(cfg, &q, key->w_p, key->w_g, key->T_bath, &warm);
        step = i > 0 ? warm - before : 0.0;
        drift_slopes(e, key, cfg, &q, gear_follows, warm, shift);
        if (!(e[HG_FT_CH_L] <= log(HG_FT_MU_MAX))) col->usable = 0;
    }
}

/* The key of column j of a table keyed k: k's with the column's load in place of W_max. */
static void column_key(const hg_ft_key *k, int j, hg_ft_key *ck)
{
    *ck = *k;
    ck->W_max = hg_ft_column_load(k->W_max, j);
}

/* Column j of t from col (its phases; the ghosts are filled when every column is in). */
static void column_into(hg_friction_table *t, int j, const hg_ft_column *col)
{
    int i;
    for (i = 0; i < HG_FT_N_PSI; i++) memcpy(t->c[i + 1][j + 1], col->c[i], sizeof col->c[i]);
    if (!col->usable) t->usable = 0;
}

static void table_start(hg_friction_table *t, const hg_ft_key *key)
{
    t->key = *key;
    t->per_W_max = 1.0 / key->W_max;
    t->usable = 1;
}

static void table_finish(hg_friction_table *t)
{
    fill_ghosts(t);
    t->built = 1;
}

void hg_friction_table_build(hg_friction_table *t, const hg_friction_config *cfg,
                             const hg_gearset *g, int flank, int level, const hg_ft_key *key,
                             int gear_follows)
{
    hg_ft_column col;
    int j;
    table_start(t, key);
    for (j = 0; j < HG_FT_N_L; j++) {
        hg_ft_key ck;
        column_key(key, j, &ck);
        hg_ft_column_build(&col, cfg, g, flank, level, &ck, gear_follows);
        column_into(t, j, &col);
    }
    table_finish(t);
}

/* Cubic Hermite on [x_lo, x_lo + h] at u = (x - x_lo) / h: the weights of the values and slopes
 * at both ends for the value, and (d..) for the derivative in x. */
typedef struct {
    double h00, h10, h01, h11, d00, d10, d11;
} hermite;

static hermite hermite_at(double u, double h)
{
    double u2 = u * u, u3 = u2 * u;
    hermite w;
    w.h00 = 2.0 * u3 - 3.0 * u2 + 1.0, w.h10 = (u3 - 2.0 * u2 + u) * h;
    w.h01 = 3.0 * u2 - 2.0 * u3, w.h11 = (u3 - u2) * h;
    w.d00 = 6.0 * (u2 - u) / h, w.d10 = 3.0 * u2 - 4.0 * u + 1.0, w.d11 = 3.0 * u2 - 2.0 * u;
    return w;
}

static double hermite_value(const hermite *w, double y_a, double s_a, double y_b, double s_b)
{
    return w->h00 * y_a + w->h10 * s_a + w->h01 * y_b + w->h11 * s_b;
}

static double hermite_slope(const hermite *w, double y_a, double s_a, double y_b, double s_b)
{
    return w->d00 * (y_a - y_b) + w->d10 * s_a + w->d11 * s_b;
}

static void table_of(hg_friction_table *t, const hg_friction_table *lo,
                     const hg_friction_table *hi, const hg_ft_key *key)
{
    t->key = *key;
    t->per_W_max = 1.0 / key->W_max;
    t->usable = lo->usable && hi->usable;
    t->built = 1;
}

/* Entry by entry (ghosts included: they are linear in the nodes, and so is the interpolant). */
void hg_friction_table_between(hg_friction_table *t, const hg_friction_table *lo,
                               const hg_friction_table *hi, const hg_ft_key *key,
                               int gear_follows)
{
    double x_lo = log(fabs(lo->key.w_p)), h = log(fabs(hi->key.w_p)) - x_lo;
    double u = (log(fabs(key->w_p)) - x_lo) / h;
    hermite hw = hermite_at(u, h);
    double g_lo = lo->key.w_g / lo->key.w_p, g_hi = hi->key.w_g / hi->key.w_p;
    double g = key->w_g / key->w_p, per_w = 1.0 / key->w_p;
    int i, j;
    for (i = 0; i < HG_FT_N_PSI + 3; i++)
        for (j = 0; j < HG_FT_N_L + 2; j++) {
            const double *a = lo->c[i][j], *b = hi->c[i][j];
            double *e = t->c[i][j];
            /* d ln mu / d ln|w_p| along w_g = g w_p */
            double s_a = lo->key.w_p * (a[HG_FT_CH_WP] + a[HG_FT_CH_WG] * g_lo);
            double s_b = hi->key.w_p * (b[HG_FT_CH_WP] + b[HG_FT_CH_WG] * g_hi);
            double dL = hermite_slope(&hw, a[HG_FT_CH_L], s_a, b[HG_FT_CH_L], s_b);
            double wg = gear_follows ? 0.0 : (1.0 - u) * a[HG_FT_CH_WG] + u * b[HG_FT_CH_WG];
            e[HG_FT_CH_L] = hermite_value(&hw, a[HG_FT_CH_L], s_a, b[HG_FT_CH_L], s_b);
            e[HG_FT_CH_WG] = wg;
            e[HG_FT_CH_WP] = dL * per_w - wg * g;
            e[HG_FT_CH_T] = (1.0 - u) * a[HG_FT_CH_T] + u * b[HG_FT_CH_T];
        }
    table_of(t, lo, hi, key);
}

void hg_friction_table_between_T(hg_friction_table *t, const hg_friction_table *lo,
                                 const hg_friction_table *hi, double T_bath)
{
    double h = hi->key.T_bath - lo->key.T_bath, u = (T_bath - lo->key.T_bath) / h;
    hermite hw = hermite_at(u, h);
    hg_ft_key key = lo->key;
    int i, j, ch;
    for (i = 0; i < HG_FT_N_PSI + 3; i++)
        for (j = 0; j < HG_FT_N_L + 2; j++) {
            const double *a = lo->c[i][j], *b = hi->c[i][j];
            double *e = t->c[i][j];
            for (ch = HG_FT_CH_WP; ch <= HG_FT_CH_WG; ch++) e[ch] = (1.0 - u) * a[ch] + u * b[ch];
            e[HG_FT_CH_L] = hermite_value(&hw, a[HG_FT_CH_L], a[HG_FT_CH_T], b[HG_FT_CH_L],
                                          b[HG_FT_CH_T]);
            e[HG_FT_CH_T] = hermite_slope(&hw, a[HG_FT_CH_L], a[HG_FT_CH_T], b[HG_FT_CH_L],
                                          b[HG_FT_CH_T]);
        }
    key.T_bath = T_bath;
    table_of(t, lo, hi, &key);
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

/* The phase part of a stencil: the cell's first node i0 (0 ... N_PSI - 1; the stencil's rows
 * are i0 ... i0 + 3 with the ghosts) and the weights, at u phase nodes. */
typedef struct {
    int i0;
    double w[4];
} phase_stencil;

static void phase_stencil_at(double u, phase_stencil *st)
{
    u -= HG_FT_N_PSI * floor(u * (1.0 / HG_FT_N_PSI));
    if (!(u >= 0.0 && u < HG_FT_N_PSI)) u = 0.0; /* the period's end after rounding (the same
                                                    node), or a non-finite phase: any node */
    st->i0 = (int)u;
    if (st->i0 >= HG_FT_N_PSI) st->i0 = HG_FT_N_PSI - 1;
    weights(u - st->i0, st->w);
}

/* The drift d of the operating point from the key, held at +-DRIFT_HOLD windows. */
static double held(double d, double window)
{
    double lim = DRIFT_HOLD * window;
    return !(d < lim) ? lim : d < -lim ? -lim : d; /* fmax(-lim, fmin(d, lim)) without calls */
}

/* The multipliers of the channels: 1 and the held drifts in w_p, w_g, T_bath. */
static void drifts(const hg_ft_key *k, double w_p, double w_g, double T_bath,
                   double d[HG_FT_N_CH])
{
    d[HG_FT_CH_L] = 1.0;
    d[HG_FT_CH_WP] = held(w_p - k->w_p, speed_window(k->w_p));
    d[HG_FT_CH_WG] = held(w_g - k->w_g, speed_window(k->w_g));
    d[HG_FT_CH_T] = held(T_bath - k->T_bath, HG_FT_T_DRIFT);
}

/* The load part of a stencil: the cell's first node j0 (0 ... N_L - 2) and the weights, at pair
 * load W of a table whose 1 / W_max is per_W_max. */
typedef struct {
    int j0;
    double w[4];
} load_stencil;

static void load_stencil_at(double per_W_max, double W, load_stencil *st)
{
    double v = (HG_FT_N_L - 1) * (1.0 + log(W * per_W_max) * (1.0 / -LN_W_SPAN));
    v = v > 0.0 ? (v < HG_FT_N_L - 1.0 ? v : HG_FT_N_L - 1.0)
                : 0.0; /* mu held beyond the load range (and NaN) */
    st->j0 = (int)v;
    if (st->j0 > HG_FT_N_L - 2) st->j0 = HG_FT_N_L - 2;
    weights(v - st->j0, st->w);
}

/* ln mu at the phase stencil ps (its first node shifted by `shift` nodes) and load stencil ls. */
static double ln_mu_at(const hg_friction_table *t, const phase_stencil *ps, int shift,
                       const load_stencil *ls, const double d[HG_FT_N_CH])
{
    double acc[HG_FT_N_CH] = {0.0, 0.0, 0.0, 0.0}, sum = 0.0;
    int i0 = (ps->i0 + shift) % HG_FT_N_PSI, k, l, ch;
    for (k = 0; k < 4; k++) { /* channel by channel (independent lanes), then the drifts */
        const double(*e)[HG_FT_N_CH] = t->c[i0 + k] + ls->j0; /* nodes i0 - 1 + k, j0 - 1 ... */
        double row[HG_FT_N_CH] = {0.0, 0.0, 0.0, 0.0};
        for (l = 0; l < 4; l++)
            for (ch = 0; ch < HG_FT_N_CH; ch++) row[ch] += ls->w[l] * e[l][ch];
        for (ch = 0; ch < HG_FT_N_CH; ch++) acc[ch] += ps->w[k] * row[ch];
    }
    for (ch = 0; ch < HG_FT_N_CH; ch++) sum += d[ch] * acc[ch];
    return sum;
}

double hg_friction_table_F(const hg_friction_table *t, double psi, double W, double w_p,
                           double w_g, double T_bath)
{
    phase_stencil ps;
    load_stencil ls;
    double d[HG_FT_N_CH];
    if (W < HG_EHL_LOAD_MIN) return 0.0;
    drifts(&t->key, w_p, w_g, T_bath, d);
    phase_stencil_at(psi * (HG_FT_N_PSI / HG_TWO_PI), &ps);
    load_stencil_at(t->per_W_max, W, &ls);
    return W * exp(ln_mu_at(t, &ps, 0, &ls, d));
}

/* What the three pairs' lookups in a table share: the drifts, the phase stencil at mesh angle
 * theta, each pair's load stencil (pair k at psi = (theta + 2 pi k) / 3); tables of one key share
 * all of it. */
typedef struct {
    double d[HG_FT_N_CH];
    phase_stencil ps;
    load_stencil ls[HG_MAX_PAIRS];
} pairs_stencil;

static void pairs_stencil_at(const hg_friction_table *t, double theta,
                             const double W[HG_MAX_PAIRS], double w_p, double w_g, double T_bath,
                             pairs_stencil *st)
{
    int k;
    drifts(&t->key, w_p, w_g, T_bath, st->d);
    phase_stencil_at(theta * (HG_FT_N_PSI / (3.0 * HG_TWO_PI)), &st->ps);
    for (k = 0; k < HG_MAX_PAIRS; k++)
        if (!(W[k] < HG_EHL_LOAD_MIN)) load_stencil_at(t->per_W_max, W[k], &st->ls[k]);
}

static void pairs_at(const hg_friction_table *t, const pairs_stencil *st,
                     const double W[HG_MAX_PAIRS], double F[HG_MAX_PAIRS])
{
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++)
        F[k] = W[k] < HG_EHL_LOAD_MIN
                   ? 0.0
                   : W[k] * exp(ln_mu_at(t, &st->ps, k * (HG_FT_N_PSI / 3), &st->ls[k], st->d));
}

void hg_friction_table_pairs(const hg_friction_table *t, double theta,
                             const double W[HG_MAX_PAIRS], double w_p, double w_g, double T_bath,
                             double F[HG_MAX_PAIRS])
{
    pairs_stencil st;
    pairs_stencil_at(t, theta, W, w_p, w_g, T_bath, &st);
    pairs_at(t, &st, W, F);
}

void hg_friction_table_pairs_blend(const hg_friction_table *lo, const hg_friction_table *hi,
                                   double w, double theta, const double W[HG_MAX_PAIRS],
                                   double w_p, double w_g, double T_bath, double F[HG_MAX_PAIRS])
{
    double F_hi[HG_MAX_PAIRS];
    pairs_stencil st;
    int k;
    pairs_stencil_at(lo, theta, W, w_p, w_g, T_bath, &st);
    pairs_at(lo, &st, W, F);
    if (!(w > 0.0) || hi == lo) return;
    /* the same key (a set's tables always): the same stencils, so they are not computed again */
    if (memcmp(&hi->key, &lo->key, sizeof lo->key) || hi->per_W_max != lo->per_W_max)
        pairs_stencil_at(hi, theta, W, w_p, w_g, T_bath, &st);
    pairs_at(hi, &st, W, F_hi);
    for (k = 0; k < HG_MAX_PAIRS; k++) F[k] += w * (F_hi[k] - F[k]);
}

void hg_ft_set_free(hg_ft_set *s)
{
    int i;
    for (i = 0; i < HG_N_FLANKS * HG_MAX_LEVELS; i++) {
        free(s->t[i]);
        s->t[i] = NULL;
    }
    s->n_flanks = s->n_levels = 0;
    s->keyed = 0;
}

/* The store's hash of what the tables depend on: the friction model (its parameters and the
 * lubricant's values, not where they are), the gear set's series and gear_follows. */
static hg_store_id content_id(const hg_friction_config *cfg, const hg_gearset *g,
                              int gear_follows)
{
    hg_store_id id = hg_store_id_of("friction table nodes");
    hg_ehl_params e;
    memcpy(&e, &cfg->ehl, sizeof e); /* the bytes, padding as the defaults zeroed it */
    e.z_table = NULL;                /* made from the lubricant hashed below */
    id = hg_store_hash(id, &cfg->model, sizeof cfg->model);
    id = hg_store_hash(id, &cfg->mu_const, sizeof cfg->mu_const);
    id = hg_store_hash(id, &e, sizeof e);
    if (cfg->lub) id = hg_store_hash(id, cfg->lub, sizeof *cfg->lub);
    id = hg_store_hash(id, g, sizeof *g);
    return hg_store_hash(id, &gear_follows, sizeof gear_follows);
}

void hg_ft_set_alloc(hg_ft_set *s, const hg_friction_config *cfg, const hg_gearset *g,
                     int gear_follows)
{
    hg_store_id id = content_id(cfg, g, gear_follows);
    int i, n = g->n_flanks * g->n_levels;
    s->n_flanks = g->n_flanks;
    s->n_levels = g->n_levels;
    s->keyed = 0;
    s->gear_follows = gear_follows;
    s->ratio = (double)g->N_g / g->N_p;
    s->content[0] = id.a;
    s->content[1] = id.b;
    for (i = 0; i < n; i++) {
        int fl = i / g->n_levels, lv = i % g->n_levels, first = 0;
        while (!hg_gearset_same_contact(g, fl, first, lv)) first++;
        s->shared[i] = fl * g->n_levels + first;
        if (s->t[i]) s->t[i]->built = 0;
    }
}

/* What a node table's column is built from. */
typedef struct {
    const hg_friction_config *cfg;
    const hg_gearset *g;
    int flank, level, gear_follows;
    const hg_ft_key *key; /* the column's (column_key) */
} column_job;

static int build_column(void *column, void *ctx)
{
    const column_job *j = ctx;
    hg_ft_column_build(column, j->cfg, j->g, j->flank, j->level, j->key, j->gear_follows);
    return 0;
}

/* The node table of table index i for key k into t, column by column from the store (read from
 * the FMU's resources or solved now if no instance of the process has it): a column is named by
 * its own load, so the node tables of the load ranges on the lattice share the columns their
 * ranges share. 0, or -1 when out of memory or a hash collision (never seen): the direct
 * solve. */
static int node(hg_ft_set *s, const hg_friction_config *cfg, const hg_gearset *g, int i,
                const hg_ft_key *k, hg_friction_table *t)
{
    int j;
    table_start(t, k);
    for (j = 0; j < HG_FT_N_L; j++) {
        hg_store_id id;
        column_job job;
        hg_ft_key ck;
        const hg_ft_column *col;
        int built, ok;
        column_key(k, j, &ck);
        id.a = s->content[0], id.b = s->content[1];
        id = hg_store_hash(id, &i, sizeof i);
        id = hg_store_hash(id, &ck, sizeof ck);
        job.cfg = cfg, job.g = g, job.flank = i / s->n_levels, job.level = i % s->n_levels;
        job.gear_follows = s->gear_follows, job.key = &ck;
        col = hg_store_get_shipped(s->resource_dir, id, sizeof *col, build_column, &job, &built);
        s->solved += (unsigned long)built;
        ok = col && !memcmp(&col->key, &ck, sizeof ck);
        if (ok) column_into(t, j, col);
        hg_store_put(col);
        if (!ok) return -1;
    }
    table_finish(t);
    return 0;
}

/* The node table of table index i at speed node key k into t: solved at k's temperature, or,
 * when T_node holds the temperature nodes around it (hg_ft_temperature_nodes), between their
 * node tables, solved into scratch[0] and scratch[1]. 0, or -1 as node. */
static int speed_node(hg_ft_set *s, const hg_friction_config *cfg, const hg_gearset *g, int i,
                      const hg_ft_key *k, const double *T_node, hg_friction_table *t,
                      hg_friction_table *scratch)
{
    int n;
    if (!T_node) return node(s, cfg, g, i, k, t);
    for (n = 0; n < 2; n++) {
        hg_ft_key k_T = *k;
        k_T.T_bath = T_node[n];
        if (node(s, cfg, g, i, &k_T, &scratch[n])) return -1;
    }
    hg_friction_table_between_T(t, &scratch[0], &scratch[1], k->T_bath);
    return 0;
}

const hg_friction_table *hg_ft_set_table(hg_ft_set *s, const hg_friction_config *cfg,
                                         const hg_gearset *g, int flank, int level)
{
    int i = s->shared[flank * s->n_levels + level];
    hg_friction_table *t = s->t[i];
    if (!t && !(t = s->t[i] = calloc(1, sizeof *t))) return NULL;
    if (!t->built || memcmp(&t->key, &s->key, sizeof s->key)) {
        hg_ft_key k_lo, k_hi;
        double T[2];
        const double *T_node = hg_ft_temperature_nodes(s->key.T_bath, &T[0], &T[1]) ? T : NULL;
        /* the two around the key, and two more for the temperature nodes */
        hg_friction_table *nodes = malloc((T_node ? 4 : 2) * sizeof *nodes);
        int ok;
        hg_ft_node_keys(&s->key, s->ratio, &k_lo, &k_hi);
        ok = nodes && !speed_node(s, cfg, g, i, &k_lo, T_node, &nodes[0], &nodes[2]) &&
             !speed_node(s, cfg, g, i, &k_hi, T_node, &nodes[1], &nodes[2]);
        if (ok) hg_friction_table_between(t, &nodes[0], &nodes[1], &s->key, s->gear_follows);
        free(nodes);
        if (!ok) return NULL; /* out of memory: the direct solve */
    }
    return t->usable ? t : NULL;
}
