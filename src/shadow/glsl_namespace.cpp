#include "shadow/glsl_namespace.hpp"

#include <cctype>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "penumbra/error.hpp"

namespace penumbra::glsl {
namespace {

enum class Kind { Identifier, Number, Punctuation, Comment, Space };

struct Token {
  Kind kind;
  std::string_view text;
  bool directive;  // part of a preprocessor line
  int line;        // 1-based, for messages
};

bool is_identifier_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool is_identifier_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// GLSL's tokens, as far as finding declarations needs: identifiers,
// numbers, comments, white space, and every other character on its own.
// A '#' first on a line starts a directive that runs to the line's end
// (continued by a backslash before the newline).
std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  int line = 1;
  bool line_start = true, directive = false;
  while (i < text.size()) {
    const char c = text[i];
    const std::size_t begin = i;
    Kind kind;
    if (c == '\n') {
      ++i;
      kind = Kind::Space;
      directive = false;
    } else if (c == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
      i += 2;  // a continued line stays in its directive
      kind = Kind::Space;
    } else if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      while (i < text.size() && text[i] != '\n' &&
             std::isspace(static_cast<unsigned char>(text[i])))
        ++i;
      kind = Kind::Space;
    } else if (text.substr(i, 2) == "//") {
      while (i < text.size() && text[i] != '\n') ++i;
      kind = Kind::Comment;
    } else if (text.substr(i, 2) == "/*") {
      const std::size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 2;
      kind = Kind::Comment;
    } else if (is_identifier_start(c)) {
      while (i < text.size() && is_identifier_char(text[i])) ++i;
      kind = Kind::Identifier;
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0 ||
               (c == '.' && i + 1 < text.size() &&
                std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0)) {
      ++i;
      while (i < text.size() &&
             (is_identifier_char(text[i]) || text[i] == '.' ||
              ((text[i] == '+' || text[i] == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E'))))
        ++i;
      kind = Kind::Number;
    } else {
      if (c == '#' && line_start) directive = true;
      ++i;
      kind = Kind::Punctuation;
    }
    const std::string_view token = text.substr(begin, i - begin);
    tokens.push_back({kind, token, directive && c != '\n', line});
    for (char ch : token) line += ch == '\n' ? 1 : 0;
    if (token == "\n") {
      line_start = true;
    } else if (kind != Kind::Space && kind != Kind::Comment) {
      line_start = false;
    }
  }
  return tokens;
}

bool is_reserved(std::string_view name) {
  return name.starts_with("gl_") || name.starts_with("GL_") ||
         name.find("__") != std::string_view::npos;
}

// Qualifiers and the like: never the name a declaration declares.
bool is_qualifier(std::string_view word) {
  static const std::set<std::string_view> words = {
      "const",   "uniform",  "buffer",        "in",        "out",       "inout",
      "shared",  "readonly", "writeonly",     "coherent",  "volatile",  "restrict",
      "flat",    "smooth",   "noperspective", "centroid",  "sample",    "patch",
      "highp",   "mediump",  "lowp",          "precise",   "invariant", "attribute",
      "varying", "struct",   "layout",        "precision", "subroutine"};
  return words.contains(word);
}

bool is_storage_qualifier(std::string_view word) {
  return word == "uniform" || word == "buffer" || word == "in" || word == "out" ||
         word == "shared" || word == "patch";
}

// Reads the global statements of the tokens outside directives.
class Parser {
 public:
  explicit Parser(const std::vector<Token>& tokens) : tokens_(tokens) {
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const Token& t = tokens[i];
      if (t.directive || t.kind == Kind::Space || t.kind == Kind::Comment) continue;
      code_.push_back(i);
    }
    find_function_defining_macros();
  }

  Declarations declarations;
  std::set<std::size_t> members;  // tokens that name a struct's or named block's member

  void parse() {
    std::size_t p = 0;
    while (p < code_.size()) {
      if (const std::optional<std::size_t> next = macro_defined_function(p)) {
        p = *next;
        continue;
      }
      const std::size_t end = statement_end(p);
      if (text(end) == ";") {
        declaration(p, end);
        p = end + 1;
      } else {
        p = braced(p, end);
      }
    }
  }

 private:
  const std::vector<Token>& tokens_;
  std::vector<std::size_t> code_;  // indices of the tokens outside directives and comments

  [[nodiscard]] std::string_view text(std::size_t k) const {
    return k < code_.size() ? tokens_[code_[k]].text : std::string_view();
  }
  [[nodiscard]] bool identifier(std::size_t k) const {
    return k < code_.size() && tokens_[code_[k]].kind == Kind::Identifier;
  }
  // Function-like macros whose body defines a function named by one of
  // their parameters (`#define X_DEFINE(NAME, ...) float NAME(...) {...}`,
  // the shadow techniques' loops written once over several maps): the
  // parameter's index, per macro name.
  std::map<std::string, std::size_t, std::less<>> function_macros_;

  void find_function_defining_macros() {
    std::vector<std::size_t> directive;  // one directive's non-space tokens
    const auto read = [&] {
      // # define NAME ( p0 , p1 , ... ) body: the parameter list must touch
      // the name (a function-like macro).
      if (directive.size() < 5 || tokens_[directive[1]].text != "define") return;
      const std::size_t name = directive[2], open = directive[3];
      if (tokens_[open].text != "(" || open != name + 1) return;
      std::vector<std::string_view> parameters;
      std::size_t k = 4;
      for (; k < directive.size() && tokens_[directive[k]].text != ")"; ++k) {
        if (tokens_[directive[k]].kind == Kind::Identifier) {
          parameters.push_back(tokens_[directive[k]].text);
        }
      }
      for (++k; k + 2 < directive.size(); ++k) {
        const Token &type = tokens_[directive[k]], &named = tokens_[directive[k + 1]];
        if (type.kind != Kind::Identifier || tokens_[directive[k + 2]].text != "(") continue;
        for (std::size_t p = 0; p < parameters.size(); ++p) {
          if (named.text == parameters[p]) {
            function_macros_.emplace(std::string(tokens_[name].text), p);
            return;
          }
        }
      }
    };
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
      const Token& t = tokens_[i];
      if (!t.directive) {
        if (!directive.empty()) read();
        directive.clear();
        continue;
      }
      if (t.kind == Kind::Space || t.kind == Kind::Comment) continue;
      if (t.text == "#" && !directive.empty()) {
        read();
        directive.clear();
      }
      directive.push_back(i);
    }
    if (!directive.empty()) read();
  }

  // At p, an invocation of a function-defining macro at global scope: the
  // function it defines is declared; returns where the next statement
  // starts (after its ')' and an optional ';').
  std::optional<std::size_t> macro_defined_function(std::size_t p) {
    if (!identifier(p) || text(p + 1) != "(") return std::nullopt;
    const auto macro = function_macros_.find(text(p));
    if (macro == function_macros_.end()) return std::nullopt;
    int depth = 0;
    std::size_t argument = 0;
    bool named = false;
    for (std::size_t k = p + 1; k < code_.size(); ++k) {
      const std::string_view t = text(k);
      if (t == "(") {
        ++depth;
      } else if (t == ")") {
        if (--depth == 0) {
          if (!named) fail(p, "a function-defining macro without the function's name");
          return text(k + 1) == ";" ? k + 2 : k + 1;
        }
      } else if (depth == 1 && t == ",") {
        ++argument;
      } else if (depth == 1 && argument == macro->second && !named) {
        add(declarations.functions, k);
        named = true;
      }
    }
    fail(p, "a macro invocation without its ')'");
  }

  [[noreturn]] void fail(std::size_t k, const std::string& what) const {
    const int line = k < code_.size() ? tokens_[code_[k]].line : tokens_.back().line;
    throw RuntimeError("shadow lookup GLSL, line " + std::to_string(line) + ": " + what);
  }

  // The ';' or '{' that ends the global statement starting at p.
  std::size_t statement_end(std::size_t p) const {
    int depth = 0;
    for (std::size_t k = p; k < code_.size(); ++k) {
      const std::string_view t = text(k);
      if (t == "(" || t == "[") ++depth;
      if (t == ")" || t == "]") --depth;
      if (depth == 0 && (t == ";" || t == "{")) return k;
      if (t == "}") fail(k, "unbalanced '}'");
    }
    fail(p, "a statement without its ';'");
  }

  // The tokens of [from, to) with every layout(...) qualifier left out.
  std::vector<std::size_t> without_layout(std::size_t from, std::size_t to) const {
    std::vector<std::size_t> kept;
    for (std::size_t k = from; k < to; ++k) {
      if (text(k) == "layout" && text(k + 1) == "(") {
        int depth = 0;
        for (++k; k < to; ++k) {
          if (text(k) == "(") ++depth;
          if (text(k) == ")" && --depth == 0) break;
        }
        continue;
      }
      kept.push_back(k);
    }
    return kept;
  }

  void add(std::set<std::string>& to, std::size_t k) {
    if (!identifier(k)) fail(k, "expected a name, found '" + std::string(text(k)) + "'");
    if (!is_reserved(text(k))) to.emplace(text(k));
  }

  // The '}' that closes the '{' at `open`.
  std::size_t matching_brace(std::size_t open) const {
    int depth = 0;
    for (std::size_t k = open; k < code_.size(); ++k) {
      if (text(k) == "{") ++depth;
      if (text(k) == "}" && --depth == 0) return k;
    }
    fail(open, "a '{' without its '}'");
  }

  // The names declared by `type a, b[N], c = value` in [from, to): in each
  // comma-separated part, the last name outside brackets before any '='.
  std::vector<std::size_t> declarators(const std::vector<std::size_t>& statement) const {
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<std::size_t> names;
    std::size_t last = kNone;
    int depth = 0;
    bool initializer = false;
    for (std::size_t k : statement) {
      const std::string_view t = text(k);
      if (t == "(" || t == "[" || t == "{") ++depth;
      if (t == ")" || t == "]" || t == "}") --depth;
      if (depth != 0) continue;
      if (t == ",") {
        if (last != kNone) names.push_back(last);
        last = kNone;
        initializer = false;
      } else if (t == "=") {
        initializer = true;
      } else if (!initializer && identifier(k) && !is_qualifier(t)) {
        last = k;
      }
    }
    if (last != kNone) names.push_back(last);
    return names;
  }

  // A global statement ending in ';': a function's prototype, variables
  // (constants, uniforms) or nothing (precision, a stage's layout).
  void declaration(std::size_t from, std::size_t end) {
    const std::vector<std::size_t> statement = without_layout(from, end);
    if (statement.empty() || text(statement.front()) == "precision") return;
    for (std::size_t i = 0; i < statement.size(); ++i) {
      const std::string_view t = text(statement[i]);
      if (t == "=") break;
      if (t == "(") {
        if (i == 0) fail(statement[i], "a statement that starts with '('");
        add(declarations.functions, statement[i - 1]);
        return;
      }
    }
    for (std::size_t name : declarators(statement)) add(declarations.variables, name);
  }

  // The members of the struct or block whose '{' is at `open`: per member
  // statement, the names the declarators() rule finds.
  std::vector<std::size_t> member_names(std::size_t open, std::size_t close) const {
    std::vector<std::size_t> names;
    std::size_t from = open + 1;
    for (std::size_t k = open + 1; k < close; ++k) {
      if (text(k) != ";") continue;
      for (std::size_t name : declarators(without_layout(from, k))) names.push_back(name);
      from = k + 1;
    }
    if (from != close) fail(from, "a member without its ';'");
    return names;
  }

  // A global statement ending in '{' at `open`: a struct, a block or a
  // function's definition. Returns where the next statement starts.
  std::size_t braced(std::size_t from, std::size_t open) {
    const std::vector<std::size_t> head = without_layout(from, open);
    if (head.empty()) fail(open, "a '{' that opens no declaration");
    const std::size_t close = matching_brace(open);
    bool has_parenthesis = false, has_storage = false;
    std::optional<std::size_t> struct_keyword;
    int depth = 0;  // a function's parameters may be "in" or "out"
    for (std::size_t k : head) {
      if (text(k) == "(") has_parenthesis = true;
      if (text(k) == "(") ++depth;
      if (text(k) == ")") --depth;
      if (depth == 0 && is_storage_qualifier(text(k))) has_storage = true;
      if (depth == 0 && text(k) == "struct") struct_keyword = k;
    }
    if (has_parenthesis && !struct_keyword && !has_storage) {
      // A function's definition: the name before the parameter list.
      for (std::size_t i = 1; i < head.size(); ++i) {
        if (text(head[i]) == "(") {
          add(declarations.functions, head[i - 1]);
          return close + 1;
        }
      }
    }
    const bool is_struct = struct_keyword.has_value();
    if (!is_struct && (!has_storage || has_parenthesis)) {
      fail(open, "a '{' after something that is no struct, block or function");
    }
    add(is_struct ? declarations.types : declarations.blocks, head.back());
    const std::vector<std::size_t> names = member_names(open, close);
    // After the '}': the struct's variables, or the block's instance name.
    const std::size_t end = statement_end(close + 1);
    if (text(end) != ";") fail(end, "a declaration after '}' without its ';'");
    std::vector<std::size_t> after;
    for (std::size_t k = close + 1; k < end; ++k) after.push_back(k);
    const std::vector<std::size_t> instances = declarators(after);
    for (std::size_t name : instances) add(declarations.variables, name);
    if (is_struct || !instances.empty()) {
      for (std::size_t name : names) members.insert(code_[name]);
    } else {
      // A block without an instance name: its members are global names.
      for (std::size_t name : names) add(declarations.variables, name);
    }
    return end + 1;
  }
};

// The directives' declarations: #define's names, and the names #if,
// #ifdef, #ifndef and #elif ask about (a lookup that tests an engine's
// macro would read the engine's configuration).
void directive_declarations(const std::vector<Token>& tokens, Declarations& declarations) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!tokens[i].directive || tokens[i].text != "#") continue;
    std::vector<std::size_t> words;
    std::size_t k = i + 1;
    for (; k < tokens.size() && tokens[k].directive; ++k) {
      if (tokens[k].kind != Kind::Space && tokens[k].kind != Kind::Comment) words.push_back(k);
    }
    if (!words.empty()) {
      const std::string_view name = tokens[words.front()].text;
      if (name == "define" && words.size() >= 2) {
        if (!is_reserved(tokens[words[1]].text)) declarations.macros.emplace(tokens[words[1]].text);
      } else if (name == "if" || name == "ifdef" || name == "ifndef" || name == "elif") {
        for (std::size_t w = 1; w < words.size(); ++w) {
          const Token& t = tokens[words[w]];
          if (t.kind == Kind::Identifier && t.text != "defined" && !is_reserved(t.text))
            declarations.macros.emplace(t.text);
        }
      }
    }
    i = k - 1;
  }
}

}  // namespace

