# Portable math: musl's C math library (src/math of musl 1.2.3, MIT licence), compiled from the
# source tree that scripts/third_party.sh fetches from Debian (never copied into the repository)
# and linked into the FMU ahead of the platform's libm, so that the linux64 and win64 binaries
# evaluate exp, log, pow, cbrt, erfc, ... with the same code and give the same bits
# (docs/portability.md). Only the double-precision functions; sqrt is musl's x86_64 one (the SSE2
# instruction, correctly rounded). The same code-generation flags on every platform: SSE2 (no
# x87), no contraction into FMA, musl's own -frounding-math / -fexcess-precision=standard.
#
# Defines HG_MATH_LIB (the library to link before libm; empty when HG_MUSL_DIR is not set).
set(HG_MUSL_DIR "" CACHE PATH
    "musl 1.2.3 source tree (scripts/third_party.sh); empty: use the platform's libm")
set(HG_MATH_LIB "")
if(NOT HG_MUSL_DIR)
  message(STATUS "portable math: HG_MUSL_DIR not set, the platform's libm is used")
  return()
endif()
if(NOT EXISTS "${HG_MUSL_DIR}/src/internal/libm.h")
  message(FATAL_ERROR "HG_MUSL_DIR=${HG_MUSL_DIR} is not a musl source tree")
endif()

file(GLOB _musl_all "${HG_MUSL_DIR}/src/math/*.c")
# files that need musl's libc internals (weak aliases, atomics) and that the FMU does not use
set(_musl_skip exp10 fma lgamma_r remainder signgam tgamma sqrt)
set(HG_MUSL_SOURCES "${HG_MUSL_DIR}/src/math/x86_64/sqrt.c")
foreach(_f ${_musl_all})
  get_filename_component(_n "${_f}" NAME_WE)
  if(_n IN_LIST _musl_skip)
    continue()
  endif()
  # float (...f, ...f_data) and long double (...l) variants out; erf and modf are doubles
  if(_n MATCHES "(f|l|f_data)$" AND NOT _n MATCHES "^(erf|modf)$")
    continue()
  endif()
  list(APPEND HG_MUSL_SOURCES "${_f}")
endforeach()

add_library(hg_musl_math STATIC ${HG_MUSL_SOURCES})
set_target_properties(hg_musl_math PROPERTIES C_STANDARD 99 C_EXTENSIONS OFF)
target_compile_options(hg_musl_math PRIVATE -w -O2 -fno-builtin -fno-strict-aliasing
                       -frounding-math -fexcess-precision=standard -ffp-contract=off
                       -msse2 -mfpmath=sse "-Dhidden="
                       -include "${CMAKE_CURRENT_LIST_DIR}/musl-shim/musl_prelude.h")
target_include_directories(hg_musl_math PRIVATE "${HG_MUSL_DIR}/src/internal"
                           "${HG_MUSL_DIR}/arch/generic")
if(WIN32)
  # mingw-w64 has no <endian.h> and <features.h>; its math.h inline helpers would clash with musl
  target_include_directories(hg_musl_math BEFORE PRIVATE "${CMAKE_CURRENT_LIST_DIR}/musl-shim")
  target_compile_definitions(hg_musl_math PRIVATE __CRT__NO_INLINE)
endif()
set(HG_MATH_LIB hg_musl_math)
message(STATUS "portable math: musl from ${HG_MUSL_DIR}")
