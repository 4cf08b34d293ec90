// A top's testbench case from its port table (CIG_HLS_PORTS_<top>, hls/types/top_ports.hpp), so
// that the signature is written once, beside the kernel:
//
//   CIG_TB_PORTS(top)            at global scope: the synthesis top's declaration (::top, the
//                                function the testbench calls and co-simulation replaces) and
//                                cig::hls_tb::top_tb::Ports: kTop and ports(), the --ports rows
//   CIG_TB_CALL_CASE(Name, top)  after CIG_TB_PORTS: a case of one call per vector,
//                                cig::hls_tb::top_tb::Case (alias Name): Input holds the in and
//                                inout ports in the table's order, Output the result, then the
//                                out and inout ports after the call; run() makes the call
//
// A sequence case (state carried from call to call) writes its own Input, Output and run() as
// top_tb::Case, derived from top_tb::Ports. The port types are the table's, unqualified: every
// case lives in a namespace that uses cig::hls.
#pragma once

#include <iostream>
#include <memory>
#include <type_traits>

#include "hls/types/top_ports.hpp"
#include "vector_io.hpp"

namespace cig {
namespace hls_tb {

// What a port's value is in the testbench: its type without reference and const.
template <class T>
using Value = std::remove_cv_t<std::remove_reference_t<T>>;
// A top's result: none (a record without fields) when it returns void.
struct NoResult {};
template <>
struct Fields<NoResult> {
  template <class V, class R>
  static void visit(V&, R&) {}
};
template <class T>
struct ResultOf {
  using type = Value<T>;
};
template <>
struct ResultOf<void> {
  using type = NoResult;
};
template <class F>
void store_result(NoResult&, F&& call) {
  call();
}
template <class R, class F>
void store_result(R& result, F&& call) {
  result = call();
}

// "name bits, name NxBits, ..." of a record (of an array's element); "" for a leaf.
template <class T>
std::string field_summary(const T& x);
template <class E, std::size_t N>
std::string field_summary(const E (&x)[N], ArrayKind) {
  return field_summary(x[0]);
}
template <class T>
std::string field_summary(const T&, LeafKind) {
  return "";
}
template <class T>
std::string field_summary(const T& x, RecordKind) {
  FieldLister lister;
  Fields<T>::visit(lister, x);
  std::string s;
  for (const FieldWidth& f : lister.fields) {
    s += s.empty() ? "" : ", ";
    s += f.name + " " + (f.count > 1 ? std::to_string(f.count) + "x" : "") + std::to_string(f.element_bits);
  }
  return s;
}
template <class T>
std::string field_summary(const T& x) {
  return field_summary(x, KindOf<T>{});
}

// --ports: one Markdown row per port (name, direction, interface, C++ type, bits, fields), the
// widths measured on a value of the port's type (on the heap: memories are large).
struct PortPrinter {
  template <class T>
  struct Holder {
    T value;
  };
  template <class T>
  void port(const char* name, const char* direction, const char* interface, const char* type) {
    if (std::is_same<T, NoResult>::value) return;  // void: no return port
    const auto v = std::make_unique<Holder<T>>();
    std::cout << "| `" << name << "` | " << direction << " | " << interface << " | `" << type << "` | "
              << bits_of(v->value) << " | " << field_summary(v->value) << " |\n";
  }
};

}  // namespace hls_tb
}  // namespace cig

