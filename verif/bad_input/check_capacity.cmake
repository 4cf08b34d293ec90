# An engine's capacity is checked for every frame before the first output: a scene whose frames
# hold 75,625 polygons (make_dense_scene.py) through `render --frames 0:1` and `compare` exits 2,
# names the scene and the limit, and writes nothing.
#   cmake -DCIG=<cig> -DPYTHON=<python3> -DSOURCE=<repo> -DWORK=<dir> -P check_capacity.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${PYTHON} ${SOURCE}/verif/bad_input/make_dense_scene.py ${WORK}/dense.json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_dense_scene.py failed")
endif()
foreach(cmd "render;${WORK}/dense.json;--engine;quadtree;--frames;0:1;--out;${WORK}/out" "compare;${WORK}/dense.json;--engine;segment;--frames;0:1;--out;${WORK}/out")
  execute_process(COMMAND ${CIG} ${cmd} RESULT_VARIABLE rc ERROR_VARIABLE err)
  list(GET cmd 0 name)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "dense.json: polygons: the .* engine takes at most 65536 polygons" OR EXISTS ${WORK}/out)
    message(FATAL_ERROR "${name}: expected status 2 naming the limit and no output; got ${rc}: ${err}")
  endif()
endforeach()
