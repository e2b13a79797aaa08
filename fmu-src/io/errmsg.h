/* Error messages passed around the FMU as (char *err, size_t errlen) buffers. */
#ifndef HG_ERRMSG_H
#define HG_ERRMSG_H

#include <stddef.h>

#define HG_ERRLEN 512 /* size of every error-message buffer passed around the FMU */

/* Marks a printf-like function for the compiler's format checks (argument fmt is the format,
 * the values start at args). mingw-w64 builds use its C99 stdio, which takes %zu as glibc does
 * (gnu_printf), not the Microsoft printf that "printf" means there. */
#if defined(__MINGW32__)
#define HG_PRINTF_LIKE(fmt, args) __attribute__((format(gnu_printf, fmt, args)))
#elif defined(__GNUC__)
#define HG_PRINTF_LIKE(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define HG_PRINTF_LIKE(fmt, args)
#endif

/* printf into err (nothing when err is NULL or errlen is 0). */
void hg_errorf(char *err, size_t errlen, const char *fmt, ...) HG_PRINTF_LIKE(3, 4);

#endif