// ---- CIG_TB_PORTS -------------------------------------------------------------------------------
// The return value's interface is the block protocol's: ap_return, valid with ap_done (ap_ctrl_hs).
#define CIG_TB_ROW_PORT(name, direction, interface, type) \
  v.template port<Value<type>>(#name, #direction, #interface, #type);
#define CIG_TB_ROW_ARRAY(name, direction, interface, element, extent) \
  v.template port<Value<element>[extent]>(#name, #direction, #interface, #element " (&)[" #extent "]");
#define CIG_TB_ROW_RESULT(rtype) v.template port<typename ResultOf<rtype>::type>("return", "out", "ap_ctrl_hs", #rtype);

#define CIG_TB_PORTS(top)                                                         \
  decltype(::cig::hls::top) top;                                                  \
  namespace cig {                                                                 \
  namespace hls_tb {                                                              \
  namespace top##_tb {                                                            \
    using namespace ::cig::hls;                                                   \
    struct Ports {                                                                \
      static constexpr const char* kTop = #top;                                   \
      template <class V>                                                          \
      static void ports(V& v) {                                                   \
        CIG_HLS_PORTS_##top(CIG_TB_ROW_PORT, CIG_TB_ROW_ARRAY, CIG_TB_ROW_RESULT) \
      }                                                                           \
    };                                                                            \
  }                                                                               \
  }                                                                               \
  }

// ---- CIG_TB_CALL_CASE ---------------------------------------------------------------------------
// Fields of Input (in, inout) and Output (out, inout), by direction.
#define CIG_TB_IN_FIELD_in(type, name) type name{};
#define CIG_TB_IN_FIELD_out(type, name)
#define CIG_TB_IN_FIELD_inout(type, name) type name{};
#define CIG_TB_OUT_FIELD_in(type, name)
#define CIG_TB_OUT_FIELD_out(type, name) type name{};
#define CIG_TB_OUT_FIELD_inout(type, name) type name{};
#define CIG_TB_INPUT_PORT(name, direction, interface, type) CIG_TB_IN_FIELD_##direction(Value<type>, name)
#define CIG_TB_INPUT_ARRAY(name, direction, interface, element, extent) \
  CIG_TB_IN_FIELD_##direction(Value<element>, name[extent])
#define CIG_TB_OUTPUT_PORT(name, direction, interface, type) CIG_TB_OUT_FIELD_##direction(Value<type>, name)
#define CIG_TB_OUTPUT_ARRAY(name, direction, interface, element, extent) \
  CIG_TB_OUT_FIELD_##direction(Value<element>, name[extent])
#define CIG_TB_OUTPUT_RESULT(rtype) typename ResultOf<rtype>::type result{};

// The visitors: v(r.name, "name") per field.
#define CIG_TB_VISIT_in(name) v(r.name, #name);
#define CIG_TB_VISIT_out(name)
#define CIG_TB_VISIT_inout(name) v(r.name, #name);
#define CIG_TB_VISIT_OUT_in(name)
#define CIG_TB_VISIT_OUT_out(name) v(r.name, #name);
#define CIG_TB_VISIT_OUT_inout(name) v(r.name, #name);
#define CIG_TB_VISIT_INPUT_PORT(name, direction, interface, type) CIG_TB_VISIT_##direction(name)
#define CIG_TB_VISIT_INPUT_ARRAY(name, direction, interface, element, extent) CIG_TB_VISIT_##direction(name)
#define CIG_TB_VISIT_OUTPUT_PORT(name, direction, interface, type) CIG_TB_VISIT_OUT_##direction(name)
#define CIG_TB_VISIT_OUTPUT_ARRAY(name, direction, interface, element, extent) CIG_TB_VISIT_OUT_##direction(name)
#define CIG_TB_VISIT_RESULT(type) v(r.result, "return");

// The call: inputs from Input, outputs (inout: copied from Input first) into Output.
#define CIG_TB_ARG_in(name) , i.name
#define CIG_TB_ARG_out(name) , o.name
#define CIG_TB_ARG_inout(name) , o.name
#define CIG_TB_ARG_PORT(name, direction, interface, type) CIG_TB_ARG_##direction(name)
#define CIG_TB_ARG_ARRAY(name, direction, interface, element, extent) CIG_TB_ARG_##direction(name)
#define CIG_TB_COPY_in(name)
#define CIG_TB_COPY_out(name)
#define CIG_TB_COPY_inout(name) copy_value(o.name, i.name);
#define CIG_TB_COPY_PORT(name, direction, interface, type) CIG_TB_COPY_##direction(name)
#define CIG_TB_COPY_ARRAY(name, direction, interface, element, extent) CIG_TB_COPY_##direction(name)

#define CIG_TB_CALL_CASE(Name, top)                                                                                \
  CIG_TB_PORTS(top)                                                                                                \
  namespace cig {                                                                                                  \
  namespace hls_tb {                                                                                               \
  namespace top##_tb {                                                                                             \
    struct Case : Ports {                                                                                          \
      struct Input {                                                                                               \
        CIG_HLS_PORTS_##top(CIG_TB_INPUT_PORT, CIG_TB_INPUT_ARRAY, CIG_HLS_SKIP_RESULT)                            \
      };                                                                                                           \
      struct Output {                                                                                              \
        CIG_HLS_PORTS_##top(CIG_HLS_SKIP_PORT, CIG_HLS_SKIP_ARRAY, CIG_TB_OUTPUT_RESULT) CIG_HLS_PORTS_            \
            ##top(CIG_TB_OUTPUT_PORT, CIG_TB_OUTPUT_ARRAY, CIG_HLS_SKIP_RESULT)                                    \
      };                                                                                                           \
      static void run(const Input& i, Output& o) {                                                                 \
        CIG_HLS_PORTS_##top(CIG_TB_COPY_PORT, CIG_TB_COPY_ARRAY, CIG_HLS_SKIP_RESULT) store_result(o.result, [&] { \
          return CIG_TB_DESIGN(top)(                                                                               \
              CIG_HLS_DROP_FIRST(CIG_HLS_PORTS_##top(CIG_TB_ARG_PORT, CIG_TB_ARG_ARRAY, CIG_HLS_SKIP_RESULT)));    \
        });                                                                                                        \
      }                                                                                                            \
    };                                                                                                             \
  }                                                                                                                \
  using Name = top##_tb::Case;                                                                                     \
  template <>                                                                                                      \
  struct Fields<Name::Input> {                                                                                     \
    template <class V, class R>                                                                                    \
    static void visit(V& v, R& r) {                                                                                \
      CIG_HLS_PORTS_##top(CIG_TB_VISIT_INPUT_PORT, CIG_TB_VISIT_INPUT_ARRAY, CIG_HLS_SKIP_RESULT)                  \
    }                                                                                                              \
  };                                                                                                               \
  template <>                                                                                                      \
  struct Fields<Name::Output> {                                                                                    \
    template <class V, class R>                                                                                    \
    static void visit(V& v, R& r) {                                                                                \
      CIG_HLS_PORTS_##top(CIG_HLS_SKIP_PORT, CIG_HLS_SKIP_ARRAY, CIG_TB_VISIT_RESULT)                              \
          CIG_HLS_PORTS_##top(CIG_TB_VISIT_OUTPUT_PORT, CIG_TB_VISIT_OUTPUT_ARRAY, CIG_HLS_SKIP_RESULT)            \
    }                                                                                                              \
  };                                                                                                               \
  }                                                                                                                \
  }
