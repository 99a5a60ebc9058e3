# artillery play --sandbox: any level opens as a sandbox (a `sandbox` command at its
# first tick, so the session replays), and the flag refuses what is not a level.
cli_test(play_sandbox_headless 0 "3 frames, [a-z]+ 640x360.*screenshot: .*play_sandbox\\.png"
         "play;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--sandbox;--frames;3;--headless;--size;640x360;--screenshot;${CMAKE_CURRENT_BINARY_DIR}/play_sandbox.png")
cli_test(play_sandbox_with_demo 2 "--sandbox opens a level: it cannot go with --demo or --replay"
         "play;--demo;--sandbox;--headless;--frames;1")
