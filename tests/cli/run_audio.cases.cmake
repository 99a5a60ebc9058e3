# artillery run --audio FILE.wav: the match's sound track, synthesized from its events.
# tests/game/sound_test.cpp checks what is in it; here, the verb as a user runs it.
cli_test(run_audio_wav 0 "sound in .*run_audio_castle\\.wav \\(16-bit PCM WAV, stereo 48 kHz, 5\\.00 s\\)"
         "run;${PROJECT_SOURCE_DIR}/levels/05_castle.json;--autoplay;--ticks;600;--audio;${CMAKE_CURRENT_BINARY_DIR}/run_audio_castle.wav")
cli_test(run_audio_not_wav 2 "--audio writes 16-bit PCM WAV; the file name must end in \\.wav, got '[^']*track\\.mp3'"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--audio;${CMAKE_CURRENT_BINARY_DIR}/track.mp3")
cli_test(run_audio_no_folder 2 "cannot write '/nonexistent-folder/track\\.wav': the folder '/nonexistent-folder' does not exist"
         "run;${PROJECT_SOURCE_DIR}/levels/01_earth_basics.json;--ticks;10;--audio;/nonexistent-folder/track.wav")
# The header, the length to the sample, the same bytes twice, the same hash as without.
add_test(NAME cli.run_audio_wav_exact
         COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:artillery>
                 -DLEVEL=${PROJECT_SOURCE_DIR}/levels/05_castle.json
                 -DOUT=${CMAKE_CURRENT_BINARY_DIR}/run_audio
                 -P ${PROJECT_SOURCE_DIR}/tests/cli/run_audio.cmake)
