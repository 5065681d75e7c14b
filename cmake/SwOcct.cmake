# SPDX-License-Identifier: MIT
# OpenCASCADE (Debian libocct-*-dev) for the STEP reader and the OCCT IGES
# cross-check: assets/import/sw_import_occt.cpp when found, the C fallback
# assets/import/sw_import_occt_none.c (a clear "built without STEP support") when not.
# Sets SW_OCCT_FOUND and defines sw_occt_apply(target core), which adds the
# right sources, libraries and the SW_HAVE_OCCT definition to target, an
# assets library built on the core library core.
option(SW_WITH_OCCT "Read STEP (and IGES as a cross-check) through OpenCASCADE when it is installed" ON)

set(SW_OCCT_FOUND OFF)
if(SW_WITH_OCCT)
  # Only the modules we link: the default (all modules) also loads Draw's
  # targets, whose libraries Debian ships in a package we do not need. The
  # order matters: each module's targets file checks, as it is loaded, that
  # the modules it refers to are loaded already (ApplicationFramework's refer
  # to Visualization's TKV3d and TKService).
  find_package(OpenCASCADE CONFIG QUIET
    COMPONENTS FoundationClasses ModelingData ModelingAlgorithms Visualization
               ApplicationFramework DataExchange)
  if(OpenCASCADE_FOUND)
    set(SW_OCCT_FOUND ON)
    message(STATUS "seamwalk: OpenCASCADE ${OpenCASCADE_VERSION} found: STEP import on")
  else()
    message(STATUS "seamwalk: OpenCASCADE not found: STEP import off (install libocct-data-exchange-dev)")
  endif()
else()
  message(STATUS "seamwalk: SW_WITH_OCCT=OFF: STEP import off")
endif()

if(SW_OCCT_FOUND)
  enable_language(CXX)
  set(CMAKE_CXX_STANDARD 17)
  set(CMAKE_CXX_STANDARD_REQUIRED ON)
  set(CMAKE_CXX_EXTENSIONS OFF)
endif()

# The toolkits sw_import_occt.cpp uses, lowest layer last.
set(SW_OCCT_LIBRARIES
  TKXDESTEP TKXDEIGES TKSTEP TKIGES TKXCAF TKLCAF TKXSBase
  TKShHealing TKTopAlgo TKGeomAlgo TKBRep TKGeomBase TKG3d TKG2d TKMath TKernel)

function(sw_occt_apply target core)
  if(NOT SW_OCCT_FOUND)
    target_sources(${target} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_import_occt_none.c)
    return()
  endif()
  # The C++ file is an object library of its own: sw_apply_warnings' C-only
  # flags (-Wstrict-prototypes, -Wmissing-prototypes) are errors for g++ under
  # -Werror, so C++ gets the equivalent set here.
  add_library(${target}_occt OBJECT ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_import_occt.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_measure.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_bspline.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_pcurve.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_convert.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_unroll.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_face.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_step_file.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/import/sw_occt_read_check.cpp)
  target_include_directories(${target}_occt PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/import
    ${CMAKE_CURRENT_SOURCE_DIR}/model)
  # SYSTEM: OCCT's headers are not ours to keep free of -Wextra warnings.
  target_include_directories(${target}_occt SYSTEM PRIVATE ${OpenCASCADE_INCLUDE_DIR})
  target_link_libraries(${target}_occt PRIVATE ${core})
  target_compile_options(${target}_occt PRIVATE -Wall -Wextra -Wshadow -Wpointer-arith
    -Wmissing-declarations)
  if(SW_WERROR)
    target_compile_options(${target}_occt PRIVATE -Werror)
  endif()
  set_target_properties(${target}_occt PROPERTIES POSITION_INDEPENDENT_CODE ON)
  # Linking the object library puts its objects into the target and tells
  # CMake that programs using the target need the C++ linker and runtime.
  target_link_libraries(${target} PRIVATE ${target}_occt ${SW_OCCT_LIBRARIES})
  target_compile_definitions(${target} PUBLIC SW_HAVE_OCCT=1)
endfunction()
