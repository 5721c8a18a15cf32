# Writes the command reference (docs/cli.md) from the option tables: each
# command prints its own with --help-markdown. Run as
#   cmake -DTG=path/to/tensorglyph -DOUT=path/to/cli.md -P cli_reference.cmake
set(text "# tensorglyph command reference\n\nGenerated from the option tables (src/app/scale/option_table.h) by the build; `tensorglyph help TOPIC` prints one group of `render`'s options, `tensorglyph COMMAND --help` a command's. A range is checked the same way on the command line, in Python's keywords and in the viewer's script.\n\n")
foreach(cmd "render" "view" "info" "synth" "bench accuracy" "bench scale")
  separate_arguments(words UNIX_COMMAND "${cmd}")
  execute_process(COMMAND ${TG} ${words} --help-markdown OUTPUT_VARIABLE md RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${TG} ${cmd} --help-markdown failed (${rc})")
  endif()
  string(APPEND text "${md}\n")
endforeach()
file(WRITE ${OUT}.tmp "${text}")
file(RENAME ${OUT}.tmp ${OUT})
