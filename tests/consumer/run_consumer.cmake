# cmake -P script: install the build tree into a fresh prefix, then configure, build and run the
# consumer project against that prefix only. Any failing step fails the test.
# Inputs: BUILD_DIR, CONFIG, PREFIX, CONSUMER_SOURCE, CONSUMER_BUILD, CXX_COMPILER.
function(run_step)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    string(REPLACE ";" " " shown "${ARGV}")
    message(FATAL_ERROR "consumer proof: step failed (${result}): ${shown}")
  endif()
endfunction()

file(REMOVE_RECURSE ${PREFIX} ${CONSUMER_BUILD})
run_step(${CMAKE_COMMAND} --install ${BUILD_DIR} --config ${CONFIG} --prefix ${PREFIX})
run_step(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${CONSUMER_BUILD} -DCMAKE_BUILD_TYPE=${CONFIG}
         -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_PREFIX_PATH=${PREFIX}
         -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
run_step(${CMAKE_COMMAND} --build ${CONSUMER_BUILD} --config ${CONFIG})
find_program(CONSUMER consumer PATHS ${CONSUMER_BUILD} ${CONSUMER_BUILD}/${CONFIG} NO_DEFAULT_PATH
             REQUIRED)
run_step(${CONSUMER})
