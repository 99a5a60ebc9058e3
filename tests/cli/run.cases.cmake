# run and replay verify: headless games from scripts and replays, and bad input.
set(levels ${PROJECT_SOURCE_DIR}/levels)
set(replays ${PROJECT_SOURCE_DIR}/tests/replays)
cli_test(run_script 0 "fired.*score [0-9]+, 3 shot"
         "run;${levels}/11_sandbox.json;--commands;${replays}/sandbox_script.json;--ticks;3000")
cli_test(run_json 0 "\"events\":\\[.*\"final_hash\":\"[0-9a-f]+\".*\"sim_ms\".*\"ticks\":600"
         "run;${levels}/01_earth_basics.json;--autoplay;--ticks;600;--json")
cli_test(run_replay_of_another_level 2 "recorded on another level"
         "run;${levels}/02_moon.json;--replay;${replays}/01_earth_basics.replay.json")
cli_test(run_replay_and_autoplay 2 "a --replay already has its turns"
         "run;${levels}/01_earth_basics.json;--replay;${replays}/01_earth_basics.replay.json;--autoplay")
cli_test(run_bad_difficulty 2 "--difficulty expects easy, normal or hard"
         "run;${levels}/01_earth_basics.json;--difficulty;insane")
cli_test(run_bad_commands 2 "bad_commands/ticks_backwards.json: \\$\\[1\\]\\.tick: expected ticks in order"
         "run;${levels}/01_earth_basics.json;--commands;${PROJECT_SOURCE_DIR}/tests/data/bad_commands/ticks_backwards.json")
cli_test(run_no_level 2 "name one level file" "run")
cli_test(replay_verify_json 0 "\"first_divergent_tick\":null,\"ok\":true"
         "replay;verify;${replays}/01_earth_basics.replay.json;--json")
cli_test(replay_verify_bad_file 2 "bad_replays/wrong_version.json: \\$\\.version: this game reads replay version 1"
         "replay;verify;${PROJECT_SOURCE_DIR}/tests/data/bad_replays/wrong_version.json")
cli_test(replay_verify_usage 2 "usage is: artillery replay verify FILE" "replay;check;x.json")
# The fired event names the model that flies the shell; the landed event measures it
# against the closed form (explicit Euler at 30 Hz flies g dt t / 2 high and lands 0.69 m long).
cli_test(run_json_model_and_landing 0
         "\"kind\":\"fired\",\"model\":\"explicit-euler\".*\"closed_form_error_m\":0\\.69[0-9]*,\"kind\":\"landed\""
         "run;${levels}/12_first_shot.json;--commands;${PROJECT_SOURCE_DIR}/tests/data/first_shot_euler_30hz.json;--ticks;200;--json")
# The verdict of a shot flown by an integrator where the closed form is exact carries the
# comparison, in the words the screen shows.
cli_test(run_json_verdict_carries_the_exact_path 0
         "\"kind\":\"verdict\"[^}]*\"text\":\"missed by [0-9.]+ m, [a-z]+; explicit Euler, 30 Hz: 0\\.69 m long of the exact path; energy \\+1\\.5 %\""
         "run;${levels}/12_first_shot.json;--commands;${PROJECT_SOURCE_DIR}/tests/data/first_shot_euler_30hz.json;--ticks;600;--json")
