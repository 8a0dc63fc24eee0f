# The layering: no file of the shadow core (include/penumbra/, src/gl/,
# src/shadow/, src/filter/, src/core/settings.cpp and shaders/shared/)
# includes anything of its clients: the renderer, scenes, the reference,
# the report, the viewer, the app or image files. And the public headers
# are self-contained as installed: they include other public headers
# (penumbra/..., or a file beside them) and system headers, never a private
# header of src/ or shaders/.
# Run as: cmake -DSOURCE_DIR=... -P check_core_structure.cmake
cmake_minimum_required(VERSION 3.25)
file(GLOB_RECURSE public_headers "${SOURCE_DIR}/include/penumbra/*.hpp")
file(GLOB core_files
     "${SOURCE_DIR}/src/gl/*.hpp" "${SOURCE_DIR}/src/gl/*.cpp"
     "${SOURCE_DIR}/src/shadow/*.hpp" "${SOURCE_DIR}/src/shadow/*.cpp"
     "${SOURCE_DIR}/src/filter/*.hpp" "${SOURCE_DIR}/src/filter/*.cpp"
     "${SOURCE_DIR}/src/core/settings.cpp" "${SOURCE_DIR}/shaders/shared/*.h")
list(APPEND core_files ${public_headers})
list(LENGTH core_files count)
if(count LESS 40)
  message(FATAL_ERROR "found only ${count} files of the shadow core: has it moved?")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/include_rules.cmake")
forbid_includes("${core_files}" "[\"<](render|scene|reference|report|viewer|app|io)/"
                "the shadow core includes its clients")

# Generated into the build's include root and installed beside the others.
set(generated penumbra/version.hpp penumbra/shared/bindings.h penumbra/shared/gpu_types.h)
set(violations "")
foreach(file IN LISTS public_headers)
  get_filename_component(dir "${file}" DIRECTORY)
  file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "\"([^\"]*)\"" _ "${line}")
    set(path "${CMAKE_MATCH_1}")
    if(path MATCHES "^penumbra/" AND (EXISTS "${SOURCE_DIR}/include/${path}"
                                      OR path IN_LIST generated))
      continue()
    endif()
    if(NOT path MATCHES "/" AND EXISTS "${dir}/${path}")
      continue()  # a public header beside this one
    endif()
    file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
    string(APPEND violations "\n  ${rel}: ${line}")
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "public headers include what is not installed:${violations}")
endif()

# The high-level API (include/penumbra/*.hpp, and the shared structs they
# include) brings no GL loader or GL header into the engine's code, nor the
# low-level headers that do (penumbra/gl/, shadow/, filter/ include epoxy).
file(GLOB high_level "${SOURCE_DIR}/include/penumbra/*.hpp" "${SOURCE_DIR}/shaders/shared/*.h")
forbid_includes("${high_level}" "[\"<](epoxy/|GL/|GLES|glad/|KHR/|EGL/|penumbra/(gl|shadow|filter)/)"
                "the high-level headers include a GL header or a low-level header")

message(STATUS "${count} files of the shadow core include none of its clients; "
               "its public headers include public headers alone, the high-level ones no GL")
