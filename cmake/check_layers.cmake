# cmake -DSOURCE_DIR=<tree> -P check_layers.cmake: fails, listing every offence, when a file of a layer includes
# a header of a layer it may not use, or when the header-only rng layer includes a library it must not need.
# The include roots of the build (cmake/layers.cmake) enforce the same rule on what is compiled; this check also
# covers headers no translation unit happens to include.
cmake_minimum_required(VERSION 3.25)

set(allowed_common common)
set(allowed_rng rng common)
set(allowed_stats stats rng common)
set(allowed_dpd dpd rng common)
set(allowed_study study dpd stats rng common)
set(allowed_cli cli study dpd stats rng common)
# Third-party headers a layer must not include (a regular expression on the include path).
set(foreign_rng "^(hdf5|H5|toml\\+\\+/|nlohmann/|gsl/|fftw3\\.h|omp\\.h|Eigen/|CLI/|benchmark/)")
set(foreign_stats "^(hdf5|H5|toml\\+\\+/|CLI/|benchmark/)")
set(foreign_dpd "^(hdf5|H5|toml\\+\\+/|gsl/|fftw3\\.h|CLI/|benchmark/)")

set(offences "")
set(checked 0)
foreach(layer common rng stats dpd study cli)
  file(GLOB_RECURSE files ${SOURCE_DIR}/include/dpdrng/${layer}/*.hpp ${SOURCE_DIR}/src/${layer}/*.hpp
    ${SOURCE_DIR}/src/${layer}/*.cpp)
  foreach(f IN LISTS files)
    math(EXPR checked "${checked} + 1")
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" path "${line}")
      file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
      if(path MATCHES "^dpdrng/([a-z_0-9]+)/")
        if(NOT CMAKE_MATCH_1 IN_LIST allowed_${layer})
          list(APPEND offences "${rel}: layer ${layer} includes ${path} (layer ${CMAKE_MATCH_1})")
        endif()
      elseif(DEFINED foreign_${layer} AND path MATCHES "${foreign_${layer}}")
        list(APPEND offences "${rel}: layer ${layer} includes ${path}")
      endif()
    endforeach()
  endforeach()
endforeach()

if(checked EQUAL 0)
  message(FATAL_ERROR "no sources found under ${SOURCE_DIR}")
endif()
if(offences)
  list(JOIN offences "\n  " text)
  message(FATAL_ERROR "layering violated:\n  ${text}")
endif()
message(STATUS "layering: ${checked} files, no layer includes a header of a layer it may not use")
