// gpu_lod/hull.h front end: diagnostics as file:line:col lines, which files are hull shaders, the user's files and
// their #includes, glslang's log.
#include "gpu_lod/hull_front.h"

#include <cctype>

#include <glslang/Public/ResourceLimits.h>

#include <mutex>
#include <regex>
#include <sstream>

namespace fftess::gpulod::hull {

std::string formatDiagnostic(const Diagnostic& d) {
  std::string where = d.at.file.empty() ? std::string("fftess") : d.at.file;
  if (!d.at.file.empty() && d.at.line > 0) {
    where += ":" + std::to_string(d.at.line);
    if (d.at.column > 0) where += ":" + std::to_string(d.at.column);
  }
  return where + (d.warning ? ": warning: " : ": error: ") + d.message;
}

std::string formatDiagnostics(const std::vector<Diagnostic>& ds) {
  std::string out;
  for (const Diagnostic& d : ds) {
    if (!out.empty()) out += '\n';
    out += formatDiagnostic(d);
  }
  return out;
}

namespace {
bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
} // namespace

Language languageOf(const std::string& file) {
  return endsWith(file, ".hlsl") || endsWith(file, ".fx") ? Language::Hlsl : Language::Glsl;
}

bool isHullShader(const std::string& file, const std::string& source) {
  const std::string text = detail::blankComments(source);
  if (std::regex_search(text, std::regex(R"(\blodMain\s*\()"))) return false;
  if (languageOf(file) == Language::Hlsl)
    return endsWith(file, ".fx") || std::regex_search(text, std::regex(R"(\[\s*patchconstantfunc\s*\()"));
  return endsWith(file, ".tesc") || endsWith(file, ".tesc.glsl") ||
         std::regex_search(text, std::regex(R"(layout\s*\(\s*vertices\s*=\s*\d+\s*\)\s*out\b)"));
}

namespace detail {

int SourceSet::add(const std::string& file, const std::string& text) {
  for (size_t i = 0; i < files.size(); ++i)
    if (files[i] == file) return static_cast<int>(i);
  files.push_back(file);
  texts.push_back(text);
  return static_cast<int>(files.size()) - 1;
}

const std::string* SourceSet::textOf(const std::string& file) const {
  for (size_t i = 0; i < files.size(); ++i)
    if (files[i] == file) return &texts[i];
  return nullptr;
}

// The Effects framework's blocks in an .fx file (Luna's Terrain.fx ships with them), which glslang refuses and which
// describe no hull shader arithmetic: `technique11 NAME { ... }` (also technique, technique10) and the state
// objects' initialisers `RasterizerState | DepthStencilState | BlendState NAME { ... };` blanked whole,
// `SamplerState NAME { ... }` keeping `SamplerState NAME` (fftess's heightmap sampling applies). Blanks keep every
// newline, so lines and columns stay the file's. Such text is never valid GLSL, so every file goes through this.
std::string blankEffectsBlocks(std::string text) {
  static const std::regex block(
      R"(\b(technique(?:10|11)?|RasterizerState|DepthStencilState|BlendState|SamplerState)\s+\w+\s*\{)");
  std::smatch m;
  size_t from = 0;
  std::string rest;
  while (std::regex_search(rest = text.substr(from), m, block)) {
    const size_t start = from + static_cast<size_t>(m.position(0));
    const size_t open = from + static_cast<size_t>(m.position(0) + m.length(0)) - 1;
    int depth = 0;
    size_t close = open;
    for (; close < text.size(); ++close) {
      if (text[close] == '{') ++depth;
      if (text[close] == '}' && --depth == 0) break;
    }
    if (close >= text.size()) break; // unbalanced: left to glslang's message
    size_t end = close + 1;
    const size_t semi = text.find_first_not_of(" \t\r\n", end);
    if (semi != std::string::npos && text[semi] == ';') end = semi + 1;
    const size_t blankFrom = m[1] == "SamplerState" ? open : start;
    for (size_t i = blankFrom; i < end; ++i)
      if (text[i] != '\n') text[i] = ' ';
    if (m[1] == "SamplerState") text[end - 1 >= open ? end - 1 : open] = ';';
    from = end;
  }
  return text;
}

bool MainSource::read(const std::string& path, SourceSet& sources, std::vector<Diagnostic>& errors) {
  file = path;
  if (!readFile(path, text)) {
    errors.push_back(inFile(path, "cannot read the shader"));
    return false;
  }
  text = blankEffectsBlocks(text);
  sources.add(file, text);
  return true;
}

void MainSource::attach(glslang::TShader& shader) {
  string = text.c_str();
  length = static_cast<int>(text.size());
  name = file.c_str();
  shader.setStringsWithLengthsAndNames(&string, &length, &name, 1);
}

bool parseAndLink(glslang::TShader& shader, glslang::TProgram& program, SourceSet& sources, EShMessages messages,
                  int defaultVersion, EProfile profile, std::vector<Diagnostic>& errors) {
  initGlslang();
  FileIncluder includer(sources);
  bool ok = shader.parse(GetDefaultResources(), defaultVersion, profile, false, false, messages, includer);
  if (ok) {
    program.addShader(&shader);
    ok = program.link(messages);
  }
  const std::string log = std::string(shader.getInfoLog()) + (ok ? "" : program.getInfoLog());
  const size_t before = errors.size();
  for (const Diagnostic& d : parseGlslangLog(log, sources))
    if (!d.warning) errors.push_back(d);
  return ok && errors.size() == before;
}

std::string resolveInclude(const std::string& name, const std::string& includer) {
  if (!name.empty() && name[0] == '/') return name;
  const size_t slash = includer.find_last_of('/');
  return slash == std::string::npos ? name : includer.substr(0, slash + 1) + name;
}

FileIncluder::IncludeResult* FileIncluder::includeLocal(const char* header, const char* includer, size_t) {
  const std::string path = resolveInclude(header, includer ? includer : "");
  auto text = std::make_unique<std::string>();
  if (!readFile(path, *text)) return nullptr; // glslang: "Could not process include directive for header name"
  *text = blankEffectsBlocks(*text);
  sources_.add(path, *text);
  kept_.push_back(std::move(text));
  return new IncludeResult(path, kept_.back()->data(), kept_.back()->size(), nullptr);
}

FileIncluder::IncludeResult* FileIncluder::includeSystem(const char* header, const char* includer, size_t depth) {
  return includeLocal(header, includer, depth);
}

void FileIncluder::releaseInclude(IncludeResult* r) { delete r; }

void initGlslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

std::string blankComments(const std::string& text) {
  std::string out = text;
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n')
        out[i++] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      size_t j = i;
      for (; j < out.size() && !(j > i + 1 && out[j - 1] == '*' && out[j] == '/'); ++j)
        if (out[j] != '\n') out[j] = ' ';
      if (j < out.size()) out[j] = ' ';
      i = j;
    }
  }
  return out;
}

