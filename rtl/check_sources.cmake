# The check every processor's source list (rtl/*/*_sources.cmake) makes of its own folder: a .sv
# file there missing from the list would silently drop out of lint, synthesis and the models; a
# module at rtl/'s top would belong to no processor (each has its folder).
include_guard(GLOBAL)

# cig_check_rtl_folder(SOURCES NAMES_VAR): SOURCES the list's absolute paths, NAMES_VAR the
# variable that names them (for the message); the folder is the calling list file's.
function(cig_check_rtl_folder sources names_var)
  file(GLOB present CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.sv)
  foreach(file IN LISTS present)
    if(NOT file IN_LIST sources)
      message(FATAL_ERROR "${file} is not listed in ${CMAKE_CURRENT_LIST_FILE} (${names_var})")
    endif()
  endforeach()
  get_filename_component(rtl_dir ${CMAKE_CURRENT_LIST_DIR} DIRECTORY)
  file(GLOB stray CONFIGURE_DEPENDS ${rtl_dir}/*.sv)
  if(stray)
    message(FATAL_ERROR "${stray}: a module at rtl/'s top; put it in its processor's folder")
  endif()
endfunction()
