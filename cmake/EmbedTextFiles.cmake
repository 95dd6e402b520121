# ag_embed_text_files(<header> <kName>=<file> ...): generates <header> (under
# the build tree) with each file as a `char kName[]` constant in
# namespace areagraph::embedded, regenerated whenever a file changes.
set(AG_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_text_files.cmake)
function(ag_embed_text_files header)
  set(files)
  foreach(entry ${ARGN})
    string(REGEX REPLACE "^[^=]*=" "" file "${entry}")
    list(APPEND files ${file})
  endforeach()
  string(REPLACE ";" "|" entries "${ARGN}")
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${header} -DENTRIES=${entries} -P ${AG_EMBED_SCRIPT}
    DEPENDS ${files} ${AG_EMBED_SCRIPT}
    COMMENT "embedding web assets in ${header}"
    VERBATIM)
endfunction()
