/* Plain-text key/value data files: see datafile.h. */
#define _POSIX_C_SOURCE 200809L /* open, fstat, fdopen, O_NONBLOCK, O_CLOEXEC */
#include "io/datafile.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#ifdef _WIN32
#include <io.h>
#include <windows.h>
#else
#include <unistd.h>
#endif

#define MAX_FILE_BYTES (4L * 1024L * 1024L)

typedef struct {
    char *key;
    char *rest; /* text after the key, trimmed */
    int line;
    int used;
} entry;

struct hg_datafile {
    char *path;
    entry *entries;
    size_t n, cap;
};


static char *dup_str(const char *s, size_t len)
{
    char *d = malloc(len + 1);
    if (d) {
        memcpy(d, s, len);
        d[len] = '\0';
    }
    return d;
}

#ifdef _WIN32
/* A file descriptor reading path, in binary mode. FMI paths are UTF-8 (they come from URIs):
 * opened through UTF-16, and in the ANSI code page only when path is not valid UTF-8. */
static int open_readonly(const char *path)
{
    int fd = -1, n = MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, path, -1, NULL, 0);
    wchar_t *wide = n > 0 ? malloc((size_t)n * sizeof *wide) : NULL;
    if (wide && MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, path, -1, wide, n) == n)
        fd = _wopen(wide, _O_RDONLY | _O_BINARY);
    else
        fd = _open(path, _O_RDONLY | _O_BINARY);
    free(wide);
    return fd;
}
#define close _close
#define fdopen _fdopen
#else
/* A file descriptor reading path; O_NONBLOCK: opening a FIFO does not wait for a writer. */
static int open_readonly(const char *path)
{
    return open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
}
#endif

FILE *hg_open_regular(const char *path, long *len, char *err, size_t errlen)
{
    struct stat st;
    FILE *fp;
    int fd = open_readonly(path);
    if (fd < 0) {
        hg_errorf(err, errlen, "cannot open data file '%s': %s", path, strerror(errno));
        return NULL;
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        hg_errorf(err, errlen, "cannot read data file '%s': not a regular file (a directory, device "
             "or pipe?)", path);
        close(fd);
        return NULL;
    }
    if (!(fp = fdopen(fd, "rb"))) {
        hg_errorf(err, errlen, "cannot open data file '%s': %s", path, strerror(errno));
        close(fd);
        return NULL;
    }
    *len = st.st_size > LONG_MAX ? LONG_MAX : (long)st.st_size;
    return fp;
}

static char *read_whole_file(const char *path, long *size, char *err, size_t errlen)
{
    char *buf = NULL;
    long len = 0;
    FILE *fp = hg_open_regular(path, &len, err, errlen);
    if (!fp) return NULL;
    if (len == 0) {
        hg_errorf(err, errlen, "data file '%s' is empty", path);
    } else if (len > MAX_FILE_BYTES) {
        hg_errorf(err, errlen, "data file '%s' is %ld bytes, more than the limit of %ld", path, len,
             MAX_FILE_BYTES);
    } else if ((buf = malloc((size_t)len + 1)) == NULL) {
        hg_errorf(err, errlen, "out of memory reading '%s'", path);
    } else if (fread(buf, 1, (size_t)len, fp) != (size_t)len) {
        hg_errorf(err, errlen, "short read on data file '%s'", path);
        free(buf);
        buf = NULL;
    } else {
        buf[len] = '\0';
        *size = len;
    }
    fclose(fp);
    return buf;
}

static char *trim(char *s)
{
    char *end;
    while (*s && isspace((unsigned char)*s)) s++;
    end = s + strlen(s);
    while (end > s && isspace((unsigned char)end[-1])) *--end = '\0';
    return s;
}

static int add_entry(hg_datafile *f, char *line, int line_no, char *err, size_t errlen)
{
    size_t klen = strcspn(line, " \t");
    entry *e;
    if (f->n == f->cap) {
        size_t cap = f->cap ? 2 * f->cap : 64;
        entry *grown = realloc(f->entries, cap * sizeof *grown);
        if (!grown) {
            hg_errorf(err, errlen, "out of memory reading '%s'", f->path);
            return -1;
        }
        f->entries = grown;
        f->cap = cap;
    }
    e = &f->entries[f->n++];
    e->key = dup_str(line, klen);
    e->rest = dup_str(trim(line + klen), strlen(trim(line + klen)));
    e->line = line_no;
    e->used = 0;
    if (!e->key || !e->rest) {
        hg_errorf(err, errlen, "out of memory reading '%s'", f->path);
        return -1;
    }
    return 0;
}

