# Writes OUTPUT, a C++ source defining `const std::string_view ceilplan::io::report_assets::NAME`
# with the bytes of INPUT, as one raw string literal split into chunks.
# Usage: cmake -DINPUT=file -DNAME=identifier -DOUTPUT=file.cpp -P embed_text.cmake
file(READ "${INPUT}" content)
string(LENGTH "${content}" length)
string(FIND "${content}" ")ceilplan_asset\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw string delimiter")
endif()
set(chunk 16000)
file(WRITE "${OUTPUT}" "// Generated from ${INPUT} by io/report/embed_text.cmake: do not edit.\n#include <string_view>\n\nnamespace ceilplan::io::report_assets {\nnamespace {\nconstexpr char k${NAME}[] =\n")
set(offset 0)
while(offset LESS length)
  string(SUBSTRING "${content}" ${offset} ${chunk} piece)
  file(APPEND "${OUTPUT}" "R\"ceilplan_asset(${piece})ceilplan_asset\"\n")
  math(EXPR offset "${offset} + ${chunk}")
endwhile()
file(APPEND "${OUTPUT}" ";\n}  // namespace\nextern const std::string_view ${NAME}(k${NAME}, sizeof(k${NAME}) - 1);\n}  // namespace ceilplan::io::report_assets\n")
