# generate: a seed gives the same bytes twice and a level `check` accepts; the JSON
# form; bad usage names the option and exits 2.
foreach(mode practice duel)
  add_test(NAME cli.generate_${mode}_same_bytes_and_checks
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:artillery>
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/generated_${mode}
                   "-DARGS=--seed;7;--mode;${mode};--difficulty;easy"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/generate_check.cmake)
endforeach()
cli_test(generate_json 0 "\"candidates\":1,.*\"hits\":\\[true,true\\],.*\"name\":\"Random duel 5 \\(hard\\)\",\"playable\":true,\"seed\":5"
         "generate;--seed;5;--mode;duel;--difficulty;hard;--output;${CMAKE_CURRENT_BINARY_DIR}/generated_json.json;--json")
cli_test(generate_text 0 "generated_text.json: \"Random practice 1 \\(easy\\)\", the solver reaches 3 stars in [0-9] shot\\(s\\) \\(candidate 1 of the seed\\)"
         "generate;--seed;1;--mode;practice;--difficulty;easy;-o;${CMAKE_CURRENT_BINARY_DIR}/generated_text.json")
cli_test(generate_help 0 "usage: artillery generate --seed N --mode practice\\|duel" "generate;--help")
cli_test(generate_no_seed 2 "artillery generate: give a seed, e.g. --seed 42" "generate;--mode;duel;-o;x.json")
cli_test(generate_bad_seed 2 "--seed expects a whole number in \\[0, 9223372036854775807\\], got '-3'" "generate;--seed;-3;--mode;duel;-o;x.json")
cli_test(generate_bad_mode 2 "--mode expects practice or duel, got 'sandbox'" "generate;--seed;1;--mode;sandbox;-o;x.json")
cli_test(generate_bad_difficulty 2 "--difficulty expects easy, normal or hard, got 'brutal'"
         "generate;--seed;1;--mode;duel;--difficulty;brutal;-o;x.json")
cli_test(generate_no_output 2 "name the output file with -o FILE" "generate;--seed;1;--mode;duel")
cli_test(generate_o_without_file 2 "-o needs a file name" "generate;--seed;1;--mode;duel;-o")
cli_test(generate_unknown_option 2 "unknown option --sed" "generate;--seed;1;--sed;2;--mode;duel;-o;x.json")
cli_test(generate_no_folder 2 "--output: cannot write '/nonexistent/dir/x.json': the folder '/nonexistent/dir' does not exist"
         "generate;--seed;1;--mode;duel;--difficulty;easy;-o;/nonexistent/dir/x.json")
cli_test(generate_unwritable 2 "--output: cannot write '/proc/x.json': the folder '/proc' does not take new files"
         "generate;--seed;1;--mode;duel;--difficulty;easy;-o;/proc/x.json")
