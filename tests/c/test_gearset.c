/* Gear-set files: the built-in set 1 against docs/physics.md §10.7, and clear errors for bad files. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "io/constants.h"
#include "io/datafile.h"
#include "mesh/gearset.h"

static void builtin_set1(void)
{
    hg_gearset g;
    char err[HG_ERRLEN] = "";
    int j, k;
    CHECK(hg_gearset_load("resources/gearsets/gearset1.txt", &g, err, sizeof err) == 0);
    if (err[0]) fprintf(stderr, "%s\n", err);
    CHECK(g.N_p == 13 && g.N_g == 36);
    CHECK(g.n_levels == 1 && g.n_flanks == 1); /* one series: both flanks, every torque */
    CHECK_CLOSE(g.s[0][0].y[HG_S_K_M].mean, 1.7111e8, 1e-3, 0.0);  /* docs/physics.md §10.7 */
    CHECK_CLOSE(g.s[0][0].y[HG_S_R_P].mean, 21.009e-3, 1e-4, 0.0);
    CHECK_CLOSE(g.s[0][0].y[HG_S_LS].mean, 1.0 / 3.0, 1e-9, 0.0);
    CHECK_CLOSE(g.e_0.s[0], 1.5e-6, 1e-9, 0.0);
    /* the contact point moves along the line of contact at 0.630 m/s at 2000 rpm, nothing across
     * it (docs/physics.md §10.4) */
    CHECK_CLOSE(hypot(g.s[0][0].y[HG_S_VC_X].mean, g.s[0][0].y[HG_S_VC_Y].mean) * 2000.0 *
                    HG_TWO_PI / 60.0,
                0.630, 0.0, 0.002);
    CHECK(fabs(g.s[0][0].y[HG_S_VC_X].mean) < 1e-15);
    for (j = 0; j < 997; j++) { /* off any fitting grid */
        double theta = 3.0 * HG_TWO_PI * j / 997.0, sum = 0.0, in_contact = 0;
        hg_pair_geometry p;
        hg_mesh_point m;
        hg_mesh_point c;
        hg_gearset_pairs(&g, HG_FLANK_DRIVE, 0.0, theta, 1, &p);
        hg_gearset_mesh(&g, HG_FLANK_DRIVE, 100.0, theta, &m);
        hg_gearset_mesh(&g, HG_FLANK_COAST, 400.0, theta, &c);
        CHECK(c.k_m == m.k_m && c.R_p == m.R_p && m.dk_dT == 0.0);
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            CHECK(p.ls[k] >= 0.0 && p.ls[k] <= 1.0);
            sum += p.ls[k];
            in_contact += p.ls[k] > 0.0;
        }
        CHECK_CLOSE(sum, 1.0, 1e-12, 0.0);
        CHECK(in_contact >= 2 && in_contact <= 3); /* eps_TCA = 2.52: two or three pairs */
        CHECK(fabs(m.k_m / 1.7111e8 - 1.0) < 0.06);  /* about +-4.6 % ripple */
    }
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

/* A minimal valid file with one line replaced by `line` (or appended when key not found). */
static void expect_error(const char *replace_key, const char *line, const char *want)
{
    static const char *const base[] = {
        "hypoid-gearset 1\n", "name test\n", "N_p 13\n", "N_g 36\n", "k_m.mean 1.7e8\n",
        "k_m.sin 1e6\n", "k_m.cos 0\n", "R_p.mean 0.021\n", "R_p.sin\n", "R_p.cos\n",
        "e_0.mean 0\n", "e_0.sin 1e-6\n", "e_0.cos 0\n", "ls.mean 0.3333333333333333\n",
        "ls.sin 0.4\n", "ls.cos 0\n", "R_x.mean 0.018\n", "R_x.sin\n", "R_x.cos\n",
        "R_y.mean 2.25\n", "R_y.sin\n", "R_y.cos\n", "up_x.mean 0.012\n", "up_x.sin\n",
        "up_x.cos\n", "up_y.mean 0.02\n", "up_y.sin\n", "up_y.cos\n", "ug_x.mean 0.03\n",
        "ug_x.sin\n", "ug_x.cos\n", "ug_y.mean 0.03\n", "ug_y.sin\n", "ug_y.cos\n"};
    char text[4096] = "", err[HG_ERRLEN] = "";
    const char *path = test_tmp_path("hg_test_gearset.txt");
    size_t i;
    hg_gearset g;
    for (i = 0; i < sizeof base / sizeof base[0]; i++) {
        if (replace_key && strncmp(base[i], replace_key, strlen(replace_key)) == 0 &&
            base[i][strlen(replace_key)] == ' ')
            strcat(text, line);
        else
            strcat(text, base[i]);
    }
    if (!replace_key) strcat(text, line);
    write_file(path, text);
    CHECK(hg_gearset_load(path, &g, err, sizeof err) != 0);
    if (!strstr(err, want)) fprintf(stderr, "error '%s' lacks '%s'\n", err, want);
    CHECK(strstr(err, want) != NULL);
}

