// hls_subset_check: enforces the HLS subset of hls/ (see README.md in this folder).
//
//   hls_subset_check --cxx <g++> --root <repository root> [--work <dir>] [--jobs <n>] <dir|header>...
//
// Every *.hpp under each directory (found when the check runs) and every header named directly is
// checked three ways:
//   1. compile: a generated translation unit per header -- the allowed standard headers, then
//      #pragma GCC poison of the forbidden identifiers, then the header -- compiled by GCC in the
//      synthesis configuration (-D__SYNTHESIS__, no CIG_HLS_SYSTEMC) with a directory of poisoned
//      standard headers searched first. The include tree (-H) must hold only hls/ headers and the
//      allowed standard headers.
//   2. call graph: the same compile emits every inline function (-fkeep-inline-functions, so every
//      top function and everything it instantiates) with -fcallgraph-info; a cycle among functions
//      defined in hls/ is recursion, a call to __indirect_call is a call through a function
//      pointer or a virtual function.
//   3. source scan: tokens with comments and literals separated out; forbidden constructs, the
//      static-loop-bound forms, static locals, and the one-top-function rule.
//
// Output: one line per violation, "FILE:LINE: rule: message" (FILE relative to the root when it
// lies under it), then a summary. Exit status: 0 in the subset, 1 violations, 2 the check itself
// could not run (usage, no headers, the compiler could not be run).
#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace fs = std::filesystem;

namespace {

// ---- The subset ---------------------------------------------------------------------------------

// Standard headers hls/ may include: fixed-width integer typedefs, size_t / ptrdiff_t, integer
// limits as macros, and compile-time type traits. None of them declares a function that runs at
// run time, allocates or touches floating point.
const std::set<std::string> kAllowedStdHeaders = {"cstdint",  "cstddef",  "climits", "type_traits",
                                                  "stdint.h", "stddef.h", "limits.h"};
// Included by the generated translation unit before the poison pragma (their own code may use
// float and the other poisoned identifiers).
const char* const kPreIncluded[] = {"cstdint", "cstddef", "climits", "type_traits"};

// Every other standard header (C++23 and the C library) is replaced by a file that fails.
const char* const kPoisonedStdHeaders[] = {
    "algorithm", "any", "array", "atomic", "barrier", "bit", "bitset", "cassert", "ccomplex", "cctype", "cerrno",
    "cfenv", "cfloat", "charconv", "chrono", "cinttypes", "ciso646", "clocale", "cmath", "codecvt", "compare",
    "complex", "concepts", "condition_variable", "coroutine", "csetjmp", "csignal", "cstdalign", "cstdarg", "cstdbool",
    "cstdio", "cstdlib", "cstring", "ctgmath", "ctime", "cuchar", "cwchar", "cwctype", "deque", "exception",
    "execution", "expected", "filesystem", "flat_map", "flat_set", "format", "forward_list", "fstream", "functional",
    "future", "generator", "initializer_list", "iomanip", "ios", "iosfwd", "iostream", "istream", "iterator", "latch",
    "limits", "list", "locale", "map", "mdspan", "memory", "memory_resource", "mutex", "new", "numbers", "numeric",
    "optional", "ostream", "print", "queue", "random", "ranges", "ratio", "regex", "scoped_allocator", "semaphore",
    "set", "shared_mutex", "source_location", "span", "spanstream", "sstream", "stack", "stacktrace", "stdexcept",
    "stdfloat", "stop_token", "streambuf", "string", "string_view", "strstream", "syncstream", "system_error", "thread",
    "tuple", "typeindex", "typeinfo", "unordered_map", "unordered_set", "utility", "valarray", "variant", "vector",
    "version",
    // C library
    "assert.h", "complex.h", "ctype.h", "errno.h", "fenv.h", "float.h", "inttypes.h", "iso646.h", "locale.h", "math.h",
    "setjmp.h", "signal.h", "stdalign.h", "stdarg.h", "stdatomic.h", "stdbool.h", "stdio.h", "stdlib.h", "string.h",
    "tgmath.h", "threads.h", "time.h", "uchar.h", "wchar.h", "wctype.h", "malloc.h", "alloca.h", "memory.h",
    "strings.h"};

// Identifiers poisoned in the translation unit, and the rule each one breaks.
const std::map<std::string, std::string> kPoisoned = {{"float", "floating-point"},
                                                      {"double", "floating-point"},
                                                      {"__float128", "floating-point"},
                                                      {"__fp16", "floating-point"},
                                                      {"__bf16", "floating-point"},
                                                      {"_Float16", "floating-point"},
                                                      {"_Float32", "floating-point"},
                                                      {"_Float64", "floating-point"},
                                                      {"_Float128", "floating-point"},
                                                      {"while", "while-loop"},
                                                      {"do", "while-loop"},
                                                      {"goto", "goto"},
                                                      {"new", "dynamic-memory"},
                                                      {"malloc", "dynamic-memory"},
                                                      {"calloc", "dynamic-memory"},
                                                      {"realloc", "dynamic-memory"},
                                                      {"aligned_alloc", "dynamic-memory"},
                                                      {"alloca", "dynamic-memory"},
                                                      {"__builtin_malloc", "dynamic-memory"},
                                                      {"__builtin_alloca", "dynamic-memory"},
                                                      {"virtual", "virtual"},
                                                      {"throw", "exceptions"},
                                                      {"try", "exceptions"},
                                                      {"catch", "exceptions"},
                                                      {"typeid", "rtti"},
                                                      {"dynamic_cast", "rtti"}};

const char* const kWaiverTag = "hls-subset-ok:";
const char* const kHelperTag = "hls-subset-helper:";

// ---- Small helpers ------------------------------------------------------------------------------

struct Violation {
  std::string file;  // canonical path
  int line = 0;
  std::string rule;
  std::string message;
  bool operator<(const Violation& o) const {
    return std::tie(file, line, rule, message) < std::tie(o.file, o.line, o.rule, o.message);
  }
};

bool read_file(const fs::path& p, std::string& out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }
bool ends_with(const std::string& s, const std::string& p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

fs::path canon(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : c;
}

bool is_under(const fs::path& p, const fs::path& dir) {
  const std::string ps = p.string(), ds = dir.string();
  return ps.size() > ds.size() && starts_with(ps, ds) && (ds.back() == '/' || ps[ds.size()] == '/');
}

// ---- Lexer --------------------------------------------------------------------------------------

struct Token {
  enum Kind { kIdent, kNumber, kString, kChar, kPunct } kind = kPunct;
  std::string text;
  int line = 0;
  bool space_before = false;
};
using Tokens = std::vector<Token>;

struct Include {
  std::string name;
  bool angled = false;
  int line = 0;
};

struct Waiver {
  std::string reason;
  bool used = false;
};

struct Lexed {
  Tokens code;                 // everything outside preprocessor directives
  std::vector<Tokens> macros;  // the body of each #define
  std::vector<Include> includes;
  std::map<int, Waiver> waivers;  // by line
  int helper_line = 0;            // "// hls-subset-helper: <reason>"
  std::string helper_reason;
};

const char* const kPuncts[] = {">>=", "<<=", "->*", "...", "::", "->", "++", "--", "<<", ">>", "<=", ">=", "==",
                               "!=",  "&&",  "||",  "+=",  "-=", "*=", "/=", "%=", "&=", "|=", "^=", ".*", "##"};

bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80;
}

Lexed lex(const std::string& s) {
  Lexed out;
  const size_t n = s.size();
  size_t i = 0;
  int line = 1;
  bool line_start = true, in_directive = false, space = true;
  Tokens directive;

  auto finish_directive = [&]() {
    in_directive = false;
    if (directive.empty()) return;
    const std::string& name = directive[0].text;
    if ((name == "include" || name == "include_next") && directive.size() >= 2) {
      Include inc;
      inc.line = directive[0].line;
      if (directive[1].kind == Token::kString) {
        inc.name = directive[1].text.substr(1, directive[1].text.size() - 2);
      } else if (directive[1].text == "<") {
        inc.angled = true;
        for (size_t k = 2; k < directive.size() && directive[k].text != ">"; ++k) inc.name += directive[k].text;
      }
      if (!inc.name.empty()) out.includes.push_back(inc);
    } else if (name == "define" && directive.size() >= 2) {
      size_t k = 2;
      if (k < directive.size() && directive[k].text == "(" && !directive[k].space_before) {
        while (k < directive.size() && directive[k].text != ")") ++k;
        ++k;
      }
      if (k < directive.size()) out.macros.emplace_back(directive.begin() + static_cast<long>(k), directive.end());
    }
    directive.clear();
  };
  auto comment = [&](const std::string& text, int at) {
    for (const char* tag : {kWaiverTag, kHelperTag}) {
      const size_t p = text.find(tag);
      if (p == std::string::npos) continue;
      std::string reason = text.substr(p + std::strlen(tag));
      reason = trim(reason.substr(0, reason.find("//")));  // another comment may follow
      if (tag == kWaiverTag) {
        out.waivers[at].reason = reason;
      } else {
        out.helper_line = at;
        out.helper_reason = reason;
      }
    }
  };

  while (i < n) {
    const char c = s[i];
    if (c == '\\' && i + 1 < n && (s[i + 1] == '\n' || (s[i + 1] == '\r' && i + 2 < n && s[i + 2] == '\n'))) {
      i += s[i + 1] == '\n' ? 2 : 3;  // line splice
      ++line;
      space = true;
      continue;
    }
    if (c == '\n') {
      if (in_directive) finish_directive();
      line_start = true;
      space = true;
      ++line;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      space = true;
      ++i;
      continue;
    }
    if (c == '/' && i + 1 < n && s[i + 1] == '/') {
      size_t e = s.find('\n', i);
      if (e == std::string::npos) e = n;
      comment(s.substr(i + 2, e - i - 2), line);
      i = e;
      space = true;
      continue;
    }
    if (c == '/' && i + 1 < n && s[i + 1] == '*') {
      size_t e = s.find("*/", i + 2);
      e = e == std::string::npos ? n : e + 2;
      line += static_cast<int>(std::count(s.begin() + static_cast<long>(i), s.begin() + static_cast<long>(e), '\n'));
      i = e;
      space = true;
      continue;
    }
    if (line_start && c == '#') {
      in_directive = true;
      line_start = false;
      directive.clear();
      space = true;
      ++i;
      continue;
    }
    line_start = false;

    Token t;
    t.line = line;
    t.space_before = space;
    space = false;
    const size_t start = i;
    auto lex_quoted = [&](char q) {  // s[i] is the opening quote
      ++i;
      while (i < n && s[i] != q && s[i] != '\n') i += s[i] == '\\' ? 2 : 1;
      if (i < n && s[i] == q) ++i;
    };
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80) {
      while (i < n && ident_char(s[i])) ++i;
      const std::string id = s.substr(start, i - start);
      const bool prefix = id == "L" || id == "u" || id == "U" || id == "u8" || id == "R" || id == "LR" || id == "uR" ||
                          id == "UR" || id == "u8R";
      if (prefix && i < n && s[i] == '"' && id.back() == 'R') {  // raw string
        const size_t open = s.find('(', i);
        const std::string delim = open == std::string::npos ? "" : s.substr(i + 1, open - i - 1);
        const size_t close = open == std::string::npos ? n : s.find(")" + delim + "\"", open);
        const size_t e = close == std::string::npos ? n : close + delim.size() + 2;
        line += static_cast<int>(std::count(s.begin() + static_cast<long>(i), s.begin() + static_cast<long>(e), '\n'));
        i = e;
        t.kind = Token::kString;
      } else if (prefix && i < n && (s[i] == '"' || s[i] == '\'') && id.back() != 'R') {
        t.kind = s[i] == '"' ? Token::kString : Token::kChar;
        lex_quoted(s[i]);
      } else {
        t.kind = Token::kIdent;
      }
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      ++i;  // a preprocessing number
      while (i < n) {
        const char d = s[i];
        if ((d == '+' || d == '-') && std::strchr("eEpP", s[i - 1]) != nullptr) {
          ++i;
        } else if (ident_char(d) || d == '.') {
          ++i;
        } else if (d == '\'' && i + 1 < n && ident_char(s[i + 1])) {
          ++i;  // digit separator
        } else {
          break;
        }
      }
      t.kind = Token::kNumber;
    } else if (c == '"' || c == '\'') {
      t.kind = c == '"' ? Token::kString : Token::kChar;
      lex_quoted(c);
    } else {
      t.kind = Token::kPunct;
      size_t len = 1;
      for (const char* p : kPuncts) {
        const size_t l = std::strlen(p);
        if (l > len && s.compare(i, l, p) == 0) len = l;
      }
      i += len;
    }
    t.text = s.substr(start, i - start);
    (in_directive ? directive : out.code).push_back(t);
  }
  if (in_directive) finish_directive();
  return out;
}

