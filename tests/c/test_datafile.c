/* The plain-text data-file parser: every malformed file gets an error naming file and line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "io/datafile.h"

static const char *write_tmp(const char *text, size_t len)
{
    char name[64];
    const char *path;
    FILE *f;
    snprintf(name, sizeof name, "hg_test_datafile_%d.txt", (int)len);
    path = test_tmp_path(name);
    f = fopen(path, "wb");
    fwrite(text, 1, len, f);
    fclose(f);
    return path;
}

/* Loading `text` fails with a message containing `want`. */
static void expect_load_error(const char *text, const char *want)
{
    char err[HG_ERRLEN] = "";
    hg_datafile *f = hg_datafile_load(write_tmp(text, strlen(text)), "hypoid-test", 1, err,
                                      sizeof err);
    CHECK(f == NULL);
    if (!strstr(err, want)) fprintf(stderr, "error '%s' lacks '%s'\n", err, want);
    CHECK(strstr(err, want) != NULL);
    hg_datafile_free(f);
}

static void errors_on_load(void)
{
    char err[HG_ERRLEN];
    CHECK(hg_datafile_load("/nonexistent/x.txt", "hypoid-test", 1, err, sizeof err) == NULL);
    CHECK(strstr(err, "/nonexistent/x.txt") != NULL);
    CHECK(hg_datafile_load("/tmp", "hypoid-test", 1, err, sizeof err) == NULL);
    expect_load_error("", "is empty");
    expect_load_error("# only a comment\n\n", "no header");
    expect_load_error("hypoid-other 1\n", "line 1: expected the header");
    expect_load_error("hypoid-test 2\n", "version");
    expect_load_error("hypoid-test 1\na 1\n# x\na 2\n", "line 4: key 'a' repeats line 2");
    {
        const char nul[] = "hypoid-test 1\na 1\0\n";
        char e2[HG_ERRLEN];
        CHECK(hg_datafile_load(write_tmp(nul, sizeof nul - 1), "hypoid-test", 1, e2,
                               sizeof e2) == NULL);
        CHECK(strstr(e2, "NUL") != NULL);
    }
    {
        size_t n = 5u * 1024u * 1024u;
        char *big = malloc(n);
        char e3[HG_ERRLEN];
        memset(big, '#', n);
        CHECK(hg_datafile_load(write_tmp(big, n), "hypoid-test", 1, e3, sizeof e3) == NULL);
        CHECK(strstr(e3, "limit") != NULL);
        free(big);
    }
}

static void values(void)
{
    const char *text = "# demo\nhypoid-test 1 # header\nname  Gear set 1, a title \n"
                       "k 1.5e8\nv 1 2 3\nbad 1 x 3\nnan nan\ninf 1e999\nrange 7\n";
    char err[HG_ERRLEN], buf[64];
    double v[4], x = -1;
    size_t n = 0;
    hg_datafile *f = hg_datafile_load(write_tmp(text, strlen(text)), "hypoid-test", 1, err,
                                      sizeof err);
    CHECK(f != NULL);
    if (!f) return;
    CHECK(hg_datafile_text(f, "name", buf, sizeof buf, err, sizeof err) == 0);
    CHECK(strcmp(buf, "Gear set 1, a title") == 0);
    CHECK(hg_datafile_number(f, "k", 0, 1e9, "N/m", &x, err, sizeof err) == 0 && x == 1.5e8);
    CHECK(hg_datafile_count(f, "v") == 3 && hg_datafile_count(f, "zz") == -1);
    CHECK(hg_datafile_numbers(f, "v", 0, 4, v, &n, err, sizeof err) == 0 && n == 3 && v[2] == 3);
    CHECK(hg_datafile_numbers(f, "v", 0, 2, v, &n, err, sizeof err) != 0);
    CHECK(strstr(err, "line 5") && strstr(err, "at most 2"));
    CHECK(hg_datafile_numbers(f, "v", 4, 4, v, &n, err, sizeof err) != 0);
    CHECK(strstr(err, "at least 4"));
    CHECK(hg_datafile_numbers(f, "bad", 0, 4, v, &n, err, sizeof err) != 0);
    CHECK(strstr(err, "line 6") && strstr(err, "'x' is not a finite number"));
    CHECK(hg_datafile_number(f, "nan", 0, 1, "", &x, err, sizeof err) != 0);
    CHECK(strstr(err, "line 7"));
    CHECK(hg_datafile_number(f, "inf", 0, 1, "", &x, err, sizeof err) != 0);
    CHECK(strstr(err, "line 8"));
    CHECK(hg_datafile_number(f, "range", 0, 5, "", &x, err, sizeof err) != 0);
    CHECK(strstr(err, "line 9") && strstr(err, "'range' = 7 is outside [0, 5]"));
    CHECK(hg_datafile_number(f, "range", 0, 5, "W/(m K)", &x, err, sizeof err) != 0);
    CHECK(strstr(err, "'range' = 7 W/(m K) is outside [0, 5] W/(m K)"));
    CHECK(hg_datafile_number(f, "missing", 0, 5, "", &x, err, sizeof err) != 0);
    CHECK(strstr(err, "missing key 'missing'"));
    CHECK(hg_datafile_check_all_used(f, err, sizeof err) == 0);
    hg_datafile_free(f);
    f = hg_datafile_load(write_tmp("hypoid-test 1\nunused 3\n", 23), "hypoid-test", 1, err,
                         sizeof err);
    CHECK(f && hg_datafile_check_all_used(f, err, sizeof err) != 0);
    CHECK(strstr(err, "line 2: unknown key 'unused'") != NULL);
    hg_datafile_free(f);
}

int main(void)
{
    errors_on_load();
    values();
    CHECK_DONE();
}
