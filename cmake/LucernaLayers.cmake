# The layers of Lucerna (README, "Architecture"): one static library per layer, linked in one
# direction only. lucerna_layer_check(TARGET MAY_INCLUDE dir...) makes an include that runs back
# up a build error: before TARGET builds, every quoted include with a folder in TARGET's sources
# must name a file under one of the given folders (its own and the layers below it).

function(lucerna_layer_check target)
  cmake_parse_arguments(L "" "" "MAY_INCLUDE" ${ARGN})
  get_target_property(sources ${target} SOURCES)
  get_target_property(sourceDir ${target} SOURCE_DIR)
  set(absolute "")
  foreach(s IN LISTS sources)
    if(NOT IS_ABSOLUTE "${s}")
      set(s "${sourceDir}/${s}")
    endif()
    if(s MATCHES "\\.(h|cpp)$")
      list(APPEND absolute "${s}")
    endif()
  endforeach()
  set(list "${CMAKE_CURRENT_BINARY_DIR}/${target}.layer_sources")
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/${target}.layer_checked")
  file(WRITE "${list}" "${absolute}")
  string(REPLACE ";" "," allowed "${L_MAY_INCLUDE}")
  add_custom_command(OUTPUT "${stamp}"
    COMMAND ${CMAKE_COMMAND} -DLAYER=${target} -DSOURCES=${list} -DALLOWED=${allowed} -DSTAMP=${stamp}
            -P "${PROJECT_SOURCE_DIR}/cmake/check_layer_includes.cmake"
    DEPENDS ${absolute} "${PROJECT_SOURCE_DIR}/cmake/check_layer_includes.cmake"
    COMMENT "Checking the includes of layer ${target}" VERBATIM)
  add_custom_target(${target}_layer_check DEPENDS "${stamp}")
  add_dependencies(${target} ${target}_layer_check)
endfunction()
