# FindArb.cmake — locate the Arb ball-arithmetic library and FLINT.
#
# Arb exists in two shapes:
#   * Arb 2.x as a separate library (Debian 12: headers /usr/include/arb.h,
#     library libflint-arb; upstream builds name it libarb) on top of FLINT 2.
#   * FLINT >= 3, which absorbed Arb: headers <flint/arb.h>, library libflint.
# vigen includes <arb.h>, <acb_calc.h>, ... so the include directory we export is
# the one that holds arb.h (…/include or …/include/flint); FLINT's own headers are
# reached as <flint/flint.h> (Arb 2) or "flint.h" next to arb.h (FLINT 3).
#
# Result: target Arb::Arb, variables Arb_FOUND, Arb_INCLUDE_DIRS, Arb_LIBRARIES,
# Arb_FLINT3 (true when Arb comes from FLINT 3).
# Hints: ARB_ROOT / FLINT_ROOT (CMake or environment variables).

find_path(FLINT_INCLUDE_DIR NAMES flint/flint.h
          HINTS ${FLINT_ROOT} ENV FLINT_ROOT PATH_SUFFIXES include)
find_library(GMP_LIBRARY NAMES gmp HINTS ${FLINT_ROOT} ENV FLINT_ROOT PATH_SUFFIXES lib lib64)
find_library(MPFR_LIBRARY NAMES mpfr HINTS ${FLINT_ROOT} ENV FLINT_ROOT PATH_SUFFIXES lib lib64)
find_library(FLINT_LIBRARY NAMES flint
             HINTS ${FLINT_ROOT} ENV FLINT_ROOT PATH_SUFFIXES lib lib64)

set(_vigen_flint_major 0)
if(FLINT_INCLUDE_DIR AND EXISTS "${FLINT_INCLUDE_DIR}/flint/flint.h")
  file(STRINGS "${FLINT_INCLUDE_DIR}/flint/flint.h" _vigen_line
       REGEX "^#define[ \t]+__FLINT_VERSION[ \t]+[0-9]+")
  string(REGEX REPLACE ".*__FLINT_VERSION[ \t]+([0-9]+).*" "\\1" _vigen_flint_major "${_vigen_line}")
endif()

set(Arb_FLINT3 FALSE)
if(_vigen_flint_major GREATER_EQUAL 3 AND EXISTS "${FLINT_INCLUDE_DIR}/flint/arb.h")
  set(Arb_FLINT3 TRUE)
  set(ARB_INCLUDE_DIR "${FLINT_INCLUDE_DIR}/flint" CACHE PATH "directory holding arb.h")
  set(ARB_LIBRARY "${FLINT_LIBRARY}" CACHE FILEPATH "Arb library")
else()
  find_path(ARB_INCLUDE_DIR NAMES arb.h
            HINTS ${ARB_ROOT} ENV ARB_ROOT PATH_SUFFIXES include include/arb)
  find_library(ARB_LIBRARY NAMES flint-arb arb
               HINTS ${ARB_ROOT} ENV ARB_ROOT PATH_SUFFIXES lib lib64)
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Arb REQUIRED_VARS ARB_LIBRARY ARB_INCLUDE_DIR FLINT_LIBRARY FLINT_INCLUDE_DIR GMP_LIBRARY MPFR_LIBRARY)

if(Arb_FOUND)
  set(Arb_INCLUDE_DIRS "${ARB_INCLUDE_DIR}" "${FLINT_INCLUDE_DIR}")
  list(REMOVE_DUPLICATES Arb_INCLUDE_DIRS)
  if(Arb_FLINT3)
    set(Arb_LIBRARIES "${FLINT_LIBRARY}")
  else()
    set(Arb_LIBRARIES "${ARB_LIBRARY}" "${FLINT_LIBRARY}")
  endif()
  if(NOT TARGET Arb::Arb)
    add_library(Arb::Arb INTERFACE IMPORTED)
    set_target_properties(Arb::Arb PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${Arb_INCLUDE_DIRS}"
      INTERFACE_LINK_LIBRARIES "${Arb_LIBRARIES};${MPFR_LIBRARY};${GMP_LIBRARY};m")
  endif()
endif()
mark_as_advanced(ARB_INCLUDE_DIR ARB_LIBRARY FLINT_INCLUDE_DIR FLINT_LIBRARY GMP_LIBRARY MPFR_LIBRARY)
