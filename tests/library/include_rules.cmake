# Shared by the structure checks (run with -P, SOURCE_DIR set): fails,
# naming each offending line, where a file of `files` (a list) has an
# #include whose line matches `pattern`; `what` says what that means.
function(forbid_includes files pattern what)
  set(violations "")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line IN LISTS includes)
      if(line MATCHES "${pattern}")
        file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
        string(APPEND violations "\n  ${rel}: ${line}")
      endif()
    endforeach()
  endforeach()
  if(violations)
    message(FATAL_ERROR "${what}:${violations}")
  endif()
endfunction()