static int by_key_then_line(const void *a, const void *b)
{
    const entry *x = *(const entry *const *)a, *y = *(const entry *const *)b;
    int c = strcmp(x->key, y->key);
    return c ? c : (x->line > y->line) - (x->line < y->line);
}

/* Fails on the first line (in file order) whose key an earlier line already has. Sorting keeps
 * this O(n log n), so that a file of many keys cannot stall the FMU. */
static int check_unique_keys(const hg_datafile *f, char *err, size_t errlen)
{
    const entry **sorted, *first = NULL, *repeat = NULL, *repeated = NULL;
    size_t i;
    if (f->n < 2) return 0;
    if (!(sorted = malloc(f->n * sizeof *sorted))) {
        hg_errorf(err, errlen, "out of memory reading '%s'", f->path);
        return -1;
    }
    for (i = 0; i < f->n; i++) sorted[i] = &f->entries[i];
    qsort(sorted, f->n, sizeof *sorted, by_key_then_line);
    for (i = 0; i < f->n; i++) {
        if (!first || strcmp(first->key, sorted[i]->key) != 0)
            first = sorted[i];
        else if (sorted[i - 1] == first && (!repeat || sorted[i]->line < repeat->line)) {
            repeat = sorted[i];
            repeated = first;
        }
    }
    free(sorted);
    if (!repeat) return 0;
    hg_errorf(err, errlen, "%s, line %d: key '%s' repeats line %d", f->path, repeat->line, repeat->key,
         repeated->line);
    return -1;
}

static int parse_header(const hg_datafile *f, char *line, int line_no, const char *magic,
                        int version, char *err, size_t errlen)
{
    size_t mlen = strlen(magic);
    char *end;
    long v;
    if (strncmp(line, magic, mlen) != 0 || !isspace((unsigned char)line[mlen])) {
        hg_errorf(err, errlen, "%s, line %d: expected the header '%s %d', found '%.60s'", f->path,
             line_no, magic, version, line);
        return -1;
    }
    v = strtol(line + mlen, &end, 10);
    if (*trim(end) != '\0' || v != version) {
        hg_errorf(err, errlen, "%s, line %d: unsupported %s format version '%s' (this FMU reads %d)",
             f->path, line_no, magic, trim(line + mlen), version);
        return -1;
    }
    return 0;
}

static int parse_lines(hg_datafile *f, char *text, long size, const char *magic, int version,
                       char *err, size_t errlen)
{
    int line_no = 0, have_header = 0;
    char *p = text;
    if ((long)strlen(text) != size) {
        hg_errorf(err, errlen, "%s: contains a NUL byte (binary file?)", f->path);
        return -1;
    }
    while (*p) {
        char *nl = strchr(p, '\n'), *hash, *line;
        if (nl) *nl = '\0';
        line_no++;
        hash = strchr(p, '#');
        if (hash) *hash = '\0';
        line = trim(p);
        if (*line) {
            if (!have_header) {
                if (parse_header(f, line, line_no, magic, version, err, errlen)) return -1;
                have_header = 1;
            } else if (add_entry(f, line, line_no, err, errlen)) {
                return -1;
            }
        }
        if (!nl) break;
        p = nl + 1;
    }
    if (!have_header) {
        hg_errorf(err, errlen, "%s: no header line '%s %d' (only comments or blanks)", f->path, magic,
             version);
        return -1;
    }
    return check_unique_keys(f, err, errlen);
}

hg_datafile *hg_datafile_load(const char *path, const char *magic, int version, char *err,
                              size_t errlen)
{
    hg_datafile *f;
    char *text;
    long size = 0;
    if (!path || !*path) {
        hg_errorf(err, errlen, "data file path is empty");
        return NULL;
    }
    text = read_whole_file(path, &size, err, errlen);
    if (!text) return NULL;
    f = calloc(1, sizeof *f);
    if (!f || !(f->path = dup_str(path, strlen(path)))) {
        hg_errorf(err, errlen, "out of memory reading '%s'", path);
        free(f);
        free(text);
        return NULL;
    }
    if (parse_lines(f, text, size, magic, version, err, errlen)) {
        hg_datafile_free(f);
        f = NULL;
    }
    free(text);
    return f;
}

void hg_datafile_free(hg_datafile *f)
{
    size_t i;
    if (!f) return;
    for (i = 0; i < f->n; i++) {
        free(f->entries[i].key);
        free(f->entries[i].rest);
    }
    free(f->entries);
    free(f->path);
    free(f);
}

