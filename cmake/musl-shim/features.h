/* musl's math headers include <features.h> (glibc has one, mingw-w64 not); nothing is needed from
 * it: `hidden` is defined on the compiler's command line (cmake/portable_math.cmake). */
#ifndef HG_MUSL_SHIM_FEATURES_H
#define HG_MUSL_SHIM_FEATURES_H
#endif