/* A file of two torque levels and both flanks: series 'name' of one flank/level as text. */
static void add_block(char *text, const char *prefix, double k_m, double R_p, double ls_sin)
{
    static const char *const contact[] = {"R_x 0.018", "R_y 2.25", "up_x 0.012", "up_y 0.02",
                                          "ug_x 0.03", "ug_y 0.03"};
    char line[256];
    size_t i;
    snprintf(line, sizeof line, "%sk_m.mean %g\n%sk_m.sin 1e6\n%sk_m.cos 0\n", prefix, k_m, prefix,
             prefix);
    strcat(text, line);
    snprintf(line, sizeof line, "%sR_p.mean %g\n%sR_p.sin\n%sR_p.cos\n", prefix, R_p, prefix, prefix);
    strcat(text, line);
    snprintf(line, sizeof line, "%sls.mean 0.3333333333333333\n%sls.sin %g\n%sls.cos 0\n", prefix,
             prefix, ls_sin, prefix);
    strcat(text, line);
    for (i = 0; i < sizeof contact / sizeof contact[0]; i++) {
        char key[16];
        double v;
        sscanf(contact[i], "%15s %lf", key, &v);
        snprintf(line, sizeof line, "%s%s.mean %g\n%s%s.sin\n%s%s.cos\n", prefix, key, v, prefix,
                 key, prefix, key);
        strcat(text, line);
    }
}

static int load_layered(const char *levels, const char *flanks, int coast_blocks, hg_gearset *g,
                        char *err, size_t errlen)
{
    static char text[16384];
    const char *path = test_tmp_path("hg_test_gearset_layered.txt");
    snprintf(text, sizeof text, "hypoid-gearset 1\nname layered\nN_p 13\nN_g 36\n%s%s"
             "e_0.mean 0\ne_0.sin 1e-6\ne_0.cos 0\n", levels, flanks);
    add_block(text, "drive.1.", 1.0e8, 0.021, 0.4);
    add_block(text, "drive.2.", 3.0e8, 0.022, 0.3);
    if (coast_blocks) {
        add_block(text, "coast.1.", 2.0e8, 0.020, 0.4);
        add_block(text, "coast.2.", 4.0e8, 0.020, 0.3);
    }
    write_file(path, text);
    return hg_gearset_load(path, g, err, errlen);
}

/* Two levels at 50 and 250 N m: k_m linear in T between them, held outside; its slope dk_dT;
 * the coast flank's own series; bad layered files named by line and value. */
