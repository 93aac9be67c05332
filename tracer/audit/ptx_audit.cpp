// PTX semantics from the PTX ISA (version 9.0), chapters "Floating-Point Instructions",
// "Comparison and Selection Instructions" and "Data Movement and Conversion Instructions: cvt".
#include "audit/ptx_audit.h"

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <set>
#include <sstream>

namespace tracer {
namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) out.push_back(trim(part));
  return out;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

const std::set<std::string> kFloatTypes = {"f32", "f64"};
const std::set<std::string> kNarrowFloatTypes = {"f16", "f16x2", "bf16", "bf16x2", "tf32", "e4m3x2", "e5m2x2"};
const std::set<std::string> kIntTypes = {"s8", "s16", "s32", "s64", "u8", "u16", "u32", "u64"};
const std::set<std::string> kRoundings = {"rn", "rz", "rm", "rp"};
const std::set<std::string> kIntegralRoundings = {"rni", "rzi", "rmi", "rpi"};
// Instructions that move bits without arithmetic: no rounding, no NaN rule.
const std::set<std::string> kMoves = {"ld", "ldu", "st", "mov", "selp", "shfl", "prmt", "cvta"};

std::string opcode_of(const std::string& statement, std::string& operands) {
  std::string s = trim(statement);
  if (starts_with(s, "@")) {  // a guard predicate: @%p1 or @!%p1
    const size_t sp = s.find_first_of(" \t");
    s = sp == std::string::npos ? "" : trim(s.substr(sp));
  }
  const size_t sp = s.find_first_of(" \t");
  operands = sp == std::string::npos ? "" : trim(s.substr(sp));
  return sp == std::string::npos ? s : s.substr(0, sp);
}

// A float immediate (0fXXXXXXXX or 0dXXXXXXXXXXXXXXXX): its bits, and whether it is one.
bool immediate_bits(const std::string& operand, uint64_t& bits, bool& is_double) {
  if (operand.size() == 10 && (starts_with(operand, "0f") || starts_with(operand, "0F"))) {
    is_double = false;
  } else if (operand.size() == 18 && (starts_with(operand, "0d") || starts_with(operand, "0D"))) {
    is_double = true;
  } else {
    return false;
  }
  char* end = nullptr;
  bits = std::strtoull(operand.c_str() + 2, &end, 16);
  return *end == '\0';
}

bool immediate_is_nan(uint64_t bits, bool is_double) {
  return is_double ? (bits & 0x7fffffffffffffffull) > 0x7ff0000000000000ull : (bits & 0x7fffffffu) > 0x7f800000u;
}

// min/max from min_of/max_of (whose source form is `a < b ? a : b`, the second operand
// winning a failed comparison) with a constant c that is not NaN and not the zero that PTX
// orders the other way (+0 for min, -0 for max): PTX and the ternary min_of(x, c) give the
// same bits for every x, NaN and both zeros included.
std::string argue_min_max(const PtxSite& site, const std::string& opcode, const std::string& operands) {
  const std::string base = opcode.substr(0, 3);
  if (opcode != base + ".f32" && opcode != base + ".f64") return "";  // .NaN, .xorsign.abs: other rules
  if (!ends_with(site.source.substr(0, site.source.rfind(':')), "kernel/base/platform.h")) return "";
  const std::vector<std::string> ops = split(operands, ',');
  const uint64_t wrong_zero_f = base == "min" ? 0x00000000u : 0x80000000u;
  const uint64_t wrong_zero_d = base == "min" ? 0ull : 0x8000000000000000ull;
  for (size_t i = 1; i < ops.size(); ++i) {
    uint64_t bits;
    bool is_double;
    if (!immediate_bits(ops[i], bits, is_double)) continue;
    if (immediate_is_nan(bits, is_double) || bits == (is_double ? wrong_zero_d : wrong_zero_f)) return "";
    return base + "_of(x, c), c a constant neither NaN nor " + (base == "min" ? "+0" : "-0") + ": PTX " + base +
           " equals the ternary for every x, NaN and both zeros included";
  }
  return "";
}

std::string argue_conversion(const PtxSite& site) {
  if (!ends_with(site.source.substr(0, site.source.rfind(':')), "kernel/base/float_to_int.h")) return "";
  return "in the range-checked conversion helper: NaN and out-of-range inputs are answered before the "
         "conversion, with cvt.rzi's saturating values, so both sides convert only exact in-range values";
}

}  // namespace