// Matching bracket of every ( [ { and ) ] } (-1 when unbalanced).
std::vector<int> match_brackets(const Tokens& ts) {
  std::vector<int> m(ts.size(), -1);
  std::vector<int> st;
  for (size_t i = 0; i < ts.size(); ++i) {
    if (ts[i].kind != Token::kPunct) continue;
    const std::string& x = ts[i].text;
    if (x == "(" || x == "[" || x == "{") {
      st.push_back(static_cast<int>(i));
    } else if (x == ")" || x == "]" || x == "}") {
      const char open = x == ")" ? '(' : x == "]" ? '[' : '{';
      if (!st.empty() && ts[static_cast<size_t>(st.back())].text[0] == open) {
        m[i] = st.back();
        m[static_cast<size_t>(st.back())] = static_cast<int>(i);
        st.pop_back();
      }
    }
  }
  return m;
}

// ---- Facts a file's loops may rely on -----------------------------------------------------------

bool is_k_constant_name(const std::string& s) {
  return s.size() >= 2 && s[0] == 'k' && std::isupper(static_cast<unsigned char>(s[1]));
}
bool is_capital_name(const std::string& s) {
  if (s.empty() || !std::isupper(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_';
  });
}

// Names declared constexpr (variables, not functions).
void collect_constexpr(const Tokens& ts, std::set<std::string>& out) {
  for (size_t i = 0; i < ts.size(); ++i) {
    if (ts[i].text != "constexpr") continue;
    int depth = 0;
    bool seen_eq = false;
    for (size_t j = i + 1; j < ts.size(); ++j) {
      const std::string& x = ts[j].text;
      const bool prev_ident = ts[j - 1].kind == Token::kIdent;
      if (x == "(" || x == "[" || x == "{") {
        if (depth == 0 && !seen_eq && x == "(") break;  // a function (or direct-initialization)
        if (depth == 0 && !seen_eq && x == "{" && prev_ident) out.insert(ts[j - 1].text);
        ++depth;
      } else if (x == ")" || x == "]" || x == "}") {
        if (--depth < 0) break;
      } else if (depth == 0) {
        if (x == ";") break;
        if (x == "=" && !seen_eq) {
          if (prev_ident) out.insert(ts[j - 1].text);
          seen_eq = true;
        }
        if (x == ",") seen_eq = false;
      }
    }
  }
}