SourcePos positionOf(const std::string& file, const std::string& text, size_t at) {
  SourcePos p{file, 1, 1};
  for (size_t i = 0; i < at && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

namespace {

// Byte offset of the start of line `line` (1-based) in text; npos past the end.
size_t lineStart(const std::string& text, int line) {
  size_t at = 0;
  for (int l = 1; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string::npos) return at;
    ++at;
  }
  return at;
}

int columnOfToken(const SourceSet& sources, const std::string& file, int line, const std::string& token) {
  const std::string* text = sources.textOf(file);
  if (!text || token.empty() || line <= 0) return 0;
  const size_t start = lineStart(*text, line);
  if (start == std::string::npos) return 0;
  const size_t end = std::min(text->find('\n', start), text->size());
  // The first occurrence that is a whole token where the token is a word ('f' is not the f of "float").
  const std::string l = text->substr(start, end - start);
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  const bool isWord = word(token.front()) && word(token.back());
  for (size_t at = l.find(token); at != std::string::npos; at = l.find(token, at + 1)) {
    if (!isWord || ((at == 0 || !word(l[at - 1])) && (at + token.size() >= l.size() || !word(l[at + token.size()]))))
      return static_cast<int>(at) + 1;
  }
  return 0;
}

} // namespace

std::vector<Diagnostic> parseGlslangLog(const std::string& log, const SourceSet& sources) {
  std::vector<Diagnostic> out;
  std::istringstream in(log);
  std::string l;
  const std::regex located(R"(^(ERROR|WARNING): (.+?):(\d+): (.*)$)");
  const std::regex plain(R"(^(ERROR|WARNING): (.*)$)");
  const std::regex token(R"(^'([^']*)' : )");
  std::smatch m;
  while (std::getline(in, l)) {
    Diagnostic d;
    if (std::regex_match(l, m, located)) {
      d.warning = m[1] == "WARNING";
      d.at.file = m[2];
      if (!d.at.file.empty() && std::isdigit(static_cast<unsigned char>(d.at.file[0])) &&
          d.at.file.find_first_not_of("0123456789") == std::string::npos) {
        const size_t s = std::stoul(d.at.file);
        d.at.file = s < sources.files.size() ? sources.files[s] : sources.files.at(0);
      }
      d.at.line = std::stoi(m[3]);
      d.message = m[4];
      std::smatch t;
      if (std::regex_search(d.message, t, token)) {
        d.at.column = columnOfToken(sources, d.at.file, d.at.line, t[1]);
        if (t[1].length() == 0) d.message = d.message.substr(t.length()); // "'' :  syntax error, ..."
        const size_t text = d.message.find_first_not_of(' ');
        d.message = text == std::string::npos ? d.message : d.message.substr(text);
      }
    } else if (std::regex_match(l, m, plain)) {
      if (std::regex_search(l, std::regex(R"(compilation errors\.|Linking tessellation)"))) continue;
      d.warning = m[1] == "WARNING";
      d.at.file = sources.files.empty() ? std::string() : sources.files[0];
      d.message = m[2];
    } else {
      continue;
    }
    d.message.erase(d.message.find_last_not_of(" \t\r") + 1);
    out.push_back(d);
  }
  return out;
}

namespace {

struct Line {
  int file = 0; // index in SourceSet::files
  int line = 0;
  std::string text; // comments blanked
};

// The user's files in the order the compiler reads them: every #include "x" replaced by x's lines.
void expandedLines(const SourceSet& sources, int file, int depth, std::vector<Line>& out) {
  static const std::regex include(R"(^\s*#\s*include\s*["<]([^">]+)[">])");
  std::istringstream in(blankComments(sources.texts[static_cast<size_t>(file)]));
  std::string text;
  std::smatch m;
  for (int n = 1; std::getline(in, text); ++n) {
    if (depth < 32 && std::regex_search(text, m, include)) {
      const std::string path = resolveInclude(m[1], sources.files[static_cast<size_t>(file)]);
      for (size_t i = 0; i < sources.files.size(); ++i)
        if (sources.files[i] == path) expandedLines(sources, static_cast<int>(i), depth + 1, out);
      continue;
    }
    out.push_back({file, n, text});
  }
}

} // namespace

SourcePos findDeclaration(const SourceSet& sources, const std::string& name, const std::string& keyword,
                          const std::string& after) {
  if (sources.files.empty()) return {};
  std::vector<Line> lines;
  expandedLines(sources, 0, 0, lines);
  const std::regex word("\\b" + name + "\\b");
  size_t from = 0;
  if (!after.empty()) {
    const std::regex block("\\b" + after + "\\b");
    while (from < lines.size() && !std::regex_search(lines[from].text, block))
      ++from;
    if (from == lines.size()) from = 0;
  }
  SourcePos first;
  std::smatch m;
  for (size_t i = from; i < lines.size(); ++i) {
    if (!std::regex_search(lines[i].text, m, word)) continue;
    const SourcePos at{sources.files[static_cast<size_t>(lines[i].file)], lines[i].line,
                       static_cast<int>(m.position()) + 1};
    if (keyword.empty() || std::regex_search(lines[i].text, std::regex("\\b" + keyword + "\\b"))) return at;
    if (first.line == 0) first = at;
  }
  return first;
}

} // namespace detail
} // namespace fftess::gpulod::hull
