# artillery run --png: frames drawn headlessly with the window's drawing code.
# The run must succeed and say it rendered; tests/ui/run_png.cmake also checks the files.
cli_test(run_png 0 "Earth basics: 60 ticks.*rendering"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;60;--png;${CMAKE_CURRENT_BINARY_DIR}/run_png;--every;30")
cli_test(run_png_json 0 "\"render_ms\":[0-9.e+]+.*\"ticks\":60"
         "run;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--ticks;60;--png;${CMAKE_CURRENT_BINARY_DIR}/run_png_json;--every;60;--size;320x180;--no-hud;--json")
cli_test(run_png_bad_size 2 "--size expects WxH"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--png;${CMAKE_CURRENT_BINARY_DIR}/run_png_bad;--size;9x")
# The frames exist, have the size asked for and are pictures of a level.
add_test(NAME cli.run_png_frames
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:artillery> -DCHECK=$<TARGET_FILE:png_check>
                 -DLEVEL=${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json
                 -DDIR=${CMAKE_CURRENT_BINARY_DIR}/run_png_frames
                 -P ${PROJECT_SOURCE_DIR}/tests/ui/run_png.cmake)
