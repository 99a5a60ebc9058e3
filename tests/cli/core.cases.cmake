# The overview and the particle-core verbs: solve, trajectory, spring.
# No arguments: the list of verbs, and never a stub.
cli_test(overview 0 "verbs:.*solve.*trajectory.*spring" "")
cli_test(unknown_verb 2 "unknown verb 'fly'" "fly")
# solve: the target practice example of Rabin (ed.), ch. 4.3, JSON, out of range, bad input.
cli_test(solve_target_practice 0 "39\\.0[0-9]*.*75\\.1[0-9]*|39\\.1.*75\\.2"
         "solve;--from;10,2;--to;50,20;--speed;30;--json")
cli_test(solve_out_of_range 0 "\"solutions\":\\[\\]" "solve;--from;0,0;--to;40,0;--speed;19;--json")
cli_test(solve_text 0 "low .*angle.*high .*angle" "solve;--from;0,0;--to;40,0;--speed;25")
cli_test(solve_bad_speed 2 "--speed expects a number" "solve;--from;0,0;--to;40,0;--speed;abc")
cli_test(solve_missing_to 2 "--to X,Y is required" "solve;--from;0,0;--speed;20")
cli_test(solve_bad_planet 2 "--planet expects one of earth" "solve;--from;0,0;--to;4,0;--speed;20;--planet;pluto")
cli_test(solve_help 0 "usage: artillery solve" "solve;--help")
# trajectory: exact integrators hit the closed form; drag has no closed form.
cli_test(trajectory_json 0 "\"closed_form\":\\{.*\"position_error_m\":[0-9.e-]+"
         "trajectory;--speed;30;--angle;45;--time;2;--integrator;rk4;--dt;0.01;--json")
cli_test(trajectory_drag 0 "\"closed_form\":null.*\"position_error_m\":null"
         "trajectory;--speed;30;--angle;45;--time;2;--cd;0.47;--diameter;0.1;--json")
cli_test(trajectory_bad_integrator 2 "--integrator expects one of explicit-euler"
         "trajectory;--speed;30;--angle;45;--time;2;--integrator;rk5")
cli_test(trajectory_bad_dt 2 "--dt expects a number in" "trajectory;--speed;30;--angle;45;--time;2;--dt;0")
cli_test(trajectory_unknown_option 2 "unknown option --sped" "trajectory;--sped;30;--speed;1;--angle;45;--time;2")
# A typo is reported as one, with the option meant, before a required option it hides.
cli_test(solve_typo_suggested 2 "unknown option --form .did you mean --from.." "solve;--form;0,0;--to;40,0;--speed;30")
# spring: energy and analytic solution.
cli_test(spring_json 0 "\"analytic_position\":.*\"energy_j\":|\"energy_j\":.*\"analytic_position\":"
         "spring;--k;100;--mass;1;--x0;0.1;--integrator;symplectic-euler;--dt;0.001;--time;1;--json")
cli_test(spring_bad_k 2 "--k expects a number" "spring;--k;-1;--mass;1;--x0;1;--time;1")
cli_test(spring_missing_mass 2 "--mass is required" "spring;--k;1;--x0;1;--time;1")
# Numbers in decimal notation only; answers that would not be finite numbers are refused;
# an option with an empty value, or an unknown one last on the line, says so.
cli_test(solve_hex_speed 2 "--speed expects a number in .*got '0x10'" "solve;--from;0,0;--to;40,0;--speed;0x10")
cli_test(solve_inf_speed 2 "--speed expects a number in .*got 'inf'" "solve;--from;0,0;--to;40,0;--speed;inf")
cli_test(solve_tiny_gravity 2 "at --gravity 1e-300 m/s\\^2 the high shot's flight time does not fit in a double"
         "solve;--from;10,2;--to;50,20;--speed;30;--gravity;1e-300")
cli_test(solve_small_gravity_low_shot 0 "low   angle   24\\.228 deg"
         "solve;--from;10,2;--to;50,20;--speed;30;--gravity;1e-9")
cli_test(solve_unknown_last 2 "unknown option --bogus" "solve;--from;0,0;--to;40,0;--speed;30;--bogus")
cli_test(solve_value_missing_last 2 "--speed needs a value" "solve;--from;0,0;--to;40,0;--speed")
cli_test(run_record_empty 2 "--record needs a value, got an empty one"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--record=")
