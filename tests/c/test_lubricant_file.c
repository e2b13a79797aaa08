/* Lubricant data files: the two built-in files parse to the paper's values; broken files give
 * clear errors (missing key, bad number, unknown key, wrong header, out of range, cross checks).
 * The repository root is taken from argv[1], else $HG_SOURCE_DIR, else derived from __FILE__. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "io/datafile.h"
#include "tribo/lubricant.h"
#include "tribo/rheology.h"

static char root[1024];

static void find_root(int argc, char **argv)
{
    const char *env = getenv("HG_SOURCE_DIR"), *f = __FILE__, *tail = "tests/c/";
    const char *pos;
    if (argc > 1) {
        snprintf(root, sizeof root, "%s", argv[1]);
    } else if (env && *env) {
        snprintf(root, sizeof root, "%s", env);
    } else if ((pos = strstr(f, tail)) != NULL) {
        snprintf(root, sizeof root, "%.*s", (int)(pos - f), f);
        if (root[0] == '\0') snprintf(root, sizeof root, ".");
    } else {
        snprintf(root, sizeof root, ".");
    }
}

static const char *good =
    "# a user lubricant\n"
    "hypoid-lubricant 1\n"
    "name  Test oil 75W-90   # trailing comment\n"
    "vogel_a 7.56e-5\n"
    "vogel_b 1109.3\n"
    "vogel_c 155.35\n"
    "alpha_star_T1 313.15\n"
    "alpha_star_1 16.09e-9\n"
    "alpha_star_T2 373.15\n"
    "alpha_star_2 11.59e-9\n"
    "alpha_star_T3 413.15\n"
    "alpha_star_3 9.38e-9\n"
    "hn_lambda 7.9e-8\n"
    "hn_alpha 0.7\n"
    "hn_beta 1\n"
    "k_f 0.18\n"
    "c_p 2090\n"
    "rho_15 870\n";

static const char *tmp_path(void) { return test_tmp_path("hg_test_lubricant.tmp"); }

/* writes text with line `key` replaced by `repl` (NULL: deleted; key NULL: text unchanged) and
 * loads it; returns the loader's result and leaves the message in err */
static int load_variant(const char *key, const char *repl, hg_lubricant *l, char *err)
{
    const char *p = good, *path = tmp_path();
    FILE *fp = fopen(path, "w");
    int rc;
    if (!fp) return -99;
    while (*p) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p + 1) : strlen(p);
        size_t klen = key ? strlen(key) : 0;
        if (key && strncmp(p, key, klen) == 0 && (p[klen] == ' ' || p[klen] == '\t')) {
            if (repl) fprintf(fp, "%s\n", repl);
        } else {
            fwrite(p, 1, len, fp);
        }
        p += len;
    }
    if (key && strcmp(key, "+") == 0) fprintf(fp, "%s\n", repl);
    fclose(fp);
    err[0] = '\0';
    rc = hg_lubricant_load(path, l, err, HG_ERRLEN);
    remove(path);
    return rc;
}

static int has(const char *err, const char *a, const char *b)
{
    int ok = strstr(err, a) != NULL && (!b || strstr(err, b) != NULL);
    if (!ok) fprintf(stderr, "unexpected message: %s\n", err);
    return ok;
}

