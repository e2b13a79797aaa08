/* Read-only binary table files: a table the model computes from its parameters alone, written at
 * build time by the FMU's own code (tools/table_files.c) and shipped in the FMU's
 * resources/tables/, so that a process need not solve it again (docs/architecture.md, "Shared
 * tables").
 *
 * A file is a 64-byte header and the table's bytes as the writer held them:
 *   "HGTABLE" and a zero byte, the format version (uint32), the header's size (uint32, 64),
 *   0x0102030405060708 (uint64) and -1.5 (IEEE 754 binary64): the reader's byte order and double
 *   layout must give the same bytes (both platforms the FMU ships, x86_64 Linux and Windows, are
 *   little-endian IEEE 754),
 *   the table's 128-bit content key (two uint64), its size in bytes (uint64), and the checksum
 *   of its bytes (uint64: FNV-1a 64 over them as little-endian 64-bit words, the tail bytewise).
 * A reader never trusts a file: a missing, short, long, foreign or corrupted file, or one whose
 * key or size is not the one asked for, is refused and the caller computes the table. */
#ifndef HG_TABLEFILE_H
#define HG_TABLEFILE_H

#include <stddef.h>

#define HG_TABLEFILE_VERSION 1u
#define HG_TABLEFILE_NAME 64 /* room for "<32 hex digits>.tbl" and the zero */

/* The file name of the table whose key is (a, b): 32 lower-case hex digits and ".tbl". */
void hg_tablefile_name(unsigned long long a, unsigned long long b,
                       char name[HG_TABLEFILE_NAME]);

/* Writes the size bytes at data as the table keyed (a, b) to path; 0, or -1 (nothing usable is
 * left at path). */
int hg_tablefile_write(const char *path, unsigned long long a, unsigned long long b,
                       const void *data, size_t size);

/* Reads the table keyed (a, b) of exactly size bytes from path into data: 0 when every check
 * passes, else -1 with data zeroed (the file is missing or does not match). */
int hg_tablefile_read(const char *path, unsigned long long a, unsigned long long b, void *data,
                      size_t size);

#endif
