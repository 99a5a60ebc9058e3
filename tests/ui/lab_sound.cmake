# The physics lab in its window under a virtual X display is heard: SDL's disk driver
# writes what the sound card would play to a file, and the first shot's report (0.1 s in)
# must be in it. Arguments: -DXVFB_RUN= -DEXE= -DRAW=
file(REMOVE ${RAW})
execute_process(COMMAND ${CMAKE_COMMAND} -E env SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE=${RAW}
                        ${XVFB_RUN} -a -s "-screen 0 960x540x24"
                        ${EXE} play --demo --frames 300 --size 960x540
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
message("${out}${err}")
if(NOT code EQUAL 0 OR NOT "${out}" MATCHES "sdl-window")
  message(FATAL_ERROR "artillery play --demo under Xvfb exited with ${code} or fell back to headless")
endif()
if("${err}" MATCHES "playing silent")
  message(FATAL_ERROR "the lab found no sound device (SDL's disk driver)")
endif()
if(NOT EXISTS ${RAW})
  message(FATAL_ERROR "the lab wrote no sound")
endif()
# The first half second: float stereo at 48 kHz, 8 bytes a frame.
file(READ ${RAW} head LIMIT 192000 HEX)
if(NOT head MATCHES "[1-9a-f]")
  message(FATAL_ERROR "the lab was silent: no report of the first shot")
endif()
