/* The data-file parser on inputs that once stalled the FMU: a FIFO or a directory named as a data
 * file (an fopen of a FIFO waits for a writer forever), and a file of many keys (the duplicate
 * check was quadratic: 400 000 keys took minutes). Each must fail or load within seconds of CPU time
 * (the process's, so that a loaded machine or a sanitizer's slowdown does not count). */
#define _XOPEN_SOURCE 700
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "check.h"
#include "io/datafile.h"

static double cpu_seconds_since(const struct timespec *t0)
{
    struct timespec t1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t1);
    return (double)(t1.tv_sec - t0->tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0->tv_nsec);
}

static void not_regular_files(void)
{
    char dir[] = "/tmp/hg_test_limits_XXXXXX", fifo[64], err[HG_ERRLEN] = "";
    CHECK(mkdtemp(dir) != NULL);
    snprintf(fifo, sizeof fifo, "%s/fifo", dir);
    CHECK(mkfifo(fifo, 0600) == 0);
    CHECK(hg_datafile_load(fifo, "hypoid-test", 1, err, sizeof err) == NULL);
    CHECK(strstr(err, "not a regular file") && strstr(err, fifo));
    CHECK(hg_datafile_load(dir, "hypoid-test", 1, err, sizeof err) == NULL);
    CHECK(strstr(err, "not a regular file") && strstr(err, dir));
    CHECK(hg_datafile_load("/dev/zero", "hypoid-test", 1, err, sizeof err) == NULL);
    CHECK(strstr(err, "not a regular file") != NULL);
    unlink(fifo);
    rmdir(dir);
}

/* A file of n keys "k0 0" ... and, when repeat >= 0, key k<repeat> again at the end. */
static const char *many_keys(int n, int repeat)
{
    const char *path = test_tmp_path("hg_test_limits_keys.txt");
    FILE *f;
    int k;
    f = fopen(path, "w");
    fprintf(f, "hypoid-test 1\n");
    for (k = 0; k < n; k++) fprintf(f, "k%d %d\n", k, k);
    if (repeat >= 0) fprintf(f, "k%d 0\n", repeat);
    fclose(f);
    return path;
}

static void many_keys_are_fast(void)
{
    char err[HG_ERRLEN] = "";
    struct timespec t0;
    hg_datafile *f;
    double x = 0;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0);
    f = hg_datafile_load(many_keys(200000, -1), "hypoid-test", 1, err, sizeof err);
    CHECK(f != NULL);
    CHECK(f && hg_datafile_number(f, "k199999", 0, 1e9, "", &x, err, sizeof err) == 0 && x == 199999);
    hg_datafile_free(f);
    CHECK(cpu_seconds_since(&t0) < 3.0); /* was minutes; generous for sanitizers */
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0);
    CHECK(hg_datafile_load(many_keys(200000, 7), "hypoid-test", 1, err, sizeof err) == NULL);
    CHECK(strstr(err, "line 200002: key 'k7' repeats line 9") != NULL);
    CHECK(cpu_seconds_since(&t0) < 3.0); /* was minutes; generous for sanitizers */
    unlink(many_keys(0, -1));
}

static void first_repeat_in_file_order(void)
{
    const char *text = "hypoid-test 1\nb 1\na 1\nc 1\nc 2\na 2\n";
    const char *path = test_tmp_path("hg_test_limits_order.txt");
    char err[HG_ERRLEN] = "";
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    CHECK(hg_datafile_load(path, "hypoid-test", 1, err, sizeof err) == NULL);
    CHECK(strstr(err, "line 5: key 'c' repeats line 4") != NULL);
    unlink(path);
}

int main(void)
{
    not_regular_files();
    many_keys_are_fast();
    first_repeat_in_file_order();
    CHECK_DONE();
}
