# CPack pre-build script (CPACK_PRE_BUILD_SCRIPTS, packaging/CMakeLists.txt): removes the .comment
# section (the compilers' version strings) from every ELF file of the staged package, as Debian's
# dh_strip does. CPack has already stripped the debug information (CPACK_STRIP_FILES).
if(NOT CPACK_TEMPORARY_INSTALL_DIRECTORY)
  set(CPACK_TEMPORARY_INSTALL_DIRECTORY "${CPACK_TEMPORARY_DIRECTORY}")
endif()
file(GLOB_RECURSE staged LIST_DIRECTORIES false "${CPACK_TEMPORARY_INSTALL_DIRECTORY}/*")
foreach(path ${staged})
  if(IS_SYMLINK "${path}")
    continue()
  endif()
  file(READ "${path}" magic LIMIT 4 HEX)
  if(magic STREQUAL "7f454c46")  # \x7fELF
    execute_process(COMMAND ${CPACK_ELASTIC_LAB_STRIP} --remove-section=.comment "${path}" RESULT_VARIABLE failed)
    if(failed)
      message(FATAL_ERROR "strip --remove-section=.comment ${path} failed")
    endif()
  endif()
endforeach()
