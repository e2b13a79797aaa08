/* Error-message buffers: see errmsg.h. */
#include "io/errmsg.h"

#include <stdarg.h>
#include <stdio.h>

void hg_errorf(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (!err || errlen == 0) return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}
