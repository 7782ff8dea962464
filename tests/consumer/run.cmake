# Installs the qmc build into a scratch prefix, builds tests/consumer against
# it with find_package(qmc), and decodes a conformance vector with it.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${QMC_BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${QMC_SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configure with find_package(qmc) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "build against qmc::decoder failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer ${QMC_SOURCE_DIR}/conformance/vectors/valid_cube_8bit.qmc
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "8 vertices, 6 faces")
  message(FATAL_ERROR "consumer could not decode: ${out}")
endif()
message(STATUS "consumer: ${out}")
