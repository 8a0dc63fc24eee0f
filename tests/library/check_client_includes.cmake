# The shadow core's clients reach it through its public headers alone: no
# file of the renderer, scenes, the reference, the report, the viewer, the
# app, io or the rest of src/core/ includes a core header by a private
# path (gl/, shadow/, filter/ under src/, shared/ under shaders/); each
# writes "penumbra/gl/resources.hpp", "penumbra/shared/bindings.h", ...
# Run as: cmake -DSOURCE_DIR=... -P check_client_includes.cmake
set(client_dirs app core io reference render report scene viewer)
set(client_files "")
foreach(dir IN LISTS client_dirs)
  file(GLOB files "${SOURCE_DIR}/src/${dir}/*.hpp" "${SOURCE_DIR}/src/${dir}/*.cpp")
  list(APPEND client_files ${files})
endforeach()
# src/core/settings.cpp is the core's own (the settings' validation).
list(FILTER client_files EXCLUDE REGEX "/src/core/settings\\.cpp$")
list(LENGTH client_files count)
if(count LESS 100)
  message(FATAL_ERROR "found only ${count} files of the core's clients: have they moved?")
endif()
set(violations "")
foreach(file IN LISTS client_files)
  file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "[\"<]([^\">]*)[\">]" _ "${line}")
    set(path "${CMAKE_MATCH_1}")
    # A private path of the core, also when spelled relative ("../gl/...").
    string(REGEX REPLACE "^(\\.\\./)+" "" stripped "${path}")
    set(private FALSE)
    if(stripped MATCHES "^(gl|shadow|filter|shared)/")
      set(private TRUE)
    elseif(stripped MATCHES "^core/" AND NOT EXISTS "${SOURCE_DIR}/src/${stripped}")
      set(private TRUE)  # the core's settings and errors: penumbra/settings.hpp, ...
    elseif(stripped MATCHES "^penumbra/"
           AND NOT stripped MATCHES "^penumbra/(version\\.hpp|shared/bindings\\.h|shared/gpu_types\\.h)$"
           AND NOT EXISTS "${SOURCE_DIR}/include/${stripped}")
      set(private TRUE)  # no such public header
    endif()
    if(private)
      file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
      string(APPEND violations "\n  ${rel}: ${line}")
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "clients include the shadow core's private headers "
                      "(include \"penumbra/...\" instead):${violations}")
endif()
message(STATUS "${count} client files include the shadow core through include/penumbra/ alone")
