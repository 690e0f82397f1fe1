# Configuring without a dependency stops with one message naming the missing package and the
# script that installs it (here Spectra is hidden from find_package).
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK} -DCMAKE_DISABLE_FIND_PACKAGE_spectra=ON
                        -DSHAPECORR_BUILD_TESTS=OFF -DSHAPECORR_BUILD_TOOLS=OFF -DSHAPECORR_BUILD_EXAMPLES=OFF
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(code EQUAL 0)
  message(FATAL_ERROR "configuring without Spectra succeeded:\n${out}\n${err}")
endif()
if(NOT err MATCHES "missing Spectra \\(libspectra-dev\\)" OR NOT err MATCHES "scripts/setup")
  message(FATAL_ERROR "the message does not name the package and scripts/setup:\n${err}")
endif()
if(err MATCHES "Unknown CMake command")
  message(FATAL_ERROR "configure failed on an unknown command instead:\n${err}")
endif()
message(STATUS "configure without Spectra: ${err}")
