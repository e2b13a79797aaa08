/* file:// URIs (fmuResourceLocation) to local paths, RFC 3986 percent-decoding included. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"

static int hex_value(char ch)
{
    if (ch >= '0' && ch <= '9') return ch - '0';
    ch = (char)tolower((unsigned char)ch);
    return ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : -1;
}

/* Does s start with prefix, ignoring ASCII case (URI schemes and host names are
 * case-insensitive)? */
static int starts_with_nocase(const char *s, const char *prefix)
{
    for (; *prefix; s++, prefix++)
        if (tolower((unsigned char)*s) != tolower((unsigned char)*prefix)) return 0;
    return 1;
}

/* Skips "file:", then "//" + authority (empty or "localhost"), leaving the absolute path. */
static const char *path_part(const char *uri, char *why, size_t whylen)
{
    const char *p;
    if (!starts_with_nocase(uri, "file:")) {
        hg_errorf(why, whylen, "'%.200s' is not a file:// URI", uri);
        return NULL;
    }
    p = uri + 5;
    if (strncmp(p, "//", 2) == 0) {
        p += 2;
        if (starts_with_nocase(p, "localhost/"))
            p += 9;
        else if (*p != '/') {
            hg_errorf(why, whylen, *p ? "'%.200s' names a remote host; only local files are "
                      "supported" : "'%.200s' has no path", uri);
            return NULL;
        }
    }
    if (*p != '/') {
        hg_errorf(why, whylen, "'%.200s' has no absolute path", uri);
        return NULL;
    }
    return p;
}

/* Windows: "/C:/dir" (from file:///C:/dir) names "C:/dir"; the slash after the drive stays.
 * Elsewhere a path is left as it is. Returns the shortest length trailing slashes may leave. */
static size_t local_path(char *path)
{
#ifdef _WIN32
    if (path[0] == '/' && isalpha((unsigned char)path[1]) && path[2] == ':' &&
        (path[3] == '/' || path[3] == '\\')) {
        memmove(path, path + 1, strlen(path));
        return 3;
    }
#endif
    (void)path;
    return 1;
}

char *hg_uri_to_path(const char *uri, char *why, size_t whylen)
{
    const char *p;
    char *out, *o;
    size_t keep;
    if (!uri || !*uri) {
        hg_errorf(why, whylen, "the resource location is empty");
        return NULL;
    }
    if (!(p = path_part(uri, why, whylen))) return NULL;
    if (!(out = malloc(strlen(p) + 1))) {
        hg_errorf(why, whylen, "out of memory");
        return NULL;
    }
    for (o = out; *p; p++) {
        if (*p == '%') {
            int hi = hex_value(p[1]), lo = hi < 0 ? -1 : hex_value(p[2]);
            if (hi < 0 || lo < 0 || (hi == 0 && lo == 0)) {
                hg_errorf(why, whylen, "'%.200s' has a bad percent escape", uri);
                free(out);
                return NULL;
            }
            *o++ = (char)(hi * 16 + lo);
            p += 2;
        } else {
            *o++ = *p;
        }
    }
    *o = '\0';
    keep = local_path(out);
    for (o = out + strlen(out); (size_t)(o - out) > keep && o[-1] == '/';)
        *--o = '\0'; /* drop trailing slashes */
    return out;
}
