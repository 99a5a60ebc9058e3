# Runs the real window under a virtual X display for a few frames, saves the last one,
# and checks the picture is a game frame (png_check). Arguments: -DXVFB_RUN= -DEXE=
# -DCHECK= -DPNG=
file(REMOVE ${PNG})
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24"
                        ${EXE} play --frames 30 --screenshot ${PNG}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
message("${out}${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "artillery play under Xvfb exited with ${code}")
endif()
if(NOT "${out}" MATCHES "sdl-window")
  message(FATAL_ERROR "the frame was not drawn by the window (fell back to headless?)")
endif()
execute_process(COMMAND ${CHECK} ${PNG} 1280 720 RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the window's screenshot is not a game frame")
endif()
# And a level played in the window: the castle after 30 frames (cannon, blocks, HUD).
string(REPLACE ".png" "_castle.png" CASTLE_PNG ${PNG})
file(REMOVE ${CASTLE_PNG})
get_filename_component(LEVELS ${CMAKE_CURRENT_LIST_DIR}/../../levels ABSOLUTE)
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x720x24"
                        ${EXE} play ${LEVELS}/05_castle.json --frames 30 --screenshot ${CASTLE_PNG}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
message("${out}${err}")
if(NOT code EQUAL 0 OR NOT "${out}" MATCHES "sdl-window")
  message(FATAL_ERROR "artillery play 05_castle.json under Xvfb exited with ${code} or fell back to headless")
endif()
execute_process(COMMAND ${CHECK} ${CASTLE_PNG} 1280 720 RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the castle level's window screenshot is not a game frame")
endif()
