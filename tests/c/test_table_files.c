/* Shipped table files (io/tablefile.h, model/table_store.h hg_store_get_shipped): a table read
 * from its file is the table its build computes, bit for bit, and is used without a build; a
 * file that is missing, truncated, extended, corrupted anywhere, a directory, or written for
 * another key or size is ignored and the table computed instead, never crashing (a fuzz of random
 * truncations and byte flips). The table is a real one: the lubricant's Z_exact over T. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#ifdef _WIN32
#include <direct.h>
#define make_dir(p) _mkdir(p)
#define remove_dir(p) _rmdir(p)
#else
#include <unistd.h>
#define make_dir(p) mkdir(p, 0755)
#define remove_dir(p) rmdir(p)
#endif

#include "check.h"
#include "io/errmsg.h"
#include "io/tablefile.h"
#include "model/table_store.h"
#include "tribo/lubricant.h"
#include "tribo/rheology.h"

static int builds;

static int build_z(void *table, void *ctx)
{
    builds++;
    hg_z_table_build(table, ctx);
    return 0;
}

static hg_lubricant lub;
static hg_store_id id;
static hg_z_table ref; /* the table as built */
static char dir[700], tables[720], path[800];

/* A fresh process's store asks for the table with the files of dir: 1 when it was read (no
 * build), 0 when built; the content must be ref's either way. */
static int fresh_get(void)
{
    const hg_z_table *t;
    int built = -1, read;
    builds = 0;
    hg_store_attach();
    t = hg_store_get_shipped(dir, id, sizeof *t, build_z, &lub, &built);
    CHECK(t != NULL);
    if (t) CHECK(memcmp(t, &ref, sizeof ref) == 0);
    read = built == 0 && builds == 0;
    CHECK(read || (built == 1 && builds == 1));
    hg_store_put(t);
    hg_store_detach();
    return read;
}

static void write_bytes(const unsigned char *b, size_t n)
{
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    CHECK(fwrite(b, 1, n, f) == n);
    fclose(f);
}

static unsigned char *read_bytes(size_t *n)
{
    unsigned char *b = NULL;
    long len;
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    if (len > 0 && (b = malloc((size_t)len)) != NULL &&
        fread(b, 1, (size_t)len, f) != (size_t)len) {
        free(b);
        b = NULL;
    }
    fclose(f);
    *n = (size_t)len;
    return b;
}

static void test_missing_file_reads_nothing(void)
{
    double d[4] = {1, 2, 3, 4};
    snprintf(path, sizeof path, "%s/missing.tbl", tables);
    remove(path);
    CHECK(hg_tablefile_read(path, 1, 2, d, sizeof d) == -1);
    CHECK(d[0] == 0.0 && d[3] == 0.0); /* zeroed for the build */
}

/* The store's key takes the bytes as 64-bit words and the tail one by one: a flip of any bit,
 * in a word or in the tail, changes both lanes, and the key depends on the length. */
static void test_store_key_sees_every_bit(void)
{
    unsigned char b[37];
    hg_store_id base, id;
    size_t k;
    int bit;
    for (k = 0; k < sizeof b; k++) b[k] = (unsigned char)(k * 37 + 11);
    base = hg_store_hash(hg_store_id_of("test"), b, sizeof b);
    for (k = 0; k < sizeof b; k++)
        for (bit = 0; bit < 8; bit++) {
            b[k] ^= (unsigned char)(1u << bit);
            id = hg_store_hash(hg_store_id_of("test"), b, sizeof b);
            CHECK(id.a != base.a && id.b != base.b);
            b[k] ^= (unsigned char)(1u << bit);
        }
    id = hg_store_hash(hg_store_id_of("test"), b, sizeof b - 1);
    CHECK(id.a != base.a && id.b != base.b);
}

static unsigned long long rng = 0x9e3779b97f4a7c15ULL;
static size_t below(size_t n)
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (size_t)(rng >> 33) % n;
}

int main(void)
{
    char err[HG_ERRLEN], name[HG_TABLEFILE_NAME];
    const hg_z_table *t;
    unsigned char *good, *bad;
    size_t n = 0, k, cut[] = {0, 1, 63, 64, 65};
    size_t flip[] = {0, 7, 8, 12, 16, 31, 32, 40, 48, 56, 64, 64 + sizeof(hg_z_table) - 1};
    hg_store_id other;
    int built = -1, i;
    snprintf(dir, sizeof dir, "%s", test_tmp_path("hg_table_files"));
    snprintf(tables, sizeof tables, "%s/tables", dir);
    make_dir(dir);
    make_dir(tables);
    test_missing_file_reads_nothing();
    test_store_key_sees_every_bit();
    CHECK(hg_lubricant_load("resources/lubricants/OS265962.txt", &lub, err, sizeof err) == 0);
    id = hg_store_hash(hg_store_id_of("test: Z_exact over T"), &lub, sizeof lub);
    other = hg_store_hash(id, "other", 5);
    hg_tablefile_name(id.a, id.b, name);
    snprintf(path, sizeof path, "%s/%s", tables, name);
    remove(path);

    /* built without files, written as the build step writes them */
    hg_store_attach();
    t = hg_store_get_shipped(NULL, id, sizeof *t, build_z, &lub, &built);
    CHECK(t != NULL && built == 1);
    if (!t) return 1;
    memcpy(&ref, t, sizeof ref);
    CHECK(hg_store_write_shipped(tables) == 1);
    hg_store_put(t);
    hg_store_detach();
    CHECK(fresh_get() == 1); /* read: the same bits, no build */
    good = read_bytes(&n);
    CHECK(good != NULL && n == 64 + sizeof ref);
    if (!good || !(bad = malloc(n + 1))) return 1;

    for (k = 0; k < sizeof cut / sizeof cut[0]; k++) { /* truncated */
        write_bytes(good, cut[k]);
        CHECK(fresh_get() == 0);
    }
    write_bytes(good, n - 1);
    CHECK(fresh_get() == 0);
    memcpy(bad, good, n), bad[n] = 0; /* one byte too many */
    write_bytes(bad, n + 1);
    CHECK(fresh_get() == 0);
    for (k = 0; k < sizeof flip / sizeof flip[0]; k++) { /* magic, version, header size, byte
                                                           order, double layout, key, size,
                                                           checksum, content */
        memcpy(bad, good, n);
        bad[flip[k]] ^= 0x10;
        write_bytes(bad, n);
        CHECK(fresh_get() == 0);
    }
    /* well-formed files of another key, of another size */
    CHECK(hg_tablefile_write(path, other.a, other.b, &ref, sizeof ref) == 0);
    CHECK(fresh_get() == 0);
    CHECK(hg_tablefile_write(path, id.a, id.b, &ref, sizeof ref - 8) == 0);
    CHECK(fresh_get() == 0);
    remove(path); /* a directory in its place */
    make_dir(path);
    CHECK(fresh_get() == 0);
    remove_dir(path);

    for (i = 0; i < 300; i++) { /* fuzz: random truncations and byte flips */
        size_t len = n, m;
        memcpy(bad, good, n);
        if (i % 3 == 0) len = below(n);
        else
            for (m = 1 + below(4); m > 0; m--) bad[below(n)] ^= (unsigned char)(1 + below(255));
        write_bytes(bad, len);
        CHECK(fresh_get() == (len == n && memcmp(bad, good, n) == 0));
    }
    write_bytes(good, n);
    CHECK(fresh_get() == 1);
    remove(path);
    free(good);
    free(bad);
    CHECK_DONE();
}
