/* The table store (model/table_store.h) under a key collision, which its 128-bit keys make
 * negligible but a defect in a key's hash would not: an entry whose build asks for its own id gets
 * NULL instead of waiting for itself for ever, an id found with content of another size or kind
 * gets NULL instead of the wrong table, and the store stays usable after both. */
#include <string.h>

#include "check.h"
#include "model/table_store.h"

typedef struct {
    hg_store_id id;
    const void *inner; /* what the nested get gave */
    int calls;
} nested_job;

/* A build that asks the store for `id` while it builds (as the phase tables' build asks for each
 * flank's table), then fills its content. */
static int build_asking(void *table, void *ctx)
{
    nested_job *j = ctx;
    j->calls++;
    j->inner = hg_store_get(j->id, sizeof(double), build_asking, j, NULL, NULL);
    hg_store_put(j->inner);
    *(double *)table = 42.0;
    return 0;
}

static int build_seven(void *table, void *ctx)
{
    (void)ctx;
    memset(table, 7, 3 * sizeof(double));
    return 0;
}

static void free_nothing(void *table) { (void)table; }

int main(void)
{
    hg_store_id id = hg_store_id_of("test: a nested build"), other, outer_id;
    nested_job job;
    const double *t, *u;
    int built = -1;
    hg_store_attach();

    /* the nested build asks for its own id: NULL, no wait; the outer entry is still built */
    job.id = id, job.inner = (const void *)&job, job.calls = 0;
    t = hg_store_get(id, sizeof *t, build_asking, &job, NULL, &built);
    CHECK(t != NULL && built == 1 && *t == 42.0);
    CHECK(job.calls == 1 && job.inner == NULL);
    hg_store_put(t);

    /* nested under another id: the inner entry is built and given */
    outer_id = hg_store_id_of("test: the outer entry");
    other = hg_store_id_of("test: the inner entry");
    job.id = other, job.inner = NULL, job.calls = 0;
    t = hg_store_get(outer_id, sizeof *t, build_asking, &job, NULL, &built);
    CHECK(t != NULL && built == 1 && job.inner != NULL && job.calls == 2);
    hg_store_put(t);

    /* the same id asked for with another size, free function or kind: NULL, not the entry */
    CHECK(hg_store_get(id, 3 * sizeof(double), build_seven, NULL, NULL, &built) == NULL);
    CHECK(built == 0);
    CHECK(hg_store_get(id, sizeof(double), build_seven, NULL, free_nothing, NULL) == NULL);
    CHECK(hg_store_get_shipped(NULL, id, sizeof(double), build_seven, NULL, NULL) == NULL);

    /* the entry as asked for before is still there, found without a build */
    u = hg_store_get(id, sizeof *u, build_asking, &job, NULL, &built);
    CHECK(u != NULL && built == 0 && *u == 42.0);
    hg_store_put(u);
    hg_store_detach();
    CHECK_DONE();
}
