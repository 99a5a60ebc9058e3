# Inputs that cannot run: check refuses them (exit 1), run and replay verify exit 2; the
# command line takes decimal numbers only and names what is wrong. (An empty argument
# cannot be passed through a CMake list; --record= is the same empty value.)
set(bad ${PROJECT_SOURCE_DIR}/tests/data/bad_levels)
cli_test(robust_check_unknown_projectile 1 "projectiles\\[0\\]: expected a weapon"
         "check;${bad}/projectile_unknown.json")
cli_test(robust_run_unknown_projectile 2 "projectiles\\[0\\]: expected a weapon"
         "run;${bad}/projectile_unknown.json;--ticks;10")
cli_test(robust_run_blocks_at_one_point 2 "expected blocks not to overlap"
         "run;${bad}/blocks_2000_at_one_point.json;--ticks;10")
cli_test(robust_check_deep_json 1 "arrays and objects nest deeper than 64 levels" "check;${bad}/deep_nesting_60000.json")
cli_test(robust_check_dev_zero 1 "/dev/zero: \\$: expected a regular file" "check;/dev/zero")
cli_test(robust_check_directory 1 "expected a regular file, got a directory" "check;${bad}")
cli_test(robust_check_invalid_byte 1 "\\\\xd7" "check;${bad}/invalid_utf8_byte.json")
cli_test(robust_check_fullest_level 0 "ok +.*max_every_collection.json"
         "check;${PROJECT_SOURCE_DIR}/tests/data/max_every_collection.json")
cli_test(robust_speed_hex 2 "--speed expects a number in \\[1e-09, 1e\\+06\\] m/s, got '0x10'"
         "solve;--from;0,0;--to;10,0;--speed;0x10")
cli_test(robust_ticks_leading_space 2 "--ticks expects a whole number in \\[1, [0-9]+\\], got ' 12'"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks; 12")
cli_test(robust_ticks_plus_sign 2 "--ticks expects a whole number in \\[1, [0-9]+\\], got '\\+12'"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;+12")
cli_test(robust_gravity_underflow 2 "flight time does not fit in a double"
         "solve;--from;0,0;--to;10,0;--speed;20;--gravity;1e-300")
cli_test(robust_record_empty 2 "--record needs a value, got an empty one"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--record=")
cli_test(robust_unknown_last_flag 2 "unknown option --bogus"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--bogus")
cli_test(robust_drop_help_rigid 0 "rigid: the same drop as a Box2D circle" "drop;--help")
