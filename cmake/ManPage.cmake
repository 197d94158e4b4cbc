# cmake -P script: one manual page from a program's --help and --version (help2man),
# compressed the way Debian wants it (gzip -9n: best compression, no time stamp).
#   -DHELP2MAN=... -DPROGRAM=path -DNAME="one-line description" -DOUTPUT=file.1.gz
#   [-DLANG_ARG=--lang=en] [-DINCLUDE=file.h2m]
# The GUI constructs a QApplication before it parses its options: it runs on the offscreen
# platform here, so that no display is needed.
set(help_option "--help")
set(version_option "--version")
if(LANG_ARG)
  set(help_option "${LANG_ARG} --help")
  set(version_option "${LANG_ARG} --version")
endif()
string(REGEX REPLACE "\\.gz$" "" page "${OUTPUT}")
# The NAME line goes through an include file: help2man would read a --name argument as
# Latin-1 and garble Chinese.
get_filename_component(program_name "${PROGRAM}" NAME)
set(include_file "${page}.h2m")
file(WRITE "${include_file}" "[NAME]\n${program_name} \\- ${NAME}\n")
if(INCLUDE)
  file(READ "${INCLUDE}" extra)
  file(APPEND "${include_file}" "\n${extra}")
endif()
set(args --no-info --section=1 --locale=C.UTF-8 "--include=${include_file}" "--help-option=${help_option}"
         "--version-option=${version_option}" --output=${page})
set(ENV{QT_QPA_PLATFORM} offscreen)
set(ENV{LC_ALL} C.UTF-8)
execute_process(COMMAND "${HELP2MAN}" ${args} "${PROGRAM}" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man ${PROGRAM} failed (${rc}): ${err}")
endif()
execute_process(COMMAND gzip -9nf "${page}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip ${page} failed")
endif()