// Names of non-type template parameters.
void collect_template_params(const Tokens& ts, std::set<std::string>& out) {
  for (size_t i = 0; i + 1 < ts.size(); ++i) {
    if (ts[i].text != "template" || ts[i + 1].text != "<") continue;
    int angle = 1, paren = 0;
    std::vector<const Token*> param;
    auto finish = [&]() {
      if (!param.empty() && param[0]->text != "class" && param[0]->text != "typename" && param[0]->text != "template") {
        size_t end = param.size();
        for (size_t k = 0; k < param.size(); ++k)
          if (param[k]->text == "=") {
            end = k;
            break;
          }
        for (size_t k = end; k-- > 0;)
          if (param[k]->kind == Token::kIdent) {
            out.insert(param[k]->text);
            break;
          }
      }
      param.clear();
    };
    for (size_t j = i + 2; j < ts.size(); ++j) {
      const std::string& x = ts[j].text;
      if (x == "(" || x == "[" || x == "{") ++paren;
      if (x == ")" || x == "]" || x == "}") --paren;
      if (paren == 0 && x == "<") ++angle;
      if (paren == 0 && x == ">") --angle;
      if (paren == 0 && x == ">>") angle -= 2;
      if (angle <= 0) {
        finish();
        break;
      }
      if (paren == 0 && angle == 1 && x == ",") {
        finish();
        continue;
      }
      param.push_back(&ts[j]);
    }
  }
}

// ---- Source scan --------------------------------------------------------------------------------

bool is_float_literal(const std::string& t) {
  if (t.size() > 1 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) return t.find_first_of(".pP") != std::string::npos;
  return t.find_first_of(".eE") != std::string::npos;
}

bool allowed_std_name(const std::string& n) {
  static const std::set<std::string> exact = {"size_t",
                                              "ptrdiff_t",
                                              "nullptr_t",
                                              "max_align_t",
                                              "byte",
                                              "intmax_t",
                                              "uintmax_t",
                                              "intptr_t",
                                              "uintptr_t",
                                              "enable_if",
                                              "enable_if_t",
                                              "conditional",
                                              "conditional_t",
                                              "integral_constant",
                                              "bool_constant",
                                              "true_type",
                                              "false_type",
                                              "conjunction",
                                              "conjunction_v",
                                              "disjunction",
                                              "disjunction_v",
                                              "negation",
                                              "negation_v",
                                              "void_t",
                                              "decay",
                                              "decay_t",
                                              "common_type",
                                              "common_type_t",
                                              "underlying_type",
                                              "underlying_type_t",
                                              "make_signed",
                                              "make_signed_t",
                                              "make_unsigned",
                                              "make_unsigned_t",
                                              "alignment_of",
                                              "alignment_of_v",
                                              "rank",
                                              "rank_v",
                                              "extent",
                                              "extent_v",
                                              "declval",
                                              "type_identity",
                                              "type_identity_t",
                                              "remove_cvref",
                                              "remove_cvref_t"};
  if (exact.count(n)) return true;
  for (const char* p : {"is_", "has_", "remove_", "add_"})
    if (starts_with(n, p)) return true;
  // <cstdint>: [u]intN_t, [u]int_leastN_t, [u]int_fastN_t.
  std::string m = n;
  if (starts_with(m, "u")) m = m.substr(1);
  if (!starts_with(m, "int") || !ends_with(m, "_t")) return false;
  m = m.substr(3, m.size() - 5);
  if (starts_with(m, "_least")) m = m.substr(6);
  else if (starts_with(m, "_fast")) m = m.substr(5);
  return m == "8" || m == "16" || m == "32" || m == "64";
}

class Scanner {
 public:
  Scanner(const fs::path& file, const Lexed& lx, const std::set<std::string>& constants,
          const std::set<std::string>& template_params, std::vector<Violation>& out)
      : file_(file), lx_(lx), constants_(constants), tparams_(template_params), out_(out) {}

  struct Top {
    std::string name;
    int line;
  };
  std::vector<Top> tops;

  void run() {
    stream(lx_.code, true);
    for (const Tokens& m : lx_.macros) stream(m, false);
  }

 private:
  const fs::path& file_;
  const Lexed& lx_;
  const std::set<std::string>& constants_;
  const std::set<std::string>& tparams_;
  std::vector<Violation>& out_;

  const Tokens* ts_ = nullptr;
  std::vector<int> match_;

  void report(int line, const std::string& rule, const std::string& msg) {
    out_.push_back({file_.string(), line, rule, msg});
  }
  const std::string& text(size_t i) const {
    static const std::string none;
    return i < ts_->size() ? (*ts_)[i].text : none;
  }
  bool ident(size_t i) const { return i < ts_->size() && (*ts_)[i].kind == Token::kIdent; }
  int line(size_t i) const { return (*ts_)[std::min(i, ts_->size() - 1)].line; }

  void stream(const Tokens& ts, bool main) {
    if (ts.empty()) return;
    ts_ = &ts;
    match_ = match_brackets(ts);
    flat_rules();
    if (main) scopes();
  }

