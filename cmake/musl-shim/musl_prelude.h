/* Included before every musl math source (cmake/portable_math.cmake). The platform's <math.h>
 * comes first; then musl's internal trigonometric kernels are renamed, because glibc's math.h
 * declares functions of the same names (__sin, __cos, __tan and their long double twins) with
 * other signatures. */
#ifndef HG_MUSL_PRELUDE_H
#define HG_MUSL_PRELUDE_H
#include <math.h>
#define __sin hg_musl_ksin
#define __cos hg_musl_kcos
#define __tan hg_musl_ktan
#define __sinl hg_musl_ksinl
#define __cosl hg_musl_kcosl
#define __tanl hg_musl_ktanl
#endif
