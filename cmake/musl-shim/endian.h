/* The byte-order macros musl's libm.h reads, for mingw-w64 (which has no <endian.h>). */
#ifndef HG_MUSL_SHIM_ENDIAN_H
#define HG_MUSL_SHIM_ENDIAN_H
#define __LITTLE_ENDIAN 1234
#define __BIG_ENDIAN 4321
#define __BYTE_ORDER __LITTLE_ENDIAN
#endif