  // Constructs that are wrong wherever they appear.
  void flat_rules() {
    const Tokens& ts = *ts_;
    for (size_t i = 0; i < ts.size(); ++i) {
      const Token& t = ts[i];
      const std::string& x = t.text;
      if (t.kind == Token::kNumber) {
        if (is_float_literal(x))
          report(t.line, "floating-point", "floating-point literal '" + x + "' (use Fixed/UFixed raw values)");
        continue;
      }
      if (t.kind == Token::kPunct) {
        if (x == "(") function_pointer_at(i);
        if (x == "::" && text(i + 1) == "*") report(t.line, "function-pointer", "pointer to member ('::*')");
        continue;
      }
      if (t.kind != Token::kIdent) continue;
      const std::string& prev = i > 0 ? ts[i - 1].text : text(ts.size());
      if (x == "float" || x == "double" || x == "__float128" || x == "__fp16" || x == "__bf16" ||
          starts_with(x, "_Float")) {
        report(t.line, "floating-point", "'" + x + "': no floating point in hls/ (use Fixed/UFixed or Int/UInt)");
      } else if (x == "while") {
        if (!closes_do_body(i))
          report(t.line, "while-loop", "'while' loop: write a for loop with a constant bound and an early break");
      } else if (x == "do") {
        report(t.line, "while-loop", "'do ... while' loop: write a for loop with a constant bound and an early break");
      } else if (x == "goto") {
        report(t.line, "goto", "'goto'");
      } else if (x == "new") {
        report(t.line, "dynamic-memory", "'new': no dynamic memory (use fixed-size arrays)");
      } else if (x == "delete" && prev != "=") {
        report(t.line, "dynamic-memory", "'delete': no dynamic memory");
      } else if ((x == "malloc" || x == "calloc" || x == "realloc" || x == "free" || x == "aligned_alloc" ||
                  x == "alloca" || starts_with(x, "__builtin_malloc") || starts_with(x, "__builtin_alloca")) &&
                 text(i + 1) == "(" && prev != "." && prev != "->") {
        report(t.line, "dynamic-memory", "'" + x + "': no dynamic memory");
      } else if (x == "virtual") {
        report(t.line, "virtual", "'virtual': no virtual functions or virtual bases");
      } else if (x == "throw" || x == "try" || x == "catch") {
        report(t.line, "exceptions", "'" + x + "': no exceptions");
      } else if (x == "typeid" || x == "dynamic_cast") {
        report(t.line, "rtti", "'" + x + "': no run-time type information");
      } else if (x == "thread_local") {
        report(t.line, "static-local", "'thread_local' state");
      } else if (x == "std" && text(i + 1) == "::" && ident(i + 2)) {
        const std::string& name = text(i + 2);
        if (!allowed_std_name(name)) {
          const std::string why = name == "function" ? " (no function pointers or type-erased callables)"
                                                     : " (no std containers, strings, streams, smart pointers "
                                                       "or algorithms)";
          report(t.line, "std-library",
                 "'std::" + name + "': only <cstdint>, <cstddef>, <climits> and <type_traits> names are allowed" + why);
        }
      } else if (x == "std" && prev == "namespace") {
        report(t.line, "std-library", "'using namespace std'");
      } else if (x == "for") {
        for_loop(i);
      }
    }
  }

  // `while` that ends a do-while (reported once, at the `do`).
  bool closes_do_body(size_t i) const {
    if (i == 0 || text(i - 1) != "}" || match_[i - 1] <= 0) return false;
    return text(static_cast<size_t>(match_[i - 1]) - 1) == "do";
  }

  // (*name)(   (*)(   (&name)(   (* const name)(
  void function_pointer_at(size_t i) {
    size_t j = i + 1;
    if (text(j) != "*" && text(j) != "&") return;
    ++j;
    while (text(j) == "const" || text(j) == "volatile") ++j;
    if (ident(j) && text(j) != "this") ++j;
    if (text(j) == ")" && text(j + 1) == "(")
      report(line(i), "function-pointer",
             "function pointer or function reference declarator '(" + text(i + 1) + "...)(...)'");
  }

  // ---- for loops: static bounds ----

  // A compile-time constant expression in the accepted forms; `bad` names the first offender.
  bool constant_expr(size_t b, size_t e, std::string& bad) const {
    if (b >= e) {
      bad = "(nothing)";
      return false;
    }
    for (size_t j = b; j < e; ++j) {
      const Token& t = (*ts_)[j];
      if (t.kind == Token::kNumber) {
        if (is_float_literal(t.text)) {
          bad = t.text;
          return false;
        }
        continue;
      }
      if (t.kind == Token::kIdent) {
        if ((t.text == "sizeof" || t.text == "alignof") && text(j + 1) == "(" && match_[j + 1] > 0) {
          j = static_cast<size_t>(match_[j + 1]);
          continue;
        }
        if (text(j + 1) == "::") {  // a qualifier: P::kMax, detail::kFoo
          ++j;
          continue;
        }
        if (is_k_constant_name(t.text)) {
          if (constants_.count(t.text)) continue;
          bad = t.text + "' (not declared constexpr in this header or the hls/ headers it includes";
          return false;
        }
        if (is_capital_name(t.text)) {
          if (tparams_.count(t.text) || constants_.count(t.text)) continue;
          bad = t.text + "' (not a template parameter or constexpr constant of this header";
          return false;
        }
        bad = t.text;
        return false;
      }
      static const std::set<std::string> ops = {"+", "-", "*", "/", "%", "<<", ">>",
                                                "&", "|", "^", "~", "(", ")",  "::"};
      if (t.kind == Token::kPunct && ops.count(t.text)) continue;
      bad = t.text;
      return false;
    }
    return true;
  }

  static std::string show_bad(const std::string& bad) {
    return "'" + bad + (bad.find('(') != std::string::npos && bad.back() != ')' ? ")" : "'");
  }

  void for_loop(size_t f) {
    const int at = line(f);
    const std::string kForms =
        "; a static loop is 'for (int i = C; i OP C; ++i)' with constant C (integer literal, k-prefixed "
        "constexpr, capital template parameter, sizeof) and a run-time limit written as 'if (...) break;'";
    if (text(f + 1) != "(" || match_[f + 1] < 0) return;
    const size_t open = f + 1, close = static_cast<size_t>(match_[open]);
    // Split at top-level ';'.
    std::vector<size_t> semis;
    bool colon = false;
    for (size_t j = open + 1; j < close; ++j) {
      const std::string& x = text(j);
      if ((x == "(" || x == "[" || x == "{") && match_[j] > 0) {
        j = static_cast<size_t>(match_[j]);
        continue;
      }
      if (x == ";") semis.push_back(j);
      if (x == ":") colon = true;
    }
    if (semis.empty() && colon) return;  // range-based for over a fixed-size array
    if (semis.size() != 2) {
      report(at, "loop-bound", "for statement not in the static form" + kForms);
      return;
    }
    // init: [type] i = C   |   [type] i(C)   |   [type] i{C}
    for (size_t j = open + 1; j < semis[0]; ++j) {
      if ((text(j) == "(" || text(j) == "[" || text(j) == "{") && match_[j] > 0) j = static_cast<size_t>(match_[j]);
      if (text(j) == ",") {
        report(at, "loop-bound", "one loop variable per for statement" + kForms);
        return;
      }
    }
    std::string var;
    size_t vb = 0, ve = 0;
    for (size_t j = open + 1; j < semis[0]; ++j) {
      const std::string& x = text(j);
      if ((x == "=" || x == "(" || x == "{") && j > open + 1 && ident(j - 1)) {
        var = text(j - 1);
        vb = j + 1;
        ve = x == "=" ? semis[0] : static_cast<size_t>(std::max(match_[j], 0));
        break;
      }
      if ((x == "(" || x == "[" || x == "{") && match_[j] > 0) j = static_cast<size_t>(match_[j]);
    }
    std::string bad;
    if (var.empty()) {
      report(at, "loop-bound", "the for statement does not initialise its loop variable" + kForms);
      return;
    }
    if (!constant_expr(vb, ve, bad)) {
      report(at, "loop-bound",
             "loop variable '" + var + "' starts at " + show_bad(bad) + ", not a compile-time constant" + kForms);
      return;
    }
    // condition: i OP C or C OP i
    size_t op = 0;
    for (size_t j = semis[0] + 1; j < semis[1]; ++j) {
      const std::string& x = text(j);
      if (x == "<" || x == "<=" || x == ">" || x == ">=" || x == "!=") {
        op = j;
        break;
      }
      if ((x == "(" || x == "[") && match_[j] > 0) j = static_cast<size_t>(match_[j]);
    }
    size_t bb = 0, be = 0;
    if (op != 0 && op == semis[0] + 2 && text(semis[0] + 1) == var) {
      bb = op + 1;
      be = semis[1];
    } else if (op != 0 && op + 2 == semis[1] && text(op + 1) == var) {
      bb = semis[0] + 1;
      be = op;
    } else {
      report(at, "loop-bound",
             "the condition must compare the loop variable '" + var + "' alone with a constant bound" + kForms);
      return;
    }
    if (!constant_expr(bb, be, bad)) {
      if (bad == "&&" || bad == "||")
        report(at, "loop-bound",
               "the condition must be one comparison of the loop variable with a constant bound" + kForms);
      else report(at, "loop-bound", "loop bound " + show_bad(bad) + " is not a compile-time constant" + kForms);
      return;
    }
    // increment: ++i, i++, --i, i--, or i op= C (op one of + - * / << >>)
    const size_t ib = semis[1] + 1, n = close - ib;
    static const std::set<std::string> compound = {"+=", "-=", "*=", "/=", "<<=", ">>="};
    const bool step1 = n == 2 && ((text(ib) == var && (text(ib + 1) == "++" || text(ib + 1) == "--")) ||
                                  (text(ib + 1) == var && (text(ib) == "++" || text(ib) == "--")));
    const bool stepc = n >= 3 && text(ib) == var && compound.count(text(ib + 1)) && constant_expr(ib + 2, close, bad);
    if (!step1 && !stepc) {
      report(at, "loop-bound",
             "the increment must be ++" + var + ", " + var + "++, --" + var + ", " + var + "--, or " + var +
                 " op= C (op: + - * / << >>, C constant)" + kForms);
      return;
    }
    // The body must not assign the loop variable.
    size_t b = close + 1, e = b;
    if (text(b) == "{" && match_[b] > 0) {
      e = static_cast<size_t>(match_[b]);
    } else {
      for (e = b; e < ts_->size() && text(e) != ";"; ++e)
        if ((text(e) == "(" || text(e) == "[" || text(e) == "{") && match_[e] > 0) e = static_cast<size_t>(match_[e]);
    }
    static const std::set<std::string> assign = {
        "=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^=", "++", "--"};
    for (size_t j = b; j < e && j < ts_->size(); ++j) {
      if (text(j) != var) continue;
      const std::string& p = text(j - 1);
      if (p == "." || p == "->" || p == "::" || ident(j - 1) || p == ">" || p == "&" || p == "*")
        continue;  // member, declaration
      if (assign.count(text(j + 1)) || p == "++" || p == "--") {
        report(line(j), "loop-bound",
               "loop variable '" + var + "' is modified in the loop body (the trip count must be static)");
        return;
      }
    }
  }

