# The docs check: the manual says what the program does.
#   cmake -DEXE=build/artillery -DSRC=. -P tests/docs/docs_check.cmake
# fails, naming each problem, when
#   - a verb that `artillery --help` lists has a `--help` text that docs/cli.md does not
#     hold word for word (the reference part of cli.md is made from them: `make cli-docs`,
#     which runs this script with -DUPDATE=ON);
#   - a level in levels/ is not listed in docs/playing.md;
#   - a relative link or image in README.md, levels/README.md or docs/*.md points at a
#     file that does not exist, or outside the repository (a clone has only what is in
#     it), or at an anchor (#part) its page has no heading or id for;
#   - README.md does not give the number of golden replays in tests/replays/ and of
#     shipped levels as they are ("the N golden replays", "M shipped levels").
cmake_minimum_required(VERSION 3.25)
if(NOT EXE OR NOT SRC)
  message(FATAL_ERROR "usage: cmake -DEXE=path/to/artillery -DSRC=source-dir [-DUPDATE=ON] -P docs_check.cmake")
endif()

get_filename_component(SRC "${SRC}" ABSOLUTE)
set(problems "")
macro(problem text)
  string(APPEND problems "  ${text}\n")
endmacro()

# --- the verbs and their --help ---------------------------------------------------------
execute_process(COMMAND ${EXE} --help OUTPUT_VARIABLE top ERROR_VARIABLE top_err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXE} --help failed (${rc}): ${top_err}")
endif()
string(REGEX MATCHALL "\n  [a-z][a-z-]*  " verb_lines "${top}")
set(verbs "")
foreach(line IN LISTS verb_lines)
  string(STRIP "${line}" verb)
  list(APPEND verbs "${verb}")
endforeach()
if(NOT verbs)
  message(FATAL_ERROR "no verbs found in `${EXE} --help`:\n${top}")
endif()

