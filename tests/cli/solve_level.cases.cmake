# solve-level: every shipped level must reach three stars (a level the solver cannot win
# fails here); the JSON form; a recorded solution that replay verify accepts; a level
# that cannot be won fails; bad usage.
file(GLOB SHIPPED_LEVELS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/levels/*.json)
list(FILTER SHIPPED_LEVELS EXCLUDE REGEX "/campaign\\.json$") # the chapters, not a level
# The arsenal's levels, each with the weapon its three stars need: solved with it (three
# stars, and the best game fires it) and without it (fewer stars), by solve_weapon.cmake.
set(WEAPON_LEVELS
    38_into_the_gale mortar
    39_crows_nests airburst
    40_scatter cluster
    41_steel_causeway bouncer
    42_round_the_corner grenade
    43_downhill roller
    44_water_tower sticky
    45_under_the_lid digger)
list(LENGTH WEAPON_LEVELS pairs)
math(EXPR lastPair "${pairs} - 1")
foreach(i RANGE 0 ${lastPair} 2)
  math(EXPR w "${i} + 1")
  list(GET WEAPON_LEVELS ${i} name)
  list(GET WEAPON_LEVELS ${w} weapon)
  list(FILTER SHIPPED_LEVELS EXCLUDE REGEX "/${name}\\.json$") # solved here, with and without
  add_test(NAME solve_level.${name}.${weapon}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:artillery>
                   -DLEVEL=${PROJECT_SOURCE_DIR}/levels/${name}.json -DWEAPON=${weapon}
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/solve_weapon
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/solve_weapon.cmake
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(solve_level.${name}.${weapon} PROPERTIES TIMEOUT 170)
endforeach()
foreach(level ${SHIPPED_LEVELS})
  get_filename_component(name ${level} NAME_WE)
  add_test(NAME solve_level.${name}
           COMMAND artillery solve-level ${level} --require-stars 3
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(solve_level.${name} PROPERTIES TIMEOUT 170)
endforeach()
cli_test(solve_level_json 0 "^\\{\"commands\":\\[\\{.*\"cmd\":\"fire\".*\"max_score\":300,.*\"shots\":1,\"star_scores\":\\[50,180,255\\],\"stars\":3\\}"
         "solve-level;--json;${PROJECT_SOURCE_DIR}/levels/09_tunnelling.json")
cli_test(solve_level_unwinnable 1 "0 stars, score 0 of 150.*fewer than the 3 required"
         "solve-level;${PROJECT_SOURCE_DIR}/tests/data/levels_unwinnable/boxed_target.json;--require-stars;3")
cli_test(solve_level_duel 0 "a duel has no stars; one shot from each side hits the other: cannon 1 yes, cannon 2 yes"
         "solve-level;${PROJECT_SOURCE_DIR}/levels/10_duel.json")
cli_test(solve_level_duel_json 0 "^\\{\"hits\":\\[true,true\\],\"mode\":\"duel\",\"playable\":true\\}"
         "solve-level;--json;${PROJECT_SOURCE_DIR}/levels/10_duel.json")
cli_test(solve_level_duel_walled 1 "cannon 1 no, cannon 2 no.*a side that cannot hit makes no duel"
         "solve-level;${PROJECT_SOURCE_DIR}/tests/data/levels_unwinnable/walled_duel.json;--require-stars;3")
cli_test(solve_level_no_level 2 "name one level file" "solve-level")
cli_test(solve_level_bad_level 2 "wrong_version.json: \\$\\.format"
         "solve-level;${PROJECT_SOURCE_DIR}/tests/data/bad_levels/wrong_version.json")
add_test(NAME cli.solve_level_record_verifies
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:artillery>
                 -DLEVEL=${PROJECT_SOURCE_DIR}/levels/04_bank_shots.json
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/solve_level_04.replay.json
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/solve_record.cmake)
