# swarmcheck_add_subsystems(layer): add_subdirectory for every layer/<name>/CMakeLists.txt, sorted.
function(swarmcheck_add_subsystems layer)
  file(GLOB children RELATIVE ${CMAKE_SOURCE_DIR}/${layer} ${CMAKE_SOURCE_DIR}/${layer}/*/CMakeLists.txt)
  list(SORT children)
  foreach(child IN LISTS children)
    get_filename_component(dir ${child} DIRECTORY)
    add_subdirectory(${layer}/${dir})
  endforeach()
endfunction()
