/* Efficiency maps: the interpolant reproduces the table at its nodes and any linear data
 * exactly, is C1 (and C2) across grid lines, holds beyond the edges; bad files get clear errors. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "io/datafile.h"
#include "model/effmap.h"

#define PATH test_tmp_path("hg_test_effmap.txt")

static const double W[] = {10, 50, 100, 300}, T[] = {10, 50, 100}, K[] = {300, 350};

static double linear(double w, double t, double k) { return 0.9 + 1e-4 * w + 2e-4 * t + 1e-4 * (k - 300); }
static double wiggly(int d, int a, int b, int c) { return 0.95 + 0.01 * sin(1.0 + a + 2 * b + 3 * c + 5 * d); }

static const char *gear_hash = "fedcba9876543210"; /* the recorded hash of the gear-set file */

/* Writes a 4 x 3 x 2 map of f; `speeds` replaces the speeds line when not NULL. */
static void write_map(double (*f)(int, int, int, int), const char *speeds)
{
    FILE *fp = fopen(PATH, "w");
    int d, a, b, c;
    fprintf(fp, "hypoid-effmap 2\nname test\ngear_set_hash %s\ngear_set_source gearsets/x.txt\n"
            "lubricant_hash 0123456789abcdef\nlubricant_source lubricants/y.txt\n"
            "model_version 0.1.0\n%s\ntorques 10 50 100\ntemperatures 300 350\n", gear_hash,
            speeds ? speeds : "speeds 10 50 100 300");
    for (d = 0; d < 2; d++)
        for (c = 0; c < 2; c++) {
            fprintf(fp, "%s.%d", d ? "coast" : "drive", c + 1);
            for (a = 0; a < 4; a++)
                for (b = 0; b < 3; b++) fprintf(fp, " %.17g", f(d, a, b, c));
            fprintf(fp, "\n");
        }
    fclose(fp);
}

static double lin_node(int d, int a, int b, int c) { (void)d; return linear(W[a], T[b], K[c]); }

static void interpolation(void)
{
    hg_effmap m;
    char err[HG_ERRLEN] = "";
    int a, b, c;
    double w, t, k, h = 1e-6;
    write_map(wiggly, NULL);
    CHECK(hg_effmap_load(PATH, &m, err, sizeof err) == 0);
    for (a = 0; a < 4; a++) /* nodes */
        for (b = 0; b < 3; b++)
            for (c = 0; c < 2; c++)
                CHECK_CLOSE(hg_effmap_eta(&m, HG_MAP_COAST, W[a], T[b], K[c]), wiggly(1, a, b, c), 1e-14, 0);
    /* C1 across the grid line w = 50 and t = 50 */
    for (t = 12; t < 100; t += 7.3) {
        double left = (hg_effmap_eta(&m, 0, 50 - h, t, 320) - hg_effmap_eta(&m, 0, 50 - 2 * h, t, 320)) / h;
        double right = (hg_effmap_eta(&m, 0, 50 + 2 * h, t, 320) - hg_effmap_eta(&m, 0, 50 + h, t, 320)) / h;
        CHECK_CLOSE(left, right, 1e-3, 1e-7);
    }
    /* held beyond the edges */
    CHECK(hg_effmap_eta(&m, 0, 1000, 5, 250) == wiggly(0, 3, 0, 0));
    CHECK(hg_effmap_eta(&m, 0, -300, -100, 400) == wiggly(0, 3, 2, 1)); /* |w|, |T| */
    hg_effmap_free(&m);
    write_map(lin_node, NULL);
    CHECK(hg_effmap_load(PATH, &m, err, sizeof err) == 0);
    for (w = 10; w <= 300; w += 13.7) /* linear data: reproduced exactly everywhere inside */
        for (t = 10; t <= 100; t += 9.1)
            for (k = 300; k <= 350; k += 12.5)
                CHECK_CLOSE(hg_effmap_eta(&m, 0, w, t, k), linear(w, t, k), 1e-13, 0);
    hg_effmap_free(&m);
}

/* A textbook natural cubic spline through (x, y) at `at` (second derivatives from the
 * tridiagonal system, Thomas algorithm), held beyond the ends: the independent reference. */
static double natural_spline(const double *x, const double *y, int n, double at)
{
    double m[8] = {0}, c[8] = {0}, d[8] = {0}, h, a, b;
    int i;
    if (at <= x[0]) return y[0];
    if (at >= x[n - 1]) return y[n - 1];
    for (i = 1; i < n - 1; i++) {
        double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
        double rhs = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
        double diag = 2.0 * (h0 + h1) - h0 * c[i - 1];
        c[i] = h1 / diag;
        d[i] = (rhs - h0 * d[i - 1]) / diag;
    }
    for (i = n - 2; i >= 1; i--) m[i] = d[i] - c[i] * m[i + 1];
    for (i = 0; at >= x[i + 1]; i++) {}
    h = x[i + 1] - x[i];
    a = (x[i + 1] - at) / h;
    b = 1.0 - a;
    return a * y[i] + b * y[i + 1] + h * h / 6.0 * ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]);
}

