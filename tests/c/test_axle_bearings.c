/* Bearing loads and friction (fmu-src/axle/bearings.c) against hand calculations of the
 * published forms (AGMA 2005 / Shigley mesh force components, ISO 281 axial loads of an
 * adjusted pair, Palmgren's friction moments as in ISO/TR 14179-2) and against statics. */
#include "check.h"
#include "axle/bearings.h"
#include "io/constants.h"

#define DEG (HG_PI / 180.0)

static void check_components(void)
{
    /* gear set 1 (Paouris et al. Table 1): pinion beta 46, delta 29.05; gear beta 27.6,
     * delta 59.65 deg; alpha_n 20 deg; F_t = 10 kN on the pinion. Hand values: */
    hg_member_geom p = {0.03157, 29.05 * DEG, 46.0 * DEG, 20.0 * DEG};
    hg_member_geom g = {0.06853, 59.65 * DEG, 27.6 * DEG, 20.0 * DEG};
    hg_mesh_force d = hg_mesh_force_components(&p, 1e4, +1.0, 1);
    hg_mesh_force c = hg_mesh_force_components(&p, 1e4, -1.0, 1);
    double F_tg = 1e4 * cos(27.6 * DEG) / cos(46.0 * DEG); /* common normal force */
    hg_mesh_force gd = hg_mesh_force_components(&g, F_tg, +1.0, 0);
    CHECK_CLOSE(d.F_a, 11596.754, 1e-7, 0);  /* drive: pushed away from the apex (out of mesh) */
    CHECK_CLOSE(d.F_r, -447.8507, 1e-6, 0);  /* and slightly drawn towards the gear */
    CHECK_CLOSE(c.F_a, -6508.3818, 1e-7, 0); /* coast: drawn into mesh */
    CHECK_CLOSE(c.F_r, 9608.6540, 1e-7, 0);
    CHECK_CLOSE(gd.F_a, 1151.5773, 1e-7, 0);
    CHECK_CLOSE(gd.F_r, 8402.8471, 1e-7, 0);
    /* spiral bevel pair (no offset, shafts at 90 deg): pinion thrust = gear separating force
     * and pinion separating force = gear thrust, in drive and coast */
    {
        hg_member_geom sp = {0.03, 20.0 * DEG, 35.0 * DEG, 20.0 * DEG};
        hg_member_geom sg = {0.09, 70.0 * DEG, 35.0 * DEG, 20.0 * DEG};
        double s;
        for (s = -1.0; s <= 1.0; s += 2.0) {
            hg_mesh_force a = hg_mesh_force_components(&sp, 5e3, s, 1);
            hg_mesh_force b = hg_mesh_force_components(&sg, 5e3, s, 0);
            CHECK_CLOSE(a.F_a, b.F_r, 1e-12, 1e-9);
            CHECK_CLOSE(a.F_r, b.F_a, 1e-12, 1e-9);
        }
    }
}

static void check_reactions(void)
{
    /* pinion overhung: head bearing 40 mm, tail bearing 100 mm from the mean point; drive
     * forces above. Hand statics: y: R_A = -6848.243, R_B = 6400.392; z: R_A = -16666.667,
     * R_B = 6666.667 -> |R_A| = 18018.774, |R_B| = 9241.724 N */
    hg_member_geom p = {0.03157, 29.05 * DEG, 46.0 * DEG, 20.0 * DEG};
    hg_mesh_force d = hg_mesh_force_components(&p, 1e4, +1.0, 1);
    double A, B, a1, a2;
    hg_shaft_reactions(&d, p.r_m, 0.040, 0.100, &A, &B);
    CHECK_CLOSE(A, 18018.774, 1e-7, 0);
    CHECK_CLOSE(B, 9241.7242, 1e-7, 0);
    /* straddle mounting symmetric about the mean point, no axial force: half the load each */
    {
        hg_mesh_force f = {1000.0, 0.0, 0.0};
        hg_shaft_reactions(&f, 0.05, -0.06, 0.06, &A, &B);
        CHECK_CLOSE(A, 500.0, 1e-12, 0);
        CHECK_CLOSE(B, 500.0, 1e-12, 0);
    }
    /* ISO 281 / SKF, two adjusted single-row bearings, Y = 1.7 both, the drive case above with
     * K_a = F_a = 11596.754 N onto bearing 1 (head) and a 3 kN preload:
     * F_i1 = 0.5 * 18018.774/1.7 = 5299.64, F_i2 = 2718.15 -> case "F_a2 = F_i2,
     * F_a1 = F_i2 + K_a" = 14314.90 N */
    hg_trb_pair_axial(18018.774, 1.7, 9241.7242, 1.7, 11596.754, 3000.0, &a1, &a2);
    CHECK_CLOSE(a2, 2718.1542, 1e-7, 0);
    CHECK_CLOSE(a1, 2718.1542 + 11596.754, 1e-7, 0);
    /* small external force: bearing 2 keeps bearing 1's induced thrust less K_a (SKF case 1c) */
    hg_trb_pair_axial(5000.0, 1.7, 1000.0, 1.7, 100.0, 0.0, &a1, &a2);
    CHECK_CLOSE(a1, 2500.0 / 1.7, 1e-12, 0);
    CHECK_CLOSE(a2, 2500.0 / 1.7 - 100.0, 1e-12, 0);
    /* no radial load: the preload shared, shifted by half the external force either way */
    hg_trb_pair_axial(0.0, 1.7, 0.0, 1.7, -400.0, 3000.0, &a1, &a2);
    CHECK_CLOSE(a1, 2800.0, 1e-12, 0);
    CHECK_CLOSE(a2, 3200.0, 1e-12, 0);
}

static void check_friction(void)
{
    /* d_m 60 mm, Y 1.7, f_0 3, f_1 0.0004, F_a 5 kN.
     * nu n = 100 mm^2/s * 2864.8 r/min = 2.86e5 >= 2000: M_0 = 1e-7*3*(2.8648e5)^(2/3)*60^3
     * = 281.60 N mm, M_1 = 0.0004*2*1.7*5000*60 = 408 N mm -> 0.689603 N m */
    hg_trb b = {0.060, 1.7, 3.0, 0.0004};
    CHECK_CLOSE(hg_trb_torque(&b, 5000.0, 1e-4, 300.0), 0.6896027, 1e-6, 0);
    CHECK_CLOSE(hg_trb_torque(&b, 5000.0, 1e-4, -300.0), 0.6896027, 1e-6, 0);
    /* nu n = 10 * 9.549 < 2000: M_0 = 160e-7*3*60^3 = 10.368 N mm -> 0.418368 N m */
    CHECK_CLOSE(hg_trb_torque(&b, 5000.0, 1e-5, 1.0), 0.418368, 1e-9, 0);
}

int main(void)
{
    check_components();
    check_reactions();
    check_friction();
    CHECK_DONE();
}
