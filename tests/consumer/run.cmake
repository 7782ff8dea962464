# Installs the qmc build into a scratch prefix, builds tests/consumer against
# it with find_package(qmc), and decodes a conformance vector with it.
file(REMOVE_RECURSE ${WORK_DIR}/prefix ${WORK_DIR}/build)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${QMC_BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${QMC_SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix ${CONSUMER_OPTIONS} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configure with find_package(qmc) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "build against qmc::decoder failed")
endif()
# Runs a consumer on the cube of quads and expects its counts in the output.
function(expect_cube consumer expected)
  execute_process(COMMAND ${WORK_DIR}/build/${consumer} ${QMC_SOURCE_DIR}/conformance/vectors/valid_cube_8bit.qmc
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${expected}")
    message(FATAL_ERROR "${consumer} could not decode: ${out}")
  endif()
  message(STATUS "${consumer}: ${out}")
endfunction()
expect_cube(consumer "8 vertices, 6 faces")
expect_cube(consumer_c "C: 8 vertices, 6 faces, 12 triangles")
