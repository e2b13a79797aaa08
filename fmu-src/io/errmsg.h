/* Error messages passed around the FMU as (char *err, size_t errlen) buffers. */
#ifndef HG_ERRMSG_H
#define HG_ERRMSG_H

#include <stddef.h>

#define HG_ERRLEN 512 /* size of every error-message buffer passed around the FMU */

/* printf into err (nothing when err is NULL or errlen is 0). */
void hg_errorf(char *err, size_t errlen, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
