/* Messages to the host: see log.h. */
#include "io/log.h"

#include <stdarg.h>
#include <stdio.h>

#include "io/errmsg.h"

void hg_logf(const hg_logger *lg, const char *category, const char *fmt, ...)
{
    char msg[HG_ERRLEN];
    va_list ap;
    if (!lg->fn) return;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    lg->fn(lg->ctx, category, msg);
}
