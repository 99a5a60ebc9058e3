# artillery run LEVEL --replay REPLAY --ticks 240 --json, without and with --video VIDEO:
# the final state hash must be the same (the video only reads the match). Arguments:
# -DEXE= -DLEVEL= -DREPLAY= -DVIDEO=
set(common run ${LEVEL} --replay ${REPLAY} --ticks 240 --json)
execute_process(COMMAND ${EXE} ${common} RESULT_VARIABLE code OUTPUT_VARIABLE plain ERROR_VARIABLE err
                TIMEOUT 120)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the run without --video exited with ${code}: ${err}")
endif()
file(REMOVE ${VIDEO})
execute_process(COMMAND ${EXE} ${common} --video ${VIDEO} --size 160x90
                RESULT_VARIABLE code OUTPUT_VARIABLE filmed ERROR_VARIABLE err TIMEOUT 120)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the run with --video exited with ${code}: ${err}")
endif()
string(JSON hashPlain GET "${plain}" final_hash)
string(JSON hashFilmed GET "${filmed}" final_hash)
string(JSON frames GET "${filmed}" video frames)
message("final hash ${hashPlain} without the video, ${hashFilmed} with it; ${frames} frames")
if(NOT hashPlain STREQUAL hashFilmed)
  message(FATAL_ERROR "writing a video changed the match: ${hashPlain} -> ${hashFilmed}")
endif()
if(NOT frames EQUAL 60 OR NOT EXISTS ${VIDEO})
  message(FATAL_ERROR "expected ${VIDEO} with 60 frames (2 s at 30 fps), got ${frames}")
endif()
