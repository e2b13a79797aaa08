# Packaging of every FMU the build makes (THIRD_PARTY.md): one function, hg_fmu, so that each FMU
# carries its binaries, its resources and the licence texts of what its binaries link.
#
# Licence texts are given as "FILE=NAME": FILE is copied at build time from the package it
# belongs to (never retyped) to documentation/licenses/NAME in the FMU. The lists:
#   HG_LICENSES_OWN      the project's licence (license.txt, the entry point FMI 3.0 names) and
#                        the FMI headers' (every binary is compiled against them)
#   HG_LICENSES_MATH     musl's, when its math library is linked (HG_MUSL_DIR)
#   HG_LICENSES_SUNDIALS SUNDIALS' LICENSE and NOTICE (HG_SUNDIALS_SOURCE: its source tree)
#   HG_LICENSES_WIN64    the mingw-w64 runtime's, added to FMUs that carry a win64 binary
# A text that is not found is left out with a warning (a build without Debian's source packages).

set(HG_SUNDIALS_SOURCE "${CMAKE_SOURCE_DIR}/build/third_party/src/sundials-${SUNDIALS_VERSION}"
    CACHE PATH "SUNDIALS source tree whose LICENSE and NOTICE the FMUs carry")
set(HG_MINGW_LICENSE "/usr/share/doc/mingw-w64-x86-64-dev/copyright" CACHE FILEPATH
    "the mingw-w64 runtime's copyright file (Debian's package), for FMUs with a win64 binary")

# hg_licenses(VAR FILE=NAME...): VAR = the pairs whose FILE exists
function(hg_licenses var)
  set(_found "")
  foreach(_pair ${ARGN})
    string(FIND "${_pair}" "=" _eq REVERSE)
    string(SUBSTRING "${_pair}" 0 ${_eq} _file)
    if(EXISTS "${_file}")
      list(APPEND _found "${_pair}")
    else()
      message(WARNING "licence text ${_file} not found: the FMUs go without it")
    endif()
  endforeach()
  set(${var} ${_found} PARENT_SCOPE)
endfunction()

hg_licenses(HG_LICENSES_OWN "${CMAKE_SOURCE_DIR}/LICENSE=license.txt"
            "${HG_FMI_LICENSE}=FMI-headers-LICENSE.txt")
set(HG_LICENSES_MATH "")
if(HG_MUSL_DIR)
  hg_licenses(HG_LICENSES_MATH "${HG_MUSL_DIR}/COPYRIGHT=musl-COPYRIGHT.txt")
endif()
hg_licenses(HG_LICENSES_SUNDIALS "${HG_SUNDIALS_SOURCE}/LICENSE=SUNDIALS-LICENSE.txt"
            "${HG_SUNDIALS_SOURCE}/NOTICE=SUNDIALS-NOTICE.txt")
set(HG_LICENSES_WIN64 "")
if(WIN32 OR HG_WIN64_DLL OR HG_WIN64_VEHICLE_DLL)
  hg_licenses(HG_LICENSES_WIN64 "${HG_MINGW_LICENSE}=mingw-w64-copyright.txt")
endif()

