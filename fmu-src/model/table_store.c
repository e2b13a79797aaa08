/* The process's store of read-only tables: see table_store.h. */
#include "model/table_store.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/tablefile.h"

#ifdef _WIN32
#include <windows.h>
static SRWLOCK store_lock = SRWLOCK_INIT;
static CONDITION_VARIABLE store_built = CONDITION_VARIABLE_INIT;
static void lock(void) { AcquireSRWLockExclusive(&store_lock); }
static void unlock(void) { ReleaseSRWLockExclusive(&store_lock); }
static void wait_built(void) { SleepConditionVariableSRW(&store_built, &store_lock, INFINITE, 0); }
static void wake_all(void) { WakeAllConditionVariable(&store_built); }
typedef DWORD thread_id;
static thread_id this_thread(void) { return GetCurrentThreadId(); }
static int same_thread(thread_id x, thread_id y) { return x == y; }
#else
#include <pthread.h>
static pthread_mutex_t store_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t store_built = PTHREAD_COND_INITIALIZER;
static void lock(void) { pthread_mutex_lock(&store_lock); }
static void unlock(void) { pthread_mutex_unlock(&store_lock); }
static void wait_built(void) { pthread_cond_wait(&store_built, &store_lock); }
static void wake_all(void) { pthread_cond_broadcast(&store_built); }
typedef pthread_t thread_id;
static thread_id this_thread(void) { return pthread_self(); }
static int same_thread(thread_id x, thread_id y) { return pthread_equal(x, y); }
#endif

typedef struct entry {
    struct entry *next;
    hg_store_id id;
    size_t size;
    int refs;                  /* holders */
    int building;              /* its build runs, on the thread `builder` that asked first */
    thread_id builder;
    int shipped;               /* plain bytes, from hg_store_get_shipped */
    unsigned long used;        /* the store's clock when last released */
    hg_store_free_fn free_fn;
    double content[1];         /* size bytes (double: aligned for any table) */
} entry;

/* Everything below is the store's state, guarded by store_lock. */
static struct {
    entry *head;
    int instances;         /* attached instances */
    size_t bytes, idle;    /* content bytes in the store, of them held by nobody */
    unsigned long clock;   /* releases so far (least recently used) */
    unsigned long built;   /* entries built so far */
} store;

static entry *entry_of(const void *table)
{
    return (entry *)(void *)((char *)table - offsetof(entry, content));
}

#define FNV_PRIME 0x100000001b3ULL

/* One step of both lanes: FNV-1a's, and a second, unrelated one (rotate, xor, multiply by the
 * golden ratio's odd 64-bit constant). Each is a bijection of its lane, so any one changed word
 * changes both. */
static void mix(hg_store_id *id, unsigned long long w)
{
    id->a = (id->a ^ w) * FNV_PRIME;
    id->b = ((id->b << 5 | id->b >> 59) ^ w) * 0x9e3779b97f4a7c15ULL;
}

/* The bytes as little-endian 64-bit words (both readers of the shipped tables are), the tail byte
 * by byte: eight times faster than byte by byte, which matters because every instance hashes its
 * gear set (94 kB) for two keys. */
hg_store_id hg_store_hash(hg_store_id id, const void *data, size_t n)
{
    const unsigned char *p = data;
    unsigned long long w;
    size_t k;
    for (k = 0; k + sizeof w <= n; k += sizeof w) {
        memcpy(&w, p + k, sizeof w);
        mix(&id, w);
    }
    for (; k < n; k++) mix(&id, p[k]);
    return id;
}

hg_store_id hg_store_id_of(const char *kind)
{
    hg_store_id id = {0xcbf29ce484222325ULL, 0x84222325cbf29ce4ULL};
    return hg_store_hash(id, kind, strlen(kind) + 1);
}

static entry *find(hg_store_id id)
{
    entry *e;
    for (e = store.head; e; e = e->next)
        if (e->id.a == id.a && e->id.b == id.b) return e;
    return NULL;
}

static void unlink_entry(entry *gone)
{
    entry **p;
    for (p = &store.head; *p; p = &(*p)->next)
        if (*p == gone) {
            *p = gone->next;
            return;
        }
}

static void destroy(entry *e)
{
    if (e->free_fn) e->free_fn(e->content);
    free(e);
}

/* Frees the least recently released idle entries while the idle ones exceed the limit. */
static void trim(void)
{
    while (store.idle > HG_STORE_IDLE_BYTES) {
        entry *e, *old = NULL;
        for (e = store.head; e; e = e->next)
            if (!e->refs && !e->building && (!old || e->used < old->used)) old = e;
        if (!old) return;
        unlink_entry(old);
        store.idle -= old->size;
        store.bytes -= old->size;
        destroy(old);
    }
}

void hg_store_attach(void)
{
    lock();
    store.instances++;
    unlock();
}