static void layered(void)
{
    static hg_gearset g;
    char err[HG_ERRLEN] = "";
    hg_mesh_point m;
    hg_pair_geometry p;
    double k0, R0;
    CHECK(load_layered("torque_levels 50 250\n", "flanks drive coast\n", 1, &g, err,
                       sizeof err) == 0);
    if (err[0]) fprintf(stderr, "%s\n", err);
    CHECK(g.n_levels == 2 && g.n_flanks == 2);
    /* at theta = 0 the k_m series is its mean (sin term 0) */
    hg_gearset_mesh(&g, HG_FLANK_DRIVE, 100.0, 0.0, &m);
    CHECK_CLOSE(m.k_m, 1.0e8 + 0.25 * 2.0e8, 1e-12, 0.0);
    CHECK_CLOSE(m.dk_dT, 2.0e8 / 200.0, 1e-12, 0.0);
    CHECK_CLOSE(m.R_p, 0.021 + 0.25 * 0.001, 1e-12, 0.0);
    CHECK_CLOSE(m.dk_m, 1e6, 1e-12, 0.0);
    hg_gearset_mesh(&g, HG_FLANK_DRIVE, 10.0, 0.0, &m);
    CHECK(m.k_m == 1.0e8 && m.dk_dT == 0.0);
    hg_gearset_mesh(&g, HG_FLANK_DRIVE, 900.0, 0.0, &m);
    CHECK(m.k_m == 3.0e8 && m.dk_dT == 0.0);
    hg_gearset_mesh(&g, HG_FLANK_COAST, 150.0, 0.0, &m);
    CHECK_CLOSE(m.k_m, 3.0e8, 1e-12, 0.0);
    CHECK_CLOSE(m.R_p, 0.020, 1e-12, 0.0);
    hg_gearset_means(&g, HG_FLANK_COAST, 150.0, &k0, &R0);
    CHECK_CLOSE(k0, 3.0e8, 1e-12, 0.0);
    hg_gearset_pairs(&g, HG_FLANK_DRIVE, 150.0, 0.0, 1, &p);
    CHECK_CLOSE(p.ls[0] + p.ls[1] + p.ls[2], 1.0, 1e-12, 0.0);
    /* k_m_scale scales every level of both flanks */
    hg_gearset_scale(&g, 2.0, 1.0);
    hg_gearset_mesh(&g, HG_FLANK_COAST, 250.0, 0.0, &m);
    CHECK_CLOSE(m.k_m, 8.0e8, 1e-12, 0.0);
    /* one flank declared: the drive series serve the coast flank too */
    CHECK(load_layered("torque_levels 50 250\n", "flanks drive\n", 0, &g, err, sizeof err) == 0);
    hg_gearset_mesh(&g, HG_FLANK_COAST, 250.0, 0.0, &m);
    CHECK(m.k_m == 3.0e8);
    /* bad files */
    CHECK(load_layered("torque_levels 250 50\n", "flanks drive coast\n", 1, &g, err,
                       sizeof err) != 0);
    CHECK(strstr(err, "line 5: torque_levels value 2 = 50 N m") != NULL);
    CHECK(load_layered("torque_levels 50 250\n", "flanks drive coast\n", 0, &g, err,
                       sizeof err) != 0);
    CHECK(strstr(err, "line 6: flanks 'drive coast' asks for a coast flank") != NULL);
    CHECK(load_layered("torque_levels 50 250\n", "flanks both\n", 1, &g, err, sizeof err) != 0);
    CHECK(strstr(err, "line 6: flanks 'both'") != NULL);
    CHECK(load_layered("torque_levels 50 250 400\n", "flanks drive coast\n", 1, &g, err,
                       sizeof err) != 0);
    CHECK(strstr(err, "missing key 'drive.3.k_m.mean'") != NULL);
    CHECK(strstr(err, "hg_test_gearset_layered.txt") != NULL);
}

int main(void)
{
    char err[HG_ERRLEN];
    hg_gearset g;
    builtin_set1();
    layered();
    /* the minimal file itself is valid */
    expect_error(NULL, "extra_key 1\n", "unknown key 'extra_key'");
    expect_error("N_p", "N_p 13.5\n", "not a whole number");
    expect_error("N_g", "N_g 0\n", "outside [3, 200]");
    expect_error("k_m.cos", "k_m.cos 0 0\n", "1 sine but 2 cosine");
    expect_error("k_m.mean", "k_m.mean -1e8\n", "k_m evaluates to");
    expect_error("R_p.mean", "R_p.mean nan\n", "not a finite number");
    expect_error("ls.mean", "ls.mean 0.5\n", "load shares of the three pairs sum to");
    expect_error("R_x.mean", "R_x.mean -0.01\n", "R_x evaluates to");
    expect_error("ug_y.mean", "# gone\n", "missing key 'ug_y.mean'");
    /* the contact point velocity is optional, but only as a pair (absent: a fixed contact) */
    expect_error(NULL, "vc_x.mean 0.003\nvc_x.sin\nvc_x.cos\n", "missing key 'vc_y.mean'");
    CHECK(hg_gearset_load("/tmp/does-not-exist.txt", &g, err, sizeof err) != 0);
    CHECK(strstr(err, "cannot open") != NULL);
    CHECK_DONE();
}
