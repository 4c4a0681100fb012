# The layers of Lucerna (README, "Architecture"): one static library per layer, linked in one
# direction only. lucerna_layer_check(TARGET DIR) names the folder of TARGET's headers and makes
# an include that runs back up a build error: before TARGET builds, every quoted include with a
# folder in TARGET's sources must name a file under DIR or under the folder of a layer TARGET
# links, directly or through others. The link graph is the one statement of what may use what.
# Call it after target_link_libraries, bottom layer first.

function(lucerna_layer_check target dir)
  set_property(TARGET ${target} PROPERTY LUCERNA_LAYER_DIR ${dir})
  set(allowedDirs ${dir})
  get_target_property(pending ${target} LINK_LIBRARIES)
  set(visited "")
  while(pending)
    list(POP_FRONT pending lib)
    if(NOT TARGET ${lib} OR lib IN_LIST visited)
      continue()
    endif()
    list(APPEND visited ${lib})
    get_target_property(libDir ${lib} LUCERNA_LAYER_DIR)
    if(libDir)
      list(APPEND allowedDirs ${libDir})
      get_target_property(below ${lib} LINK_LIBRARIES)
      if(below)
        list(APPEND pending ${below})
      endif()
    endif()
  endwhile()
  list(REMOVE_DUPLICATES allowedDirs)
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
  string(REPLACE ";" "," allowed "${allowedDirs}")
  add_custom_command(OUTPUT "${stamp}"
    COMMAND ${CMAKE_COMMAND} -DLAYER=${target} -DSOURCES=${list} -DALLOWED=${allowed} -DSTAMP=${stamp}
            -P "${PROJECT_SOURCE_DIR}/cmake/check_layer_includes.cmake"
    DEPENDS ${absolute} "${PROJECT_SOURCE_DIR}/cmake/check_layer_includes.cmake"
    COMMENT "Checking the includes of layer ${target}" VERBATIM)
  add_custom_target(${target}_layer_check DEPENDS "${stamp}")
  add_dependencies(${target} ${target}_layer_check)
endfunction()
