/* The block-triangular dense solve (solver/block_dense.h) against SUNDIALS' LU of the whole
 * matrix: a Newton matrix of 23 states of which 12, spread over the vector as the model's energy
 * integrals are, have unit columns; which columns count as passive; a singular coupled block. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "solver/block_dense.h"
#include <sundials/sundials_dense.h>

#define N 23

/* Uniform in [-1, 1) from a fixed linear congruential sequence. */
static double uniform(unsigned long *state)
{
    *state = (*state * 6364136223846793005UL + 1442695040888963407UL) & 0xffffffffffffUL;
    return 2.0 * (double)(*state >> 16) / 4294967296.0 - 1.0;
}

static int passive(sunindextype j)
{
    return (j >= 9 && j <= 14) || (j >= 16 && j <= 20) || j == 22;
}

/* M = I - gamma J with J's passive columns zero; cols[j] points into store. */
static void newton_matrix(double store[N][N], double *cols[N], unsigned long *seed)
{
    sunindextype i, j;
    for (j = 0; j < N; j++) {
        cols[j] = store[j];
        for (i = 0; i < N; i++)
            store[j][i] = (i == j ? 1.0 : 0.0) - (passive(j) ? 0.0 : 0.3 * uniform(seed));
    }
}

static void check_split(void)
{
    static double store[N][N];
    double *cols[N];
    sunindextype idx[N], j, k;
    unsigned long seed = 7;
    newton_matrix(store, cols, &seed);
    k = hg_block_split(cols, N, idx);
    CHECK(k == 11);
    for (j = 0; j < N; j++) CHECK(passive(idx[j]) == (j >= k));
    for (j = 1; j < k; j++) CHECK(idx[j] > idx[j - 1]);
    store[10][3] = 1e-300; /* nearly a unit column: coupled */
    CHECK(hg_block_split(cols, N, idx) == 12);
}

static void check_solve(void)
{
    static double store[N][N], full[N][N], blk_store[N][N];
    double *cols[N], *full_cols[N], *blk[N], b[N], x[N], work[N];
    sunindextype idx[N], piv[N], full_piv[N], i, j, k;
    unsigned long seed = 12345;
    int trial;
    for (j = 0; j < N; j++) blk[j] = blk_store[j], full_cols[j] = full[j];
    for (trial = 0; trial < 20; trial++) {
        newton_matrix(store, cols, &seed);
        memcpy(full, store, sizeof full);
        for (i = 0; i < N; i++) b[i] = x[i] = uniform(&seed);
        k = hg_block_split(cols, N, idx);
        CHECK(hg_block_factor(cols, idx, k, blk, piv) == 0);
        hg_block_solve(cols, N, idx, k, blk, piv, x, work);
        CHECK(SUNDlsMat_denseGETRF(full_cols, N, N, full_piv) == 0);
        SUNDlsMat_denseGETRS(full_cols, N, full_piv, b);
        for (i = 0; i < N; i++) CHECK_CLOSE(x[i], b[i], 1e-12, 1e-12);
    }
}

static void check_singular(void)
{
    static double store[N][N], blk_store[N][N];
    double *cols[N], *blk[N];
    sunindextype idx[N], piv[N], j, k;
    unsigned long seed = 99;
    for (j = 0; j < N; j++) blk[j] = blk_store[j];
    newton_matrix(store, cols, &seed);
    for (j = 0; j < N; j++) store[4][j] = 0.0; /* a zero coupled column */
    k = hg_block_split(cols, N, idx);
    CHECK(hg_block_factor(cols, idx, k, blk, piv) > 0);
}

int main(void)
{
    check_split();
    check_solve();
    check_singular();
    CHECK_DONE();
}
