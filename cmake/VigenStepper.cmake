# VigenStepper.cmake — vigen_add_stepper: compile a tableau (or a spec,
# generated into a tableau first) into a stepper library at build time.
# Included by vigenConfig.cmake (find_package(vigen)).
#
#   vigen_add_stepper(TARGET <target> TABLEAU <file.lua or method name> NAME <name>
#                     [REAL double|long-double|float128]
#                     [OUTPUT_DIR <dir>] [ALLOW_INEXACT] [DIM <n>] [BATCH]
#                     [VARIANT <variant>])
#   vigen_add_stepper(TARGET <target> SPEC <spec.lua> [DIGITS <n>] NAME <name> ...)
#
# With SPEC, a first rule runs
#   vigen generate <spec.lua> --digits <n> -o <dir>/<name>.tableau.lua -q
# (DIGITS defaults to 40, enough for every REAL; re-run when the spec or the
# vigen executable changes) and the tableau it writes is emitted as below.
#
# adds a build rule that runs
#   vigen emit <file.lua> --name <name> --real <REAL> -o <dir> -q
# writing <dir>/<name>.c and <dir>/<name>.h (default <dir>:
# ${CMAKE_CURRENT_BINARY_DIR}/vigen/<target>), re-run when the tableau file,
# the vigen executable or its templates change, and a static library
# <target> compiled from <name>.c, with <dir> on its public include path and
# linked to vigen::runtime.  A program then does
#   target_link_libraries(app PRIVATE <target>)
# and `#include "<name>.h"`.  TABLEAU and SPEC are relative to the current
# source directory; exactly one of them is given.  A TABLEAU that is no file
# there but a method name (gauss_2, generated/gauss_legendre_s3; `vigen
# list`) is resolved by vigen as every command resolves names.  NAME must be a C
# identifier (it prefixes every emitted symbol) and not a C keyword (the list: src/emit/c_keywords.def in the vigen sources);
# REAL defaults to double.  ALLOW_INEXACT passes --allow-inexact (round the
# decimal entries as written when they have too few digits for REAL).  DIM
# passes --dim N (a static dimension: NAME_alloc and NAME_alloc_mechanical
# refuse problems of another dimension).  BATCH passes --batch (NAME_step_batch
# too: W trajectories per call, docs/ensembles.md; double, explicit tableaux).
# VARIANT passes --variant (e.g. split: the flows of the parts of H called
# back, NAME_alloc_split; docs/splitting.md).
# Compile the program without -ffast-math (the emitted code refuses it).

