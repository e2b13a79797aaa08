/* Messages to the host, passed down as a function and its context so that no layer needs to know
 * who listens. */
#ifndef HG_LOG_H
#define HG_LOG_H

#include "io/errmsg.h"

/* category: "logEvents", "logStatusWarning", "logStatusError" or "logAll". */
typedef void (*hg_log_fn)(void *ctx, const char *category, const char *message);

typedef struct {
    hg_log_fn fn; /* NULL: messages are dropped */
    void *ctx;
} hg_logger;

/* printf-style message through lg (at most HG_ERRLEN - 1 characters). */
void hg_logf(const hg_logger *lg, const char *category, const char *fmt, ...) HG_PRINTF_LIKE(3, 4);

#endif
