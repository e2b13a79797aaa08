/* A table of a flank pair's friction force over its engagement, so that the right-hand side
 * interpolates instead of solving the friction model (the thermal EHL solve) at every call.
 *
 * The three pairs follow the same path of contact a third of the load-share period apart, so one
 * table serves all of them: F_f(psi, W) over the pair phase psi (period 2 pi, hg_gearset_pair_point)
 * on one flank at one torque level of the gear set (hg_ft_set holds one per flank and level)
 * and the pair load W in [0, W_max], at reference pinion and gear speeds and bath temperature,
 * with its first derivatives in those three for the operating point's drift around them. The
 * entries come from hg_friction_pair itself, so the table wraps whichever friction model runs.
 * What is tabulated is ln(mu) = ln(F_f / W), smooth along the path and in ln W (mu varies as a
 * small power of the load, or exponentially with the pressure for the isothermal shear), and its
 * derivatives; interpolation is Catmull-Rom cubic in psi (periodic) and in ln W over
 * [W_max / 1024, W_max], mu held beyond. Its error against the direct solve is tested in
 * tests/c/test_friction_table.c. */
#ifndef HG_FRICTION_TABLE_H
#define HG_FRICTION_TABLE_H

#include "model/friction.h"
#include "mesh/gearset.h"

/* phases over the load-share period: a multiple of 3, so that the three pairs, a third of the
 * period apart, fall on the same fraction of their cells (hg_friction_table_pairs) */
#define HG_FT_N_PSI 129
#define HG_FT_N_L 21    /* loads: W_max 2^(-(20 - j) / 2), j = 0 ... 20, half powers of 2 over
                           [W_max / 1024, W_max] (16 loads over three decades left 1.7e-3 of mu
                           at the design point with the moving contact of docs/physics.md §10.4) */

enum { HG_FT_CH_L, HG_FT_CH_WP, HG_FT_CH_WG, HG_FT_CH_T, HG_FT_N_CH };

/* What a table is built for; equal keys give bit-identical tables. */
typedef struct {
    double w_p, w_g; /* reference pinion and gear speeds [rad/s] */
    double T_bath;   /* reference bath temperature [K] */
    double W_max;    /* top of the load range [N] */
    double w_dir;    /* how w_p was last moved (hg_ft_key_next): +1 up, -1 down, 0 centred or new
                        (a double: the key is compared as bytes and has no padding) */
} hg_ft_key;

typedef struct {
    hg_ft_key key;
    int built;
    int usable; /* every tabulated mu is a friction coefficient (<= HG_FT_MU_MAX) */
    double per_W_max; /* 1 / key.W_max [1/N] */
    /* At phase node i and load node j, [i + 1][j + 1]: ln mu and its derivatives per rad/s of
     * w_p and w_g and per K of T_bath, side by side (HG_FT_CH_*), so that an interpolation reads
     * each node once. Around them ghost nodes: the phases wrap (i = -1, N_PSI, N_PSI + 1), the
     * loads continue on the line through the last two nodes (j = -1, N_L). */
    double c[HG_FT_N_PSI + 3][HG_FT_N_L + 2][HG_FT_N_CH];
} hg_friction_table;

/* Node speeds: the tables the friction model is solved for sit at pinion speeds
 * +-exp(n HG_FT_NODE_STEP) rad/s (n = 0, 1, ...; the gear's w_p / ratio), and the table of an
 * operating point is the cubic Hermite in ln|w_p| between the two nodes around it, from their
 * values and speed derivatives (hg_friction_table_between): about 28 % of speed per node, where
 * the key's window is 4 %, so a ramp or a launch's swing solves a node table every seventh
 * window or less, and an operating point that comes back finds its nodes built. The
 * interpolant stays within 4e-5 of ln mu of a table solved at the point (0.25 in ln w; 1e-4 at
 * 0.5), against the tables' own 1.5e-3 (tests/c/test_friction_table.c). */
#define HG_FT_NODE_STEP 0.25

/* Relative drift of the pinion speed, drift of the bath temperature [K] and load fraction of
 * W_max beyond which hg_ft_key_covers asks for a rebuild. The gear speed's own excursions from
 * w_p N_p / N_g (the dynamic transmission error's rate, about 1 %) are left to the derivative.
 * 4 % of speed: the derivative's error there stays within the test's bound (worst 1.2e-3 of the
 * pair's friction against 1.1e-3 at 2 %), and a resonance's speed swing (+-2.5 % at 1200 rpm,
 * 300 N m) fits one table. */
#define HG_FT_SPEED_DRIFT 0.04
/* [rad/s] Speed windows are relative to at least this, and below it the table is not used:
 * there the window is a growing fraction of the speed and ln mu, which drops to the film's
 * limit at standstill, is far from linear in it (F_f at a pair load of 3 kN: 1 N at rest, 27 N
 * at 0.1 rad/s, 36 N at 0.3 rad/s), so the direct solve runs. */
#define HG_FT_SPEED_MIN 1.0
#define HG_FT_T_DRIFT 1.0
#define HG_FT_LOAD_FILL 0.7

