# The renderer sits below the traced reference it is measured against: no
# file of src/render/, src/scene/, src/io/ or src/core/ includes the
# reference, the report, the viewer or the app. What both need (the light
# source's sample points) lives in src/core/.
# Run as: cmake -DSOURCE_DIR=... -P check_renderer_structure.cmake
cmake_minimum_required(VERSION 3.25)
set(files "")
foreach(dir IN ITEMS render scene io core)
  file(GLOB dir_files "${SOURCE_DIR}/src/${dir}/*.hpp" "${SOURCE_DIR}/src/${dir}/*.cpp")
  list(APPEND files ${dir_files})
endforeach()
list(LENGTH files count)
if(count LESS 40)
  message(FATAL_ERROR "found only ${count} files of the renderer: has it moved?")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/include_rules.cmake")
forbid_includes("${files}" "[\"<](\\.\\./)*(reference|report|viewer|app)/"
                "the renderer includes the layers above it")
message(STATUS "${count} files of the renderer include nothing of the reference or the tool")
