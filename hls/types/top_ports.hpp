// The port table of a top function: its signature, written once beside the kernel. A kernel header
// describes its top as
//
//   #define CIG_HLS_PORTS_<top>(PORT, ARRAY, RESULT)
//     RESULT(type)                                         the return type (void: none)
//     PORT(name, direction, interface, type)               a parameter `type name`
//     ARRAY(name, direction, interface, element, extent)   a parameter `element (&name)[extent]`
//
// in the order of the parameters; direction is in, out or inout, interface the port's HLS protocol
// (ap_none, ap_vld, ap_ovld, ap_memory). `inline CIG_HLS_TOP(<top>) { ... }` then defines the
// kernel with exactly that signature, and the hand-off (tools/hls_export.sh, verif/hls_export/)
// expands the same table into the synthesis top at global scope, the testbench's inputs, outputs
// and call, the bundle's port table and its Vitis and Catapult interface directives.
#pragma once

// The signature `RESULT top(PORTS...)`.
#define CIG_HLS_TOP(top) CIG_HLS_TOP_RESULT(top) top(CIG_HLS_TOP_PARAMS(top))
#define CIG_HLS_TOP_RESULT(top) CIG_HLS_PORTS_##top(CIG_HLS_SKIP_PORT, CIG_HLS_SKIP_ARRAY, CIG_HLS_RESULT_TYPE)
#define CIG_HLS_TOP_PARAMS(top) \
  CIG_HLS_DROP_FIRST(CIG_HLS_PORTS_##top(CIG_HLS_PARAM, CIG_HLS_ARRAY_PARAM, CIG_HLS_SKIP_RESULT))

// Expansions of one entry; a list of parameters is built with a leading comma that
// CIG_HLS_DROP_FIRST removes (every top has at least one parameter).
#define CIG_HLS_SKIP_PORT(name, direction, interface, type)
#define CIG_HLS_SKIP_ARRAY(name, direction, interface, element, extent)
#define CIG_HLS_SKIP_RESULT(type)
#define CIG_HLS_RESULT_TYPE(type) type
#define CIG_HLS_PARAM(name, direction, interface, type) , type name
#define CIG_HLS_ARRAY_PARAM(name, direction, interface, element, extent) , element(&name)[extent]
#define CIG_HLS_DROP_FIRST(...) CIG_HLS_DROP_FIRST_I(__VA_ARGS__)
#define CIG_HLS_DROP_FIRST_I(first, ...) __VA_ARGS__