void hg_store_detach(void)
{
    entry *all = NULL;
    lock();
    if (--store.instances == 0) { /* nobody left: the store empties (no entry is held) */
        all = store.head;
        store.head = NULL;
        store.bytes = store.idle = 0;
    }
    unlock();
    while (all) {
        entry *next = all->next;
        destroy(all);
        all = next;
    }
}

static void take(entry *e)
{
    if (e->refs++ == 0) store.idle -= e->size;
}

/* Whether entry e, found under the id asked for, cannot be what was asked for: a key collision
 * (never seen with the 128-bit keys). Either the entry is being built by this very thread (the
 * build asks for an id equal to its own, and waiting for it would wait forever) or it holds
 * another kind of content. */
static int collides(const entry *e, size_t size, hg_store_free_fn free_fn, int shipped)
{
    return (e->building && same_thread(e->builder, this_thread())) || e->size != size ||
           e->free_fn != free_fn || e->shipped != shipped;
}

static const void *get(hg_store_id id, size_t size, hg_store_build_fn build, void *ctx,
                       hg_store_free_fn free_fn, int shipped, int *built)
{
    entry *e;
    if (built) *built = 0;
    lock();
    while ((e = find(id)) != NULL && e->building && !collides(e, size, free_fn, shipped))
        wait_built();
    if (e && collides(e, size, free_fn, shipped)) {
        unlock();
        return NULL;
    }
    if (e) {
        take(e);
        unlock();
        return e->content;
    }
    e = calloc(1, offsetof(entry, content) + (size > sizeof e->content ? size : sizeof e->content));
    if (!e) {
        unlock();
        return NULL;
    }
    e->id = id;
    e->size = size;
    e->refs = 1;
    e->building = 1;
    e->builder = this_thread();
    e->free_fn = free_fn;
    e->shipped = shipped;
    e->next = store.head;
    store.head = e;
    store.bytes += size;
    unlock();
    if (build(e->content, ctx)) { /* failed: not kept; waiting threads try themselves */
        lock();
        unlink_entry(e);
        store.bytes -= size;
        wake_all();
        unlock();
        free(e);
        return NULL;
    }
    if (built) *built = 1;
    lock();
    e->building = 0;
    store.built++;
    wake_all();
    unlock();
    return e->content;
}

const void *hg_store_get(hg_store_id id, size_t size, hg_store_build_fn build, void *ctx,
                         hg_store_free_fn free_fn, int *built)
{
    return get(id, size, build, ctx, free_fn, 0, built);
}

/* A shipped table's build: its file, or the build. */
typedef struct {
    const char *resource_dir;
    hg_store_id id;
    size_t size;
    hg_store_build_fn build;
    void *ctx;
    int loaded;
} shipped_job;

static int load_or_build(void *table, void *ctx)
{
    shipped_job *j = ctx;
    char name[HG_TABLEFILE_NAME], *path;
    size_t n;
    hg_tablefile_name(j->id.a, j->id.b, name);
    n = strlen(j->resource_dir) + strlen("/tables/") + strlen(name) + 1;
    if ((path = malloc(n)) != NULL) {
        snprintf(path, n, "%s/tables/%s", j->resource_dir, name);
        j->loaded = hg_tablefile_read(path, j->id.a, j->id.b, table, j->size) == 0;
        free(path);
        if (j->loaded) return 0;
    }
    return j->build(table, j->ctx);
}

const void *hg_store_get_shipped(const char *resource_dir, hg_store_id id, size_t size,
                                 hg_store_build_fn build, void *ctx, int *built)
{
    shipped_job job;
    const void *table;
    int made;
    if (!resource_dir || !*resource_dir) return get(id, size, build, ctx, NULL, 1, built);
    job.resource_dir = resource_dir, job.id = id, job.size = size;
    job.build = build, job.ctx = ctx, job.loaded = 0;
    table = get(id, size, load_or_build, &job, NULL, 1, &made);
    if (built) *built = made && !job.loaded;
    return table;
}

int hg_store_write_shipped(const char *dir)
{
    entry *e;
    int n = 0;
    lock();
    for (e = store.head; e && n >= 0; e = e->next) {
        char name[HG_TABLEFILE_NAME], path[4096];
        if (!e->shipped || e->building) continue;
        hg_tablefile_name(e->id.a, e->id.b, name);
        if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path ||
            hg_tablefile_write(path, e->id.a, e->id.b, e->content, e->size))
            n = -1;
        else
            n++;
    }
    unlock();
    return n;
}

void hg_store_put(const void *table)
{
    entry *e;
    if (!table) return;
    e = entry_of(table);
    lock();
    if (--e->refs == 0) {
        e->used = ++store.clock;
        store.idle += e->size;
        trim();
    }
    unlock();
}

void hg_store_stats(size_t *entries, size_t *bytes, unsigned long *built)
{
    entry *e;
    size_t n = 0;
    lock();
    for (e = store.head; e; e = e->next) n++;
    if (entries) *entries = n;
    if (bytes) *bytes = store.bytes;
    if (built) *built = store.built;
    unlock();
}
