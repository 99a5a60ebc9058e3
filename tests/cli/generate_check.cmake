# generate twice with the same arguments into two files: both runs exit 0, the files are
# byte-identical, and `check` accepts the level. Args: EXE, OUT (a prefix), ARGS (the
# generate options as a ;-list, without -o).
foreach(n 1 2)
  execute_process(COMMAND ${EXE} generate ${ARGS} -o ${OUT}.${n}.json
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "generate exited ${code}\n${out}${err}")
  endif()
endforeach()
file(SHA256 ${OUT}.1.json first)
file(SHA256 ${OUT}.2.json second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "the same seed gave different files: ${OUT}.1.json, ${OUT}.2.json")
endif()
execute_process(COMMAND ${EXE} check ${OUT}.1.json RESULT_VARIABLE code OUTPUT_VARIABLE out)
if(NOT code EQUAL 0 OR NOT out MATCHES "^ok ")
  message(FATAL_ERROR "check refused the generated level (exit ${code}):\n${out}")
endif()