std::set<std::string> Declarations::all() const {
  std::set<std::string> names;
  for (const auto* kind : {&macros, &types, &blocks, &functions, &variables})
    names.insert(kind->begin(), kind->end());
  return names;
}

Declarations global_declarations(std::string_view text) {
  const std::vector<Token> tokens = tokenize(text);
  Parser parser(tokens);
  parser.parse();
  directive_declarations(tokens, parser.declarations);
  return std::move(parser.declarations);
}

bool has_namespace_prefix(std::string_view name) {
  return name.starts_with("penumbra_") || name.starts_with("PENUMBRA_") ||
         name.starts_with("Penumbra");
}

std::string prefixed_name(std::string_view name) {
  if (has_namespace_prefix(name)) return std::string(name);
  bool lower = false;
  for (char c : name) lower = lower || std::islower(static_cast<unsigned char>(c)) != 0;
  if (!lower) return "PENUMBRA_" + std::string(name);
  if (std::isupper(static_cast<unsigned char>(name.front())) != 0) {
    return "Penumbra" + std::string(name);
  }
  return "penumbra_impl_" + std::string(name);
}

std::string prefix_declarations(std::string_view text) {
  const std::vector<Token> tokens = tokenize(text);
  Parser parser(tokens);
  parser.parse();
  directive_declarations(tokens, parser.declarations);

  std::set<std::string_view> used;
  for (const Token& t : tokens)
    if (t.kind == Kind::Identifier) used.insert(t.text);
  std::map<std::string, std::string, std::less<>> renamed;
  for (const std::string& name : parser.declarations.all()) {
    if (has_namespace_prefix(name)) continue;
    std::string prefixed = prefixed_name(name);
    if (used.contains(prefixed)) {
      throw RuntimeError("shadow lookup GLSL: '" + name + "' would become '" + prefixed +
                         "', a name it already uses");
    }
    renamed.emplace(name, std::move(prefixed));
  }

  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::string_view previous;  // the last token that is no space or comment
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind == Kind::Identifier && previous != "." && !parser.members.contains(i)) {
      if (auto it = renamed.find(t.text); it != renamed.end()) {
        out += it->second;
        previous = t.text;
        continue;
      }
    }
    out += t.text;
    if (t.kind != Kind::Space && t.kind != Kind::Comment) previous = t.text;
  }
  return out;
}

