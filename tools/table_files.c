/* The read-only tables the FMU ships in resources/tables/ (docs/architecture.md, "Shared
 * tables"), written at build time by the FMU's own code:
 *
 *   table_files RESOURCE_DIR OUT_DIR [T]
 *
 * sets the model up at its start values (the full level, the built-in gear set and lubricant)
 * with its data files from RESOURCE_DIR, runs it T s (default 0.01) at 1 ms steps, and writes
 * every table of plain bytes the process's table store then holds (the gear-set file as read
 * and checked, the lubricant's Z_exact table, the friction node tables the start needed) to
 * OUT_DIR/<content key>.tbl (io/tablefile.h). An instance whose parameters give the same
 * content key reads the file instead of computing the table; any other computes it as before. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/hypoid.h"
#include "model/table_store.h"

int main(int argc, char **argv)
{
    hg_model *m;
    hg_vars v;
    hg_inputs du;
    char err[HG_ERRLEN] = "";
    double T = argc > 3 ? atof(argv[3]) : 0.01;
    int k, n = -1;
    if (argc < 3 || !(T >= 0.0 && T <= 10.0)) {
        fprintf(stderr, "usage: table_files RESOURCE_DIR OUT_DIR [T]\n");
        return 2;
    }
    if (!(m = hg_model_new(argv[1], NULL, NULL))) return 1;
    hg_model_start_values(&v);
    memset(&du, 0, sizeof du);
    if (hg_model_setup(m, &v, 0.0, err, sizeof err) == 0) {
        for (k = 0; k < (int)(T / 1e-3 + 0.5) && !err[0]; k++)
            if (hg_model_step(m, &v, &du, 1e-3, err, sizeof err)) break;
        if (!err[0]) n = hg_store_write_shipped(argv[2]);
    }
    hg_model_free(m);
    if (n <= 0) {
        fprintf(stderr, "table_files: %s\n", err[0] ? err : "no table written to OUT_DIR");
        return 1;
    }
    printf("table_files: %d tables written to %s\n", n, argv[2]);
    return 0;
}
