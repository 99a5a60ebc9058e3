# check: shipped levels are valid; a bad file fails with file, JSON path and expectation.
cli_test(check_shipped 0 "ok +.*01_earth_basics.json" "check;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;${PROJECT_SOURCE_DIR}/levels/10_duel.json")
cli_test(check_bad 1 "FAIL +.*wrong_version.json: \\$\\.format: this game reads level format 1"
         "check;${PROJECT_SOURCE_DIR}/tests/data/bad_levels/wrong_version.json")
cli_test(check_json 1 "\"ok\":false.*\"path\":\"\\$\\.cannons\\[0\\]\\.speed_mps\""
         "check;--json;${PROJECT_SOURCE_DIR}/tests/data/bad_levels/cannon_speed_over_max.json")
cli_test(check_no_files 2 "name at least one level file" "check")
# The campaign file is checked against the levels folder beside it.
cli_test(check_campaign 0 "ok +.*campaign.json  campaign: 9 chapter\\(s\\), 44 level\\(s\\), 1 outside"
         "check;${PROJECT_SOURCE_DIR}/levels/campaign.json")
cli_test(check_campaign_bad 1 "FAIL +.*campaign.json: \\$\\.chapters\\[0\\]\\.levels\\[0\\]: the level does not load.*FAIL +.*campaign.json: \\$\\.chapters: the level loose.json is in no chapter"
         "check;${PROJECT_SOURCE_DIR}/tests/data/bad_campaign/campaign.json")
