/* The force law of a loaded mesh (mesh/mesh_law.h): levels on one power law W = C a^p give it
 * back exactly (force, tangent p W/a, energy C a^(p+1)/(p+1)); the energy's derivatives by
 * central differences (dU/da = W, dW/da = k, dU/dtheta at fixed a with k_m,l varying in theta);
 * the energy against the quadrature of W; the tangent beyond the last level; the inverse. */
#include <math.h>

#include "check.h"
#include "mesh/mesh_law.h"

#define N 5
static const double W_L[N] = {1190.0, 2380.0, 4760.0, 9520.0, 19040.0}; /* [N] */

/* Points on W = C a^p: k_l = W_l / a_l, a_l = (W_l / C)^(1/p); each level's k scaled by
 * (1 + e_l sin theta) to make the law depend on the mesh angle. */
/* Approach of level l's point. */
static double a_of(const hg_mesh_law *law, int l) { return exp(law->ln_a[l]); }

static void law_at(double theta, double C, double p, const double e[N], hg_mesh_law *law)
{
    static hg_law_levels lv; /* the law points to it */
    double k[N], dk[N];
    int l;
    for (l = 0; l < N; l++) {
        double k0 = W_L[l] / pow(W_L[l] / C, 1.0 / p);
        k[l] = k0 * (1.0 + e[l] * sin(theta));
        dk[l] = k0 * e[l] * cos(theta);
    }
    hg_mesh_law_levels(N, W_L, &lv);
    hg_mesh_law_points(&lv, k, dk, law);
}

static void one_power_law(void)
{
    const double p = 1.8, C = 4760.0 / pow(18.9e-6, 1.8), none[N] = {0};
    const double a[] = {1e-7, 3e-6, 8.8e-6, 12e-6, 18.9e-6, 30e-6, 40e-6};
    hg_mesh_law law;
    unsigned i;
    law_at(0.3, C, p, none, &law);
    for (i = 0; i < sizeof a / sizeof a[0]; i++) {
        hg_law_force f;
        double W = C * pow(a[i], p);
        hg_mesh_law_force(&law, a[i], &f);
        CHECK_CLOSE(f.W, W, 1e-12, 0.0);
        CHECK_CLOSE(f.k, p * W / a[i], 1e-12, 0.0);
        CHECK_CLOSE(f.U, W * a[i] / (p + 1.0), 1e-12, 0.0);
        CHECK(fabs(f.dU) < 1e-12 * f.U); /* no dependence on theta */
        CHECK_CLOSE(hg_mesh_law_approach(&law, W), a[i], 1e-12, 0.0);
    }
}

#define P 1.6
#define C (4760.0 / pow(18.9e-6, P)) /* the law through 4760 N at 18.9 um */

/* U(a) of the law at theta. */
static double energy(double theta, double a, const double e[N])
{
    hg_mesh_law law;
    hg_law_force f;
    law_at(theta, C, P, e, &law);
    hg_mesh_law_force(&law, a, &f);
    return f.U;
}

static void derivatives(void)
{
    const double e[N] = {0.30, 0.25, 0.20, 0.12, 0.08}, theta = 0.7, h = 1e-5;
    const double a[] = {2e-6, 9e-6, 15e-6, 25e-6, 40e-6, 80e-6, 150e-6};
    unsigned i;
    for (i = 0; i < sizeof a / sizeof a[0]; i++) {
        hg_mesh_law law;
        hg_law_force f, lo, hi;
        double da = 1e-4 * a[i];
        law_at(theta, C, P, e, &law);
        hg_mesh_law_force(&law, a[i], &f);
        hg_mesh_law_force(&law, a[i] - da, &lo);
        hg_mesh_law_force(&law, a[i] + da, &hi);
        CHECK_CLOSE((hi.U - lo.U) / (2.0 * da), f.W, 1e-7, 0.0);
        CHECK_CLOSE((hi.W - lo.W) / (2.0 * da), f.k, 1e-6, 0.0);
        CHECK_CLOSE((energy(theta + h, a[i], e) - energy(theta - h, a[i], e)) / (2.0 * h), f.dU,
                    1e-6, 1e-9 * f.U);
        CHECK(fabs(f.dU) > 1e-3 * f.U); /* the case tests something */
        CHECK_CLOSE(hg_mesh_law_approach(&law, f.W), a[i], 1e-11, 0.0);
    }
}

/* Composite Simpson of the law's W over [lo, hi] in n (even) intervals. */
static double simpson(const hg_mesh_law *law, double lo, double hi, int n)
{
    double h = (hi - lo) / n, sum = 0.0;
    int i;
    for (i = 0; i <= n; i++) {
        hg_law_force f;
        hg_mesh_law_force(law, lo + i * h, &f);
        sum += (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * f.W;
    }
    return sum * h / 3.0;
}

/* U against the quadrature of W from 0 (Simpson piece by piece between the level points, where
 * W has its kinks): the closed-form energies of the segments below and of the last tangent. */
static void energy_is_the_integral(void)
{
    const double e[N] = {0.30, 0.25, 0.20, 0.12, 0.08}, theta = 2.3;
    const double a[] = {1e-6, 7e-6, 13e-6, 33e-6, 61e-6, 120e-6};
    hg_mesh_law law;
    unsigned i;
    law_at(theta, C, P, e, &law);
    for (i = 0; i < sizeof a / sizeof a[0]; i++) {
        hg_law_force f;
        double lo = 0.0, U = 0.0;
        int l;
        for (l = 0; l <= N && lo < a[i]; l++) {
            double hi = l < N && a_of(&law, l) < a[i] ? a_of(&law, l) : a[i];
            U += simpson(&law, lo, hi, 2000);
            lo = hi;
        }
        hg_mesh_law_force(&law, a[i], &f);
        CHECK_CLOSE(f.U, U, 1e-9, 0.0);
    }
    CHECK(a[5] > a_of(&law, N - 1) && a[0] < a_of(&law, 0)); /* below the first, beyond the last */
}

static void ends_and_nodes(void)
{
    const double e[N] = {0.30, 0.25, 0.20, 0.12, 0.08};
    hg_mesh_law law;
    hg_law_force f, g;
    int l;
    law_at(1.1, C, P, e, &law);
    for (l = 0; l < N; l++) { /* each level's static point lies on the law */
        hg_mesh_law_force(&law, a_of(&law, l), &f);
        CHECK_CLOSE(f.W, W_L[l], 1e-12, 0.0);
    }
    /* beyond the last level: the last point's tangent */
    hg_mesh_law_force(&law, a_of(&law, N - 1) * (1.0 - 1e-12), &f);
    hg_mesh_law_force(&law, 2.0 * a_of(&law, N - 1), &g);
    CHECK_CLOSE(g.k, f.k, 1e-9, 0.0);
    CHECK_CLOSE(g.W, W_L[N - 1] + f.k * a_of(&law, N - 1), 1e-9, 0.0);
    hg_mesh_law_force(&law, 0.0, &f);
    CHECK(f.W == 0.0 && f.k == 0.0 && f.U == 0.0 && f.dU == 0.0);
    hg_mesh_law_force(&law, -1e-6, &f);
    CHECK(f.W == 0.0 && f.U == 0.0);
    CHECK(hg_mesh_law_approach(&law, 0.0) == 0.0);
}

int main(void)
{
    one_power_law();
    derivatives();
    energy_is_the_integral();
    ends_and_nodes();
    CHECK_DONE();
}