int main(int argc, char **argv)
{
    char path[1200], err[HG_ERRLEN];
    hg_lubricant l, ref;
    const char *names[2] = {"OS265962", "OS265963"};
    int i;
    find_root(argc, argv);

    /* built-in files */
    for (i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "%s/resources/lubricants/%s.txt", root, names[i]);
        err[0] = '\0';
        CHECK(hg_lubricant_load(path, &l, err, sizeof err) == 0);
        if (err[0]) fprintf(stderr, "%s\n", err);
        CHECK(strcmp(l.name, names[i]) == 0);
        CHECK_CLOSE(l.vogel_a, 7.560e-5, 1e-3, 0);
        CHECK_CLOSE(l.vogel_b, 1109.3, 1e-4, 0);
        CHECK_CLOSE(l.vogel_c - 273.15, -117.8, 1e-3, 0);
        CHECK_CLOSE(l.alpha_T[0], 313.15, 1e-12, 0);
        CHECK_CLOSE(l.alpha_T[2], 413.15, 1e-12, 0);
        CHECK_CLOSE(l.alpha_star[0], i == 0 ? 16.09e-9 : 19.31e-9, 1e-12, 0);
        CHECK_CLOSE(l.alpha_star[1], i == 0 ? 11.59e-9 : 13.89e-9, 1e-12, 0);
        CHECK_CLOSE(l.alpha_star[2], i == 0 ? 9.38e-9 : 12.28e-9, 1e-12, 0);
        CHECK_CLOSE(l.hn_lambda, i == 0 ? 7.9e-8 : 8.0e-8, 1e-12, 0);
        CHECK_CLOSE(l.hn_alpha, i == 0 ? 0.70 : 0.97, 1e-12, 0);
        CHECK(l.hn_beta == 1.0 && l.k_f == 0.18 && l.c_p_f == 2090.0 && l.rho_15 == 870.0);
        /* docs/physics.md §4.1 table and §4.2 interpolation values, through the rheology that runs */
        {
            hg_rheology rh;
            hg_rheo_state s60, s100;
            hg_rheology_init(&rh, &l, 0, NULL);
            hg_rheology_at(&rh, 60 + 273.15, &s60);
            hg_rheology_at(&rh, 100 + 273.15, &s100);
            CHECK_CLOSE(exp(s60.ln_eta0), 38.8e-3, 0.002, 0);
            CHECK_CLOSE(exp(s100.ln_eta0), 12.3e-3, 0.003, 0);
            CHECK_CLOSE(s60.alpha, i == 0 ? 14.43e-9 : 17.10e-9, 0.001, 0);
        }
    }

    /* a user file */
    CHECK(load_variant(NULL, NULL, &ref, err) == 0);
    CHECK(strcmp(ref.name, "Test oil 75W-90") == 0);
    CHECK(ref.vogel_c == 155.35 && ref.alpha_star[1] == 11.59e-9);

    /* errors */
    CHECK(load_variant("k_f", NULL, &l, err) == -1 &&
          has(err, "missing key 'k_f'", "hg_test_lubricant.tmp"));
    CHECK(load_variant("vogel_b", "vogel_b 11O9.3", &l, err) == -1 &&
          has(err, "line 5", "not a finite number"));
    CHECK(load_variant("vogel_b", "vogel_b nan", &l, err) == -1 && has(err, "line 5", "vogel_b"));
    CHECK(load_variant("hn_beta", "hn_beta 1 2", &l, err) == -1 && has(err, "line 15", "hn_beta"));
    CHECK(load_variant("+", "viscosity_index 150", &l, err) == -1 &&
          has(err, "unknown key 'viscosity_index'", "line 19"));
    CHECK(load_variant("c_p", "c_pf 2090", &l, err) == -1 && has(err, "'c_p'", NULL));
    CHECK(load_variant("hypoid-lubricant", "hypoid-gearset 1", &l, err) == -1 &&
          has(err, "line 2", "expected the header 'hypoid-lubricant 1'"));
    CHECK(load_variant("hypoid-lubricant", "hypoid-lubricant 2", &l, err) == -1 &&
          has(err, "unsupported", "version"));
    CHECK(load_variant("k_f", "k_f 0", &l, err) == -1 && has(err, "line 16", "outside"));
    CHECK(load_variant("alpha_star_2", "alpha_star_2 11.59", &l, err) == -1 &&
          has(err, "line 10", "alpha_star_2"));
    CHECK(load_variant("alpha_star_T2", "alpha_star_T2 300", &l, err) == -1 &&
          has(err, "alpha_star_T2", "must exceed"));
    CHECK(load_variant("alpha_star_3", "alpha_star_3 15e-9", &l, err) == -1 &&
          has(err, "must not increase", NULL));
    CHECK(load_variant("vogel_c", "vogel_c 290", &l, err) == -1 && has(err, "vogel_c", "pole"));
    CHECK(load_variant("hn_beta", "hn_beta 2", &l, err) == -1 && has(err, "hn_alpha * hn_beta",
                                                                        NULL));
    CHECK(load_variant("name", "name", &l, err) == -1 && has(err, "name", NULL));
    CHECK(hg_lubricant_load("/nonexistent/oil.txt", &l, err, sizeof err) == -1 &&
          has(err, "/nonexistent/oil.txt", NULL));
    /* the struct is untouched on failure */
    l = ref;
    CHECK(load_variant("k_f", NULL, &l, err) == -1 && l.k_f == ref.k_f &&
          strcmp(l.name, ref.name) == 0);
    CHECK(load_variant("hn_alpha", "hn_alpha 0", &l, err) == -1 && has(err, "hn_alpha", "outside"));
    CHECK_DONE();
}
