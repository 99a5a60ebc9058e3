# artillery play --replay: the replay viewer drawn headless with the window's code
# and replay files it must refuse with the loader's one message (exit 2).
cli_test(play_replay_headless 0 "30 frames, [a-z]+ 640x360.*screenshot: .*play_replay\\.png"
         "play;--replay;${PROJECT_SOURCE_DIR}/tests/replays/05_castle.replay.json;--frames;30;--headless;--size;640x360;--warmup;9;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_replay.png")
cli_test(play_replay_bad_file 2 "artillery play: .*bad_level_hash\\.json: \\$\\.level\\.content_hash: expected 16 lowercase hex digits"
         "play;--replay;${PROJECT_SOURCE_DIR}/tests/data/bad_replays/bad_level_hash.json;--headless;--frames;1")
cli_test(play_replay_missing_level 2 "artillery play: .*missing_level\\.json: \\$: missing field \"level\""
         "play;--replay;${PROJECT_SOURCE_DIR}/tests/data/bad_replays/missing_level.json;--headless;--frames;1")
cli_test(play_replay_and_level 2 "give a LEVEL or --replay FILE, not both"
         "play;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--replay;${PROJECT_SOURCE_DIR}/tests/replays/05_castle.replay.json;--headless")
