# The layering: no file of the shadow core (include/penumbra/, src/gl/,
# src/shadow/, src/filter/, and the settings and errors of src/core/ it
# carries) includes anything of its clients: the renderer, scenes, the
# reference, the report, the viewer, the app or image files.
# Run as: cmake -DSOURCE_DIR=... -P check_core_structure.cmake
file(GLOB core_files
     "${SOURCE_DIR}/include/penumbra/*.hpp"
     "${SOURCE_DIR}/src/gl/*.hpp" "${SOURCE_DIR}/src/gl/*.cpp"
     "${SOURCE_DIR}/src/shadow/*.hpp" "${SOURCE_DIR}/src/shadow/*.cpp"
     "${SOURCE_DIR}/src/filter/*.hpp" "${SOURCE_DIR}/src/filter/*.cpp"
     "${SOURCE_DIR}/src/core/settings.hpp" "${SOURCE_DIR}/src/core/settings.cpp"
     "${SOURCE_DIR}/src/core/enum_names.hpp" "${SOURCE_DIR}/src/core/error.hpp"
     "${SOURCE_DIR}/shaders/shared/*.h")
list(LENGTH core_files count)
if(count LESS 40)
  message(FATAL_ERROR "found only ${count} files of the shadow core: has it moved?")
endif()
set(violations "")
foreach(file IN LISTS core_files)
  file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
  foreach(line IN LISTS includes)
    if(line MATCHES "[\"<](render|scene|reference|report|viewer|app|io)/")
      file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
      string(APPEND violations "\n  ${rel}: ${line}")
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "the shadow core includes its clients:${violations}")
endif()
message(STATUS "${count} files of the shadow core include none of its clients")