std::string drop_unused_macros(std::string_view text) {
  // Each dropped #define becomes a line holding only kDropped, until the
  // paragraphs are tidied below.
  constexpr char kDropped = '\x01';
  std::string current(text);
  for (bool dropped = true; dropped;) {
    dropped = false;
    const std::vector<Token> tokens = tokenize(current);
    std::map<std::string_view, int> uses;
    for (const Token& t : tokens)
      if (t.kind == Kind::Identifier) ++uses[t.text];
    std::string out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      if (tokens[i].directive && tokens[i].text == "#") {
        // The directive's words, and where it ends (before its newline).
        std::vector<std::size_t> words;
        std::size_t end = i + 1;
        for (; end < tokens.size() && tokens[end].directive; ++end) {
          if (tokens[end].kind != Kind::Space && tokens[end].kind != Kind::Comment)
            words.push_back(end);
        }
        if (words.size() >= 2 && tokens[words[0]].text == "define" &&
            uses[tokens[words[1]].text] == 1) {
          dropped = true;
          out += kDropped;
          i = end - 1;
          continue;
        }
      }
      out += tokens[i].text;
    }
    current = std::move(out);
  }
  // A paragraph (lines between blank ones) of nothing but dropped macros
  // and comments goes whole, with the blank line after it: its comments
  // were about those macros. Elsewhere only the dropped lines go.
  std::vector<std::string> lines;
  std::istringstream in(current);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  const auto blank = [](const std::string& line) {
    return line.find_first_not_of(" \t") == std::string::npos;
  };
  const auto comment = [](const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t");
    return first != std::string::npos && line.compare(first, 2, "//") == 0;
  };
  std::string out;
  for (std::size_t i = 0; i < lines.size();) {
    if (blank(lines[i])) {
      out += lines[i++] + "\n";
      continue;
    }
    std::size_t end = i;
    bool only_dropped_and_comments = true, any_dropped = false;
    for (; end < lines.size() && !blank(lines[end]); ++end) {
      const bool is_dropped = lines[end] == std::string(1, kDropped);
      any_dropped = any_dropped || is_dropped;
      only_dropped_and_comments = only_dropped_and_comments && (is_dropped || comment(lines[end]));
    }
    if (any_dropped && only_dropped_and_comments) {
      i = end < lines.size() ? end + 1 : end;
      continue;
    }
    for (; i < end; ++i)
      if (lines[i] != std::string(1, kDropped)) out += lines[i] + "\n";
  }
  if (!text.ends_with('\n') && out.ends_with('\n')) out.pop_back();
  return out;
}

