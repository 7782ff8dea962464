# The decoder-only package on a machine without OpenMesh and Eigen: builds qmc
# with QMC_BUILD_ENCODER=OFF and QMC_SHARED=ON while find_package cannot see
# either, installs it to a scratch prefix, checks that libqmc exports the C
# API alone, then builds and runs tests/consumer (via run.cmake) hiding them too.
file(REMOVE_RECURSE ${WORK_DIR})
set(hide_encoder_deps -DCMAKE_DISABLE_FIND_PACKAGE_OpenMesh=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${QMC_SOURCE_DIR} -B ${WORK_DIR}/qmc -G Ninja -DCMAKE_BUILD_TYPE=Release
                        -DQMC_BUILD_ENCODER=OFF -DQMC_BUILD_TESTS=OFF -DQMC_SHARED=ON ${hide_encoder_deps}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring qmc with QMC_BUILD_ENCODER=OFF failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/qmc -j 1 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the decoder-only qmc failed")
endif()
file(GLOB shared_library ${WORK_DIR}/qmc/src/libqmc.so)
execute_process(COMMAND nm -D --defined-only ${shared_library} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
string(REGEX MATCHALL "[0-9a-f]+ T [^\n]+" functions "${symbols}")
list(FILTER functions EXCLUDE REGEX " T (qmc_|_init$|_fini$)")
if(NOT rc EQUAL 0 OR NOT symbols MATCHES " T qmc_decoder_feed" OR functions)
  message(FATAL_ERROR "libqmc.so must export the qmc_* functions alone; also exports: ${functions}")
endif()
set(QMC_BUILD_DIR ${WORK_DIR}/qmc)
set(CONSUMER_OPTIONS ${hide_encoder_deps})
include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)
