/* The tribology layer's view of one flank pair in mesh: what a friction model needs to know of
 * it (the model's dynamics fills it in) and what the friction model returns. Frame (physics.md
 * §1): x along the minor axis of the contact ellipse (across the contact line), y along the major
 * axis. */
#ifndef HG_PAIR_CONTACT_H
#define HG_PAIR_CONTACT_H

typedef struct {
    double W;      /* normal load carried by the pair [N], >= 0 */
    double u_p[2]; /* pinion surface velocity relative to the contact point (x, y) [m/s] */
    double u_g[2]; /* gear surface velocity relative to the contact point (x, y) [m/s] */
    double R_x;    /* reduced radius of curvature along x [m] */
    double R_y;    /* reduced radius of curvature along y [m], R_y >= R_x */
    double T_bath; /* lubricant bath temperature [K] */
} hg_pair_contact;

typedef struct {
    double F_f;    /* friction force magnitude F_v + F_b [N], opposes the sliding V_s = u_p - u_g */
    double F_v;    /* viscous friction [N] */
    double F_b;    /* boundary (asperity) friction [N] */
    double mu;     /* F_f / W */
    double h_c;    /* central film thickness [m] */
    double lambda; /* Stribeck ratio h_c / sigma_c */
    double T_c;    /* lubricant temperature at the conjunction centre [K] */
    double u_e;    /* entrainment speed |U_e| [m/s] */
    double V_s;    /* sliding speed |V_s| [m/s] */
    double R_e;    /* effective radius along the entrainment direction [m] */
    double R_s;    /* effective radius along the side-leakage direction [m] */
    double p_h;    /* maximum Hertzian pressure [Pa] */
    double g_V;    /* regime viscosity parameter (docs/physics.md §7) */
    double g_E;    /* regime elasticity parameter (docs/physics.md §7) */
} hg_pair_friction;

#endif
