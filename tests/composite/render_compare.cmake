# pfrender-mpi against pfrender (tests/CMakeLists.txt, label mpi): the composited PNG and depth
# buffer must equal, byte for byte, what one pfrender process draws of the same scene -- the
# promise of sort-last compositing (PixelFlow's image composition, Molnar et al. 1992, cited in
# seed 003 section 1). KIND: cloud (a sphere cloud written as a scene file, drawn from the file),
# procedural (the same cloud made by each rank, the reference still pfrender on the file), or
# showcase (scenes/showcase.json). ARGS ('|'-separated) go to pfrender-mpi.
#   cmake -DMPIEXEC=... -DPFRENDER=... -DPFRENDER_MPI=... -DWORK=DIR -DNAME=N -DNP=P -DKIND=K
#         -DARGS=... -DSHOWCASE=... -P render_compare.cmake
string(REPLACE "|" ";" args "${ARGS}")
set(dir ${WORK}/${NAME})
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
set(size 160x96)
set(count 3000)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 100)
  string(REPLACE ";" " " shown "${ARGN}")
  message("command: ${shown}\nexit status: ${rc}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render_compare: '${shown}' failed")
  endif()
endfunction()

if(KIND STREQUAL "showcase")
  set(scene ${SHOWCASE})
else()
  set(scene ${dir}/cloud.json)
  run(${PFRENDER_MPI} --sphere-cloud ${count} --per-object 64 --write-scene ${scene} --size ${size})
endif()
run(${PFRENDER} ${scene} --size ${size} --threads 2 -o ${dir}/one.png --depth-out ${dir}/one.pfm)
if(KIND STREQUAL "procedural")
  set(input --sphere-cloud ${count} --per-object 64)
else()
  set(input ${scene})
endif()
run(${MPIEXEC} -np ${NP} --oversubscribe ${PFRENDER_MPI} ${input} --size ${size} --threads 1 ${args}
    -o ${dir}/composite.png --depth-out ${dir}/composite.pfm --stats)
foreach(f png pfm)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${dir}/one.${f} ${dir}/composite.${f} RESULT_VARIABLE differ)
  if(differ)
    message(FATAL_ERROR "render_compare: ${NAME}: composite.${f} differs from pfrender's one.${f} (in ${dir})")
  endif()
endforeach()
message("render_compare: ${NAME}: identical")