  // ---- Scope-dependent rules: static locals, top functions ----

  enum Kind { kNamespace, kClass, kCode, kInit };

  void scopes() {
    const Tokens& ts = *ts_;
    std::vector<Kind> stack = {kNamespace};
    std::vector<int> kind_of(ts.size(), -1);  // kind of the scope a '{' opens
    for (size_t i = 0; i < ts.size(); ++i) {
      const std::string& x = ts[i].text;
      if (ts[i].kind == Token::kPunct && x == "{") {
        const Kind k = classify(i, stack.back(), kind_of);
        kind_of[i] = k;
        stack.push_back(k);
      } else if (ts[i].kind == Token::kPunct && x == "}") {
        if (stack.size() > 1) stack.pop_back();
      } else if (ts[i].kind == Token::kIdent && x == "static") {
        const bool in_code = std::find(stack.begin(), stack.end(), kCode) != stack.end();
        if (in_code && stack.back() != kClass) static_local(i);
      } else if (ts[i].kind == Token::kIdent && x.size() > 4 && ends_with(x, "_top") && text(i + 1) == "(" &&
                 std::all_of(stack.begin(), stack.end(), [](Kind k) { return k == kNamespace; })) {
        if (is_definition(i + 1)) tops.push_back({x, ts[i].line});
      } else if (ts[i].kind == Token::kIdent && x == "CIG_HLS_TOP" && text(i + 1) == "(" && text(i + 3) == ")" &&
                 text(i + 4) == "{" && ends_with(text(i + 2), "_top") &&
                 std::all_of(stack.begin(), stack.end(), [](Kind k) { return k == kNamespace; })) {
        tops.push_back({text(i + 2), ts[i].line});  // the signature from its port table (hls/types/top_ports.hpp)
      }
    }
  }

  Kind classify(size_t i, Kind top, const std::vector<int>& kind_of) const {
    if (i == 0) return kCode;
    const Token& p = (*ts_)[i - 1];
    const std::string& x = p.text;
    if (x == ")" || x == "]" || x == "else" || x == "do" || x == "try" || x == "mutable" || x == "&&") return kCode;
    if (x == "=" || x == "(" || x == "," || x == "[" || x == "return" || x == "?" || x == "<") return kInit;
    if (x == "{" || x == ";" || x == "}") return top == kInit ? kInit : kCode;
    if (x == ":") return top == kCode ? kCode : kInit;
    // Otherwise look at the declaration head: namespace, class, function with a trailing return
    // type or a qualifier, or a variable with a brace initializer.
    std::vector<const Token*> head;
    for (size_t j = i; j-- > 0;) {
      const std::string& y = text(j);
      if ((y == ")" || y == "]") && match_[j] >= 0) {
        j = static_cast<size_t>(match_[j]);
        head.push_back(&(*ts_)[j]);
        continue;
      }
      if (y == "}" && match_[j] >= 0 && kind_of[static_cast<size_t>(match_[j])] == kInit) {
        j = static_cast<size_t>(match_[j]);
        continue;
      }
      if (y == ";" || y == "{" || y == "}") break;
      if (y == ":" && j > 0 && (text(j - 1) == "public" || text(j - 1) == "private" || text(j - 1) == "protected"))
        break;
      head.push_back(&(*ts_)[j]);
    }
    std::reverse(head.begin(), head.end());
    for (const Token* t : head)
      if (t->text == "namespace" || (t->text == "extern" && head.size() >= 2)) return kNamespace;
    size_t k = 0;
    while (k < head.size()) {  // skip template<...> heads and attributes
      if (head[k]->text == "template" && k + 1 < head.size() && head[k + 1]->text == "<") {
        int angle = 0;
        for (++k; k < head.size(); ++k) {
          const std::string& y = head[k]->text;
          angle += y == "<" ? 1 : y == ">" ? -1 : y == ">>" ? -2 : 0;
          if (angle <= 0) break;
        }
        ++k;
      } else if (head[k]->text == "typedef" || head[k]->text == "export" || head[k]->text == "[" ||
                 head[k]->text == "alignas") {
        ++k;
      } else {
        break;
      }
    }
    if (k < head.size()) {
      const std::string& y = head[k]->text;
      if (y == "class" || y == "struct" || y == "union" || y == "enum") return kClass;
    }
    if (x == "const" || x == "noexcept" || x == "override" || x == "final" || x == "volatile" || x == "&") return kCode;
    for (const Token* t : head)
      if (t->text == "->") return kCode;
    if (p.kind == Token::kString) return kInit;
    return kInit;
  }

  void static_local(size_t i) {
    for (size_t j = i + 1; j < ts_->size(); ++j) {
      const std::string& x = text(j);
      if (x == "const" || x == "constexpr") return;  // a ROM
      if (x == ";" || x == "=" || x == "{" || x == "(" || x == "[") break;
    }
    report(line(i), "static-local",
           "non-const static local variable (state kept between calls); pass state explicitly, or waive a "
           "deliberate register with // hls-subset-ok: <reason>");
  }

