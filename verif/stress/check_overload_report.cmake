# `cig raster POLYS --engine segment --report FILE` on the overload scene, then the report's
# fields (engine_report.overload, .segments, .frame_memory) checked with string(JSON):
#   * more segments than the 2 x 48K segment memory (an overload), no frame-memory overflow;
#   * the threshold T is the largest code whose cumulative segments (code 0 holds the protected
#     polygons' and the light points') fit both banks: codes 0..T fit, codes 0..T+1 do not;
#   * polygons are dropped only with codes above T, some are, and none with code 0;
#   * what is kept is stored: banks within 48K, nothing lost to a full bank, and the stored
#     segments equal the kept codes' counts.
#   * the drops are never silent: the report's "dropped" and a warning on stderr count them.
# The scene's vertex intensities are random (not planar): with the fan split its 1,711 polygons
# become triangles whose extra edges overflow the frame memory, a different test; the scene is
# sized for the segment memory, so it runs with --fan-split off.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CIG} raster ${POLYS} --engine segment --fan-split off --out ${WORK}/overload.png --report ${WORK}/report.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cig raster failed (${rc}): ${err}")
endif()
file(READ ${WORK}/report.json report)

function(get_field var)
  string(JSON value ERROR_VARIABLE json_error GET "${report}" engine_report ${ARGN})
  if(json_error)
    message(FATAL_ERROR "report: ${json_error}")
  endif()
  set(${var} ${value} PARENT_SCOPE)
endfunction()
function(expect condition_text)
  if(NOT (${ARGN}))
    message(FATAL_ERROR "report check failed: ${condition_text}")
  endif()
endfunction()

get_field(capacity overload bank_capacity)
get_field(threshold overload threshold)
get_field(dropped overload polygons_dropped)
get_field(polygon_segments segments polygon)
get_field(light_segments segments light)
get_field(stored_even segments stored_even)
get_field(stored_odd segments stored_odd)
get_field(lost segments dropped_memory_full)
get_field(overflowed frame_memory polygons_overflowed)
expect("capacity is 48K" capacity EQUAL 49152)

set(sum_even 0)
set(sum_odd 0)
set(kept 0)
set(all 0)
set(dropped_sum 0)
set(fits_next TRUE)
math(EXPR next_code "${threshold} + 1")
foreach(code RANGE 0 15)
  get_field(even overload per_area_code ${code} segments_even)
  get_field(odd overload per_area_code ${code} segments_odd)
  get_field(code_dropped overload per_area_code ${code} polygons_dropped)
  math(EXPR all "${all} + ${even} + ${odd}")
  math(EXPR dropped_sum "${dropped_sum} + ${code_dropped}")
  if(code LESS_EQUAL threshold)
    math(EXPR sum_even "${sum_even} + ${even}")
    math(EXPR sum_odd "${sum_odd} + ${odd}")
    expect("code ${code} <= T = ${threshold} has no dropped polygon" code_dropped EQUAL 0)
  elseif(code EQUAL next_code)
    math(EXPR next_even "${sum_even} + ${even}")
    math(EXPR next_odd "${sum_odd} + ${odd}")
    if(next_even GREATER capacity OR next_odd GREATER capacity)
      set(fits_next FALSE)
    endif()
  endif()
endforeach()
math(EXPR twice_capacity "2 * ${capacity}")
expect("more segments (${all}) than the segment memory (${twice_capacity})" all GREATER twice_capacity)
expect("no frame-memory overflow" overflowed EQUAL 0)
expect("codes 0..T = ${threshold} fit each bank (${sum_even}, ${sum_odd})"
       sum_even LESS_EQUAL capacity AND sum_odd LESS_EQUAL capacity)
expect("T = ${threshold} is the largest that fits" threshold EQUAL 15 OR NOT fits_next)
expect("polygons are dropped" dropped GREATER 0)
expect("per-code drops add up" dropped_sum EQUAL dropped)
expect("banks within capacity" stored_even LESS_EQUAL capacity AND stored_odd LESS_EQUAL capacity)
expect("nothing lost to a full bank" lost EQUAL 0)
expect("stored even = kept even" stored_even EQUAL sum_even)
expect("stored odd = kept odd" stored_odd EQUAL sum_odd)
math(EXPR generated "${polygon_segments} + ${light_segments}")
math(EXPR stored "${stored_even} + ${stored_odd}")
expect("generated segments are stored" generated EQUAL stored)
message(STATUS "ok: threshold ${threshold}, ${dropped} polygons dropped, stored ${stored_even} + ${stored_odd} of ${all}")

# Never silent: the drops are in the report's "dropped" and in a warning on stderr that counts them.
get_field(dropped_report dropped polygons_overload)
get_field(dropped_count overload polygons_dropped)
expect("dropped.polygons_overload equals overload.polygons_dropped" dropped_report EQUAL dropped_count)
string(FIND "${err}" "warning: ${POLYS}: the segment engine's memories were full: ${dropped_count} polygon(s) dropped by the overload threshold" warned)
expect("stderr warns of the ${dropped_count} dropped polygons (stderr: ${err})" NOT warned EQUAL -1)
