/* Bearing loads and friction (fmu-src/axle/bearings.c) against hand calculations of the
 * published forms (AGMA 2005 / Shigley mesh force components, ISO 281 axial loads of an
 * adjusted pair, the SKF model's rolling and sliding moments of tapered roller bearings, the
 * preload's thermal change) and against statics. */
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

/* the replenishment factor: flooded (K_rs = 0) against the low-level feed, warm and cold */
static void check_replenishment(const hg_trb *low, double w)
{
    /* the 32308 of check_friction, flooded: phi_rs = 1, so 13 mm^2/s, 2000 r/min gives
     * M_rr = 0.967691 1.321449 26000^0.6 = 569.864 N mm (2.5 % above the low-level feed);
     * cold oil, 2000 mm^2/s: phi_ish = 1/(1 + 1.84e-9 130000^1.28 2000^0.64) = 0.544024,
     * flooded M_rr = 0.544024 1.321449 (4e6)^0.6 = 6575.13 N mm; the low-level feed's
     * phi_rs = exp(-3e-8 4e6 130 sqrt(0.06)) = 0.0219014 leaves 144.005 N mm; sliding at
     * mu_EHL: 0.002 5802.323 = 11.6046 N mm either way */
    hg_trb b = *low;
    hg_trb_moment m, s;
    b.K_rs = 0.0;
    CHECK_CLOSE(hg_trb_phi_rs(0.0, 4e6, 31.843), 1.0, 0, 0);
    CHECK_CLOSE(hg_trb_phi_rs(HG_TRB_K_RS_LOW_LEVEL, 4e6, 130.0 * sqrt(0.06)), 0.0219014, 2e-6,
                0);
    m = hg_trb_friction(&b, 3000.0, 2000.0, 13e-6, w);
    CHECK_CLOSE(m.M_rr, 0.56986358, 1e-7, 0);
    CHECK_CLOSE(m.M_sl, 0.07775140, 1e-7, 0);
    m = hg_trb_friction(&b, 3000.0, 2000.0, 2000e-6, w);
    s = hg_trb_friction(low, 3000.0, 2000.0, 2000e-6, w);
    CHECK_CLOSE(m.M_rr, 6.5751256, 1e-7, 0);
    CHECK_CLOSE(s.M_rr, 0.14400456, 1e-6, 0);
    CHECK_CLOSE(m.M_sl, 0.01160465, 1e-6, 0);
    CHECK_CLOSE(s.M_sl, m.M_sl, 1e-12, 0);
    /* by hand, 30 r/min in 300 mm^2/s: 311.240 against 308.576 N mm (0.9 %) */
    m = hg_trb_friction(&b, 3000.0, 2000.0, 300e-6, 30.0 * 3.14159265358979323846 / 30.0);
    CHECK_CLOSE(m.M_rr, 0.31124027, 1e-7, 0);
}

static void check_friction(void)
{
    /* a 32308 (d 40, D 90 mm, d_m 65 mm, Y 1.74, series 323: R_1 2.38e-6, S_1 0.019), F_r 3 kN,
     * F_a 2 kN. By hand (SKF catalogue, frictional moment; N mm, mm, r/min, mm^2/s):
     * G_rr = 2.38e-6 65^2.38 (3000 + 10.9 1.74 2000)^0.31 = 1.321449,
     * G_sl = 0.019 65^0.82 (3000 + 2 1.74 2000) = 5802.323.
     * nu 13 mm^2/s, n 2000 r/min: phi_ish = 1/(1 + 1.84e-9 (130000)^1.28 13^0.64) = 0.967691,
     * phi_rs = exp(-3e-8 13 2000 130 sqrt(6/100)) = 0.975468, phi_bl = exp(-2.6e-8 26000^1.4
     * 65) = 0.077027, mu_sl = 0.013400: M_rr = 0.967691 0.975468 1.321449 26000^0.6 = 555.884,
     * M_sl = 77.7514 N mm (fed as by a low-level bath or a jet, K_rs = 3e-8). */
    hg_trb b = {0.040, 0.090, 1.74, 2.38e-6, 0.019, HG_TRB_K_RS_LOW_LEVEL};
    double w = 2000.0 * 3.14159265358979323846 / 30.0;
    hg_trb_moment m = hg_trb_friction(&b, 3000.0, 2000.0, 13e-6, w);
    CHECK_CLOSE(m.M_rr, 0.55588374, 1e-7, 0);
    CHECK_CLOSE(m.M_sl, 0.07775140, 1e-7, 0);
    m = hg_trb_friction(&b, 3000.0, 2000.0, 13e-6, -w); /* either direction */
    CHECK_CLOSE(m.M_rr, 0.55588374, 1e-7, 0);
    /* turned by hand, 30 r/min in 300 mm^2/s oil: phi_bl = 0.559601, mu_sl = 0.084821, the
     * boundary sliding now the larger part: M_rr = 308.576, M_sl = 492.158 N mm */
    m = hg_trb_friction(&b, 3000.0, 2000.0, 300e-6, 30.0 * 3.14159265358979323846 / 30.0);
    CHECK_CLOSE(m.M_rr, 0.30857579, 1e-7, 0);
    CHECK_CLOSE(m.M_sl, 0.49215813, 1e-7, 0);
    /* at rest only the boundary sliding: mu_bl G_sl = 0.15 5802.323 N mm */
    m = hg_trb_friction(&b, 3000.0, 2000.0, 13e-6, 0.0);
    CHECK_CLOSE(m.M_rr, 0.0, 0, 1e-15);
    CHECK_CLOSE(m.M_sl, 0.15 * 5.8023229, 1e-7, 0);
    /* unloaded: no moment */
    m = hg_trb_friction(&b, 0.0, 0.0, 13e-6, w);
    CHECK_CLOSE(m.M_rr + m.M_sl, 0.0, 0, 1e-15);
    check_replenishment(&b, w);
}

static void check_preload(void)
{
    /* 1580 N set at 20 degC, an aluminium carrier (23e-6 against steel's 11.5e-6), spread 60 mm,
     * 1e8 N/m: -69 N/K; 40 K warmer 1580 - 2760 < 0 -> no preload left; 10 K: 890 N; a cast
     * iron carrier (10.5e-6) tightens: 1580 + 1e8 1e-6 0.06 40 = 1820 N */
    CHECK_CLOSE(hg_trb_preload(1580.0, 1e8, 11.5e-6, 0.06, 40.0), 0.0, 0, 1e-12);
    CHECK_CLOSE(hg_trb_preload(1580.0, 1e8, 11.5e-6, 0.06, 10.0), 890.0, 1e-12, 0);
    CHECK_CLOSE(hg_trb_preload(1580.0, 1e8, -1e-6, 0.06, 40.0), 1820.0, 1e-12, 0);
}

int main(void)
{
    check_components();
    check_reactions();
    check_friction();
    check_preload();
    CHECK_DONE();
}
