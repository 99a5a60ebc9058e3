# Runs EXE with the arguments after the script name, and checks the exit code is EXIT and that stdout+stderr
# match the regular expression PATTERN.
# The command line as on a machine with no display (CI): `artillery` with no arguments
# must print its verbs and the headless demo, not open a window a developer would see.
unset(ENV{DISPLAY})
unset(ENV{WAYLAND_DISPLAY})
set(ARGS "")
math(EXPR last "${CMAKE_ARGC} - 1")
set(collect OFF)
foreach(i RANGE 0 ${last})
  if(collect)
    list(APPEND ARGS "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" MATCHES "expect\\.cmake$")
    set(collect ON)
  endif()
endforeach()
execute_process(COMMAND ${EXE} ${ARGS}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT code EQUAL EXIT)
  message(FATAL_ERROR "exit code ${code}, expected ${EXIT}\n${all}")
endif()
string(REGEX MATCH "${PATTERN}" found "${all}")
if(NOT found)
  message(FATAL_ERROR "output does not match '${PATTERN}':\n${all}")
endif()
