# cmake -DNM=<nm> -DLIBRARY=<libwavecontact_runtime.a> -P simd_units_export_entry_points_only.cmake
#
# The kernel units are compiled for AVX2/AVX-512 and only called after a CPU check. If one
# of them emitted an out-of-line copy of an inline function (a generated evaluator, a
# standard template), the linker could keep that copy for the portable callers too, which
# would then fault on CPUs without those instructions. So they may define their entry
# points only.
execute_process(COMMAND ${NM} -A -C --defined-only ${LIBRARY}
                OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${LIBRARY}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
set(units_seen 0)
foreach(line IN LISTS lines)
  if(NOT line MATCHES "pressure_simd_avx(2|512)\\.cpp\\.o:")
    continue()
  endif()
  set(units_seen 1)
  # Global or weak definitions (T, W, V, u); local ones (t, r, ...) cannot be shared.
  if(line MATCHES " [TWVu] (.*)$")
    set(symbol "${CMAKE_MATCH_1}")
    # Data, no instruction of the unit's ISA: DW.ref.__gxx_personality_v0, the same pointer in
    # every unit (AddressSanitizer's stack cleanups ask for it), and the typeinfo of function
    # types that clang's UndefinedBehaviorSanitizer checks indirect calls against.
    if(NOT symbol MATCHES "^wavecontact::detail::avx(2|512)::(simd_pressure|simd_point_pressure|simd_add_roughness_pressure|simd_point_angles|simd_all_finite)\\(" AND
       NOT symbol STREQUAL "DW.ref.__gxx_personality_v0" AND NOT symbol MATCHES "^typeinfo (name )?for ")
      message(FATAL_ERROR "a SIMD unit exports ${symbol}:\n  ${line}")
    endif()
  endif()
endforeach()
if(NOT units_seen)
  message(FATAL_ERROR "no pressure_simd_avx*.cpp.o in ${LIBRARY}")
endif()
message(STATUS "the SIMD units export their entry points only")