function(vigen_add_stepper)
  cmake_parse_arguments(PARSE_ARGV 0 VAS "ALLOW_INEXACT;BATCH" "TARGET;TABLEAU;SPEC;DIGITS;NAME;REAL;OUTPUT_DIR;DIM;VARIANT" "")
  if(VAS_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "vigen_add_stepper: unknown arguments: ${VAS_UNPARSED_ARGUMENTS}")
  endif()
  foreach(req TARGET NAME)
    if(NOT VAS_${req})
      message(FATAL_ERROR "vigen_add_stepper: ${req} is required")
    endif()
  endforeach()
  if((VAS_TABLEAU AND VAS_SPEC) OR (NOT VAS_TABLEAU AND NOT VAS_SPEC))
    message(FATAL_ERROR "vigen_add_stepper: give either TABLEAU <file> or SPEC <file> (exactly one)")
  endif()
  if(DEFINED VAS_DIGITS AND NOT VAS_SPEC)
    message(FATAL_ERROR "vigen_add_stepper: DIGITS goes with SPEC (a TABLEAU file has its digits already)")
  endif()
  if(NOT DEFINED VAS_DIGITS)
    set(VAS_DIGITS 40)
  endif()
  if(NOT VAS_DIGITS MATCHES "^[1-9][0-9]*$" OR VAS_DIGITS GREATER 100000)
    message(FATAL_ERROR "vigen_add_stepper: DIGITS must be an integer from 1 to 100000, not '${VAS_DIGITS}'")
  endif()
  if(NOT TARGET vigen::vigen OR NOT TARGET vigen::runtime)
    message(FATAL_ERROR "vigen_add_stepper: targets vigen::vigen and vigen::runtime not found; "
                        "use find_package(vigen REQUIRED) first")
  endif()

  # The emitter would sanitise any other name (and then write other files):
  # accept only names it keeps as they are.  The rule is vigen_emit_identifier
  # (src/emit/names.c); the keyword list is src/emit/c_keywords.def, which an
  # installed package does not carry: the words below are that table's rows,
  # in its order, and change with it.
  set(keywords auto break case char const continue default do double else enum extern float for
      goto if inline int long register restrict return short signed sizeof static struct switch
      typedef union unsigned void volatile while bool true false asm typeof main)
  list(FIND keywords "${VAS_NAME}" keyword_index)
  if(NOT VAS_NAME MATCHES "^[A-Za-z][A-Za-z0-9_]*$" OR NOT keyword_index EQUAL -1)
    message(FATAL_ERROR "vigen_add_stepper: NAME '${VAS_NAME}' is not usable as a C identifier "
                        "prefix (letters, digits and '_', starting with a letter, not a keyword)")
  endif()

  if(NOT VAS_REAL)
    set(VAS_REAL double)
  endif()
  if(NOT VAS_REAL MATCHES "^(double|long-double|float128)$")
    message(FATAL_ERROR "vigen_add_stepper: REAL must be double, long-double or float128, not '${VAS_REAL}'")
  endif()

  if(VAS_OUTPUT_DIR)
    get_filename_component(outdir "${VAS_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  else()
    set(outdir "${CMAKE_CURRENT_BINARY_DIR}/vigen/${VAS_TARGET}")
  endif()
  if(VAS_SPEC)
    # the spec's tableau, generated into the build tree before it is emitted
    get_filename_component(spec "${VAS_SPEC}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(spec_base "${spec}" NAME)
    set(tableau "${outdir}/${VAS_NAME}.tableau.lua")
    add_custom_command(
      OUTPUT "${tableau}"
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${outdir}"
      COMMAND "$<TARGET_FILE:vigen::vigen>" generate "${spec}" --digits "${VAS_DIGITS}" -o "${tableau}" -q
      DEPENDS "${spec}" vigen::vigen
      COMMENT "vigen generate ${spec_base} --digits ${VAS_DIGITS}"
      VERBATIM)
  else()
    get_filename_component(tableau "${VAS_TABLEAU}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    # TABLEAU may name a method of vigen's library (vigen list) instead of a
    # file: vigen resolves the name when it emits, and the rule reruns when
    # vigen (and so its library) changes
    if(NOT EXISTS "${tableau}" AND VAS_TABLEAU MATCHES "^((published|generated)/)?[A-Za-z0-9_]+$")
      set(tableau "${VAS_TABLEAU}")
      set(tableau_is_name TRUE)
    endif()
  endif()

  set(extra)
  if(VAS_ALLOW_INEXACT)
    list(APPEND extra --allow-inexact)
  endif()
  if(VAS_BATCH)
    list(APPEND extra --batch)
  endif()
  if(VAS_VARIANT)
    if(NOT VAS_VARIANT MATCHES "^[a-z][a-z0-9_]*$")
      message(FATAL_ERROR "vigen_add_stepper: VARIANT must be a variant's name (prk, split), not '${VAS_VARIANT}'")
    endif()
    list(APPEND extra --variant ${VAS_VARIANT})
  endif()
  if(DEFINED VAS_DIM)
    if(NOT VAS_DIM MATCHES "^[1-9][0-9]*$")
      message(FATAL_ERROR "vigen_add_stepper: DIM must be a positive integer, not '${VAS_DIM}'")
    endif()
    list(APPEND extra --dim ${VAS_DIM})
  endif()
  if(tableau_is_name)
    set(deps vigen::vigen)
  else()
    set(deps "${tableau}" vigen::vigen)
  endif()
  if(vigen_TEMPLATE_DIR)
    # every variant's templates (templates/<variant>/*.in)
    file(GLOB templates "${vigen_TEMPLATE_DIR}/*/*.in")
    list(APPEND deps ${templates})
  endif()
  get_filename_component(tableau_base "${tableau}" NAME)

  add_custom_command(
    OUTPUT "${outdir}/${VAS_NAME}.c" "${outdir}/${VAS_NAME}.h"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${outdir}"
    COMMAND "$<TARGET_FILE:vigen::vigen>" emit "${tableau}" --name "${VAS_NAME}" --real "${VAS_REAL}"
            -o "${outdir}" -q ${extra}
    DEPENDS ${deps}
    COMMENT "vigen emit ${tableau_base} --name ${VAS_NAME} --real ${VAS_REAL}"
    VERBATIM)

  add_library(${VAS_TARGET} STATIC "${outdir}/${VAS_NAME}.c" "${outdir}/${VAS_NAME}.h")
  target_include_directories(${VAS_TARGET} PUBLIC "${outdir}")
  target_link_libraries(${VAS_TARGET} PUBLIC vigen::runtime)
  set_target_properties(${VAS_TARGET} PROPERTIES C_STANDARD 11 C_STANDARD_REQUIRED ON
    POSITION_INDEPENDENT_CODE ON)
  # no fused multiply-adds by contraction (GNU C mode allows it where the
  # target has FMA): the batched stepper, compiled without, must have the
  # scalar stepper's bits
  if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${VAS_TARGET} PRIVATE -ffp-contract=off)
  endif()
endfunction()
