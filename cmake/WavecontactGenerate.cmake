# wavecontact_generate(TARGET <target> N <n> [<n>...])
#
# Generates the roughness evaluators roughness_n<N>.hpp for the given even n at build
# time, with wavecontact-derive, and makes <target> an INTERFACE library that provides
# them (and links wavecontact::runtime). Register them with the runtime:
#   wavecontact::register_roughness_evaluator({96, &wavecontact::generated::roughness_n96_pressure<double>,
#                                              &wavecontact::generated::roughness_n96_load<double>});
# Needs WAVECONTACT_DERIVE_EXECUTABLE (set by find_package(wavecontact)).
function(wavecontact_generate)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "TARGET" "N")
  if(NOT ARG_TARGET OR NOT ARG_N)
    message(FATAL_ERROR "wavecontact_generate: usage: wavecontact_generate(TARGET <target> N <n>...)")
  endif()
  if(NOT WAVECONTACT_DERIVE_EXECUTABLE)
    message(FATAL_ERROR "wavecontact_generate: WAVECONTACT_DERIVE_EXECUTABLE is not set")
  endif()
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_generated")
  set(outputs)
  set(arguments)
  foreach(n IN LISTS ARG_N)
    if(NOT n MATCHES "^[0-9]+$")
      message(FATAL_ERROR "wavecontact_generate: N ${n} is not a positive integer")
    endif()
    math(EXPR odd "${n} % 2")
    if(n LESS 2 OR odd)
      message(FATAL_ERROR "wavecontact_generate: N ${n} must be an even integer >= 2")
    endif()
    list(APPEND outputs "${out}/roughness_n${n}.hpp")
    list(APPEND arguments --n ${n})
  endforeach()
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND "${WAVECONTACT_DERIVE_EXECUTABLE}" ${arguments} --out "${out}"
    DEPENDS "${WAVECONTACT_DERIVE_EXECUTABLE}"
    COMMENT "wavecontact-derive: roughness evaluators for n = ${ARG_N}"
    VERBATIM)
  add_library(${ARG_TARGET} INTERFACE ${outputs})
  target_include_directories(${ARG_TARGET} INTERFACE "${out}")
  target_link_libraries(${ARG_TARGET} INTERFACE wavecontact::runtime)
endfunction()
