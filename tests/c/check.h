/* Minimal assertion helpers for the C unit tests (one executable per test file, run by ctest).
 * A failed check prints file, line and the values, and makes main() return 1. */
#ifndef HG_CHECK_H
#define HG_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_failures = 0;

#define CHECK(cond)                                                                   \
    do {                                                                              \
        if (!(cond)) {                                                                \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);  \
            check_failures++;                                                         \
        }                                                                             \
    } while (0)

/* |got - want| <= rel * |want| (+ abs_tol) */
#define CHECK_CLOSE(got, want, rel, abs_tol)                                                     \
    do {                                                                                         \
        double g_ = (got), w_ = (want);                                                          \
        if (!(fabs(g_ - w_) <= (rel) * fabs(w_) + (abs_tol))) {                                  \
            fprintf(stderr, "%s:%d: CHECK_CLOSE failed: %s = %.10g, want %.10g (rel %g, abs %g)\n", \
                    __FILE__, __LINE__, #got, g_, w_, (double)(rel), (double)(abs_tol));         \
            check_failures++;                                                                    \
        }                                                                                        \
    } while (0)

#define CHECK_DONE()                                                            \
    do {                                                                        \
        if (check_failures) fprintf(stderr, "%d check(s) failed\n", check_failures); \
        return check_failures ? 1 : 0;                                          \
    } while (0)

#endif
