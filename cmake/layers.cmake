# Layer targets. Every layer's public headers live in include/dpdrng/<layer>/; a layer's target compiles against
# an include root of its own, <build>/layers/<layer>, that holds only dpdrng/<layer> (a link to those headers).
# A target sees the roots of the layers it links and no others, so `#include "dpdrng/stats/..."` in the engine
# is a compile error, not a review comment. The installed package has the usual single include/ root.
set(DPDRNG_LAYER_ROOTS ${PROJECT_BINARY_DIR}/layers)

function(dpdrng_layer_root layer)
  set(root ${DPDRNG_LAYER_ROOTS}/${layer}/dpdrng)
  file(MAKE_DIRECTORY ${root})
  if(NOT IS_SYMLINK ${root}/${layer})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/include/dpdrng/${layer} ${root}/${layer} SYMBOLIC)
  endif()
endfunction()

# dpdrng_<name>, alias dpdrng::<name>, exported as dpdrng::<name>: a static library of every .cpp under `dir`,
# compiled against the include root of `layer`.
function(dpdrng_layer_library name layer dir)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  add_library(dpdrng_${name} STATIC ${sources})
  add_library(dpdrng::${name} ALIAS dpdrng_${name})
  set_target_properties(dpdrng_${name} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(dpdrng_${name} PUBLIC $<BUILD_INTERFACE:${DPDRNG_LAYER_ROOTS}/${layer}>
    $<INSTALL_INTERFACE:include>)
  target_compile_features(dpdrng_${name} PUBLIC cxx_std_20)
  target_link_libraries(dpdrng_${name} PRIVATE $<BUILD_INTERFACE:dpdrng_flags>)
endfunction()

# The test suite builds as unity sources (each test file keeps its helpers in a namespace of its own, so the files
# combine without clashes): at -O0 a test file's time is spent parsing GoogleTest and the library's headers, once
# per group instead of once per file. The files that include a generator with compiled round counts (TEA,
# Random123) or every generator (dispatch, batch) directly are grouped apart, six to a group, so that editing a
# generator rebuilds those groups and no other test code; the rest go twelve to a group, in directory order. The
# suite's main stays on its own.
function(dpdrng_test_unity_groups target)
  set(generator_files "")
  set(other_files "")
  foreach(src IN LISTS ARGN)
    file(READ ${src} text)
    if(text MATCHES "#include \"dpdrng/rng/(tea|dispatch|random123|batch)\\.hpp\"")
      list(APPEND generator_files ${src})
    elseif(NOT src MATCHES "/test_main\\.cpp$")
      list(APPEND other_files ${src})
    endif()
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  foreach(kind IN ITEMS generator other)
    if(kind STREQUAL "generator")
      set(size 6)
    else()
      set(size 12)
    endif()
    set(index 0)
    foreach(src IN LISTS ${kind}_files)
      math(EXPR group "${index} / ${size}")
      set_source_files_properties(${src} TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP ${kind}_${group})
      math(EXPR index "${index} + 1")
    endforeach()
  endforeach()
endfunction()
