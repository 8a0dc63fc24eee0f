# Embeds the files FILES (names relative to DIR, separated by commas) into
# OUTPUT as a C++ table of (name, bytes) returned by FUNCTION (declared in
# HEADER, in namespace penumbra), so the installed tool needs no data
# directory. Run as:
#   cmake -DDIR=... -DFILES=a,b -DOUTPUT=... -DHEADER=... -DFUNCTION=... -P embed_files.cmake
string(REPLACE "," ";" files "${FILES}")
set(body "")
set(table "")
set(index 0)
foreach(rel IN LISTS files)
  file(READ "${DIR}/${rel}" hex HEX)
  string(LENGTH "${hex}" hex_len)
  math(EXPR size "${hex_len} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  string(APPEND body "const unsigned char file_${index}[] = {${bytes}0x00};\n")
  string(APPEND table "    {\"${rel}\", std::string_view(reinterpret_cast<const char*>(file_${index}), ${size})},\n")
  math(EXPR index "${index} + 1")
endforeach()

set(content "// Generated from ${DIR} by cmake/embed_files.cmake. Do not edit.
#include \"${HEADER}\"

namespace penumbra {
namespace {
${body}
const EmbeddedFile files[] = {
${table}};
}  // namespace

std::span<const EmbeddedFile> ${FUNCTION}() { return files; }
}  // namespace penumbra
")

# Only touch the output when it changes, so unrelated rebuilds stay quick.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
  if(old STREQUAL content)
    return()
  endif()
endif()
file(WRITE "${OUTPUT}" "${content}")
