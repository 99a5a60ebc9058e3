# drop: the bounce experiment of Claypool, Game Physics (ch. 10): apex k = e^(2k) H, and its bad input.
# Golf (e = 0.858) from 1 m: 0.736164, 0.541937..., 0.398954... m, with the default
# velocity Verlet and with RK4 at dt = 1/60 s (time-of-impact response: no dt error).
cli_test(drop_golf_json 0
         "\"bounces\":\\[\\{\"apex_m\":0\\.73616(39|40)[0-9]*,\"expected_apex_m\":0\\.73616(39|40).*\"expected_apex_m\":0\\.5419374[0-9]*.*\"expected_apex_m\":0\\.3989548"
         "drop;--height;1;--material;golf;--json")
cli_test(drop_rk4_coarse 0 "\"apex_m\":0\\.50694[34][0-9]*,\"expected_apex_m\":0\\.506944"
         "drop;--height;1;--material;tennis;--integrator;rk4;--dt;0.0166666667;--bounces;1;--json")
cli_test(drop_cor_text 0 "e = 0\\.5 against the floor.*1 +0\\.25 +0\\.25 .*2 +0\\.0625[0-9]* +0\\.0625 "
         "drop;--height;1;--cor;0.5;--bounces;2")
cli_test(drop_discrete 0 "overlap \\(bisection\\) detection.*1 +0\\.50694[34][0-9]* +0\\.506944 "
         "drop;--height;1;--material;tennis;--discrete;--bounces;1")
cli_test(drop_plastic 0 "came to rest" "drop;--height;1;--material;perfectly-plastic")
cli_test(drop_euler_shows_error 0 "explicit-euler.*1 +0\\.278[0-9]* +0\\.25 +\\+11\\.2"
         "drop;--height;1;--cor;0.5;--integrator;explicit-euler;--dt;0.0166666667;--bounces;1")
cli_test(drop_help 0 "usage: artillery drop --height H \\(--cor E \\| --material NAME\\)" "drop;--help")
cli_test(drop_rigid 0 "\"apex_m\".*\"model\":\"rigid\"" "drop;--height;1;--material;golf;--model;rigid;--json")
cli_test(drop_bad_model 2 "--model expects particle or rigid" "drop;--height;1;--material;golf;--model;soft")
cli_test(drop_bad_material 2 "--material expects one of default, floor, .*golf" "drop;--height;1;--material;pluto")
cli_test(drop_both_cor_and_material 2 "give exactly one of --cor E or --material NAME"
         "drop;--height;1;--cor;0.5;--material;golf")
cli_test(drop_neither 2 "give exactly one of --cor E or --material NAME" "drop;--height;1")
cli_test(drop_bad_cor 2 "--cor expects a number in" "drop;--height;1;--cor;1.5")
cli_test(drop_missing_height 2 "--height is required" "drop;--material;golf")
cli_test(drop_bad_bounces 2 "--bounces" "drop;--height;1;--material;golf;--bounces;0")
cli_test(drop_too_many_steps 2 "more than 5e7 steps" "drop;--height;10000;--material;golf;--dt;0.000001")
cli_test(drop_moon 0 "\"apex_m\":0\\.73616" "drop;--height;1;--material;golf;--planet;moon;--bounces;1;--json")
# The penalty model: it sinks centimetres into the floor, and at w dt > 2 it explodes.
cli_test(drop_penalty 0 "penalty contact at 10 Hz: the ball sank up to 0\\.0688[0-9]* m.*1 +0\\.72746"
         "drop;--height;1;--material;golf;--contact;penalty")
cli_test(drop_penalty_unstable 0 "w dt = 2\\.09; unstable above 2.*1 +7\\.8[0-9]* +0\\.736164 +\\+963"
         "drop;--height;1;--material;golf;--contact;penalty;--stiffness;40;--bounces;1")
cli_test(drop_bad_contact 2 "--contact expects impulse or penalty" "drop;--height;1;--material;golf;--contact;soft")
