/* Minimal assertion helpers for the C unit tests (one executable per test file, run by ctest).
 * A failed check prints file, line and the values, and makes main() return 1. */
#ifndef HG_CHECK_H
#define HG_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

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

/* The path of the test's scratch file `name`: in $HG_TEST_TMP (ctest gives each build tree its own
 * folder, so runs of several checkouts or platforms side by side never share a file), else in
 * $TMPDIR or /tmp. Each call returns its own buffer of a ring of four. */
static inline const char *test_tmp_path(const char *name)
{
    static char paths[4][600];
    static int next = 0;
    const char *dir = getenv("HG_TEST_TMP");
    char *p = paths[next++ % 4];
    if (!dir || !*dir) dir = getenv("TMPDIR");
    if (!dir || !*dir) dir = "/tmp";
    snprintf(p, sizeof paths[0], "%s/%s", dir, name);
    return p;
}

#endif