set(begin_marker "<!-- reference: made by `make cli-docs` from each verb's --help; do not edit below -->")
set(cli_file "${SRC}/docs/cli.md")
file(READ "${cli_file}" cli)
set(reference "${begin_marker}\n\n## Reference: every verb's --help\n\n```text\n${top}```\n")
foreach(verb IN LISTS verbs)
  execute_process(COMMAND ${EXE} ${verb} --help OUTPUT_VARIABLE help ERROR_VARIABLE help_err
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    problem("`artillery ${verb} --help` exits ${rc}: ${help_err}")
  endif()
  string(APPEND reference "\n### artillery ${verb}\n\n```text\n${help}```\n")
  if(NOT UPDATE)
    string(FIND "${cli}" "${help}" at)
    if(at EQUAL -1 OR help STREQUAL "")
      problem("docs/cli.md does not hold `artillery ${verb} --help` as the program prints it (run `make cli-docs`)")
    endif()
  endif()
endforeach()

if(UPDATE)
  string(FIND "${cli}" "${begin_marker}" at)
  if(at EQUAL -1)
    set(head "${cli}\n")
  else()
    string(SUBSTRING "${cli}" 0 ${at} head)
  endif()
  file(WRITE "${cli_file}" "${head}${reference}")
  message(STATUS "docs/cli.md: reference rewritten for ${verbs}")
endif()

# --- every level in docs/playing.md -----------------------------------------------------
file(READ "${SRC}/docs/playing.md" playing)
file(GLOB level_files RELATIVE "${SRC}/levels" "${SRC}/levels/*.json")
foreach(level IN LISTS level_files)
  if(level STREQUAL "campaign.json")
    continue()
  endif()
  string(FIND "${playing}" "${level}" at)
  if(at EQUAL -1)
    problem("docs/playing.md does not list the level levels/${level}")
  endif()
endforeach()

# --- links and images resolve -----------------------------------------------------------
file(GLOB docs "${SRC}/docs/*.md")
set(pages "${SRC}/README.md" "${SRC}/levels/README.md" ${docs})

# The anchors a page offers: each heading's GitHub slug (lower case; letters, digits,
# spaces, hyphens and underscores kept; spaces to hyphens) and each id="...".
function(page_anchors page out)
  file(STRINGS "${page}" headings REGEX "^#+ ")
  set(anchors "")
  foreach(h IN LISTS headings)
    string(REGEX REPLACE "^#+ +" "" h "${h}")
    string(REGEX REPLACE "<a id=\"[^\"]*\"></a>" "" h "${h}")
    string(TOLOWER "${h}" h)
    string(REGEX REPLACE "[^a-z0-9 _-]" "" h "${h}")
    string(REPLACE " " "-" h "${h}")
    list(APPEND anchors "${h}")
  endforeach()
  file(READ "${page}" text)
  string(REGEX MATCHALL "id=\"[^\"]+\"" ids "${text}")
  foreach(id IN LISTS ids)
    string(REGEX REPLACE "^id=\"([^\"]+)\"$" "\\1" id "${id}")
    list(APPEND anchors "${id}")
  endforeach()
  set(${out} "${anchors}" PARENT_SCOPE)
endfunction()

foreach(page IN LISTS pages)
  file(READ "${page}" text)
  get_filename_component(dir "${page}" DIRECTORY)
  file(RELATIVE_PATH page_name "${SRC}" "${page}")
  # Square brackets would keep CMake from splitting the list of matches: mark the links,
  # then drop the brackets.
  string(REPLACE "](" "<link>(" text "${text}")
  string(REPLACE "[" "" text "${text}")
  string(REPLACE "]" "" text "${text}")
  string(REGEX MATCHALL "<link>\\([^) ]+\\)" links "${text}")
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^<link>\\(([^) ]+)\\)$" "\\1" target "${link}")
    if(target MATCHES "^(https?|mailto):")
      continue()
    endif()
    string(REGEX REPLACE "#.*$" "" path "${target}")
    if(path STREQUAL "")
      set(file "${page}")
    else()
      cmake_path(ABSOLUTE_PATH path BASE_DIRECTORY "${dir}" NORMALIZE OUTPUT_VARIABLE file)
    endif()
    cmake_path(IS_PREFIX SRC "${file}" NORMALIZE inside)
    if(NOT inside)
      problem("${page_name}: the link ${target} points outside the repository")
    elseif(NOT EXISTS "${file}")
      problem("${page_name}: the link ${target} points at nothing")
    elseif(target MATCHES "#" AND file MATCHES "\\.md$")
      string(REGEX REPLACE "^[^#]*#" "" anchor "${target}")
      page_anchors("${file}" anchors)
      if(NOT anchor IN_LIST anchors)
        problem("${page_name}: the link ${target}: its page has no heading or id '${anchor}'")
      endif()
    endif()
  endforeach()
endforeach()

# --- the README says what the golden replays cover -----------------------------------------
file(GLOB goldens "${SRC}/tests/replays/*.replay.json")
list(LENGTH goldens ngoldens)
list(LENGTH level_files nfiles)
math(EXPR nshipped "${nfiles} - 1") # campaign.json is no level
file(READ "${SRC}/README.md" readme)
string(REGEX REPLACE "[ \n]+" " " readme "${readme}")
foreach(phrase "the ${ngoldens} golden replays" "${nshipped} shipped levels")
  string(FIND "${readme}" "${phrase}" at)
  if(at EQUAL -1)
    problem("README.md does not say \"${phrase}\" (tests/replays/ holds ${ngoldens} goldens, levels/ ${nshipped} levels)")
  endif()
endforeach()

if(problems)
  message(FATAL_ERROR "docs check failed:\n${problems}")
endif()
list(LENGTH verbs nverbs)
list(LENGTH level_files nlevels)
list(LENGTH pages npages)
message(STATUS "docs check: ${nverbs} verbs' --help in docs/cli.md, ${nlevels} levels in docs/playing.md, links of ${npages} pages resolve")
