/* Read-only binary table files: see tablefile.h. */
#include "io/tablefile.h"

#include "io/datafile.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const char MAGIC[8] = "HGTABLE";
#define ORDER_MARK 0x0102030405060708ULL
#define DOUBLE_MARK (-1.5) /* 0xbff8000000000000 */

/* The header as it lies in the file (no padding: every field at a multiple of its size). */
typedef struct {
    char magic[8];
    uint32_t version, header_size;
    uint64_t order_mark;
    double double_mark;
    uint64_t key_a, key_b, size, checksum;
} header;

typedef char header_is_64_bytes[sizeof(header) == 64 ? 1 : -1];

/* FNV-1a 64 over the bytes taken as little-endian 64-bit words (the tail byte by byte): each
 * step is a bijection of the state, so any one changed word changes the sum; eight times faster
 * than byte by byte, which matters for the phase tables' megabyte. */
static uint64_t checksum(const void *data, size_t n)
{
    const unsigned char *p = data;
    uint64_t h = 0xcbf29ce484222325ULL, w;
    size_t k;
    for (k = 0; k + 8 <= n; k += 8) {
        memcpy(&w, p + k, 8); /* the reader is little-endian (the header's order mark) */
        h = (h ^ w) * 0x100000001b3ULL;
    }
    for (; k < n; k++) h = (h ^ p[k]) * 0x100000001b3ULL;
    return h;
}

static void header_of(header *h, unsigned long long a, unsigned long long b, const void *data,
                      size_t size)
{
    memset(h, 0, sizeof *h);
    memcpy(h->magic, MAGIC, sizeof MAGIC);
    h->version = HG_TABLEFILE_VERSION;
    h->header_size = (uint32_t)sizeof *h;
    h->order_mark = ORDER_MARK;
    h->double_mark = DOUBLE_MARK;
    h->key_a = a, h->key_b = b, h->size = size;
    h->checksum = data ? checksum(data, size) : 0;
}

void hg_tablefile_name(unsigned long long a, unsigned long long b,
                       char name[HG_TABLEFILE_NAME])
{
    snprintf(name, HG_TABLEFILE_NAME, "%016llx%016llx.tbl", a, b);
}

int hg_tablefile_write(const char *path, unsigned long long a, unsigned long long b,
                       const void *data, size_t size)
{
    header h;
    FILE *fp = fopen(path, "wb");
    int ok;
    if (!fp) return -1;
    header_of(&h, a, b, data, size);
    ok = fwrite(&h, sizeof h, 1, fp) == 1 && fwrite(data, 1, size, fp) == size;
    ok &= fclose(fp) == 0;
    if (!ok) remove(path);
    return ok ? 0 : -1;
}

int hg_tablefile_read(const char *path, unsigned long long a, unsigned long long b, void *data,
                      size_t size)
{
    header want, got;
    char why[HG_ERRLEN];
    long len = 0;
    FILE *fp = hg_open_regular(path, &len, why, sizeof why);
    int ok;
    if (!fp) {
        memset(data, 0, size);
        return -1;
    }
    header_of(&want, a, b, NULL, size);
    ok = len >= 0 && (size_t)len == sizeof got + size && fread(&got, sizeof got, 1, fp) == 1;
    want.checksum = got.checksum; /* compared below, over the bytes read */
    ok = ok && memcmp(&want, &got, sizeof want) == 0 && fread(data, 1, size, fp) == size &&
         fgetc(fp) == EOF && checksum(data, size) == got.checksum;
    fclose(fp);
    if (!ok) memset(data, 0, size);
    return ok ? 0 : -1;
}
