# The installed penumbra::shadows needs none of the tool's dependencies:
# installs the core's component into a fresh prefix and reads the exported
# targets (INTERFACE_LINK_LIBRARIES, INTERFACE_INCLUDE_DIRECTORIES) and the
# pkg-config file.
# Run as: cmake -DBUILD_DIR=... -DWORK_DIR=... -P check_installed_interface.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}"
                        --component shadows
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install --component shadows failed")
endif()
file(GLOB_RECURSE targets "${WORK_DIR}/*/penumbraShadowsTargets.cmake")
file(GLOB_RECURSE config "${WORK_DIR}/*/penumbraConfig.cmake")
file(GLOB_RECURSE pc "${WORK_DIR}/*/penumbra-shadows.pc")
if(NOT targets OR NOT config OR NOT pc)
  message(FATAL_ERROR "missing penumbraShadowsTargets.cmake, penumbraConfig.cmake or penumbra-shadows.pc")
endif()
file(READ "${targets}" exported)
string(REGEX MATCH "INTERFACE_LINK_LIBRARIES \"([^\"]*)\"" _ "${exported}")
set(link "${CMAKE_MATCH_1}")
if(NOT link MATCHES "PkgConfig::EPOXY" OR NOT link MATCHES "glm")
  message(FATAL_ERROR "penumbra::shadows links '${link}': expected epoxy and GLM")
endif()
file(READ "${pc}" pc_text)
# The client keeps its own GLM configuration (issue 30, item 9).
if(exported MATCHES "INTERFACE_COMPILE_DEFINITIONS" OR pc_text MATCHES "-DGLM_")
  message(FATAL_ERROR "the installed penumbra::shadows forces compile definitions on its client")
endif()
foreach(forbidden CLI11 assimp embree TBB tbb glfw imgui nlohmann tinyexr stb Threads)
  if(exported MATCHES "${forbidden}")
    message(FATAL_ERROR "the installed penumbra::shadows interface mentions ${forbidden}")
  endif()
  if(pc_text MATCHES "${forbidden}")
    message(FATAL_ERROR "penumbra-shadows.pc mentions ${forbidden}")
  endif()
endforeach()
# Only the public include root: no src/ or generic paths like gl/resources.hpp.
string(REGEX MATCH "INTERFACE_INCLUDE_DIRECTORIES \"([^\"]*)\"" _ "${exported}")
if(NOT CMAKE_MATCH_1 STREQUAL "\${_IMPORT_PREFIX}/include")
  message(FATAL_ERROR "penumbra::shadows include directories: ${CMAKE_MATCH_1}")
endif()
foreach(installed include/penumbra/shadow_maps.hpp include/penumbra/version.hpp
                  share/penumbra/penumbra_shadows.glsl)
  if(NOT EXISTS "${WORK_DIR}/${installed}")
    message(FATAL_ERROR "not installed: ${installed}")
  endif()
endforeach()
if(EXISTS "${WORK_DIR}/bin/penumbra")
  message(FATAL_ERROR "the shadows component installed the tool")
endif()
# A client asking for the renderer of a shadows-only install is told why
# it cannot have it; one asking for the shadows finds them.
set(client "${WORK_DIR}/client")
file(MAKE_DIRECTORY "${client}")
foreach(case shadows renderer)
  file(WRITE "${client}/CMakeLists.txt"
       "cmake_minimum_required(VERSION 3.20)\nproject(client NONE)\n"
       "find_package(penumbra REQUIRED COMPONENTS ${case})\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S "${client}" -B "${client}/build-${case}"
                          "-DCMAKE_PREFIX_PATH=${WORK_DIR}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(case STREQUAL "shadows" AND NOT status EQUAL 0)
    message(FATAL_ERROR "find_package(penumbra COMPONENTS shadows) failed:\n${err}")
  endif()
  if(case STREQUAL "renderer")
    # CMake wraps the reason at a width, wherever the install path puts the breaks.
    string(REGEX REPLACE "[ \t\r\n]+" " " err_line "${err}")
    if(status EQUAL 0 OR NOT err_line MATCHES "installed without the renderer component")
      message(FATAL_ERROR "find_package(penumbra COMPONENTS renderer) on a shadows-only install: "
                          "expected a failure that names the missing component, got "
                          "status ${status}:\n${err}")
    endif()
  endif()
endforeach()
message(STATUS "penumbra::shadows links: ${link}")
