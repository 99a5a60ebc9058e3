# The debug view headless, in both screens: with every draw toggle on, `artillery play
# --replay REPLAY --headless` (a level) and `artillery play --demo --headless` (the
# physics playground) must each give a real frame (png_check) that shows the toggles'
# colours (png_colours; the colours of ui/render/world_view.h), while the same frames
# without the toggles show none of them. Arguments: -DEXE= -DCHECK= -DCOLOURS= -DREPLAY=
# -DDIR= -DWARMUP= (seconds into the replay: a shell in the air over a castle).
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
set(toggles --velocities --forces --ghosts --contacts --cells --sleeping --models)

# Runs `artillery play ARGS` twice, with the toggles (NAME-on.png) and without
# (NAME-off.png), and checks that each of COLOURS (RRGGBB, opaque strokes) is in the
# first picture and not in the second.
function(check_toggles name colours)
  foreach(mode on off)
    set(extra)
    if(mode STREQUAL "on")
      set(extra ${toggles})
    endif()
    set(png ${DIR}/${name}-${mode}.png)
    execute_process(COMMAND ${EXE} play ${ARGN} ${extra} --headless --size 1280x720
                            --screenshot ${png}
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
    message("${out}${err}")
    if(NOT code EQUAL 0)
      message(FATAL_ERROR "artillery play ${ARGN} (${mode}) exited with ${code}")
    endif()
    execute_process(COMMAND ${CHECK} ${png} 1280 720 RESULT_VARIABLE code)
    if(NOT code EQUAL 0)
      message(FATAL_ERROR "${png} is not a frame of the game")
    endif()
    set(wanted)
    foreach(c ${colours})
      if(mode STREQUAL "on")
        list(APPEND wanted "${c}>=6")
      else()
        list(APPEND wanted "${c}<=2")
      endif()
    endforeach()
    execute_process(COMMAND ${COLOURS} ${png} ${wanted} RESULT_VARIABLE code)
    if(NOT code EQUAL 0)
      if(mode STREQUAL "on")
        message(FATAL_ERROR "${png} lacks a toggle's colour")
      else()
        message(FATAL_ERROR "${png} shows a toggle's colour without the toggles: the check proves nothing")
      endif()
    endif()
  endforeach()
endfunction()

# The castle: forces, velocities, contacts, the ghost's outline, the shell's ring
# (integrated), the blocks' outlines (rigid, awake and asleep) and the sleeping marker.
check_toggles(level "ff3df0;ffe14d;ff1f1f;f2d9ff;ff9b21;ff7ad0;8c5a7c;a98bff"
              --replay ${REPLAY} --warmup ${WARMUP} --frames 2)
# The playground: the chain's grid cells, the drag-free shell's closed-form ring, the
# ghost's error line, forces and velocities.
check_toggles(demo "3dff5a;3ce070;ff7a45;ff3df0;ffe14d"
              --demo --warmup 2 --frames 5)
