# -DPENUMBRA_BUILD_TOOLS=OFF configures with libepoxy and GLM alone: no
# find_package of the tool's dependencies is made (none leaves its *_DIR
# in the cache).
# Run as: cmake -DSOURCE_DIR=... -DWORK_DIR=... -P configure_tools_off.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}"
                        -DPENUMBRA_BUILD_TOOLS=OFF
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configuring with PENUMBRA_BUILD_TOOLS=OFF failed:\n${out}\n${err}")
endif()
file(READ "${WORK_DIR}/CMakeCache.txt" cache)
foreach(package CLI11 assimp embree TBB glfw3 nlohmann_json tinyexr GTest benchmark)
  if(cache MATCHES "\n${package}_DIR:")
    message(FATAL_ERROR "PENUMBRA_BUILD_TOOLS=OFF still looked for ${package}")
  endif()
endforeach()
if(cache MATCHES "pkgcfg_lib_IMGUI" OR cache MATCHES "pkgcfg_lib_STB")
  message(FATAL_ERROR "PENUMBRA_BUILD_TOOLS=OFF still looked for imgui or stb")
endif()
if(NOT EXISTS "${WORK_DIR}/build.ninja" AND NOT EXISTS "${WORK_DIR}/Makefile")
  message(FATAL_ERROR "no build files generated")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
