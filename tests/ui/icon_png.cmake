# `artillery icon`: the icon drawn headless at 256 px shows the sky, the hill, the shell
# and the blocks in their colours (ui/icon/game_icon.cpp), and leaves the corners outside
# the rounded square as cleared (transparent: RGB 0 in png_colours, which reads RGB);
# at 16 px it is still a picture. Arguments: -DEXE= -DCOLOURS= -DDIR=
file(MAKE_DIRECTORY ${DIR})
foreach(size 256 16)
  file(REMOVE ${DIR}/icon_${size}.png)
  execute_process(COMMAND ${EXE} icon --size ${size} --png ${DIR}/icon_${size}.png --json
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(NOT code EQUAL 0 OR NOT out MATCHES "\"size\":${size}" OR NOT EXISTS ${DIR}/icon_${size}.png)
    message(FATAL_ERROR "artillery icon --size ${size} exited ${code}:\n${out}${err}")
  endif()
endforeach()
# 256 px: the corners cut off by the rounded square are (4 - pi) (0.18 x 256)^2 = 1820
# pixels; sky, ground, shell and blocks are each hundreds at least.
execute_process(COMMAND ${COLOURS} ${DIR}/icon_256.png 000000>=1500 24406b>=2000 4f8f3a>=5000
                        e4572e>=200 c9a66b>=20
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the 256 px icon lacks a part:\n${out}${err}")
endif()
execute_process(COMMAND ${COLOURS} ${DIR}/icon_16.png 000000>=4 4f8f3a>=20
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the 16 px icon lacks its corners or its hill:\n${out}${err}")
endif()
