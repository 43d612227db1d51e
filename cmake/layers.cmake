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