  // ( ... ) followed by qualifiers and a body.
  bool is_definition(size_t open) const {
    if (match_[open] < 0) return false;
    for (size_t j = static_cast<size_t>(match_[open]) + 1; j < ts_->size(); ++j) {
      const std::string& x = text(j);
      if (x == "{") return true;
      if (x == ";" || x == "=" || x == "," || x == ")" || x == "}") return false;
      if ((x == "(" || x == "[") && match_[j] > 0) j = static_cast<size_t>(match_[j]);
    }
    return false;
  }
};

// ---- Running the compiler -----------------------------------------------------------------------

struct Job {
  fs::path header, tu, obj, ci, err;
  std::vector<std::string> args;
  int status = -1;
};

// Runs every job, at most `jobs` at a time; stderr of each to its `err` file.
bool run_jobs(std::vector<Job>& all, unsigned jobs) {
  std::map<pid_t, size_t> running;
  size_t next = 0;
  bool ok = true;
  while (next < all.size() || !running.empty()) {
    while (next < all.size() && running.size() < jobs) {
      Job& j = all[next];
      std::vector<char*> argv;
      for (std::string& a : j.args) argv.push_back(a.data());
      argv.push_back(nullptr);
      const pid_t pid = fork();
      if (pid < 0) return false;
      if (pid == 0) {
        const int fd = open(j.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (fd >= 0) dup2(fd, 2);
        if (null >= 0) dup2(null, 1);
        setenv("LC_ALL", "C", 1);
        setenv("GCC_COLORS", "", 1);
        execvp(argv[0], argv.data());
        _exit(127);
      }
      running[pid] = next++;
    }
    int status = 0;
    const pid_t pid = wait(&status);
    if (pid < 0) break;
    auto it = running.find(pid);
    if (it == running.end()) continue;
    all[it->second].status = status;
    running.erase(it);
  }
  for (const Job& j : all)
    if (!WIFEXITED(j.status) || WEXITSTATUS(j.status) > 1) ok = false;
  return ok;
}

// ---- The checker --------------------------------------------------------------------------------

class Checker {
 public:
  fs::path root, work, cxx;
  unsigned jobs = 1;
  bool temp_work = false;        // remove the work folder after a clean run
  std::vector<fs::path> inputs;  // canonical files and directories as given
  std::vector<fs::path> headers;
  std::set<Violation> violations;
  std::vector<std::string> notes;

  bool hls_owned(const fs::path& p) const {
    if (is_under(p, root / "hls")) return true;
    for (const fs::path& in : inputs)
      if (p == in || is_under(p, in)) return true;
    return false;
  }

  std::string show(const fs::path& p) const {
    return is_under(p, root) ? p.lexically_relative(root).string() : p.string();
  }

  const Lexed& lexed(const fs::path& p) {
    auto it = cache_.find(p);
    if (it != cache_.end()) return *it->second;
    std::string src;
    read_file(p, src);
    return *(cache_[p] = std::make_unique<Lexed>(lex(src)));
  }

  void add(const fs::path& file, int line, const std::string& rule, const std::string& msg) {
    violations.insert({canon(file).string(), line, rule, msg});
  }

  // Resolves a quoted include against the including file's folder, then the root.
  fs::path resolve_include(const fs::path& from, const std::string& name) const {
    for (const fs::path& base : {from.parent_path(), root}) {
      const fs::path p = canon(base / name);
      if (fs::is_regular_file(p)) return p;
    }
    return {};
  }

  // constexpr names of a header and of the hls/ headers it includes, transitively.
  void constants_of(const fs::path& p, std::set<std::string>& out, std::set<fs::path>& seen) {
    if (!seen.insert(p).second) return;
    const Lexed& lx = lexed(p);
    collect_constexpr(lx.code, out);
    for (const Include& inc : lx.includes) {
      if (inc.angled) continue;
      const fs::path q = resolve_include(p, inc.name);
      if (!q.empty() && hls_owned(q)) constants_of(q, out, seen);
    }
  }

  void scan(const fs::path& h) {
    const Lexed& lx = lexed(h);
    std::set<std::string> constants, tparams;
    std::set<fs::path> seen;
    constants_of(h, constants, seen);
    collect_template_params(lx.code, tparams);
    for (const Tokens& m : lx.macros) collect_template_params(m, tparams);
    std::vector<Violation> found;
    Scanner sc(h, lx, constants, tparams, found);
    sc.run();
    // Rule d: one top function per kernel header.
    const std::string rel = show(h), name = h.filename().string();
    const bool exempt = is_under(h, root / "hls" / "types") || name == "records.hpp" ||
                        ends_with(name, "_formats.hpp") || ends_with(name, "_tables.hpp");
    if (lx.helper_line != 0) {
      if (lx.helper_reason.empty())
        found.push_back({h.string(), lx.helper_line, "waiver", "'hls-subset-helper:' needs a reason"});
      for (const auto& t : sc.tops)
        found.push_back({h.string(), t.line, "top-function",
                         "helper header (hls-subset-helper) defines the top function '" + t.name + "'"});
    } else if (!exempt) {
      if (sc.tops.empty())
        found.push_back({h.string(), 1, "top-function",
                         "no *_top function: a kernel header defines exactly one top function (a header of "
                         "shared helpers says so with // hls-subset-helper: <reason>)"});
      for (size_t k = 1; k < sc.tops.size(); ++k)
        found.push_back({h.string(), sc.tops[k].line, "top-function",
                         "second top function '" + sc.tops[k].name + "' (the first is '" + sc.tops[0].name +
                             "' at line " + std::to_string(sc.tops[0].line) + "): one top function per kernel header"});
    }
    // Waivers: a reasoned waiver silences the scan findings on its own line.
    std::map<int, Waiver> waivers = lx.waivers;
    for (Violation& v : found) {
      auto w = waivers.find(v.line);
      if (v.rule != "waiver" && w != waivers.end() && !w->second.reason.empty()) {
        w->second.used = true;
        continue;
      }
      add(v.file, v.line, v.rule, v.message);
    }
    for (const auto& [l, w] : waivers) {
      if (w.reason.empty()) add(h, l, "waiver", "'hls-subset-ok:' needs a reason");
      else if (!w.used) add(h, l, "waiver", "'hls-subset-ok:' on a line without a source-scan finding");
    }
  }

  void write_poisoned_headers() {
    const fs::path dir = work / "poisoned";
    fs::create_directories(dir);
    for (const char* h : kPoisonedStdHeaders) {
      std::ofstream f(dir / h);
      f << "// generated by hls_subset_check: <" << h << "> is outside the HLS subset\n"
        << "#ifdef HLS_SUBSET_ALLOWED_CONTEXT\n#include_next <" << h << ">\n#else\n"
        << "#error \"hls subset: <" << h << "> is not allowed in hls/\"\n#endif\n";
    }
  }

  Job make_job(size_t k, const fs::path& h) {
    Job j;
    j.header = h;
    const std::string base = "tu_" + std::to_string(k);
    j.tu = work / (base + ".cpp");
    j.obj = work / (base + ".o");
    j.ci = work / (base + ".ci");
    j.err = work / (base + ".log");
    std::ofstream f(j.tu);
    f << "// generated by hls_subset_check for " << h.string() << "\n"
      << "#define HLS_SUBSET_ALLOWED_CONTEXT 1\n";
    for (const char* a : kPreIncluded) f << "#include <" << a << ">\n";
    f << "#undef HLS_SUBSET_ALLOWED_CONTEXT\n#pragma GCC poison";
    for (const auto& [id, rule] : kPoisoned) f << " " << id;
    f << "\n#include \"" << h.string() << "\"\n";
    j.args = {cxx.string(),
              "-std=c++14",  // the HLS tools' standard; a later construct is an error, rule later-standard
              "-Werror=c++17-extensions",
              "-Werror=c++20-extensions",
              "-pedantic-errors",  // GCC reports some later constructs (nested namespaces) only as pedantic
              "-D__SYNTHESIS__",
              "-UCIG_HLS_SYSTEMC",
              "-I" + (work / "poisoned").string(),
              "-I" + root.string(),
              "-H",
              "-c",
              "-O0",
              "-fkeep-inline-functions",
              "-fcallgraph-info",
              "-fno-diagnostics-show-caret",
              "-fdiagnostics-color=never",
              "-fmax-errors=50",
              "-o",
              j.obj.string(),
              j.tu.string()};
    return j;
  }

  int include_line(const fs::path& parent, const fs::path& child) {
    for (const Include& inc : lexed(parent).includes)
      if (child.string() == inc.name || ends_with(child.string(), "/" + inc.name)) return inc.line;
    return 1;
  }

  // "path:line[:col]" at the start of s.
  static bool location(const std::string& s, std::string& file, int& line) {
    size_t p = s.find(':');
    while (p != std::string::npos) {
      size_t q = p + 1;
      while (q < s.size() && std::isdigit(static_cast<unsigned char>(s[q]))) ++q;
      if (q > p + 1 && (q == s.size() || s[q] == ':' || s[q] == ',')) {
        file = s.substr(0, p);
        line = std::atoi(s.c_str() + p + 1);
        return !file.empty();
      }
      p = s.find(':', p + 1);
    }
    return false;
  }

  // Reads a compile's stderr; returns how many errors it recognised.
  int parse_log(const Job& j) {
    std::ifstream in(j.err);
    int recognised = 0;
    std::string l;
    std::vector<fs::path> tree = {j.tu};
    bool forbidden_header = false;
    int suppressed = 0;
    fs::path ctx_file;
    int ctx_line = 0;
    const fs::path poisoned = canon(work / "poisoned");
    while (std::getline(in, l)) {
      if (!l.empty() && l[0] == '.') {  // -H: include tree
        size_t d = 0;
        while (d < l.size() && l[d] == '.') ++d;
        if (d >= l.size() || l[d] != ' ') continue;
        const fs::path child = canon(l.substr(d + 1));
        tree.resize(std::min(tree.size(), d));
        const fs::path parent = tree.empty() ? j.tu : tree.back();
        tree.push_back(child);
        if (!hls_owned(parent) || hls_owned(child)) continue;
        const std::string name = child.filename().string();
        ++recognised;
        if (is_under(child, poisoned)) {
          add(parent, include_line(parent, child), "forbidden-header",
              "<" + name +
                  "> is not in the HLS subset (allowed standard headers: <cstdint>, <cstddef>, <climits>, <type_traits>)");
          forbidden_header = true;
        } else if (!kAllowedStdHeaders.count(name) || is_under(child, root)) {
          add(parent, include_line(parent, child), "forbidden-header",
              "includes '" + show(child) +
                  "': hls/ headers include only hls/ headers and the allowed standard headers");
          forbidden_header = true;
        }
        continue;
      }
      std::string rest = l;
      if (starts_with(rest, "In file included from ")) rest = rest.substr(22);
      else if (starts_with(trim(rest), "from ")) rest = trim(rest).substr(5);
      size_t e = rest.find(": error: ");
      size_t elen = 9;
      if (e == std::string::npos) {
        e = rest.find(": fatal error: ");
        elen = 15;
      }
      std::string file;
      int line = 0;
      if (e == std::string::npos) {  // context: remember the innermost hls/ location
        if (location(rest, file, line) && hls_owned(canon(file))) {
          ctx_file = canon(file);
          ctx_line = line;
        }
        continue;
      }
      const std::string msg = rest.substr(e + elen);
      if (!location(rest.substr(0, e + 1), file, line)) continue;
      ++recognised;
      fs::path f = canon(file);
      const fs::path cf = ctx_file;
      const int cl = ctx_line;
      ctx_file.clear();
      if (is_under(f, poisoned)) continue;  // reported from the include tree
      if (starts_with(msg, "attempt to use poisoned \"") && hls_owned(f)) {
        const std::string id = msg.substr(25, msg.size() - 26);
        auto r = kPoisoned.find(id);
        add(f, line, r == kPoisoned.end() ? "compile" : r->second, "'" + id + "' (poisoned in the synthesis build)");
        continue;
      }
      if (forbidden_header) {
        ++suppressed;
        continue;
      }
      // A construct of a later standard than C++14 (GCC names the standard it needs).
      const char* rule = msg.find("c++17") != std::string::npos || msg.find("c++2") != std::string::npos
                             ? "later-standard"
                             : "compile";
      if (f == canon(j.tu)) {
        add(j.header, 1, rule, msg);
      } else if (hls_owned(f)) {
        add(f, line, rule, msg);
      } else {
        add(cf.empty() ? j.header : cf, cf.empty() ? 1 : cl, rule,
            msg + " [in " + show(f) + ":" + std::to_string(line) + "]");
      }
    }
    if (suppressed > 0)
      notes.push_back("note: " + std::to_string(suppressed) + " further compiler error(s) in " + show(j.header) +
                      " not shown: they may follow from the forbidden header");
    return recognised;
  }

  static std::string short_sig(std::string s) {
    for (const std::string ns : {"cig::hls::native_types::", "cig::hls::systemc_types::"}) {
      size_t p;
      while ((p = s.find(ns)) != std::string::npos) s.erase(p, ns.size());
    }
    return s;
  }

  static std::string quoted_after(const std::string& l, const std::string& key, size_t& pos) {
    const size_t b = l.find(key + ": \"", pos);
    if (b == std::string::npos) return {};
    const size_t s = b + key.size() + 3;
    size_t e = s;
    while (e < l.size() && !(l[e] == '"' && l[e - 1] != '\\')) ++e;
    pos = e;
    return l.substr(s, e - s);
  }

  void parse_callgraph(const Job& j) {
    std::ifstream in(j.ci);
    if (!in) {
      add(j.header, 1, "compile", "no call graph was written (" + j.ci.string() + ")");
      return;
    }
    struct Node {
      std::string sig;
      fs::path file;
      int line = 0;
    };
    std::map<std::string, Node> nodes;
    std::vector<std::tuple<std::string, std::string, std::string>> edges;
    std::string l;
    while (std::getline(in, l)) {
      size_t pos = 0;
      if (starts_with(l, "node: ")) {
        const std::string title = quoted_after(l, "title", pos);
        const std::string label = quoted_after(l, "label", pos);
        const size_t nl = label.rfind("\\n");
        Node nd;
        nd.sig = short_sig(label.substr(0, nl));
        std::string file;
        if (nl != std::string::npos && location(label.substr(nl + 2), file, nd.line)) nd.file = canon(file);
        nodes[title] = nd;
      } else if (starts_with(l, "edge: ")) {
        const std::string s = quoted_after(l, "sourcename", pos);
        const std::string t = quoted_after(l, "targetname", pos);
        const std::string at = quoted_after(l, "label", pos);
        edges.emplace_back(s, t, at);
      }
    }
    auto owned = [&](const std::string& title) {
      auto it = nodes.find(title);
      return it != nodes.end() && !it->second.file.empty() && hls_owned(it->second.file);
    };
    std::map<std::string, std::set<std::string>> adj;
    for (const auto& [s, t, at] : edges) {
      if (!owned(s)) continue;
      if (t == "__indirect_call") {
        std::string file;
        int line = 0;
        if (location(at, file, line) && hls_owned(canon(file)))
          add(canon(file), line, "indirect-call",
              "'" + nodes[s].sig + "' calls through a function pointer or a virtual function");
        else
          add(nodes[s].file, nodes[s].line, "indirect-call",
              "'" + nodes[s].sig + "' calls through a function pointer or a virtual function");
      } else if (owned(t)) {
        adj[s].insert(t);
      }
    }
    // Strongly connected components (Tarjan, iterative).
    std::map<std::string, int> index, low;
    std::set<std::string> on_stack;
    std::vector<std::string> st;
    int counter = 0;
    for (const auto& [start, unused] : adj) {
      (void)unused;
      if (index.count(start)) continue;
      std::vector<std::pair<std::string, std::set<std::string>::const_iterator>> call;
      auto enter = [&](const std::string& v) {
        index[v] = low[v] = counter++;
        st.push_back(v);
        on_stack.insert(v);
        call.emplace_back(v, adj[v].cbegin());
      };
      enter(start);
      while (!call.empty()) {
        const std::string v = call.back().first;
        auto& it = call.back().second;
        if (it != adj[v].cend()) {
          const std::string w = *it++;
          if (!index.count(w)) {
            enter(w);
          } else if (on_stack.count(w)) {
            low[v] = std::min(low[v], index[w]);
          }
          continue;
        }
        call.pop_back();
        if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[v]);
        if (low[v] != index[v]) continue;
        std::vector<std::string> comp;
        std::string w;
        do {
          w = st.back();
          st.pop_back();
          on_stack.erase(w);
          comp.push_back(w);
        } while (w != v);
        if (comp.size() == 1 && !adj[v].count(v)) continue;
        std::sort(comp.begin(), comp.end(), [&](const std::string& a, const std::string& b) {
          return std::tie(nodes[a].file, nodes[a].line) < std::tie(nodes[b].file, nodes[b].line);
        });
        std::string msg = "'" + nodes[comp[0]].sig + "'";
        if (comp.size() == 1) {
          msg += " calls itself";
        } else {
          msg += " is in a call cycle with";
          for (size_t k = 1; k < comp.size(); ++k) msg += (k > 1 ? ", '" : " '") + nodes[comp[k]].sig + "'";
        }
        add(nodes[comp[0]].file, nodes[comp[0]].line, "recursion", msg + ": no recursion in hls/");
      }
    }
  }

  int run() {
    for (const fs::path& in : inputs) {
      if (fs::is_directory(in)) {
        for (const auto& e : fs::recursive_directory_iterator(in))
          if (e.is_regular_file() && e.path().extension() == ".hpp") headers.push_back(canon(e.path()));
      } else if (fs::is_regular_file(in)) {
        headers.push_back(in);
      } else {
        std::cerr << "hls_subset_check: no such file or directory: " << in.string() << "\n";
        return 2;
      }
    }
    std::sort(headers.begin(), headers.end());
    headers.erase(std::unique(headers.begin(), headers.end()), headers.end());
    if (headers.empty()) {
      std::cerr << "hls_subset_check: no *.hpp headers to check\n";
      return 2;
    }
    std::error_code ec;
    fs::remove_all(work, ec);
    fs::create_directories(work);
    write_poisoned_headers();
    std::vector<Job> all;
    for (size_t k = 0; k < headers.size(); ++k) all.push_back(make_job(k, headers[k]));
    for (const fs::path& h : headers) scan(h);
    if (!run_jobs(all, jobs)) {
      for (const Job& j : all)
        if (!WIFEXITED(j.status) || WEXITSTATUS(j.status) > 1)
          std::cerr << "hls_subset_check: the compiler did not run normally for " << show(j.header) << " ("
                    << (WIFEXITED(j.status) ? WEXITSTATUS(j.status) == 127
                                                  ? std::string("could not be started")
                                                  : "exit status " + std::to_string(WEXITSTATUS(j.status))
                                            : "signal " + std::to_string(WTERMSIG(j.status)))
                    << "; " << cxx.string() << "); see " << j.err.string() << "\n";
      return 2;
    }
    for (const Job& j : all) {
      if (parse_log(j) == 0 && WEXITSTATUS(j.status) != 0) {
        add(j.header, 1, "compile",
            "the compiler failed without a diagnostic this check understands; see " + j.err.string());
        temp_work = false;  // keep the log
      }
      if (WEXITSTATUS(j.status) == 0) parse_callgraph(j);
      else
        notes.push_back("note: no call-graph check (recursion, indirect calls) for " + show(j.header) +
                        ": it does not compile");
    }
    for (const Violation& v : violations)
      std::cout << show(v.file) << ":" << v.line << ": " << v.rule << ": " << v.message << "\n";
    for (const std::string& n : notes) std::cout << n << "\n";
    if (violations.empty()) {
      std::cout << "hls-subset: " << headers.size() << " header(s) checked, all in the HLS subset\n";
      if (temp_work) fs::remove_all(work, ec);
      return 0;
    }
    std::set<std::string> files;
    for (const Violation& v : violations) files.insert(v.file);
    std::cout << "hls-subset: " << violations.size() << " violation(s) in " << files.size() << " file(s); "
              << headers.size() << " header(s) checked (rules: verif/hls_subset/README.md)\n";
    if (temp_work) fs::remove_all(work, ec);
    return 1;
  }

 private:
  std::map<fs::path, std::unique_ptr<Lexed>> cache_;
};

int usage() {
  std::cerr << "usage: hls_subset_check --cxx <g++> --root <repository root> [--work <dir>] [--jobs <n>] "
               "<dir|header>...\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Checker c;
  c.jobs = std::max(1u, std::thread::hardware_concurrency());
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string { return k + 1 < argc ? argv[++k] : ""; };
    if (a == "--cxx") c.cxx = value();
    else if (a == "--root") c.root = value();
    else if (a == "--work") c.work = value();
    else if (a == "--jobs") c.jobs = static_cast<unsigned>(std::max(1, std::atoi(value().c_str())));
    else if (starts_with(a, "--")) return usage();
    else c.inputs.push_back(canon(fs::absolute(a)));
  }
  if (c.cxx.empty() || c.root.empty() || c.inputs.empty()) return usage();
  c.root = canon(fs::absolute(c.root));
  if (c.work.empty()) {
    c.work = fs::temp_directory_path() / ("hls_subset." + std::to_string(getpid()));
    c.temp_work = true;
  }
  c.work = canon(fs::absolute(c.work));
  return c.run();
}
