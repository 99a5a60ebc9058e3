# artillery play --edit: the level editor opens on a level (or a new one), headless too,
# so it can be looked at without a display; the flag refuses what is not a level to edit.
cli_test(play_edit_headless 0 "2 frames, [a-z]+ 640x360.*screenshot: .*play_edit\\.png"
         "play;--edit;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--headless;--frames;2;--size;640x360;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_edit.png")
cli_test(play_edit_new_level 0 "1 frames, [a-z]+ 640x360.*screenshot: .*play_edit_new\\.png"
         "play;--edit;--headless;--frames;1;--size;640x360;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_edit_new.png")
cli_test(play_edit_with_sandbox 2 "--edit opens the level editor: it cannot go with --demo, --replay or --sandbox"
         "play;--edit;--sandbox;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--headless;--frames;1")
cli_test(play_edit_missing_level 2 "level file 'no_such_level.json' does not exist"
         "play;--edit;no_such_level.json;--headless;--frames;1")
