#include "audit/draw_lint.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "io/input_error.h"
#include "io/text_file.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

// Comments, string and character literals become spaces (newlines kept, so lines still count).
std::string code_only(const std::string& text) {
  std::string out = text;
  enum { Code, Line, Block, String, Char } state = Code;
  for (size_t i = 0; i < out.size(); ++i) {
    const char c = text[i], next = i + 1 < text.size() ? text[i + 1] : '\0';
    switch (state) {
      case Code:
        if (c == '/' && next == '/')
          state = Line;
        else if (c == '/' && next == '*')
          state = Block;
        else if (c == '"')
          state = String;
        else if (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(text[i - 1]))))
          state = Char;
        else
          continue;  // 0x1'000 digit separators stay code
        out[i] = ' ';
        continue;
      case Line:
        if (c == '\n') state = Code;
        break;
      case Block:
        if (c == '*' && next == '/') {
          out[i] = out[i + 1] = ' ';
          ++i;
          state = Code;
          continue;
        }
        break;
      case String:
      case Char:
        if (c == '\\') {
          out[i] = ' ';
          if (i + 1 < out.size() && text[i + 1] != '\n') out[++i] = ' ';
          continue;
        }
        if (c == (state == String ? '"' : '\'')) state = Code;
        break;
    }
    if (out[i] != '\n') out[i] = ' ';
  }
  return out;
}

bool is_ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether the '(' at `open` starts a call's argument list (not if/while/for/switch/return...).
bool opens_call(const std::string& code, size_t open) {
  size_t i = open;
  while (i > 0 && std::isspace(static_cast<unsigned char>(code[i - 1]))) --i;
  if (i == 0) return false;
  const char before = code[i - 1];
  if (before == ')' || before == ']' || before == '>') return true;
  if (!is_ident(before)) return false;
  size_t start = i;
  while (start > 0 && is_ident(code[start - 1])) --start;
  static const std::set<std::string> kKeywords = {"if",    "while",    "for",     "switch",   "return",       "sizeof",
                                                  "catch", "decltype", "alignof", "noexcept", "static_assert"};
  return !kKeywords.count(code.substr(start, i - start));
}

// Length of a draw (".next(" and the like, "->" too) starting at i, else 0.
size_t draw_at(const std::string& code, size_t i) {
  size_t j = i;
  if (code[j] == '.')
    ++j;
  else if (code.compare(j, 2, "->") == 0)
    j += 2;
  else
    return 0;
  while (j < code.size() && std::isspace(static_cast<unsigned char>(code[j]))) ++j;
  size_t k = j;
  while (k < code.size() && is_ident(code[k])) ++k;
  static const std::set<std::string> kDraws = {"next", "next_bits", "bits", "uniform"};
  if (!kDraws.count(code.substr(j, k - j))) return 0;
  while (k < code.size() && std::isspace(static_cast<unsigned char>(code[k]))) ++k;
  return k < code.size() && code[k] == '(' ? k - i : 0;
}

}  // namespace

std::vector<DrawLintFinding> lint_draws(const std::string& text, const std::string& file) {
  const std::string code = code_only(text);
  struct Group {
    char kind;
    bool call;
    int line;
    int draws;
  };
  std::vector<Group> stack;
  std::vector<DrawLintFinding> findings;
  int line = 1;
  for (size_t i = 0; i < code.size(); ++i) {
    const char c = code[i];
    if (c == '\n') {
      ++line;
    } else if (const size_t n = draw_at(code, i)) {
      if (!stack.empty()) ++stack.back().draws;
      i += n - 1;  // up to the draw's own '(', pushed next
    } else if (c == '(' || c == '{' || c == '[') {
      stack.push_back({c, c == '(' && opens_call(code, i), line, 0});
    } else if ((c == ')' || c == '}' || c == ']') && !stack.empty()) {
      const Group g = stack.back();
      stack.pop_back();
      if (g.kind != '(') continue;  // a brace or bracket ends the search
      const bool flagged = g.call && g.draws >= 2;
      if (flagged) findings.push_back({file, g.line, g.draws});
      // Outer lists see a flagged call as one draw, so a problem is reported once.
      if (!stack.empty() && stack.back().kind == '(') stack.back().draws += flagged ? 1 : g.draws;
    }
  }
  return findings;
}

std::vector<DrawLintFinding> lint_draws_in_tree(const std::string& root) {
  std::vector<DrawLintFinding> all;
  std::vector<std::string> files;
  for (const char* dir : {"tracer/kernel", "cuda", "tests"}) {
    const fs::path base = fs::path(root) / dir;
    if (!fs::is_directory(base)) continue;
    for (const auto& e : fs::recursive_directory_iterator(base)) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file() && (ext == ".h" || ext == ".cpp" || ext == ".cu"))
        files.push_back(fs::relative(e.path(), root).string());
    }
  }
  if (files.empty())
    throw InputError(root + ": none of tracer/kernel, cuda and tests holds a .h, .cpp or .cu file: nothing to lint");
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) {
    const std::vector<DrawLintFinding> found = lint_draws(read_text_file((fs::path(root) / f).string(), "source"), f);
    all.insert(all.end(), found.begin(), found.end());
  }
  return all;
}

}  // namespace tracer
