/* The paper's two lubricants as structs (Table 2; docs/physics.md §4.1 Vogel fit at full precision,
 * rounded there to 7.560e-5 Pa s, 1109.3 K, -117.8 degC): independent of the resource files, so
 * the physics tests do not depend on the file parser. which = 62 or 63 (OS2659xx). */
#ifndef HG_TEST_PAPER_OILS_H
#define HG_TEST_PAPER_OILS_H

#include <string.h>

#include "tribo/lubricant.h"

#define C0 273.15

static hg_lubricant paper_oil(int which)
{
    hg_lubricant l;
    memset(&l, 0, sizeof l);
    strcpy(l.name, which == 62 ? "OS265962" : "OS265963");
    l.vogel_a = 7.560103250811039e-05;
    l.vogel_b = 1109.2767960557555;
    l.vogel_c = 155.39875251733173;
    l.alpha_T[0] = 40 + C0, l.alpha_T[1] = 100 + C0, l.alpha_T[2] = 140 + C0;
    if (which == 62) {
        l.alpha_star[0] = 16.09e-9, l.alpha_star[1] = 11.59e-9, l.alpha_star[2] = 9.38e-9;
        l.hn_lambda = 7.9e-8, l.hn_alpha = 0.70;
    } else {
        l.alpha_star[0] = 19.31e-9, l.alpha_star[1] = 13.89e-9, l.alpha_star[2] = 12.28e-9;
        l.hn_lambda = 8.0e-8, l.hn_alpha = 0.97;
    }
    l.hn_beta = 1.0, l.k_f = 0.18, l.c_p_f = 2090, l.rho_15 = 870;
    return l;
}

#endif
