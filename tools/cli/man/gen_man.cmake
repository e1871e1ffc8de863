# cmake -DSSDA=<ssda executable> -DHELP2MAN=<help2man> -DINCLUDE=<ssda.h2m>
#       -DOUT=<ssda.1> -P gen_man.cmake
# The man page of the `ssda` tool, made by help2man from the built tool's
# own --help and --version, so it says what that tool does and which
# library version it carries. The page's COMMANDS section holds, for every
# command that `ssda --help` lists, the text of `ssda COMMAND --help`
# verbatim (its aligned option tables would not survive help2man's
# reflowing); a new subcommand appears without an edit here. help2man
# honours SOURCE_DATE_EPOCH for the page date.
execute_process(COMMAND "${SSDA}" --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "ssda --help failed (exit ${rc})")
endif()

# Text as roff that prints it unchanged in no-fill mode: backslashes and
# hyphens escaped, lines starting with a control character guarded.
function(roff_verbatim text out)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# Commands: the lines "  NAME     summary" of the top-level help.
string(REGEX MATCHALL "\n  [a-z][a-z0-9-]* +[^\n]+" lines "${help}")
set(commands "")
foreach(line IN LISTS lines)
  string(REGEX MATCH "^\n  ([a-z][a-z0-9-]*) +" _ "${line}")
  set(cmd "${CMAKE_MATCH_1}")
  execute_process(COMMAND "${SSDA}" ${cmd} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "ssda ${cmd} --help failed (exit ${rc})")
  endif()
  roff_verbatim("${text}" text)
  string(APPEND commands ".SS \"ssda ${cmd}\"\n.nf\n${text}.fi\n")
endforeach()
if(NOT commands)
  message(FATAL_ERROR "no commands found in 'ssda --help'")
endif()

get_filename_component(dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
file(READ "${INCLUDE}" include)
file(WRITE "${OUT}.h2m" "[COMMANDS]\n${commands}\n${include}")
execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr
                        "--name=exact SSDA template matching, grid tracking and pitch"
                        "--include=${OUT}.h2m" "--output=${OUT}.tmp" "${SSDA}"
                RESULT_VARIABLE rc)
file(REMOVE "${OUT}.h2m")
if(rc)
  file(REMOVE "${OUT}.tmp")
  message(FATAL_ERROR "help2man failed (exit ${rc})")
endif()
file(RENAME "${OUT}.tmp" "${OUT}")
