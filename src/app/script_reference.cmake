# Writes the viewer's script reference (docs/script.md) from its command
# table (src/app/script_commands.cpp). Run as
#   cmake -DTG=path/to/tensorglyph -DOUT=path/to/script.md -P script_reference.cmake
execute_process(COMMAND ${TG} help script --markdown OUTPUT_VARIABLE md RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${TG} help script --markdown failed (${rc})")
endif()
file(WRITE ${OUT}.tmp "${md}")
file(RENAME ${OUT}.tmp ${OUT})
