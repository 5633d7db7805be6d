# Writes what `cmake --install` puts beside the binary, all from the binary's
# own definitions (vibra --man, vibra --completion): the man pages vibra.1 and
# vibra-COMMAND.1 for every command vibra(1) lists under SEE ALSO, and the
# bash, zsh and fish completions. Everything goes into OUTPUT_DIR/share/...,
# built in OUTPUT_DIR.tmp first and put in place whole, so a failed step
# leaves the previous build's files, never a part.
#   cmake -DVIBRA=path/to/vibra -DOUTPUT_DIR=build/manuals -P write_manuals.cmake
function(vibra_output arguments file)
  execute_process(COMMAND ${VIBRA} ${arguments} OUTPUT_FILE ${file} RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "vibra ${arguments} failed (${failed}): rebuild vibra and read its message above")
  endif()
endfunction()

set(staging ${OUTPUT_DIR}.tmp)
file(REMOVE_RECURSE ${staging})
set(man ${staging}/share/man/man1)
file(MAKE_DIRECTORY ${man} ${staging}/share/bash-completion/completions ${staging}/share/zsh/vendor-completions
     ${staging}/share/fish/vendor_completions.d)
vibra_output("--man;vibra" ${man}/vibra.1)
file(STRINGS ${man}/vibra.1 see_also REGEX "^\\.BR vibra\\\\-[a-z0-9-]+ \\(1\\)")
if(NOT see_also)
  message(FATAL_ERROR "vibra --man vibra names no command pages under SEE ALSO: the page generator changed")
endif()
foreach(line ${see_also})
  string(REGEX REPLACE "^\\.BR vibra\\\\-([a-z0-9-]+) .*" "\\1" command "${line}")
  vibra_output("--man;${command}" ${man}/vibra-${command}.1)
endforeach()
vibra_output("--completion;bash" ${staging}/share/bash-completion/completions/vibra)
vibra_output("--completion;zsh" ${staging}/share/zsh/vendor-completions/_vibra)
vibra_output("--completion;fish" ${staging}/share/fish/vendor_completions.d/vibra.fish)
file(REMOVE_RECURSE ${OUTPUT_DIR})
file(RENAME ${staging} ${OUTPUT_DIR})
file(TOUCH ${OUTPUT_DIR}/stamp)