static double gw(int a) { return 0.97 + 0.01 * sin(2.0 * a); }
static double gt(int b) { return 0.99 + 0.005 * cos(1.3 * b + 0.4); }
static double gk(int c) { return 1.0 - 0.003 * c; }
static double product(int d, int a, int b, int c) { return (d ? 0.999 : 1.0) * gw(a) * gt(b) * gk(c); }

/* Data that are a product of one function per axis: the tensor-product spline is the product of
 * the three one-axis splines, at any point inside and beyond the grid. */
static void tensor_product(void)
{
    hg_effmap m;
    char err[HG_ERRLEN] = "";
    double yw[4], yt[3], yk[2], w, t, k;
    int i;
    for (i = 0; i < 4; i++) yw[i] = gw(i);
    for (i = 0; i < 3; i++) yt[i] = gt(i);
    for (i = 0; i < 2; i++) yk[i] = gk(i);
    write_map(product, NULL);
    CHECK(hg_effmap_load(PATH, &m, err, sizeof err) == 0);
    for (w = 3; w <= 330; w += 17.3)
        for (t = 4; t <= 110; t += 8.9)
            for (k = 290; k <= 360; k += 11.0) {
                double want = natural_spline(W, yw, 4, w) * natural_spline(T, yt, 3, t) *
                              natural_spline(K, yk, 2, k);
                CHECK_CLOSE(hg_effmap_eta(&m, HG_MAP_DRIVE, w, t, k), want, 1e-14, 0);
                CHECK_CLOSE(hg_effmap_eta(&m, HG_MAP_COAST, w, t, k), 0.999 * want, 1e-14, 0);
            }
    hg_effmap_free(&m);
}

static void expect_error(const char *speeds, double (*f)(int, int, int, int), const char *want)
{
    hg_effmap m;
    char err[HG_ERRLEN] = "";
    write_map(f, speeds);
    CHECK(hg_effmap_load(PATH, &m, err, sizeof err) != 0);
    if (!strstr(err, want)) fprintf(stderr, "error '%s' lacks '%s'\n", err, want);
    CHECK(strstr(err, want) != NULL && strstr(err, PATH) != NULL);
}

static double too_high(int d, int a, int b, int c) { return d == 1 && a == 2 && b == 1 && c == 0 ? 1.2 : 0.98; }

/* What the map records of its sources is read back as written. */
static void provenance(void)
{
    hg_effmap m;
    char err[HG_ERRLEN] = "";
    write_map(wiggly, NULL);
    CHECK(hg_effmap_load(PATH, &m, err, sizeof err) == 0);
    CHECK(strcmp(m.gear_set.hash, "fedcba9876543210") == 0);
    CHECK(strcmp(m.gear_set.source, "gearsets/x.txt") == 0);
    CHECK(strcmp(m.lubricant.hash, "0123456789abcdef") == 0);
    CHECK(strcmp(m.model_version, "0.1.0") == 0);
    hg_effmap_free(&m);
    gear_hash = "not-a-hash";
    expect_error(NULL, wiggly, "16 hex digits");
    gear_hash = "fedcba9876543210";
}

/* hg_datafile_hash is FNV-1a 64 (the published test vectors of Fowler, Noll and Vo) of the bytes
 * without carriage returns. */
static void content_hash(void)
{
    static const char *const text[] = {"a", "foobar", "a\r\nb\n", "a\nb\n"};
    static const char *const want[] = {"af63dc4c8601ec8c", "85944171f73967e8", NULL, NULL};
    char hex[4][HG_HASH_HEX], err[HG_ERRLEN] = "";
    int i;
    for (i = 0; i < 4; i++) {
        FILE *fp = fopen(PATH, "wb");
        fputs(text[i], fp);
        fclose(fp);
        CHECK(hg_datafile_hash(PATH, hex[i], err, sizeof err) == 0);
        if (want[i]) CHECK(strcmp(hex[i], want[i]) == 0);
    }
    CHECK(strcmp(hex[2], hex[3]) == 0);
    CHECK(hg_datafile_hash("/nonexistent/x.txt", hex[0], err, sizeof err) != 0);
    CHECK(strstr(err, "/nonexistent/x.txt") != NULL);
}

int main(void)
{
    interpolation();
    tensor_product();
    provenance();
    content_hash();
    expect_error("speeds 10 100 50 300", wiggly, "ascending");
    expect_error("speeds 10 50 100", wiggly, "at most 9");
    expect_error(NULL, too_high, "efficiency 1.2");
    CHECK_DONE();
}
