# The keyed-hash generator families: the one list every part of dpdrng takes its generators from. An entry is
# `<family>=<header>`, the header under include/dpdrng/rng/ that defines the family's generator and its
# FamilyTraits (dpdrng/rng/generator.hpp states what both must provide). From this list CMake writes
#   dpdrng/rng/families.hpp        the family names as an X-macro, DPDRNG_KEYED_FAMILIES(X)
#   dpdrng/rng/family_headers.hpp  every listed header, for the code that dispatches over all families
# and the per-family translation units: the pair forces of each family and pair seeding, and per header the
# decomposition check and bench rng's scalar timing. They stay separate files so that they build in parallel and
# an edit of a generator header rebuilds only its own families' code. plugin (a user's shared library) and
# mt19937 (the reference stream, not a keyed hash) are not listed: the code names them where it treats them apart.
set(DPDRNG_KEYED_FAMILIES
  tea32=tea.hpp
  tea64=tea.hpp
  philox4x32=random123.hpp
  threefry2x64=random123.hpp
  splitmix64=splitmix.hpp
  saru=saru.hpp
  defect=defect.hpp
  squares64=squares.hpp
)

set(DPDRNG_FAMILY_INCLUDE ${PROJECT_BINARY_DIR}/families/include)
set(DPDRNG_FAMILY_SOURCE_DIR ${PROJECT_BINARY_DIR}/families/src)
set(templates ${CMAKE_CURRENT_LIST_DIR}/families)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${templates}/decomposition.instance
  ${templates}/bench_rng_scalar.instance)

# Writes `path` only when its text changes, so that a reconfigure rebuilds nothing that did not change.
function(dpdrng_write_if_changed path text)
  if(EXISTS ${path})
    file(READ ${path} old)
    if(old STREQUAL text)
      return()
    endif()
  endif()
  file(WRITE ${path} "${text}")
endfunction()

set(xmacro "")
set(headers "")
set(DPDRNG_FAMILY_DPD_SOURCES "")
set(DPDRNG_FAMILY_CLI_SOURCES "")
foreach(entry IN LISTS DPDRNG_KEYED_FAMILIES)
  string(REPLACE "=" ";" parts ${entry})
  list(GET parts 0 family)
  list(GET parts 1 header)
  string(APPEND xmacro " X(${family})")
  list(APPEND headers ${header})
  list(APPEND families_of_${header} ${family})
  set(FAMILY_HEADER "dpdrng/rng/${header}")
  foreach(seeding IN ITEMS distance pair_step)
    set(FAMILY ${family})
    set(SEEDING ${seeding})
    configure_file(${templates}/pair_forces.cpp.in ${DPDRNG_FAMILY_SOURCE_DIR}/pair_forces_${family}_${seeding}.cpp @ONLY)
    list(APPEND DPDRNG_FAMILY_DPD_SOURCES ${DPDRNG_FAMILY_SOURCE_DIR}/pair_forces_${family}_${seeding}.cpp)
  endforeach()
endforeach()
list(REMOVE_DUPLICATES headers)

set(include_lines "")
foreach(header IN LISTS headers)
  string(APPEND include_lines "#include \"dpdrng/rng/${header}\"\n")
  string(REGEX REPLACE "\\.hpp$" "" stem ${header})
  set(FAMILY_HEADER "dpdrng/rng/${header}")
  foreach(part IN ITEMS decomposition bench_rng_scalar)
    set(INSTANTIATIONS "")
    foreach(family IN LISTS families_of_${header})
      file(READ ${templates}/${part}.instance INSTANCE)
      string(REPLACE "@FAMILY@" ${family} INSTANCE "${INSTANCE}")
      string(APPEND INSTANTIATIONS "${INSTANCE}")
    endforeach()
    configure_file(${templates}/${part}.cpp.in ${DPDRNG_FAMILY_SOURCE_DIR}/${part}_${stem}.cpp @ONLY)
  endforeach()
  list(APPEND DPDRNG_FAMILY_DPD_SOURCES ${DPDRNG_FAMILY_SOURCE_DIR}/decomposition_${stem}.cpp)
  list(APPEND DPDRNG_FAMILY_CLI_SOURCES ${DPDRNG_FAMILY_SOURCE_DIR}/bench_rng_scalar_${stem}.cpp)
endforeach()

set(banner "// Written by cmake/families.cmake from its list DPDRNG_KEYED_FAMILIES: edit the list, not this file.\n")
dpdrng_write_if_changed(${DPDRNG_FAMILY_INCLUDE}/dpdrng/rng/families.hpp
  "#pragma once\n${banner}#define DPDRNG_KEYED_FAMILIES(X)${xmacro}\n")
dpdrng_write_if_changed(${DPDRNG_FAMILY_INCLUDE}/dpdrng/rng/family_headers.hpp
  "#pragma once\n${banner}${include_lines}")
# The generated sources find their family's internal headers beside the hand-written ones, and build apart from
# the unity batches. Source properties belong to a directory: each directory that compiles them calls this.
function(dpdrng_family_source_properties)
  set_source_files_properties(${DPDRNG_FAMILY_DPD_SOURCES} PROPERTIES
    INCLUDE_DIRECTORIES ${PROJECT_SOURCE_DIR}/src/dpd SKIP_UNITY_BUILD_INCLUSION ON)
  set_source_files_properties(${DPDRNG_FAMILY_CLI_SOURCES} PROPERTIES
    INCLUDE_DIRECTORIES ${PROJECT_SOURCE_DIR}/src/cli SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()