/* The key for an operating point: pinion speed w_p and the gear's kinematic speed w_p / ratio,
 * bath temperature, loads up to twice W_t. */
void hg_ft_key_for(double w_p, double ratio, double T_bath, double W_t, hg_ft_key *key);

/* Whether the table serves the pinion speed w_p [rad/s] at all (|w_p| >= HG_FT_SPEED_MIN). */
int hg_ft_speed_tabulated(double w_p);

/* Whether the table built for key still serves the operating point (w_p, T_bath, W_t). */
int hg_ft_key_covers(const hg_ft_key *key, double w_p, double T_bath, double W_t);

/* The next key when *key (if valid) no longer covers the operating point: what still covers it
 * keeps its value (a load rebuild keeps the speed and temperature); a speed that left the window
 * the way the last move went (a ramp) becomes the new key, one that left it the other way (an
 * oscillation) moves the key to halfway between the two extremes when that covers it, so a
 * resonance's speed swing of up to two windows keeps one table instead of a rebuild at every
 * extreme; temperature and load as hg_ft_key_for. The result always covers the point. */
void hg_ft_key_next(hg_ft_key *key, int valid, double w_p, double ratio, double T_bath,
                    double W_t);

/* The load range the tables are keyed on (friction_table_policy.h): the smallest
 * 1000 N x 4^k at or above W_max. The tables' loads are spaced evenly in ln W over three decades
 * below W_max whatever it is, so the range serves as well; a launch, a tip-out or a drive
 * cycle's load swings then meet a few ranges again and again instead of a new one at every 40 %
 * of load, and their node tables are found in the store (each new range solves its own), with
 * fewer step events. */
double hg_ft_load_range_on_lattice(double W_max);

/* The bath temperature the tables are keyed on once it moves (friction_table_policy.h): the
 * nearest multiple of 2 HG_FT_T_DRIFT [K], which still covers T_bath (hg_ft_key_covers: within HG_FT_T_DRIFT), so
 * the drift from the key stays within the window the tables' error is tested over. An oil that
 * warms through a drive cycle then keys its tables at a few temperatures, each every 2 K, and
 * finds their node tables again at every speed and load range it comes back to, where a key at
 * the temperature itself was new at every kelvin. */
double hg_ft_temperature_on_lattice(double T_bath);

/* Temperature nodes [K]. A key temperature on that lattice (a bath temperature that moved) has
 * its node tables solved at the multiples of HG_FT_T_NODE_STEP around it and interpolated
 * between them (hg_friction_table_between_T), so an oil that warms through a drive cycle
 * solves the node tables of every speed and load range it meets once per HG_FT_T_NODE_STEP
 * instead of at every key; a key on a node, or off the lattice (the first key, at the bath
 * temperature itself), is solved there. 1 and the nodes T_lo < T_bath < T_hi = T_lo +
 * HG_FT_T_NODE_STEP when T_bath lies between nodes, else 0. */
#define HG_FT_T_NODE_STEP 8.0
int hg_ft_temperature_nodes(double T_bath, double *T_lo, double *T_hi);

/* Beyond this friction coefficient (parameters far outside physics, e.g. a vanishing k_f) the
 * table is not used: the direct solve runs, and fails as it would without the table. */
#define HG_FT_MU_MAX 10.0

/* Fills the table from the friction model cfg on gear set g's series of flank `flank` and torque
 * level `level` (as for hg_gearset_pair_point): four solves per node, or three when
 * gear_follows (a rigid mesh: w_g stays w_p w_g / w_p of the key, so one speed derivative along
 * that line serves, in the w_p channel, and the w_g channel is 0). */
void hg_friction_table_build(hg_friction_table *t, const hg_friction_config *cfg,
                             const hg_gearset *g, int flank, int level, const hg_ft_key *key,
                             int gear_follows);

/* One load of a table along the path: ln mu and its derivatives at the phase nodes at load
 * key.W_max. A table is its columns side by side (hg_friction_table_build), and the columns of the
 * node tables live in the store one by one, named by their own load: column j of a table keyed
 * W_max has the load hg_ft_column_load(W_max, j), with the same bits as column j + 4 of a table
 * keyed 4 W_max, so node tables on the load lattice (hg_ft_load_range_on_lattice) share all but
 * four of their columns with the range above and below. */
typedef struct {
    hg_ft_key key; /* W_max: the column's load [N] */
    int usable;    /* every mu of the column <= HG_FT_MU_MAX */
    double c[HG_FT_N_PSI][HG_FT_N_CH];
} hg_ft_column;

/* The load of column j of a table whose load range ends at W_max [N]: W_max 2^-k (exact) for
 * even N_L - 1 - j = 2 k, times sqrt(1/2) for odd ones. */
double hg_ft_column_load(double W_max, int j);

/* The column of hg_friction_table_build at load key->W_max. */
void hg_ft_column_build(hg_ft_column *col, const hg_friction_config *cfg, const hg_gearset *g,
                        int flank, int level, const hg_ft_key *key, int gear_follows);

