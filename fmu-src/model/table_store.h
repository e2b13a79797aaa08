/* The process's store of read-only tables: what set-up and the friction tables compute from the
 * parameters alone (the lubricant's Z_exact over temperature, the gear set's phase tables, the
 * friction model's node tables) is computed once per content and shared by every instance in
 * the process, on any thread, and survives fmi2Reset (docs/architecture.md, "Shared tables").
 *
 * An entry is identified by a 128-bit hash of everything its content depends on
 * (hg_store_hash), so equal parameters find it whatever instance built it; its content is a pure
 * function of that, so an instance computes the same bits whether it builds the entry or finds
 * it. Entries are built once, under the entry's own lock (a second thread asking for it waits),
 * never changed, and freed when the last instance of the process is freed; an entry nobody holds
 * may be freed earlier to keep the store within HG_STORE_IDLE_BYTES.
 *
 * This is the FMU's one piece of process-wide mutable state (the store's list and its lock);
 * tests/python/test_no_global_state.py names it and allows nothing else. */
#ifndef HG_TABLE_STORE_H
#define HG_TABLE_STORE_H

#include <stddef.h>

/* Bytes of entries that no instance holds kept for later use (node tables of operating points a
 * run may come back to, tables of an instance that is being reset or replaced). */
#define HG_STORE_IDLE_BYTES (48u * 1024u * 1024u)

typedef struct {
    unsigned long long a, b;
} hg_store_id;

/* The hash of n bytes continued from id (start from hg_store_id_of(kind), a distinct constant per
 * kind of table); every byte counts, so hash structs whose padding is zeroed. */
hg_store_id hg_store_hash(hg_store_id id, const void *data, size_t n);
hg_store_id hg_store_id_of(const char *kind);

/* Builds an entry's content of `size` bytes at `table` (zeroed) from ctx; returns 0, or -1 (the
 * entry is then not kept and hg_store_get returns NULL). */
typedef int (*hg_store_build_fn)(void *table, void *ctx);
/* Frees what the content points to (not the content itself), or NULL. */
typedef void (*hg_store_free_fn)(void *table);

/* An instance's life in the store: attach at creation, detach at free (the last detach frees
 * every entry). */
void hg_store_attach(void);
void hg_store_detach(void);

/* The entry id, held until hg_store_put: found, or built now by build(table, ctx) (*built set to
 * 1 then, else 0; built may be NULL); NULL when out of memory, when the build failed, or when id
 * collides with another entry's: one this thread is building (a build that asks for its own id
 * gets NULL rather than waiting for itself), or one of another size, free function or kind. */
const void *hg_store_get(hg_store_id id, size_t size, hg_store_build_fn build, void *ctx,
                         hg_store_free_fn free_fn, int *built);

/* hg_store_get for a table of plain bytes (no pointers: nothing to free) that the FMU may ship:
 * on a miss, the file resource_dir/tables/<id>.tbl (io/tablefile.h, written at build time by
 * hg_store_write_shipped) gives the content when it passes every check of its header and
 * checksum, else build computes it as hg_store_get does (*built is 1 only then). The file holds
 * what build computed for the same id, so the content is the same either way. resource_dir NULL
 * or "": no file is looked for. */
const void *hg_store_get_shipped(const char *resource_dir, hg_store_id id, size_t size,
                                 hg_store_build_fn build, void *ctx, int *built);

/* Writes every entry that hg_store_get_shipped gave as dir/<id>.tbl; the number written, or -1
 * (tools/table_files.c, at build time). */
int hg_store_write_shipped(const char *dir);

/* Releases an entry that hg_store_get gave (NULL: nothing). */
void hg_store_put(const void *table);

/* Diagnostics: entries and bytes in the store, and how many entries were built so far. */
void hg_store_stats(size_t *entries, size_t *bytes, unsigned long *built);

#endif
