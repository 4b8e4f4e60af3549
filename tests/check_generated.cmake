# Regenerates into FRESH and fails, printing a unified diff, if COMMITTED differs.
file(REMOVE_RECURSE "${FRESH}")
execute_process(COMMAND "${DERIVE}" --out "${FRESH}" RESULT_VARIABLE derive_result)
if(NOT derive_result EQUAL 0)
  message(FATAL_ERROR "wavecontact-derive failed (${derive_result})")
endif()
execute_process(COMMAND diff -ru "${COMMITTED}" "${FRESH}"
                RESULT_VARIABLE diff_result OUTPUT_VARIABLE diff_output)
if(NOT diff_result EQUAL 0)
  message(FATAL_ERROR "generated/ is stale; regenerate with `cmake --build <build> --target regenerate`:\n${diff_output}")
endif()
message(STATUS "generated/ is current")