/* The table for key between the node tables lo and hi (hg_ft_node_keys of key; the same flank,
 * level and gear_follows): cubic Hermite in ln|w_p| of ln mu along the line w_g / w_p of the
 * keys from the nodes' values and speed derivatives, its derivative there the table's speed
 * derivative along that line; the w_g and temperature derivatives interpolated linearly. */
void hg_friction_table_between(hg_friction_table *t, const hg_friction_table *lo,
                               const hg_friction_table *hi, const hg_ft_key *key,
                               int gear_follows);

/* The table at bath temperature T_bath between the tables lo and hi of the temperature nodes
 * around it (keys alike but for their temperatures): cubic Hermite in T of ln mu from the
 * nodes' values and temperature derivatives, its derivative there the table's temperature
 * derivative; the speed derivatives interpolated linearly. */
void hg_friction_table_between_T(hg_friction_table *t, const hg_friction_table *lo,
                                 const hg_friction_table *hi, double T_bath);

/* The keys of the node tables around key's pinion speed (|w_p| >= HG_FT_SPEED_MIN): node speeds
 * with w_p's sign, w_g = w_p / ratio, key's temperature and load range. */
void hg_ft_node_keys(const hg_ft_key *key, double ratio, hg_ft_key *lo, hg_ft_key *hi);

/* F_f [N] of a pair at phase psi carrying W at speeds w_p, w_g and bath temperature T_bath; the
 * drifts from the key enter up to twice the rebuild window (speeds relative to at least
 * HG_FT_SPEED_MIN, temperature HG_FT_T_DRIFT) and are held beyond, so that mu stays bounded when the operating
 * point leaves the window within a step. */
double hg_friction_table_F(const hg_friction_table *t, double psi, double W, double w_p,
                           double w_g, double T_bath);

/* The same for the three pairs at mesh angle theta (pair k at psi = (theta + 2 pi k) / 3), pair k
 * carrying W[k]: F[k]. */
void hg_friction_table_pairs(const hg_friction_table *t, double theta,
                             const double W[HG_MAX_PAIRS], double w_p, double w_g, double T_bath,
                             double F[HG_MAX_PAIRS]);

/* Between two torque levels: (1 - w) F_lo + w F_hi from the tables lo and hi of the levels (w the
 * upper level's weight of hg_gearset_level_at; lo alone when w = 0 or hi is lo). The direct solve
 * blends the levels' geometry instead; the difference is tested in tests/c/test_friction_table.c. */
void hg_friction_table_pairs_blend(const hg_friction_table *lo, const hg_friction_table *hi,
                                   double w, double theta, const double W[HG_MAX_PAIRS],
                                   double w_p, double w_g, double T_bath, double F[HG_MAX_PAIRS]);

/* The tables of every flank and torque level of a gear set, t[flank * n_levels + level], for one
 * key: a table is made when first asked for under the key (hg_ft_set_table) between the node
 * tables around the key's speed (and temperature: hg_ft_temperature_nodes), which come from the
 * process's table store (model/table_store.h: solved by the first instance that needs them, kept while the store has room), so a run builds
 * only the levels its torque reaches, and levels whose contact series are the same
 * (hg_gearset_same_contact: the friction at a pair load depends on the contact alone) share one.
 * What a table holds depends on the key, flank and level alone, so when and from which stored
 * nodes it was made changes nothing but the cost. */
typedef struct {
    hg_ft_key key;
    int keyed; /* key is set */
    int gear_follows; /* the tables are built for a rigid mesh (hg_friction_table_build) */
    int n_flanks, n_levels;
    double ratio;     /* N_g / N_p of the gear set (the node keys' w_g) */
    int shared[HG_N_FLANKS * HG_MAX_LEVELS]; /* the table each flank and level uses */
    hg_friction_table *t[HG_N_FLANKS * HG_MAX_LEVELS]; /* allocated when first used */
    unsigned long long content[2]; /* the store's hash of the friction model, gear set and
                                      gear_follows (hg_ft_set_alloc) */
    unsigned long solved;          /* node table columns this set solved (diagnostics) */
    const char *resource_dir;      /* where shipped node tables lie (resources/tables/), or
                                      NULL (hg_store_get_shipped) */
} hg_ft_set;

/* Prepares s, which must be zeroed or prepared before, for the tables of friction model cfg on
 * gear set g, to be built with gear_follows (none built yet). */
void hg_ft_set_alloc(hg_ft_set *s, const hg_friction_config *cfg, const hg_gearset *g,
                     int gear_follows);
void hg_ft_set_free(hg_ft_set *s);

/* The table of `flank` and `level` (as hg_gearset_level_at gives them) for s->key, built now
 * with cfg on g (those of hg_ft_set_alloc) if it is not; NULL when it is not usable or out of
 * memory (the direct solve runs). */
const hg_friction_table *hg_ft_set_table(hg_ft_set *s, const hg_friction_config *cfg,
                                         const hg_gearset *g, int flank, int level);

#endif
