# Writes OUT, the compiled-in copies of the shipped templates (so that an
# installed binary works without the source tree), from the files of
# TEMPLATES_DIR. Run by the build whenever a template changes:
#   cmake -DTEMPLATES_DIR=templates -DOUT=template_builtin.c -P embed-templates.cmake
# Byte arrays, not string literals, because C11 only promises
# 4095-character literals.
set(names report.txt calc.txt starter.yaml ac156.yaml)
set(c "/* Compiled-in copies of templates/, generated at build time by\n")
string(APPEND c " * tools/embed-templates.cmake. */\n#include <string.h>\n")
string(APPEND c "#include \"rockbolt/report.h\"\n\n")
set(lookup "")
foreach(n ${names})
  string(MAKE_C_IDENTIFIER "${n}" id)
  file(READ "${TEMPLATES_DIR}/${n}" hex HEX)
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  # sixteen bytes a line
  string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){16})" "\\1\n    " bytes "${bytes}")
  string(APPEND c "static const char tmpl_${id}[] = {\n    ${bytes}0\n};\n\n")
  string(APPEND lookup "    if (strcmp(name, \"${n}\") == 0)\n        return tmpl_${id};\n")
endforeach()
string(APPEND c "const char *rb_template_builtin(const char *name)\n{\n${lookup}")
string(APPEND c "    return NULL;\n}\n")
# only touch OUT when it changes, so that an unrelated build does not
# recompile it
file(WRITE "${OUT}.new" "${c}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUT}.new" "${OUT}")
file(REMOVE "${OUT}.new")
