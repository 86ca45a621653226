# pfview's headless test: under Xvfb, pfview renders SCENE for a few frames in scripted mode and
# writes primflow's last frame; pfrender writes the same view; the two PNGs must be identical.
# Arguments: XVFB_RUN, PFVIEW, PFRENDER, SCENE (empty: the showcase), SIZE, WORK_DIR; optional
# KEYS (pfview's --keys, pressed before the first frame) and RENDER_ARGS (pfrender's arguments
# separated by '|', the settings the keys make: e.g. KEYS MMM with RENDER_ARGS --method|march).
file(MAKE_DIRECTORY ${WORK_DIR})
set(view_png ${WORK_DIR}/pfview.png)
set(render_png ${WORK_DIR}/pfrender.png)
file(REMOVE ${view_png} ${render_png} ${WORK_DIR}/Xauthority)
string(REPLACE "|" ";" render_args "${RENDER_ARGS}")
set(keys_arg "")
if(KEYS)
  set(keys_arg --keys ${KEYS})
endif()
# Under AddressSanitizer, Mesa's GL driver (dlopen'ed by the window's libGL, unloaded at exit)
# leaves allocations LeakSanitizer can only attribute to an "unknown module": leak checking is
# off for pfview's window process (the suite's other programs check primflow's own code).
execute_process(COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0
                        ${XVFB_RUN} -a -f ${WORK_DIR}/Xauthority ${PFVIEW} ${SCENE} --size ${SIZE} --frames 3
                        --screenshot ${view_png} ${keys_arg}
                RESULT_VARIABLE view_rc OUTPUT_VARIABLE view_out ERROR_VARIABLE view_err)
if(NOT view_rc EQUAL 0)
  message(FATAL_ERROR "pfview failed (${view_rc}):\n${view_out}${view_err}")
endif()
execute_process(COMMAND ${PFRENDER} ${SCENE} --size ${SIZE} ${render_args} -o ${render_png}
                RESULT_VARIABLE render_rc ERROR_VARIABLE render_err)
if(NOT render_rc EQUAL 0)
  message(FATAL_ERROR "pfrender failed (${render_rc}):\n${render_err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${view_png} ${render_png} RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "pfview's frame differs from pfrender's image: ${view_png} vs ${render_png}")
endif()
