# Fault injection for the mutation checks, from tests/ only (DESIGN.md; STYLE.md 10, 12): the
# library users link carries no hook, no flag, no branch for a fault. A fault is a file under
# tests/faults/<subsystem>/ that rewrites exact lines of impl/ sources, the way an engineer
# optimising impl/ would really get them wrong:
#
#   # what the fault is, in one sentence (first line)
#   file: impl/exploration/lazy_grid.hpp
#   find: cells_[k].written = static_cast<int32_t>(tick);
#   replace: cells_[k].written = static_cast<int32_t>(tick) - 1;
#
# (several file/find/replace groups may follow; each find must occur exactly once in its file).
# A variant of a library is built from the library's own objects, except that each source file a
# fault rewrites is compiled from its rewritten copy; a fault in a header recompiles every source.
#
# swarmcheck_faultable_library(target SOURCES a.cpp b.cpp ... [FIXED c.cpp d.cpp ...]): a static
#   library whose variants can be built; each of SOURCES is its own object library, so a variant
#   reuses the others' objects. FIXED sources (never rewritten by a fault: a fault naming one fails
#   the configuration) share one object library (one unity batch, not one compilation each).
# swarmcheck_fault_variant(variant target fault_file): the variant of target with that fault.
function(swarmcheck_faultable_library target)
  cmake_parse_arguments(ARG "" "" "SOURCES;FIXED" ${ARGN})
  set(objects "")
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(stem ${src} NAME_WE)
    set(obj ${target}_obj_${stem})
    add_library(${obj} OBJECT ${abs})
    list(APPEND objects $<TARGET_OBJECTS:${obj}>)
    set_property(TARGET ${obj} PROPERTY POSITION_INDEPENDENT_CODE ON)
  endforeach()
  set(fixed_abs "")
  if(ARG_FIXED)
    foreach(src IN LISTS ARG_FIXED)
      get_filename_component(abs ${src} ABSOLUTE)
      list(APPEND fixed_abs ${abs})
    endforeach()
    add_library(${target}_obj_fixed OBJECT ${fixed_abs})
    set_property(TARGET ${target}_obj_fixed PROPERTY POSITION_INDEPENDENT_CODE ON)
    list(APPEND objects $<TARGET_OBJECTS:${target}_obj_fixed>)
  endif()
  add_library(${target} STATIC ${objects})
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(abs ${src} ABSOLUTE)
    list(APPEND abs_sources ${abs})
  endforeach()
  set_property(TARGET ${target} PROPERTY SWARMCHECK_FAULTABLE_SOURCES "${abs_sources}")
  set_property(TARGET ${target} PROPERTY SWARMCHECK_FAULTABLE_FIXED "${fixed_abs}")
endfunction()

# The settings an object library of `target` needs: call after target_link_libraries etc. of the
# library, with the same PRIVATE/PUBLIC settings (object libraries take them through
# swarmcheck_faultable_settings below).
function(swarmcheck_faultable_settings target)
  cmake_parse_arguments(ARG "" "" "LINK;INCLUDE;WARNINGS" ${ARGN})
  get_target_property(sources ${target} SWARMCHECK_FAULTABLE_SOURCES)
  get_target_property(fixed ${target} SWARMCHECK_FAULTABLE_FIXED)
  set(objs "")
  foreach(abs IN LISTS sources)
    get_filename_component(stem ${abs} NAME_WE)
    list(APPEND objs ${target}_obj_${stem})
  endforeach()
  if(fixed)
    list(APPEND objs ${target}_obj_fixed)
  endif()
  foreach(obj IN LISTS objs)
    target_link_libraries(${obj} PRIVATE ${ARG_LINK})
    target_include_directories(${obj} PRIVATE ${ARG_INCLUDE})
    swarmcheck_warnings(${obj})
  endforeach()
  set_property(TARGET ${target} PROPERTY SWARMCHECK_FAULTABLE_LINK "${ARG_LINK}")
  set_property(TARGET ${target} PROPERTY SWARMCHECK_FAULTABLE_INCLUDE "${ARG_INCLUDE}")
endfunction()

# The files a fault rewrites (relative to the source root), read at configure time.
function(swarmcheck_fault_files fault_file out_var)
  file(STRINGS ${fault_file} lines REGEX "^file: ")
  set(files "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^file: *" "" f "${line}")
    string(STRIP "${f}" f)
    list(APPEND files ${f})
  endforeach()
  list(REMOVE_DUPLICATES files)
  if(NOT files)
    message(FATAL_ERROR "${fault_file}: no 'file:' line (a fault rewrites at least one file)")
  endif()
  set(${out_var} ${files} PARENT_SCOPE)
endfunction()

