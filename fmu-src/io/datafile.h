/* Plain-text data files (gear sets, lubricants, efficiency maps).
 *
 * Format (documented for users in docs/data-files.md):
 *   - '#' starts a comment that runs to the end of the line; blank lines are ignored.
 *   - The first non-comment line is the header "<magic> <version>", e.g. "hypoid-gearset 1".
 *   - Every other line is "<key> <value> [<value> ...]", whitespace separated. Keys are unique.
 *   - Values are numbers (strtod syntax, must be finite) unless read with hg_datafile_text().
 *
 * Every error message names the file, and the line where there is one. Nothing here knows what a
 * gear or a lubricant is.
 */
#ifndef HG_DATAFILE_H
#define HG_DATAFILE_H

#include <stddef.h>
#include <stdio.h>

#include "io/errmsg.h"

typedef struct hg_datafile hg_datafile;

/* Reads and tokenises `path`. Rejects missing, empty, oversized (> 4 MiB) or binary files, a wrong
 * header or version, duplicate keys. Returns NULL and fills err on failure. */
hg_datafile *hg_datafile_load(const char *path, const char *magic, int version, char *err,
                              size_t errlen);

void hg_datafile_free(hg_datafile *f);

/* Number of values on the line of `key`, or -1 when the key is absent. */
int hg_datafile_count(const hg_datafile *f, const char *key);

/* Line number of `key` in the file, or -1 when the key is absent (for messages about a value). */
int hg_datafile_line(const hg_datafile *f, const char *key);

/* Reads between n_min and n_max finite numbers of `key` into vals; *n receives the count (may be
 * NULL when n_min == n_max). Returns 0, or -1 with err naming file, line and key. */
int hg_datafile_numbers(const hg_datafile *f, const char *key, size_t n_min, size_t n_max,
                        double *vals, size_t *n, char *err, size_t errlen);

/* One finite number within [lo, hi]; `unit` ("" if none) is quoted with the value and the range
 * when it is outside. */
int hg_datafile_number(const hg_datafile *f, const char *key, double lo, double hi,
                       const char *unit, double *val, char *err, size_t errlen);

/* The rest of the line after `key`, whitespace-trimmed, copied into buf (truncated to buflen). */
int hg_datafile_text(const hg_datafile *f, const char *key, char *buf, size_t buflen, char *err,
                     size_t errlen);

/* Fails, naming the first one, when a key was never read: catches misspelt keys in user files. */
int hg_datafile_check_all_used(const hg_datafile *f, char *err, size_t errlen);

/* Content hash of a data file: FNV-1a 64 of its bytes with carriage returns left out (a CRLF
 * checkout hashes like an LF one), as 16 lower-case hex digits in hex[HG_HASH_HEX]. What
 * `hypoid effmap` records of the gear set and lubricant a map was made from. */
#define HG_HASH_HEX 17
int hg_datafile_hash(const char *path, char hex[HG_HASH_HEX], char *err, size_t errlen);

/* Opens path for reading ("rb") only when it is a regular file: a directory, device or FIFO is
 * refused at once (a plain fopen of a FIFO would wait for a writer forever). *len receives the
 * file size. NULL with err filled when it cannot. */
FILE *hg_open_regular(const char *path, long *len, char *err, size_t errlen);

/* Is path absolute on this platform? ("/..."; on Windows also "C:\\...", "C:/..." and "\\\\...") */
int hg_path_is_absolute(const char *path);

#endif