PtxCounts PtxAudit::total() const {
  PtxCounts t;
  for (const auto& [name, c] : by_function) {
    t.equal += c.equal;
    t.differs += c.differs;
    t.forbidden += c.forbidden;
  }
  return t;
}

// std::nullopt: not a floating-point or conversion instruction (integer arithmetic, moves,
// branches, a call to our own code, which is audited where it is defined).
std::optional<PtxSite> classify(const std::string& statement, const std::string& source) {
  std::string operands;
  const std::string opcode = opcode_of(statement, operands);
  const std::vector<std::string> mods = split(opcode, '.');
  const std::string& base = mods[0];
  const std::set<std::string> m(mods.begin() + 1, mods.end());
  PtxSite site;
  site.source = source;
  site.text = trim(statement);
  const auto verdict = [&](PtxClass cls, const std::string& reason) {
    site.cls = cls;
    site.reason = reason;
    return std::optional<PtxSite>(site);
  };
  if (base == "call") {
    if (operands.find("__nv_") != std::string::npos)
      return verdict(PtxClass::Forbidden, "a call into libdevice (CUDA's math library), which rounds differently");
    return std::nullopt;
  }
  bool is_float = false, is_narrow = false;
  for (const std::string& x : m) {
    is_float = is_float || kFloatTypes.count(x) > 0;
    is_narrow = is_narrow || kNarrowFloatTypes.count(x) > 0;
  }
  if (is_narrow) return verdict(PtxClass::Forbidden, "a half or narrow float type, which kernel code never uses");
  if (!is_float) return std::nullopt;
  if (kMoves.count(base)) return std::nullopt;
  if (base == "atom" || base == "red")
    return verdict(PtxClass::Forbidden, "a floating-point atomic: its sum depends on the order threads arrive in");
  if (m.count("ftz")) return verdict(PtxClass::Forbidden, ".ftz flushes subnormals to zero; the host keeps them");
  if (m.count("sat")) return verdict(PtxClass::Forbidden, ".sat clamps to [0, 1]; the host does not");
  if (m.count("approx") || m.count("full"))
    return verdict(PtxClass::Forbidden, "an approximation, not the correctly rounded operation");
  std::string rounding;
  for (const std::string& r : kRoundings)
    if (m.count(r)) rounding = r;
  if (base == "add" || base == "sub" || base == "mul" || base == "div" || base == "sqrt" || base == "rcp") {
    if (rounding.empty())
      return verdict(PtxClass::Forbidden, "no rounding modifier: ptxas may contract it into an fma");
    if (rounding != "rn") return verdict(PtxClass::Forbidden, "directed rounding; the host rounds to nearest");
    return verdict(PtxClass::Equal, "");
  }
  if (base == "fma" || base == "mad")
    return verdict(PtxClass::Forbidden, "a fused multiply-add rounds once where the host rounds twice");
  if (base == "rsqrt" || base == "sin" || base == "cos" || base == "lg2" || base == "ex2" || base == "tanh")
    return verdict(PtxClass::Forbidden, "an approximate transcendental");
  if (base == "abs" || base == "neg" || base == "copysign" || base == "setp" || base == "set" || base == "testp")
    return verdict(PtxClass::Equal, "");
  if (base == "min" || base == "max")
    return verdict(
        PtxClass::Differs,
        "PTX " + base + ": a NaN operand yields the other and -0 orders below +0; a C++ ternary does neither");
  if (base == "cvt") {
    std::vector<std::string> types;
    std::string integral;
    for (size_t i = 1; i < mods.size(); ++i) {
      if (kFloatTypes.count(mods[i]) || kIntTypes.count(mods[i])) types.push_back(mods[i]);
      if (kIntegralRoundings.count(mods[i])) integral = mods[i];
    }
    if (types.size() != 2) return verdict(PtxClass::Forbidden, "a conversion the audit cannot read");
    const bool to_float = kFloatTypes.count(types[0]) > 0, from_float = kFloatTypes.count(types[1]) > 0;
    if (!to_float)
      return verdict(PtxClass::Differs,
                     "float to integer: PTX saturates and gives 0 for NaN; C++ leaves both undefined and x86 gives "
                     "INT_MIN");
    if (!from_float)
      return rounding == "rn" ? verdict(PtxClass::Equal, "")
                              : verdict(PtxClass::Forbidden, "an integer-to-float conversion not rounded to nearest");
    if (types[0] == types[1])
      return integral.empty() ? verdict(PtxClass::Forbidden, "a float-to-float conversion the audit cannot read")
                              : verdict(PtxClass::Equal, "");  // IEEE roundToIntegral: exact
    // Widening is exact, but turns a signaling NaN quiet where GCC may fold the round trip
    // away; kernel functions answer NaN before widening (det_log; test math.unoptimized).
    if (types[0] == "f64") return verdict(PtxClass::Equal, "");
    return rounding == "rn" ? verdict(PtxClass::Equal, "")
                            : verdict(PtxClass::Forbidden, "a narrowing conversion not rounded to nearest");
  }
  return verdict(PtxClass::Forbidden, "a floating-point instruction the audit's table does not know");
}

