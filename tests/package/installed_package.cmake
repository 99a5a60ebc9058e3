# The Debian package as a player gets it: unpacked into a temporary root (dpkg-deb -x,
# no root rights needed), then the installed game is run from `/`, so nothing can come
# from the source tree or the working folder:
#   - the package holds the executable, the levels, the docs, the desktop entry, the
#     icon at every size, the man page; it depends on the font and the libraries;
#   - `artillery check` passes on every installed level and the campaign;
#   - a golden replay whose level is "levels/05_castle.json" verifies, its level found
#     in the data folder beside the executable (../share/artillery);
#   - a headless frame of an installed level is a real game frame (png_check).
# Arguments: -DDEB_DIR= (where package.build left the .deb) -DVERSION= -DROOT= (scratch)
#            -DREPLAY= (a golden replay) -DCHECK= (png_check) -DICON_SIZES=
cmake_minimum_required(VERSION 3.25)
file(GLOB debs ${DEB_DIR}/artillery_${VERSION}_*.deb)
list(LENGTH debs n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "expected one .deb in ${DEB_DIR}, found ${n}: ${debs}")
endif()
file(REMOVE_RECURSE ${ROOT})
file(MAKE_DIRECTORY ${ROOT}/unpacked ${ROOT}/work)
set(root ${ROOT}/unpacked)

function(run)
  cmake_parse_arguments(R "" "EXPECT" "COMMAND" ${ARGN})
  execute_process(COMMAND ${R_COMMAND} WORKING_DIRECTORY / RESULT_VARIABLE code
                  OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  if(NOT code EQUAL 0 OR NOT "${out}${err}" MATCHES "${R_EXPECT}")
    message(FATAL_ERROR "`${R_COMMAND}` (from /) exited ${code}, expected 0 and /${R_EXPECT}/:\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

list(GET debs 0 deb)
run(COMMAND dpkg-deb -x ${deb} ${root} EXPECT "")
run(COMMAND dpkg-deb --field ${deb} Depends EXPECT "fonts-dejavu-core")
foreach(lib libsdl2-2.0-0 libosmesa6 libenet7 libbox2d libavcodec)
  if(NOT out MATCHES "${lib}")
    message(FATAL_ERROR "the package's Depends has no ${lib} (dpkg-shlibdeps): ${out}")
  endif()
endforeach()

set(installed usr/bin/artillery usr/share/artillery/levels/campaign.json
    usr/share/artillery/levels/README.md usr/share/artillery/README.md
    usr/share/artillery/docs/references.md usr/share/applications/artillery.desktop
    usr/share/man/man6/artillery.6.gz)
foreach(size IN LISTS ICON_SIZES)
  list(APPEND installed usr/share/icons/hicolor/${size}x${size}/apps/artillery.png)
endforeach()
foreach(f IN LISTS installed)
  if(NOT EXISTS ${root}/${f})
    message(FATAL_ERROR "the package has no /${f}")
  endif()
endforeach()
file(GLOB levels ${root}/usr/share/artillery/levels/*.json)
list(LENGTH levels nlevels)

set(exe ${root}/usr/bin/artillery)
run(COMMAND ${exe} --version EXPECT "^artillery [0-9]+\\.[0-9]+\\.[0-9]+\n$")
run(COMMAND ${exe} check ${levels} --json EXPECT "\"failed\":0")
string(REGEX MATCHALL "\"ok\":true" oks "${out}")
list(LENGTH oks nok)
if(NOT nok EQUAL nlevels)
  message(FATAL_ERROR "check passed ${nok} of the ${nlevels} installed files:\n${out}")
endif()

# The replay names its level "levels/05_castle.json": not beside the copy, not under /,
# so only the installed data folder has it.
configure_file(${REPLAY} ${ROOT}/work/golden.replay.json COPYONLY)
run(COMMAND ${exe} replay verify ${ROOT}/work/golden.replay.json --json EXPECT "\"ok\":true")

run(COMMAND ${exe} play ${root}/usr/share/artillery/levels/05_castle.json --headless --frames 2
            --size 640x360 --screenshot ${ROOT}/work/castle.png EXPECT "")
run(COMMAND ${CHECK} ${ROOT}/work/castle.png 640 360 EXPECT "")
message(STATUS "installed package: its ${nlevels} level files (the campaign with them) check, "
               "the golden replay verifies from /, a frame is drawn")
