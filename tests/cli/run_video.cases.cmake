# artillery run --video: the match as a video, drawn headlessly like --png.
# tests/ui/video_writer_test.cpp decodes what the writer and the frame sink write.
cli_test(run_video_mp4_json 0
         "\"video\":{\"codec\":\"(h264|mpeg4)\",\"file\":\"[^\"]*run_video\\.mp4\",\"frames\":15,\"seconds\":0\\.5}"
         "run;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--replay;${PROJECT_SOURCE_DIR}/tests/replays/05_castle.replay.json;--ticks;60;--video;${CMAKE_CURRENT_BINARY_DIR}/run_video.mp4;--size;160x90;--json")
cli_test(run_video_gif 0 "video in .*run_video\\.gif \\(gif, 10 frames, 1\\.00 s\\)"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;120;--video;${CMAKE_CURRENT_BINARY_DIR}/run_video.gif;--fps;10;--size;96x54")
cli_test(run_video_bad_extension 2 "unknown format '\\.avi'; the file name must end in \\.mp4 or \\.gif"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--video;${CMAKE_CURRENT_BINARY_DIR}/run_video.avi")
cli_test(run_video_unwritable 2 "--video: cannot write '/nonexistent-folder/run_video\\.mp4': the folder '/nonexistent-folder' does not exist"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--video;/nonexistent-folder/run_video.mp4")
cli_test(run_video_odd_size 2 "even in both"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--video;${CMAKE_CURRENT_BINARY_DIR}/run_video_odd.mp4;--size;161x90")
cli_test(run_video_bad_fps 2 "--fps"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--video;${CMAKE_CURRENT_BINARY_DIR}/run_video_fps.mp4;--fps;61")
cli_test(run_video_fps_alone 2 "add --video FILE"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--fps;30")
cli_test(run_video_and_png 2 "give --png or --video, not both"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--png;${CMAKE_CURRENT_BINARY_DIR}/run_video_png;--video;${CMAKE_CURRENT_BINARY_DIR}/run_video_png.mp4")
# The video is a view: the castle replay's hash after 2 s is the same with it as without.
add_test(NAME cli.run_video_same_hash
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:artillery>
                 -DLEVEL=${PROJECT_SOURCE_DIR}/levels/05_castle.json
                 -DREPLAY=${PROJECT_SOURCE_DIR}/tests/replays/05_castle.replay.json
                 -DVIDEO=${CMAKE_CURRENT_BINARY_DIR}/run_video_hash.mp4
                 -P ${PROJECT_SOURCE_DIR}/tests/ui/run_video_hash.cmake)
