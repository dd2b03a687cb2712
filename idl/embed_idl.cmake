# Writes a C++ source holding the text of each IDL file (used as the MCAP schema of its channel).
set(body "// Generated from idl/*.idl. Do not edit.\n#include \"entourage_msg/idl_text.hpp\"\n\nnamespace entourage::msg {\n\n")
string(APPEND body "std::string_view idl_text(std::string_view type_name) {\n")
foreach(t ${TYPES})
  file(READ ${IDL_DIR}/${t}.idl text)
  string(APPEND body "  if (type_name == \"${t}\") {\n    return R\"ENTOURAGEIDL(${text})ENTOURAGEIDL\";\n  }\n")
endforeach()
string(APPEND body "  return {};\n}\n\n}  // namespace entourage::msg\n")
file(WRITE ${OUT} "${body}")