PtxSite classify_instruction(const std::string& statement, const std::string& source) {
  const std::optional<PtxSite> site = classify(statement, source);
  if (site) return *site;
  PtxSite none;
  none.source = source;
  none.text = trim(statement);
  none.reason = "not a floating-point instruction";
  return none;
}

// The line of `text` that starts at `start` (without its '\n'); `next` gets the start of the
// one after. The audit walks the module line by line and keeps no copy of it: a vector of its
// lines peaked at 44 times the file (a string of 32 bytes for a 1-byte empty line).
std::string line_at(const std::string& text, size_t start, size_t& next) {
  size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  next = end + 1;
  return text.substr(start, end - start);
}

PtxAudit audit_ptx(const std::string& ptx_text, const std::string& root) {
  PtxAudit audit;
  const auto parse_error = [&](size_t i, const std::string& why, const std::string& text) {
    if (audit.parse_error_count++ < static_cast<long>(kPtxSitesKept))
      audit.parse_errors.push_back(std::to_string(i + 1) + ": " + why + ": " + trim(text).substr(0, 200));
  };
  const auto fail = [&](const PtxSite& s) {
    if (audit.failure_count++ < static_cast<long>(kPtxSitesKept)) audit.failures.push_back(s);
  };
  // .file entries come after the code: read them first.
  std::map<int, std::string> files;
  std::string prefix = root;
  if (!prefix.empty() && prefix.back() != '/') prefix += '/';
  for (size_t start = 0, next = 0; start < ptx_text.size(); start = next) {
    const std::string line = trim(line_at(ptx_text, start, next));
    if (!starts_with(line, ".file")) continue;
    std::istringstream in(line.substr(5));
    int id = 0;
    std::string path;
    in >> id >> path;
    if (path.size() >= 2 && path.front() == '"') path = path.substr(1, path.find('"', 1) - 1);
    if (!prefix.empty() && starts_with(path, prefix)) path = path.substr(prefix.size());
    files[id] = path;
  }
  enum class State { Module, Header, Body, Section, Directive };
  State state = State::Module;
  int depth = 0;
  std::string function = "(module)", source = "unknown", statement;
  size_t statement_line = 0, line_count = 0;
  std::string statement_first_line;  // the text of statement_line, for its parse error
  for (size_t i = 0, start = 0, next = 0; start < ptx_text.size(); ++i, start = next, line_count = i) {
    const std::string raw = line_at(ptx_text, start, next);
    std::string line = raw;
    const size_t comment = line.find("//");
    if (comment != std::string::npos) line = line.substr(0, comment);
    line = trim(line);
    if (line.empty()) continue;
    switch (state) {
      case State::Section:  // .section NAME { ... }: debug strings, skipped
        if (line == "}") state = State::Module;
        continue;
      case State::Directive:  // a module-level directive that ends at its ';'
        if (line.find(';') != std::string::npos) state = State::Module;
        continue;
      case State::Header:  // .entry/.func NAME( params ) [performance directives] then { or ;
        if (line == "{") {
          state = State::Body;
          depth = 1;
        } else if (line.back() == ';') {
          state = State::Module;  // a prototype
        }
        continue;
      case State::Module: {
        if (starts_with(line, ".version") || starts_with(line, ".target") || starts_with(line, ".address_size") ||
            starts_with(line, ".file"))
          continue;
        if (starts_with(line, ".section")) {
          state = State::Section;
          continue;
        }
        const size_t entry = line.find(".entry"), func = line.find(".func");
        if (entry != std::string::npos || func != std::string::npos) {
          std::string rest = line.substr(entry != std::string::npos ? entry + 6 : func + 5);
          rest = trim(rest);
          if (starts_with(rest, "(")) rest = trim(rest.substr(rest.find(')') + 1));  // return parameters
          const size_t end = rest.find_first_of("( \t;");
          function = rest.substr(0, end);
          if (function.find("__nv_") != std::string::npos) {
            PtxSite site = classify_instruction("call.uni " + function, "unknown");
            site.function = function;
            site.ptx_line = static_cast<int>(i + 1);
            audit.failures.push_back(site);
          }
          if (line.back() == ';') continue;  // a declaration on one line
          audit.by_function[function];       // listed even when it holds no floating-point instruction
          state = line.back() == '{' ? State::Body : State::Header;
          depth = 1;
          continue;
        }
        if (line[0] == '.') {  // .global, .const, .shared, .extern ... up to ';'
          if (line.find(';') == std::string::npos) {
            state = State::Directive;
          }
          continue;
        }
        parse_error(i, "not a PTX module-level statement", raw);
        continue;
      }
      case State::Body: break;
    }
    // Inside a function body: statements end at ';' and may span lines (calls) or share one
    // (inline assembly blocks such as CUB's `{ .reg .u32 r0; shfl.sync.up.b32 ...; }`).
    size_t pos = 0;
    while (pos < line.size()) {
      pos = line.find_first_not_of(" \t", pos);
      if (pos == std::string::npos) break;
      if (statement.empty()) {
        const std::string rest = line.substr(pos);
        if (rest[0] == '{' || rest[0] == '}') {
          ++pos;
          if (rest[0] == '{') {
            ++depth;
          } else if (--depth == 0) {
            state = State::Module;
            function = "(module)";
            source = "unknown";
            break;
          }
          continue;
        }
        if (starts_with(rest, ".loc") && (rest.size() == 4 || rest[4] == ' ' || rest[4] == '\t')) {
          // .loc FILE LINE COLUMN[, function_name LABEL, inlined_at FILE LINE COLUMN]
          std::istringstream in(rest.substr(4));
          int file = 0, number = 0;
          if (!(in >> file >> number) || !files.count(file))
            parse_error(i, ".loc names no .file", raw);
          else
            source = files[file] + ":" + std::to_string(number);
          break;
        }
        size_t label = 0;
        while (label < rest.size() &&
               (std::isalnum(static_cast<unsigned char>(rest[label])) || rest[label] == '_' || rest[label] == '$'))
          ++label;
        if (label > 0 && label < rest.size() && rest[label] == ':') {
          pos += label + 1;  // a label
          continue;
        }
        const char c = rest[0];
        if (!(c == '@' || c == '.' || (c >= 'a' && c <= 'z'))) {
          parse_error(i, "not a PTX instruction or directive", raw);
          break;
        }
        statement_line = i;
        statement_first_line = raw;
      }
      const size_t semi = line.find(';', pos);
      if (semi == std::string::npos) {  // the statement goes on on the next line
        statement += line.substr(pos) + " ";
        break;
      }
      statement += line.substr(pos, semi - pos);
      pos = semi + 1;
      const std::string done = trim(statement);
      statement.clear();
      if (done[0] == '.') continue;  // a directive: .reg, .local, .param, .pragma ...
      std::string operands;
      if (opcode_of(done, operands).empty()) {  // `@%p1;`: a guard predicate with nothing to guard
        parse_error(statement_line, "a guard predicate with no instruction", statement_first_line);
        continue;
      }
      const std::optional<PtxSite> site = classify(done, source);
      if (!site) continue;
      PtxSite s = *site;
      s.function = function;
      s.ptx_line = static_cast<int>(statement_line + 1);
      const std::string opcode = opcode_of(s.text, operands);
      ++audit.by_opcode[opcode];
      PtxCounts& counts = audit.by_function[function];
      if (s.cls == PtxClass::Equal) {
        ++counts.equal;
        continue;
      }
      if (s.cls == PtxClass::Forbidden) {
        ++counts.forbidden;
        fail(s);
        continue;
      }
      ++counts.differs;
      const std::string base = opcode.substr(0, opcode.find('.'));
      s.argument = base == "cvt" ? argue_conversion(s) : argue_min_max(s, opcode, operands);
      if (s.argument.empty()) {
        fail(s);
        continue;
      }
      auto& [count, argument] = audit.explained[s.source + "  " + opcode];
      ++count;
      argument = s.argument;
    }
  }
  if (state != State::Module || !statement.empty()) {
    ++audit.parse_error_count;
    audit.parse_errors.push_back(std::to_string(line_count) + ": the module ends inside a function or statement");
  }
  return audit;
}

}  // namespace tracer
