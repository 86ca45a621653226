# Driver for the install tests (label "install"): configures, builds and runs a consumer
# project (tests/consumer in C++, tests/consumer/c in C) in a scratch directory.
#   MODE=build_tree  find_package(primflow) from the build tree (-Dprimflow_DIR=<build>)
#   MODE=install     cmake --install <build> --prefix <scratch>/prefix, then find_package from
#                    there (-DCMAKE_PREFIX_PATH); also checks that the pkg-config file is installed
# PKG_CONFIG (pkg-config's path; C consumers): the consumer's main.c is also compiled and linked
# by the C compiler with `pkg-config --cflags --libs primflow`, with and without --static, from
# the build tree's primflow-uninstalled.pc or the installed primflow.pc, and run.
# Other inputs: CONSUMER_SOURCE, PRIMFLOW_BUILD_DIR, WORK_DIR, GENERATOR, CXX_COMPILER,
# C_COMPILER, BUILD_TYPE, LIBDIR, SANITIZE (the consumer is built with the same sanitizers as
# the library it links, or it would not link).
foreach(v CONSUMER_SOURCE PRIMFLOW_BUILD_DIR WORK_DIR MODE)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: ${v} is not set")
  endif()
endforeach()

function(run)
  string(REPLACE ";" " " shown "${ARGN}")
  message("run.cmake: ${shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run.cmake: FAILED (exit status ${rc}): ${shown}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

set(config_args -S ${CONSUMER_SOURCE} -B ${WORK_DIR}/build)
if(GENERATOR)
  list(APPEND config_args -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND config_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(C_COMPILER)
  list(APPEND config_args -DCMAKE_C_COMPILER=${C_COMPILER})
endif()
if(BUILD_TYPE)
  list(APPEND config_args -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
endif()
set(sanitize_flags "")
if(SANITIZE)
  set(sanitize_flags -fsanitize=${SANITIZE})
  list(APPEND config_args "-DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE}" "-DCMAKE_C_FLAGS=-fsanitize=${SANITIZE}"
                          "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE}")
endif()

if(MODE STREQUAL "build_tree")
  list(APPEND config_args -Dprimflow_DIR=${PRIMFLOW_BUILD_DIR})
elseif(MODE STREQUAL "install")
  set(prefix ${WORK_DIR}/prefix)
  run(${CMAKE_COMMAND} --install ${PRIMFLOW_BUILD_DIR} --prefix ${prefix})
  if(NOT LIBDIR)
    set(LIBDIR lib)
  endif()
  foreach(f ${LIBDIR}/pkgconfig/primflow.pc ${LIBDIR}/cmake/primflow/primflowConfig.cmake
            include/primflow/gl.h include/primflow/context.h include/primflow/gl_mangle.h)
    if(NOT EXISTS ${prefix}/${f})
      message(FATAL_ERROR "run.cmake: not installed: ${prefix}/${f}")
    endif()
  endforeach()
  # Nothing may be found from the build tree: only the prefix.
  list(APPEND config_args -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
else()
  message(FATAL_ERROR "run.cmake: unknown MODE '${MODE}'")
endif()

run(${CMAKE_COMMAND} ${config_args})
if(MODE STREQUAL "install")
  # The package must have come from the prefix, not from the build tree.
  file(STRINGS ${WORK_DIR}/build/CMakeCache.txt found REGEX "^primflow_DIR:")
  string(FIND "${found}" "${prefix}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "run.cmake: primflow was not found in the install prefix: ${found}")
  endif()
endif()
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/app)

if(PKG_CONFIG)
  if(MODE STREQUAL "build_tree")
    set(pc_path ${PRIMFLOW_BUILD_DIR}/pkgconfig)
  else()
    set(pc_path ${prefix}/${LIBDIR}/pkgconfig)
  endif()
  foreach(static "" "--static")
    execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pc_path}
                            ${PKG_CONFIG} --cflags --libs ${static} primflow
                    RESULT_VARIABLE rc OUTPUT_VARIABLE flags ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "run.cmake: pkg-config ${static} primflow failed: ${err}")
    endif()
    separate_arguments(flags UNIX_COMMAND "${flags}")
    run(${C_COMPILER} -std=c99 -pedantic -Wall -Wextra -Werror ${sanitize_flags} ${CONSUMER_SOURCE}/main.c ${flags}
        -o ${WORK_DIR}/app_pkgconfig${static})
    run(${WORK_DIR}/app_pkgconfig${static})
  endforeach()
endif()
message("run.cmake: ok (${MODE})")