std::string strip_cplusplus_sections(std::string_view text) {
  // One entry per open conditional: whether its current branch is C++ only,
  // and whether it is a __cplusplus test at all.
  struct Conditional {
    bool cplusplus;
    bool skipping;
  };
  std::vector<Conditional> open;
  const auto skipping = [&] {
    for (const Conditional& c : open)
      if (c.skipping) return true;
    return false;
  };
  std::istringstream in{std::string(text)};
  std::string line, out;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == "#") {  // "# ifdef X"
      first += second;
      words >> second;
    }
    bool keep = true;
    if (first == "#ifdef" || first == "#ifndef" || first == "#if") {
      const bool cplusplus = second == "__cplusplus" && first != "#if";
      open.push_back({cplusplus, cplusplus && first == "#ifdef"});
      keep = !cplusplus && !skipping();
    } else if ((first == "#else" || first == "#elif") && !open.empty()) {
      if (open.back().cplusplus) {
        if (first == "#elif") throw RuntimeError("#elif after #ifdef __cplusplus");
        open.back().skipping = !open.back().skipping;
        keep = false;
      } else {
        keep = !skipping();
      }
    } else if (first == "#endif" && !open.empty()) {
      const bool cplusplus = open.back().cplusplus;
      open.pop_back();
      keep = !cplusplus && !skipping();
    } else {
      keep = !skipping();
    }
    if (keep && line.find("__cplusplus") != std::string::npos) {
      throw RuntimeError("a test of __cplusplus other than #ifdef/#ifndef: " + line);
    }
    out += keep ? line : std::string();
    out += "\n";
  }
  return out;
}

}  // namespace penumbra::glsl
