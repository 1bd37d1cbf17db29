# The installable package (docs/package.md): `cmake --install build --prefix P`
# puts the library rocking_core (exported as rocking_q::core), its public
# headers under P/include/rocking_q, the `rocking` command under P/bin, the
# Python module (python/CMakeLists.txt) and a CMake package config, so that
# another project does find_package(rocking_q) and links rocking_q::core.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The headers a user of the library includes, and only those (their includes
# stay inside this list: the consumer test compiles each one alone against
# the installed tree).  The rest of src/ is internal: the closed form of a
# step, the record kernel and the run's rules (dynamics/closed_piece.hpp,
# exact_record.hpp, run_rules.hpp), root finding (numerics/), the FFT and
# the CWT (records/fft.hpp, cwt.hpp), the scaled input of the studies
# (studies/scaled_input.hpp), the batch engine (batch/), the harness's
# tables and diffs (harness/) and the command line (cli/).
set(ROCKING_PUBLIC_HEADERS
  pulse/pulse_train.hpp
  qfactor/superposition.hpp
  qfactor/closed_forms.hpp
  qfactor/printed.hpp
  qfactor/imperfect_q.hpp
  dynamics/model.hpp
  dynamics/ground_input.hpp
  dynamics/stepper.hpp
  dynamics/simulate.hpp
  dynamics/imperfect_block.hpp
  records/record.hpp
  records/measures.hpp
  records/collapse.hpp
  records/synthetic.hpp
  records/floor_motion.hpp
  studies/intervals.hpp
  studies/overturning_set.hpp
  studies/resampling.hpp
  studies/fragility.hpp
  studies/stripe_fit.hpp
  studies/ida.hpp
  studies/spectrum.hpp
  studies/eq27_at_scale.hpp
  studies/eq27_of_block.hpp)
foreach(header ${ROCKING_PUBLIC_HEADERS})
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rocking_q/${folder})
endforeach()

# The build tree's include folders as they are, the installed one from the
# prefix; position independent, so that it also links into shared objects
# (the Python module, a consumer's plugin).
get_target_property(rocking_core_includes rocking_core INTERFACE_INCLUDE_DIRECTORIES)
set(rocking_core_interface)
foreach(folder ${rocking_core_includes})
  list(APPEND rocking_core_interface "$<BUILD_INTERFACE:${folder}>")
endforeach()
set_target_properties(rocking_core PROPERTIES
  EXPORT_NAME core
  POSITION_INDEPENDENT_CODE ON
  INTERFACE_INCLUDE_DIRECTORIES "${rocking_core_interface};$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/rocking_q>")
add_library(rocking_q::core ALIAS rocking_core)

install(TARGETS rocking_core EXPORT rocking_qTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS rocking RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT rocking_qTargets NAMESPACE rocking_q:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rocking_q)
configure_package_config_file(cmake/rocking_qConfig.cmake.in ${CMAKE_BINARY_DIR}/rocking_qConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rocking_q)
install(FILES ${CMAKE_BINARY_DIR}/rocking_qConfig.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rocking_q)

# Install into a temporary prefix, build tests/consumer against it and run it;
# import the installed Python module from the prefix.
add_test(NAME install_package
         COMMAND ${CMAKE_SOURCE_DIR}/tests/install_test.sh ${CMAKE_COMMAND} ${CMAKE_BINARY_DIR}
                 ${CMAKE_SOURCE_DIR}/tests/consumer ${CMAKE_CXX_COMPILER} ${ROCKING_PYTHON_MODULE}
                 ${CMAKE_INSTALL_LIBDIR} ${ROCKING_PYTHON_INSTALL_DIR})
