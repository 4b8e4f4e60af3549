# wavecontact_generate(TARGET <target> [N <n>...]
#                      [PROFILE <name> EXPRESSION <expr> [PARAMETERS <p>[=<sample>]...]])
#
# Generates evaluators at build time with wavecontact-derive and makes <target> an
# INTERFACE library that provides them (and links wavecontact::runtime):
# - N: the roughness evaluators roughness_n<N>.hpp for the given even n. Register them:
#     wavecontact::register_roughness_evaluator({96, &wavecontact::generated::roughness_n96_pressure<double>,
#                                                &wavecontact::generated::roughness_n96_load<double>,
#                                                &wavecontact::generated::roughness_n96_legendre<double>});
# - PROFILE: a user profile y(x) (wavecontact-derive --profile, derive/formulas/user_profile.hpp) into
#   profile_<name>.hpp. Register it:
#     wavecontact::register_profile(wavecontact::generated::<name>_profile_evaluator());
# Needs WAVECONTACT_DERIVE_EXECUTABLE (set by find_package(wavecontact)). An optional
# WAVECONTACT_DERIVE_LAUNCHER (a command prefix, e.g. `cmake -E env VAR=VALUE`) runs it, as the
# project's own sanitizer build does to pass LeakSanitizer its suppressions.
function(wavecontact_generate)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "TARGET;PROFILE;EXPRESSION" "N;PARAMETERS")
  set(usage "usage: wavecontact_generate(TARGET <target> [N <n>...] [PROFILE <name> EXPRESSION <expr> [PARAMETERS <p>...]])")
  if(NOT ARG_TARGET OR (NOT ARG_N AND NOT ARG_PROFILE))
    message(FATAL_ERROR "wavecontact_generate: ${usage}")
  endif()
  if((ARG_PROFILE AND NOT ARG_EXPRESSION) OR (ARG_EXPRESSION AND NOT ARG_PROFILE) OR
     (ARG_PARAMETERS AND NOT ARG_PROFILE))
    message(FATAL_ERROR "wavecontact_generate: PROFILE and EXPRESSION go together; ${usage}")
  endif()
  if(NOT WAVECONTACT_DERIVE_EXECUTABLE)
    message(FATAL_ERROR "wavecontact_generate: WAVECONTACT_DERIVE_EXECUTABLE is not set")
  endif()
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}_generated")
  set(all_outputs)
  set(include_dirs)
  if(ARG_N)
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
      COMMAND ${WAVECONTACT_DERIVE_LAUNCHER} "${WAVECONTACT_DERIVE_EXECUTABLE}" ${arguments} --out "${out}"
      DEPENDS "${WAVECONTACT_DERIVE_EXECUTABLE}"
      COMMENT "wavecontact-derive: roughness evaluators for n = ${ARG_N}"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
    list(APPEND include_dirs "${out}")
  endif()
  if(ARG_PROFILE)
    # Its own directory, apart from the roughness evaluators'.
    set(profile_out "${out}/profile_${ARG_PROFILE}")
    set(arguments --profile "${ARG_EXPRESSION}" --name "${ARG_PROFILE}")
    foreach(p IN LISTS ARG_PARAMETERS)
      list(APPEND arguments --param "${p}")
    endforeach()
    set(outputs "${profile_out}/profile_${ARG_PROFILE}.hpp" "${profile_out}/profile_${ARG_PROFILE}_manifest.txt")
    add_custom_command(
      OUTPUT ${outputs}
      COMMAND ${WAVECONTACT_DERIVE_LAUNCHER} "${WAVECONTACT_DERIVE_EXECUTABLE}" ${arguments} --out "${profile_out}"
      DEPENDS "${WAVECONTACT_DERIVE_EXECUTABLE}"
      COMMENT "wavecontact-derive: profile ${ARG_PROFILE} = ${ARG_EXPRESSION}"
      VERBATIM)
    list(APPEND all_outputs ${outputs})
    list(APPEND include_dirs "${profile_out}")
  endif()
  add_library(${ARG_TARGET} INTERFACE ${all_outputs})
  target_include_directories(${ARG_TARGET} INTERFACE ${include_dirs})
  target_link_libraries(${ARG_TARGET} INTERFACE wavecontact::runtime)
endfunction()
