# artillery play --progress: the level select screen (the campaign) opens headless with
# the progress of a file; a check run reads it and never moves or writes it, even a
# damaged one (the message names the file and the JSON path); bad combinations refused.
cli_test(play_progress_select 0 "2 frames, [a-z]+ 640x360.*screenshot: .*play_select\\.png"
         "play;--progress;${PROJECT_SOURCE_DIR}/tests/data/progress/some_stars.json;--headless;--frames;2;--size;640x360;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_select.png")
cli_test(play_progress_missing 0 "1 frames, [a-z]+ 320x180"
         "play;--progress;${CMAKE_CURRENT_BINARY_DIR}/no_such_progress.json;--headless;--frames;1;--size;320x180;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_progress.png")
cli_test(play_progress_damaged 0 "1 frames.*damaged\\.json: \\$\\.levels\\.02_moon\\.json\\.stars: expected a whole number in \\[0, 3\\], got 7"
         "play;--progress;${PROJECT_SOURCE_DIR}/tests/data/progress/damaged.json;--headless;--frames;1;--size;320x180;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_progress.png")
cli_test(play_progress_with_demo 2 "--progress is for the levels: it cannot go with --demo or --replay"
         "play;--demo;--progress;x.json;--headless;--frames;1")
