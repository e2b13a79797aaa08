/* The Newton matrix M = I - gamma J of a system in which nothing depends on some states (the
 * energy audit's integrals, the efficiency integrals): their columns of M are unit vectors, so
 * that, with the others ("coupled") first, M = [A 0; C I], and M x = b is A x_c = b_c and
 * x_p = b_p - C x_c. A dense LU of the coupled block alone solves it: for the rigid mesh 11 of
 * 23 states, a quarter of the work of the full matrix's forward and back substitution.
 *
 * The kernels work on a column-major n x n matrix given as its columns (SUNDIALS' dense layout);
 * hg_block_dense_new wraps them as a SUNDIALS direct linear solver for CVODE. Which states are
 * passive is found in M itself at every set-up (a column exactly e_j), so nothing is assumed of
 * the model; a column that is not exactly a unit vector counts as coupled. */
#ifndef HG_BLOCK_DENSE_H
#define HG_BLOCK_DENSE_H

#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_types.h>
#include <sundials/sundials_nvector.h>
#include <sundials/sundials_matrix.h>

/* idx[0 .. k-1] the coupled columns of the n x n matrix m (ascending), idx[k .. n-1] the passive
 * ones (their column the unit vector); returns k. */
sunindextype hg_block_split(double *const *m, sunindextype n, sunindextype *idx);

/* LU of the coupled block of m (rows and columns idx[0 .. k-1]) into blk (k columns of k, the
 * caller's) with pivots piv; 0, or the 1-based column of a zero pivot. */
sunindextype hg_block_factor(double *const *m, const sunindextype *idx, sunindextype k,
                             double **blk, sunindextype *piv);

/* Solves m x = b in place in b (n entries) from hg_block_factor's blk and piv; work holds k. */
void hg_block_solve(double *const *m, sunindextype n, const sunindextype *idx, sunindextype k,
                    double **blk, const sunindextype *piv, double *b, double *work);

/* The linear solver over a dense matrix A (SUNDenseMatrix) of y's length; NULL when out of
 * memory. */
SUNLinearSolver hg_block_dense_new(N_Vector y, SUNMatrix A, SUNContext ctx);

#endif
