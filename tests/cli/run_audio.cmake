# artillery run LEVEL --autoplay --ticks 600 --audio F.wav, twice, and once without:
# the WAV's header says 16-bit PCM stereo at 48 kHz and holds exactly 600 ticks of sound
# (400 samples each at 120 Hz), the two files are byte-identical, and the final hash is
# the same with the sound track as without. An empty file name is refused with exit 2.
# Arguments: -DEXE= -DLEVEL= -DOUT= (a folder)
set(common run ${LEVEL} --autoplay --ticks 600 --json)
function(run_ok out_var)
  execute_process(COMMAND ${EXE} ${common} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err TIMEOUT 120)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "run ${ARGN} exited with ${code}: ${err}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${OUT})
file(REMOVE ${OUT}/a.wav ${OUT}/b.wav)
run_ok(first --audio ${OUT}/a.wav)
run_ok(second --audio ${OUT}/b.wav)
run_ok(plain)

string(JSON frames GET "${first}" audio frames)
if(NOT frames EQUAL 240000)
  message(FATAL_ERROR "expected 240000 frames (600 ticks x 400 samples), got ${frames}")
endif()
file(SIZE ${OUT}/a.wav size)
if(NOT size EQUAL 960044) # 44-byte header + 240000 frames x 2 channels x 2 bytes
  message(FATAL_ERROR "expected a 960044-byte WAV, got ${size} bytes")
endif()
file(READ ${OUT}/a.wav header LIMIT 44 HEX)
# RIFF <size> WAVE "fmt " 16 PCM(1) 2 channels 48000 Hz 192000 B/s align 4, 16 bits "data" <size>
set(expected "5249464624a60e0057415645666d7420100000000100020080bb000000ee0200040010006461746100a60e00")
if(NOT header STREQUAL expected)
  message(FATAL_ERROR "WAV header\n  ${header}\nexpected\n  ${expected}")
endif()
file(SHA256 ${OUT}/a.wav hashA)
file(SHA256 ${OUT}/b.wav hashB)
if(NOT hashA STREQUAL hashB)
  message(FATAL_ERROR "the same run gave two different WAV files")
endif()
string(JSON hashPlain GET "${plain}" final_hash)
string(JSON hashHeard GET "${first}" final_hash)
if(NOT hashPlain STREQUAL hashHeard)
  message(FATAL_ERROR "the sound track changed the match: ${hashPlain} -> ${hashHeard}")
endif()

execute_process(COMMAND ${EXE} run ${LEVEL} --ticks 10 --audio ""
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "--audio needs a value, got an empty one")
  message(FATAL_ERROR "--audio '' gave exit ${code}: ${out}${err}")
endif()
message("600 ticks -> ${frames} frames, ${size} bytes, identical twice, hash ${hashPlain}")