# swarmcheck_fault_rewrite(variant fault_file): the command that writes the fault's rewritten copies
# under ${CMAKE_BINARY_DIR}/faults/<variant>; sets, in the caller, fault_root (that folder),
# fault_files (the files it rewrites, relative to the source root), fault_rewritten (the copies)
# and fault_header_rewritten (ON if a header is among them). Used here and by fmi/'s FMU variants.
function(swarmcheck_fault_rewrite variant fault_file)
  get_filename_component(fault_file ${fault_file} ABSOLUTE)
  swarmcheck_fault_files(${fault_file} files)
  set(root ${CMAKE_BINARY_DIR}/faults/${variant})
  set(rewritten "")
  set(header_rewritten OFF)
  set(files_abs "")
  foreach(f IN LISTS files)
    list(APPEND rewritten ${root}/${f})
    list(APPEND files_abs ${CMAKE_SOURCE_DIR}/${f})
    if(f MATCHES "\\.(hpp|h)$")
      set(header_rewritten ON)
    endif()
  endforeach()
  add_custom_command(OUTPUT ${rewritten}
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/apply-fault ${fault_file} ${CMAKE_SOURCE_DIR} ${root}
    DEPENDS ${fault_file} ${CMAKE_SOURCE_DIR}/scripts/apply-fault ${files_abs}
    COMMENT "fault ${variant}: rewriting ${files}" VERBATIM)
  set(fault_root ${root} PARENT_SCOPE)
  set(fault_files ${files} PARENT_SCOPE)
  set(fault_rewritten ${rewritten} PARENT_SCOPE)
  set(fault_header_rewritten ${header_rewritten} PARENT_SCOPE)
endfunction()

function(swarmcheck_fault_variant variant target fault_file)
  get_filename_component(fault_file ${fault_file} ABSOLUTE)
  swarmcheck_fault_rewrite(${variant} ${fault_file})
  set(root ${fault_root})
  set(files ${fault_files})
  set(rewritten ${fault_rewritten})
  set(header_rewritten ${fault_header_rewritten})
  get_target_property(sources ${target} SWARMCHECK_FAULTABLE_SOURCES)
  get_target_property(fixed ${target} SWARMCHECK_FAULTABLE_FIXED)
  get_target_property(link ${target} SWARMCHECK_FAULTABLE_LINK)
  get_target_property(include ${target} SWARMCHECK_FAULTABLE_INCLUDE)
  set(variant_sources "")
  set(reused "")
  foreach(abs IN LISTS fixed)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${abs})
    if(rel IN_LIST files)
      message(FATAL_ERROR "${fault_file}: ${rel} is not faultable (a FIXED source of ${target}: "
                          "list it under SOURCES in swarmcheck_faultable_library)")
    endif()
  endforeach()
  if(fixed)
    if(header_rewritten)
      list(APPEND variant_sources ${fixed})
    else()
      list(APPEND reused $<TARGET_OBJECTS:${target}_obj_fixed>)
    endif()
  endif()
  foreach(abs IN LISTS sources)
    file(RELATIVE_PATH rel ${CMAKE_SOURCE_DIR} ${abs})
    get_filename_component(stem ${abs} NAME_WE)
    if(rel IN_LIST files)
      list(APPEND variant_sources ${root}/${rel})
    elseif(header_rewritten)
      list(APPEND variant_sources ${abs})
    else()
      list(APPEND reused $<TARGET_OBJECTS:${target}_obj_${stem}>)
    endif()
  endforeach()
  # The rewritten files are sources even when they are headers, so that they are always generated.
  add_library(${variant} STATIC ${rewritten} ${variant_sources} ${reused})
  # The catalogue measures the harness: a debug build's SWARM_ASSERTs in the rewritten sources
  # would abort on the fault before the campaign can catch it, so they are off in a variant.
  target_compile_definitions(${variant} PRIVATE NDEBUG)
  list(REMOVE_DUPLICATES rewritten)
  # A rewritten header shadows the original: its copy's root comes first on the include path.
  target_include_directories(${variant} BEFORE PRIVATE ${root})
  target_include_directories(${variant} PRIVATE ${include})
  target_link_libraries(${variant} PRIVATE ${link})
  swarmcheck_warnings(${variant})
  # Whatever links the variant gets the original's public interface.
  get_target_property(iface_inc ${target} INTERFACE_INCLUDE_DIRECTORIES)
  get_target_property(iface_link ${target} INTERFACE_LINK_LIBRARIES)
  if(iface_inc)
    target_include_directories(${variant} INTERFACE ${iface_inc})
  endif()
  if(iface_link)
    target_link_libraries(${variant} INTERFACE ${iface_link})
  endif()
endfunction()