static entry *find(const hg_datafile *f, const char *key)
{
    size_t i;
    for (i = 0; i < f->n; i++)
        if (strcmp(f->entries[i].key, key) == 0) return &f->entries[i];
    return NULL;
}

static int count_tokens(const char *s)
{
    int n = 0;
    while (*s) {
        while (*s && isspace((unsigned char)*s)) s++;
        if (!*s) break;
        n++;
        while (*s && !isspace((unsigned char)*s)) s++;
    }
    return n;
}

int hg_datafile_count(const hg_datafile *f, const char *key)
{
    const entry *e = find(f, key);
    return e ? count_tokens(e->rest) : -1;
}

int hg_datafile_line(const hg_datafile *f, const char *key)
{
    const entry *e = find(f, key);
    return e ? e->line : -1;
}

int hg_datafile_numbers(const hg_datafile *f, const char *key, size_t n_min, size_t n_max,
                        double *vals, size_t *n, char *err, size_t errlen)
{
    entry *e = find(f, key);
    const char *s;
    size_t count = 0;
    if (!e) {
        hg_errorf(err, errlen, "%s: missing key '%s'", f->path, key);
        return -1;
    }
    e->used = 1;
    for (s = e->rest; *s;) {
        char *end;
        double v;
        while (*s && isspace((unsigned char)*s)) s++;
        if (!*s) break;
        if (count == n_max) {
            hg_errorf(err, errlen, "%s, line %d: key '%s' takes at most %zu value(s)", f->path, e->line,
                 key, n_max);
            return -1;
        }
        errno = 0;
        v = strtod(s, &end);
        if (end == s || (*end && !isspace((unsigned char)*end)) || !isfinite(v) ||
            errno == ERANGE) {
            size_t tlen = strcspn(s, " \t");
            hg_errorf(err, errlen, "%s, line %d: key '%s': '%.*s' is not a finite number", f->path,
                 e->line, key, (int)(tlen > 40 ? 40 : tlen), s);
            return -1;
        }
        vals[count++] = v;
        s = end;
    }
    if (count < n_min) {
        hg_errorf(err, errlen, "%s, line %d: key '%s' needs at least %zu value(s), found %zu", f->path,
             e->line, key, n_min, count);
        return -1;
    }
    if (n) *n = count;
    return 0;
}

int hg_datafile_number(const hg_datafile *f, const char *key, double lo, double hi,
                       const char *unit, double *val, char *err, size_t errlen)
{
    double v;
    const char *sep = *unit ? " " : "";
    if (hg_datafile_numbers(f, key, 1, 1, &v, NULL, err, errlen)) return -1;
    if (!(v >= lo && v <= hi)) {
        hg_errorf(err, errlen, "%s, line %d: key '%s' = %g%s%s is outside [%g, %g]%s%s", f->path,
             find(f, key)->line, key, v, sep, unit, lo, hi, sep, unit);
        return -1;
    }
    *val = v;
    return 0;
}

int hg_datafile_text(const hg_datafile *f, const char *key, char *buf, size_t buflen, char *err,
                     size_t errlen)
{
    entry *e = find(f, key);
    if (!e) {
        hg_errorf(err, errlen, "%s: missing key '%s'", f->path, key);
        return -1;
    }
    e->used = 1;
    if (buflen) snprintf(buf, buflen, "%s", e->rest);
    return 0;
}

int hg_datafile_check_all_used(const hg_datafile *f, char *err, size_t errlen)
{
    size_t i;
    for (i = 0; i < f->n; i++) {
        if (!f->entries[i].used) {
            hg_errorf(err, errlen, "%s, line %d: unknown key '%s'", f->path, f->entries[i].line,
                 f->entries[i].key);
            return -1;
        }
    }
    return 0;
}

int hg_datafile_hash(const char *path, char hex[HG_HASH_HEX], char *err, size_t errlen)
{
    unsigned long long h = 0xcbf29ce484222325ULL; /* FNV-1a 64: offset basis and prime */
    long size = 0, i;
    char *text = read_whole_file(path, &size, err, errlen);
    if (!text) return -1;
    for (i = 0; i < size; i++) {
        if (text[i] == '\r') continue;
        h = (h ^ (unsigned char)text[i]) * 0x100000001b3ULL;
    }
    free(text);
    snprintf(hex, HG_HASH_HEX, "%016llx", h);
    return 0;
}

int hg_path_is_absolute(const char *path)
{
#ifdef _WIN32
    if (isalpha((unsigned char)path[0]) && path[1] == ':' && (path[2] == '\\' || path[2] == '/'))
        return 1;
    if (path[0] == '\\') return 1;
#endif
    return path[0] == '/';
}
