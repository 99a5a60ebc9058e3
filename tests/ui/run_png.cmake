# artillery run LEVEL --ticks 60 --png DIR --every 30 writes frame_000030.png and
# frame_000060.png, each a 1280x720 game frame (png_check). Arguments: -DEXE= -DCHECK=
# -DLEVEL= -DDIR=
file(REMOVE_RECURSE ${DIR})
execute_process(COMMAND ${EXE} run ${LEVEL} --ticks 60 --png ${DIR} --every 30
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
message("${out}${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "artillery run --png exited with ${code}")
endif()
foreach(tick 000030 000060)
  if(NOT EXISTS ${DIR}/frame_${tick}.png)
    message(FATAL_ERROR "missing ${DIR}/frame_${tick}.png")
  endif()
  execute_process(COMMAND ${CHECK} ${DIR}/frame_${tick}.png 1280 720 RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "frame_${tick}.png is not a game frame")
  endif()
endforeach()
file(GLOB frames ${DIR}/*.png)
list(LENGTH frames count)
if(NOT count EQUAL 2)
  message(FATAL_ERROR "expected 2 frames (every 30 ticks of 60), found ${count}")
endif()
