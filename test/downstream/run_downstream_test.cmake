# Install ShapeCorr into a scratch prefix, then configure, build and run a downstream project that
# only does find_package(ShapeCorr).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${code}):\n${out}\n${err}")
  endif()
endfunction()
step(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK}/lib -DSHAPECORR_BUILD_TESTS=OFF -DSHAPECORR_BUILD_TOOLS=OFF
     -DSHAPECORR_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=${WORK}/prefix)
step(${CMAKE_COMMAND} --install ${WORK}/lib)
step(${CMAKE_COMMAND} -S ${DOWNSTREAM} -B ${WORK}/app -DCMAKE_PREFIX_PATH=${WORK}/prefix -DCMAKE_BUILD_TYPE=Release)
step(${CMAKE_COMMAND} --build ${WORK}/app)
step(${WORK}/app/downstream)
message(STATUS "downstream project built and ran against the installed package")
