# One cycle count per frame (cmake -DCIG=<cig> -DSOURCE=<repo> -DWORK=<dir> -DARCHS=<a;b> -P <this>):
# for each architecture, `cig cosim` and `cig render --engine quadtree` on airfield frame 0, channel
# 1 (a frame with non-planar polygons, which both split into triangle fans), compared through
# their JSON reports:
#   * cig cosim: exit 0 (zero mismatches, RTL cycles = model cycles);
#   * its cycles = the engine's raster.cycles.frame;
#   * the stream it counted = the engine's: the fan split on, the same polygons split and triangles
#     added (some: the frame exercises the split), the same polygon count.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(scene ${SOURCE}/scenes/airfield.json)
set(summary "")
foreach(arch IN LISTS ARCHS)
  execute_process(COMMAND ${CIG} cosim ${scene} --frame 0 --channel 1 --arch ${arch} --report ${WORK}/cosim_${arch}.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cig cosim --arch ${arch} exited with ${rc}\n${out}\n${err}")
  endif()
  execute_process(COMMAND ${CIG} render ${scene} --frame 0 --channel 1 --engine quadtree --arch ${arch}
                          --out ${WORK}/render_${arch} --report ${WORK}/render_${arch}.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE rout ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cig render --arch ${arch} exited with ${rc}\n${rout}\n${err}")
  endif()
  file(READ ${WORK}/cosim_${arch}.json cosim)
  file(READ ${WORK}/render_${arch}.json render)
  string(JSON cycles_rtl GET "${cosim}" runs 0 cycles_rtl)
  string(JSON cycles_model GET "${cosim}" runs 0 cycles_model)
  string(JSON cosim_split GET "${cosim}" runs 0 stream polygons_split)
  string(JSON cosim_added GET "${cosim}" runs 0 stream triangles_added)
  string(JSON cosim_polys GET "${cosim}" runs 0 stream polygons)
  string(JSON cosim_on GET "${cosim}" runs 0 stream fan_split)
  string(JSON raster GET "${render}" frames 0 channels 0 raster)
  string(JSON engine_cycles GET "${raster}" cycles frame)
  string(JSON engine_split GET "${raster}" fan_split polygons_split)
  string(JSON engine_added GET "${raster}" fan_split triangles_added)
  string(JSON engine_polys GET "${raster}" polygons)
  if(NOT cycles_rtl EQUAL engine_cycles OR NOT cycles_model EQUAL engine_cycles)
    message(FATAL_ERROR "${arch}: cig cosim counts ${cycles_rtl} cycles (model ${cycles_model}), the quadtree "
                        "engine ${engine_cycles}\n${out}")
  endif()
  if(NOT cosim_on OR NOT cosim_split EQUAL engine_split OR NOT cosim_added EQUAL engine_added
     OR NOT cosim_polys EQUAL engine_polys OR cosim_split LESS 1)
    message(FATAL_ERROR "${arch}: the streams differ: cosim split ${cosim_split} (+${cosim_added} triangles, "
                        "${cosim_polys} polygons), engine ${engine_split} (+${engine_added}, ${engine_polys})")
  endif()
  string(APPEND summary "${arch}: ${cycles_rtl} cycles on both (${cosim_split} polygons split, +${cosim_added} triangles); ")
endforeach()
message(STATUS "${summary}")
