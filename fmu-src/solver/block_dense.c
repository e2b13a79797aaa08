/* The block-triangular dense linear solver: see block_dense.h. */
#include "solver/block_dense.h"

#include <stdlib.h>
#include <sundials/sundials_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

/* Whether column j of the n x n matrix m is the unit vector e_j. */
static int unit_column(const double *col, sunindextype n, sunindextype j)
{
    sunindextype i;
    for (i = 0; i < n; i++)
        if (col[i] != (i == j ? 1.0 : 0.0)) return 0;
    return 1;
}

sunindextype hg_block_split(double *const *m, sunindextype n, sunindextype *idx)
{
    sunindextype j, k = 0, p = n;
    for (j = n - 1; j >= 0; j--) /* passive ones from the back, in descending order */
        if (unit_column(m[j], n, j)) idx[--p] = j;
    for (j = 0; j < n; j++)
        if (!unit_column(m[j], n, j)) idx[k++] = j;
    return k;
}

sunindextype hg_block_factor(double *const *m, const sunindextype *idx, sunindextype k,
                             double **blk, sunindextype *piv)
{
    sunindextype r, c;
    for (c = 0; c < k; c++)
        for (r = 0; r < k; r++) blk[c][r] = m[idx[c]][idx[r]];
    return SUNDlsMat_denseGETRF(blk, k, k, piv);
}

void hg_block_solve(double *const *m, sunindextype n, const sunindextype *idx, sunindextype k,
                    double **blk, const sunindextype *piv, double *b, double *work)
{
    sunindextype r, c;
    for (r = 0; r < k; r++) work[r] = b[idx[r]];
    if (k > 0) SUNDlsMat_denseGETRS(blk, k, (sunindextype *)piv, work);
    for (r = k; r < n; r++) { /* x_p = b_p - C x_c */
        double acc = b[idx[r]];
        for (c = 0; c < k; c++) acc -= m[idx[c]][idx[r]] * work[c];
        b[idx[r]] = acc;
    }
    for (r = 0; r < k; r++) b[idx[r]] = work[r];
}

/* ------------------------------------------------------------------ the SUNDIALS solver */

typedef struct {
    sunindextype n, k, last_flag;
    sunindextype *idx, *piv;
    double **blk, *work;
} block_content;

#define CONTENT(S) ((block_content *)(S)->content)

static SUNLinearSolver_Type get_type(SUNLinearSolver S)
{
    (void)S;
    return SUNLINEARSOLVER_DIRECT;
}

static SUNLinearSolver_ID get_id(SUNLinearSolver S)
{
    (void)S;
    return SUNLINEARSOLVER_CUSTOM;
}

static int initialize(SUNLinearSolver S)
{
    CONTENT(S)->last_flag = 0;
    return SUNLS_SUCCESS;
}

static int setup(SUNLinearSolver S, SUNMatrix A)
{
    block_content *c = CONTENT(S);
    double **m = SM_COLS_D(A);
    c->k = hg_block_split(m, c->n, c->idx);
    c->last_flag = hg_block_factor(m, c->idx, c->k, c->blk, c->piv);
    return c->last_flag > 0 ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
}

static int solve(SUNLinearSolver S, SUNMatrix A, N_Vector x, N_Vector b, realtype tol)
{
    block_content *c = CONTENT(S);
    (void)tol;
    N_VScale(1.0, b, x);
    hg_block_solve(SM_COLS_D(A), c->n, c->idx, c->k, c->blk, c->piv, N_VGetArrayPointer(x),
                   c->work);
    c->last_flag = SUNLS_SUCCESS;
    return SUNLS_SUCCESS;
}

static sunindextype last_flag(SUNLinearSolver S)
{
    return CONTENT(S)->last_flag;
}

static int free_solver(SUNLinearSolver S)
{
    block_content *c;
    if (!S) return SUNLS_SUCCESS;
    c = CONTENT(S);
    if (c) {
        if (c->blk) free(c->blk[0]);
        free(c->blk);
        free(c->idx);
        free(c->piv);
        free(c->work);
        free(c);
        S->content = NULL;
    }
    SUNLinSolFreeEmpty(S);
    return SUNLS_SUCCESS;
}

static int alloc_content(block_content *c, sunindextype n)
{
    sunindextype j;
    c->n = n;
    c->idx = malloc((size_t)n * sizeof *c->idx);
    c->piv = malloc((size_t)n * sizeof *c->piv);
    c->work = malloc((size_t)n * sizeof *c->work);
    c->blk = malloc((size_t)n * sizeof *c->blk);
    if (!c->idx || !c->piv || !c->work || !c->blk) return -1;
    if (!(c->blk[0] = malloc((size_t)n * (size_t)n * sizeof **c->blk))) return -1;
    for (j = 1; j < n; j++) c->blk[j] = c->blk[0] + j * n; /* rows of k used of each column */
    return 0;
}

SUNLinearSolver hg_block_dense_new(N_Vector y, SUNMatrix A, SUNContext ctx)
{
    sunindextype n = SM_COLUMNS_D(A);
    SUNLinearSolver S;
    block_content *c;
    if (SUNMatGetID(A) != SUNMATRIX_DENSE || SM_ROWS_D(A) != n || N_VGetLength(y) != n)
        return NULL;
    if (!(S = SUNLinSolNewEmpty(ctx))) return NULL;
    S->ops->gettype = get_type;
    S->ops->getid = get_id;
    S->ops->initialize = initialize;
    S->ops->setup = setup;
    S->ops->solve = solve;
    S->ops->lastflag = last_flag;
    S->ops->free = free_solver;
    if (!(c = S->content = calloc(1, sizeof *c)) || alloc_content(c, n)) {
        free_solver(S);
        return NULL;
    }
    return S;
}
