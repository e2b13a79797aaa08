/* Backlash dead zone of the mesh (Kahraman & Singh 1990; b is the HALF backlash), exact or
 * smoothed, with its potential so that the energy audit closes for both. */
#ifndef HG_BACKLASH_H
#define HG_BACKLASH_H

/* Contact modes of the exact dead zone: the right-hand side uses the branch of the current mode,
 * so no internal step ever straddles a contact change; root-finding switches the mode. */
enum { HG_MODE_BACK = -1, HG_MODE_FREE = 0, HG_MODE_DRIVE = 1 };

typedef struct {
    double b;   /* half backlash [m] */
    double eps; /* smoothing width [m]; 0 = exact dead zone */
} hg_backlash;

/* f(x) [m]: exact: x - b (drive), 0 (free), x + b (back) by `mode`; smoothed (eps > 0):
 *   f = r(x - b) - r(-x - b),  r(u) = (u + sqrt(u^2 + eps^2)) / 2,
 * a C-infinity ramp that differs from the exact f by at most eps/2 (at x = +-b). */
double hg_backlash_f(const hg_backlash *bl, double x, int mode);

/* The dead zone by flank: f = f_d + f_b, the drive flank's share f_d >= 0 (x > b) and the back
 * flank's f_b <= 0 (x < -b), and each flank's engagement g = df/dx in [0, 1]: 1 in contact and 0
 * apart for the exact dead zone (by `mode`), the slope of the smooth ramp when eps > 0. The mesh
 * damper acts through the engagement, so that a damper between separated teeth does not act. */
typedef struct {
    double f_d, f_b; /* [m] */
    double g_d, g_b; /* [1] */
} hg_flank_split;

void hg_backlash_flanks(const hg_backlash *bl, double x, int mode, hg_flank_split *s);

/* Potential Phi(x) with dPhi/dx = f(x) and Phi(0) = 0 [m^2]: the mesh spring stores k_m Phi. */
double hg_backlash_potential(const hg_backlash *bl, double x, int mode);

/* The exact contact mode that x lies in (boundaries belong to the contact). */
int hg_backlash_mode(double x, double b);

#endif
