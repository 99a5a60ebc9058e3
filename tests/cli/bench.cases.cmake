# bench: speed against accuracy. Tiny sweeps (--quick) so each case takes a few seconds;
# the default and --full sweeps are for people (make charts), not for the suite.
set(BENCH_OUT ${CMAKE_CURRENT_BINARY_DIR})
cli_test(bench_help 0 "usage: artillery bench work-precision.*--tolerance M" "bench;--help")
cli_test(bench_listed 0 "bench +speed against accuracy" "")
cli_test(bench_missing_subcommand 2 "which bench\\? expected work-precision, stability, scaling or choose" "bench")
cli_test(bench_unknown_subcommand 2 "unknown bench 'speed'" "bench;speed")
cli_test(bench_bad_scene 2 "--scene expects one of projectile-drag, spring, orbit, pendulum, cloth \\(got 'moon'\\)"
         "bench;work-precision;--scene;moon;--csv;${BENCH_OUT}/x.csv;--png;${BENCH_OUT}/x.png")
cli_test(bench_missing_csv 2 "--csv FILE is required" "bench;stability;--png;${BENCH_OUT}/x.png")
cli_test(bench_missing_folder 2 "--png: cannot write '/no/such/folder/s.png': the folder '/no/such/folder' does not exist"
         "bench;scaling;--csv;${BENCH_OUT}/x.csv;--png;/no/such/folder/s.png")
cli_test(bench_full_and_quick 2 "--full and --quick cannot be combined"
         "bench;stability;--full;--quick;--csv;${BENCH_OUT}/x.csv;--png;${BENCH_OUT}/x.png")
cli_test(bench_unknown_option 2 "unknown option --scen"
         "bench;stability;--scen;spring;--csv;${BENCH_OUT}/x.csv;--png;${BENCH_OUT}/x.png")
# An unknown option before another one does not take that one as its value.
cli_test(bench_unknown_option_before_another 2 "unknown option --bogus"
         "bench;scaling;--bogus;--csv;${BENCH_OUT}/x.csv;--png;${BENCH_OUT}/x.png")
cli_test(bench_option_without_its_value 2 "--csv needs a value"
         "bench;scaling;--csv;--png;${BENCH_OUT}/x.png")
cli_test(bench_choose_missing_tolerance 2 "--tolerance is required" "bench;choose;--scene;spring")
cli_test(bench_choose_bad_tolerance 2 "--tolerance expects a number" "bench;choose;--scene;spring;--tolerance;-1")
# Good input: the figures are printed and the files written.
cli_test(bench_work_precision_spring 0
         "spring \\(analytic.*rk4 +4 +[34]\\.[0-9]+.*cheapest within 1e-02 m: [a-z0-9-]+ +dt.*wrote .*wp_spring\\.csv and .*wp_spring\\.png"
         "bench;work-precision;--scene;spring;--quick;--csv;${BENCH_OUT}/wp_spring.csv;--png;${BENCH_OUT}/wp_spring.png")
cli_test(bench_work_precision_json 0
         "\"scenes\":\\[\\{\"cheapest\":\\[\\{\"cpu_s_per_sim_s\":[0-9.e-]+,\"dt_s\":[0-9.e-]+,\"error_m\":[0-9.e-]+,\"integrator\":\"[a-z0-9-]+\",\"tolerance_m\":0\\.01\\}"
         "bench;work-precision;--scene;orbit;--quick;--json;--csv;${BENCH_OUT}/wp_orbit.csv;--png;${BENCH_OUT}/wp_orbit.png")
cli_test(bench_stability_quick 0
         "explicit-euler +0 +0 +agree.*symplectic-euler +(1\\.99[0-9]*|2) +2 .*rk4 +2\\.8[0-9]* +2\\.828.*implicit-euler +inf +inf +agree"
         "bench;stability;--quick;--csv;${BENCH_OUT}/stab.csv;--png;${BENCH_OUT}/stab.png")
cli_test(bench_scaling_quick 0
         "1-minute load average before the run  \\[load [0-9.]+\\].*flight .*\\[load [0-9.]+\\].*pile of 200 balls, ticks 61-[0-9]+, one run: particles .*faster  \\[load.*against Box2D at the size it is tuned for \\(every length x10, no time of impact\\): [0-9.e-]+ ms/step .*faster.*heap \\(staggered rows\\) of 200 balls, ticks 61-[0-9]+, one run: particles .*faster  \\[load.*2000 in flight, symplectic-euler: update [0-9.e-]+ ms/step, reference of its arithmetic \\([124] lanes\\) [0-9.e-]+ ms: [0-9.]+x.*92 B/particle moved: update [0-9.e+]+ GB/s, reference [0-9.e+]+ GB/s, memcpy of as many bytes [0-9.e+]+ GB/s.*2000 in flight, velocity-verlet.*20000 in flight, velocity-verlet.*replay 01_earth_basics.replay.json +4800 ticks: slowest seek.*cloth 64x64, 8 sub-steps: [0-9.]+ ms"
         "bench;scaling;--quick;--replays;${PROJECT_SOURCE_DIR}/tests/replays;--csv;${BENCH_OUT}/scal.csv;--png;${BENCH_OUT}/scal.png")
# Into a docs/ folder with --under-load whatever the load is: written, and marked.
file(MAKE_DIRECTORY ${BENCH_OUT}/docs)
cli_test(bench_scaling_docs_under_load 0
         "1-minute load average before the run  \\[load [0-9.]+\\]  \\(taken under load: --under-load\\).*wrote .*docs/scal.csv and .*docs/scal.png"
         "bench;scaling;--quick;--under-load;--replays;${PROJECT_SOURCE_DIR}/tests/replays;--csv;${BENCH_OUT}/docs/scal.csv;--png;${BENCH_OUT}/docs/scal.png")
cli_test(bench_scaling_missing_replays 2 "--replays: folder '.*no_such_folder' does not exist"
         "bench;scaling;--quick;--replays;${BENCH_OUT}/no_such_folder;--csv;${BENCH_OUT}/scal.csv;--png;${BENCH_OUT}/scal.png")
cli_test(bench_choose_spring 0
         "spring within 0\\.001 m: [a-z0-9-]+ at dt = [0-9.e-]+ s \\([0-9]+ sub-steps per 1/120 s tick\\).*measured error [0-9.e-]+ m, cost"
         "bench;choose;--scene;spring;--tolerance;1e-3;--quick")
cli_test(bench_choose_impossible 1 "no integrator and dt of the sweep is within 1e-15 m"
         "bench;choose;--scene;pendulum;--tolerance;1e-15;--quick")