# hg_fmu(TARGET FILE fmu STAGE dir XML xml BINARY target [PLATFORM name] [WIN64_DLL dll]
#        [WIN64_PLATFORM name] [RESOURCES dir] [TABLES dir stamp target] [EXTRA dir]
#        LICENSES FILE=NAME...)
# FILE zips STAGE: XML as modelDescription.xml, BINARY's library under binaries/<PLATFORM>/
# (HG_PLATFORM unless given; copied there unless it is built there), WIN64_DLL under
# binaries/<WIN64_PLATFORM>/ (win64 unless given; Linux builds), RESOURCES as resources/, TABLES
# (the directory, the file its generator last wrote and the target that writes it: built first,
# so that parallel FMU builds never write the tables side by side) as resources/tables/, EXTRA
# as extra/, the LICENSES (and HG_LICENSES_WIN64 with a win64 binary) under
# documentation/licenses/. TARGET (in ALL) makes it.
function(hg_fmu target)
  cmake_parse_arguments(F "" "FILE;STAGE;XML;BINARY;PLATFORM;WIN64_DLL;WIN64_PLATFORM;RESOURCES;EXTRA"
                        "LICENSES;TABLES" ${ARGN})
  if(NOT F_PLATFORM)
    set(F_PLATFORM ${HG_PLATFORM})
  endif()
  if(NOT F_WIN64_PLATFORM)
    set(F_WIN64_PLATFORM win64)
  endif()
  set(_bin "${F_STAGE}/binaries/${F_PLATFORM}")
  set(_deps ${F_BINARY} "${F_XML}")
  set(_zip modelDescription.xml binaries documentation)
  set(_cmds COMMAND ${CMAKE_COMMAND} -E copy "${F_XML}" "${F_STAGE}/modelDescription.xml")
  get_target_property(_built_in ${F_BINARY} LIBRARY_OUTPUT_DIRECTORY)
  if(WIN32)
    get_target_property(_built_in ${F_BINARY} RUNTIME_OUTPUT_DIRECTORY)
  endif()
  if(NOT _built_in STREQUAL _bin)
    list(APPEND _cmds COMMAND ${CMAKE_COMMAND} -E rm -rf "${F_STAGE}/binaries"
         COMMAND ${CMAKE_COMMAND} -E make_directory "${_bin}"
         COMMAND ${CMAKE_COMMAND} -E copy "$<TARGET_FILE:${F_BINARY}>" "${_bin}/")
  endif()
  set(_licenses ${F_LICENSES})
  if(NOT WIN32)
    list(APPEND _cmds COMMAND ${CMAKE_COMMAND} -E rm -rf "${F_STAGE}/binaries/${F_WIN64_PLATFORM}")
    if(F_WIN64_DLL)
      list(APPEND _cmds
           COMMAND ${CMAKE_COMMAND} -E make_directory "${F_STAGE}/binaries/${F_WIN64_PLATFORM}"
           COMMAND ${CMAKE_COMMAND} -E copy "${F_WIN64_DLL}" "${F_STAGE}/binaries/${F_WIN64_PLATFORM}/")
      list(APPEND _deps "${F_WIN64_DLL}")
      list(APPEND _licenses ${HG_LICENSES_WIN64})
    endif()
  else()
    list(APPEND _licenses ${HG_LICENSES_WIN64})
  endif()
  foreach(_kind resources extra) # RESOURCES -> resources/, EXTRA -> extra/
    string(TOUPPER ${_kind} _arg)
    if(F_${_arg})
      file(GLOB_RECURSE _files CONFIGURE_DEPENDS "${F_${_arg}}/*")
      list(APPEND _cmds COMMAND ${CMAKE_COMMAND} -E rm -rf "${F_STAGE}/${_kind}"
           COMMAND ${CMAKE_COMMAND} -E copy_directory "${F_${_arg}}" "${F_STAGE}/${_kind}")
      list(APPEND _deps ${_files})
      list(APPEND _zip ${_kind})
    endif()
  endforeach()
  if(F_TABLES)
    list(GET F_TABLES 0 _tables)
    list(GET F_TABLES 1 _stamp)
    list(APPEND _cmds COMMAND ${CMAKE_COMMAND} -E copy_directory "${_tables}"
         "${F_STAGE}/resources/tables")
    list(APPEND _deps "${_stamp}")
  endif()
  set(_lic_dir "${F_STAGE}/documentation/licenses")
  list(APPEND _cmds COMMAND ${CMAKE_COMMAND} -E rm -rf "${_lic_dir}"
       COMMAND ${CMAKE_COMMAND} -E make_directory "${_lic_dir}")
  foreach(_pair ${_licenses})
    string(FIND "${_pair}" "=" _eq REVERSE)
    string(SUBSTRING "${_pair}" 0 ${_eq} _file)
    math(EXPR _eq "${_eq} + 1")
    string(SUBSTRING "${_pair}" ${_eq} -1 _name)
    list(APPEND _cmds COMMAND ${CMAKE_COMMAND} -E copy "${_file}" "${_lic_dir}/${_name}")
    list(APPEND _deps "${_file}")
  endforeach()
  add_custom_command(
    OUTPUT "${F_FILE}"
    ${_cmds}
    COMMAND ${CMAKE_COMMAND} -E rm -f "${F_FILE}"
    COMMAND ${CMAKE_COMMAND} -E chdir "${F_STAGE}" ${CMAKE_COMMAND} -E tar cf "${F_FILE}"
            --format=zip ${_zip}
    DEPENDS ${_deps}
    COMMENT "Assembling ${F_FILE}")
  add_custom_target(${target} ALL DEPENDS "${F_FILE}")
  if(F_TABLES)
    list(GET F_TABLES 2 _tables_target)
    add_dependencies(${target} ${_tables_target})
  endif()
endfunction()
