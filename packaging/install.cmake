# Installs like a game: `cmake --install build` (prefix /usr/local) or the Debian package
# (`make package`, CPack, prefix /usr):
#   bin/artillery
#   share/artillery/levels/    the shipped levels, the campaign, the level format
#   share/artillery/docs/      the manual, README.md beside it (its links still resolve)
#   share/applications/artillery.desktop
#   share/icons/hicolor/NxN/apps/artillery.png   drawn by `artillery icon` at build time
#   share/man/man6/artillery.6.gz                made from --help by help2man
# The executable finds its data as ../share/artillery from its own folder
# (game/files/data_folder.h), so the layout below keeps bin/ and share/ side by side.

set(ARTILLERY_ICON_SIZES 16 22 24 32 48 64 128 256)
set(icon_files "")
foreach(size IN LISTS ARTILLERY_ICON_SIZES)
  set(dir ${PROJECT_BINARY_DIR}/icons/hicolor/${size}x${size}/apps)
  add_custom_command(OUTPUT ${dir}/artillery.png
                     COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}
                     COMMAND artillery icon --size ${size} --png ${dir}/artillery.png
                     DEPENDS artillery
                     COMMENT "Drawing the ${size}x${size} icon"
                     VERBATIM)
  list(APPEND icon_files ${dir}/artillery.png)
  install(FILES ${dir}/artillery.png DESTINATION share/icons/hicolor/${size}x${size}/apps)
endforeach()

# The man page is the program's own --help (section 6: games), with the files it reads.
find_program(HELP2MAN help2man REQUIRED)
set(man_page ${PROJECT_BINARY_DIR}/man/artillery.6)
add_custom_command(OUTPUT ${man_page}.gz
                   COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
                   COMMAND ${HELP2MAN} --no-info --section 6
                           --name "a 2D physics playground and artillery game"
                           --include ${CMAKE_CURRENT_LIST_DIR}/artillery.h2m
                           --output ${man_page} $<TARGET_FILE:artillery>
                   COMMAND gzip -9nf ${man_page}
                   DEPENDS artillery ${CMAKE_CURRENT_LIST_DIR}/artillery.h2m
                   COMMENT "Making the man page from artillery --help"
                   VERBATIM)
add_custom_target(artillery_desktop_files ALL DEPENDS ${icon_files} ${man_page}.gz)

install(TARGETS artillery RUNTIME DESTINATION bin)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/levels/ DESTINATION share/artillery/levels
        FILES_MATCHING PATTERN "*.json" PATTERN "README.md")
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION share/artillery)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION share/artillery/docs)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/artillery.desktop DESTINATION share/applications)
install(FILES ${man_page}.gz DESTINATION share/man/man6)

# The Debian package. Its run-time libraries come from dpkg-shlibdeps (dpkg-dev); what
# the program opens without linking it is named here: the font the panels use
# (ui/platform/imgui_layer.cpp) and the GL drivers SDL and EGL load.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME artillery)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "Aim, fire and knock down castles, bank shots and duels, on a particle layer with
closed-form ballistics, eight integrators, forces and collisions with restitution, plus
Box2D rigid bodies. Every physics choice is a live control, and the game shows what each
one costs and how wrong it is. Campaign, duels against the computer, hotseat or over
the network, a sandbox, a level editor, replays.")
set(CPACK_PACKAGE_CONTACT "The artillery maintainers <maintainers@artillery.invalid>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "fonts-dejavu-core, libgl1, libglx-mesa0 | libglx-vendor, libegl-mesa0 | libegl-vendor")
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/package)
include(CPack)
