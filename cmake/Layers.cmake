# The one dependency rule of the house (DESIGN.md), enforced by the build: each layer's targets
# expose only their own include directory, so a target sees the headers of the layers it links
# and no others. `#include "model/..."` in impl/ then fails to compile, as does any include of a
# layer above spec/ from spec/. (tests/ and bench/ sit above everything and see the whole tree.)
#
# The include directory of layer L is ${CMAKE_BINARY_DIR}/layers/L, holding one symbolic link
# L -> ${CMAKE_SOURCE_DIR}/L, so sources keep writing "spec/exploration/types.hpp".
set(SWARMCHECK_LAYERS_DIR ${CMAKE_BINARY_DIR}/layers)

function(swarmcheck_layer_dir layer out_var)
  set(dir ${SWARMCHECK_LAYERS_DIR}/${layer})
  if(NOT EXISTS ${dir}/${layer})
    file(MAKE_DIRECTORY ${dir})
    file(CREATE_LINK ${CMAKE_SOURCE_DIR}/${layer} ${dir}/${layer} SYMBOLIC)
  endif()
  set(${out_var} ${dir} PARENT_SCOPE)
endfunction()

# swarmcheck_layer(target layer [PRIVATE]): target belongs to `layer`; its dependents see the
# layer's headers unless PRIVATE (executables, or libraries whose headers nobody includes).
function(swarmcheck_layer target layer)
  swarmcheck_layer_dir(${layer} dir)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${dir}>)
  elseif("PRIVATE" IN_LIST ARGN)
    target_include_directories(${target} PRIVATE $<BUILD_INTERFACE:${dir}>)
  else()
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${dir}>)
  endif()
endfunction()
