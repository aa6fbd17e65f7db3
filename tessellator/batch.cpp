#include "batch.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

#include "fixed.h"
#include "names.h"

namespace fftess {
namespace {

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> t;
  std::istringstream in(line);
  std::string s;
  while (in >> s) t.push_back(s);
  return t;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void appendHex8(std::string& out, uint32_t v) {
  static const char* digits = "0123456789abcdef";
  char buf[8];
  for (int i = 7; i >= 0; --i, v >>= 4) buf[i] = digits[v & 15];
  out.append(buf, 8);
}

} // namespace

bool isBatchSkippable(const std::string& line) {
  for (char c : line) {
    if (c == '#') return true;
    if (!std::isspace(static_cast<unsigned char>(c))) return false; // blank as the tokenizer sees it
  }
  return true;
}

bool parseFactor(const std::string& token, float& out, std::string* why) {
  auto fail = [&](const char* reason) {
    if (why) *why = reason;
    return false;
  };
  if (token.size() >= 2 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X')) {
    if (token.size() != 10) return fail("hex factor needs 0x and exactly 8 hex digits");
    uint32_t bits = 0;
    for (size_t i = 2; i < 10; ++i) {
      const int d = hexDigit(token[i]);
      if (d < 0) return fail("hex factor needs 0x and exactly 8 hex digits");
      bits = (bits << 4) | uint32_t(d);
    }
    out = fx::floatOf(bits);
    return true;
  }
  if (token.empty()) return fail("not a number");
  // strtof also reads C99 hex floats; an 'x' in a token that is not nan/inf (which have an 'n') is one of those.
  if (token.find_first_of("xX") != std::string::npos && token.find_first_of("nN") == std::string::npos)
    return fail("not a decimal float (hex factors are 0x and exactly 8 hex digits)");
  // Decimal: digits, sign, point, exponent, or the words strtof knows (inf, nan).
  char* end = nullptr;
  errno = 0;
  const float v = std::strtof(token.c_str(), &end);
  if (end == token.c_str() || end != token.c_str() + token.size()) return fail("not a number");
  out = v; // overflow gives +-Inf and underflow a denormal or zero, as a float literal would
  return true;
}

const char* factorName(Domain domain, int i) {
  static const char* const names[3][6] = {
      {"Ueq0", "Veq0", "Ueq1", "Veq1", "insideU", "insideV"},
      {"Ueq0", "Veq0", "Weq0", "inside", "f4", "f5"},
      {"density", "detail", "f2", "f3", "f4", "f5"},
  };
  static const char* const plain[6] = {"f0", "f1", "f2", "f3", "f4", "f5"};
  if (i < 0 || i > 5) return "?";
  switch (domain) {
  case Domain::Quad: return names[0][i];
  case Domain::Tri: return names[1][i];
  case Domain::Isoline: return names[2][i];
  }
  return plain[i];
}

bool parseBatchLine(const std::string& line, Patch& patch, BatchError& err) {
  static const char* const kFormat = "DOMAIN PARTITIONING TOPOLOGY STAGE f0 f1 f2 f3 f4 f5";
  static const std::string kTopologies = joinNames(outputPrimitiveNames());
  static const std::string kStages = joinNames(stageNames());
  const std::vector<std::string> t = tokens(line);
  auto fail = [&](int column, const std::string& token, const std::string& message) {
    err.column = column;
    err.token = token;
    err.message = message;
    return false;
  };
  Patch p;
  if (t.empty()) return fail(1, "", std::string("empty line (expected ") + kFormat + ")");
  if (!parseDomain(t[0].c_str(), p.domain))
    return fail(1, t[0], "unknown domain (expected " + joinNames(domainNames()) + ")");
  if (t.size() < 2)
    return fail(2, "", "missing partitioning after '" + t[0] + "' (expected " + kFormat + ")");
  if (!parsePartitioning(t[1].c_str(), p.partitioning))
    return fail(2, t[1], "unknown partitioning (expected " + joinNames(partitioningNames()) + ")");
  if (t.size() < 3) return fail(3, "", "missing topology (expected " + kTopologies + ")");
  if (!parseOutputPrimitive(t[2].c_str(), p.primitive))
    return fail(3, t[2], "unknown topology (expected " + kTopologies + ")");
  if (p.domain == Domain::Isoline &&
      (p.primitive == OutputPrimitive::TriangleCw || p.primitive == OutputPrimitive::TriangleCcw))
    return fail(3, t[2], "isoline output is point or line");
  if (t.size() < 4) return fail(4, "", "missing stage (expected " + kStages + ")");
  if (!parseStage(t[3].c_str(), p.stage)) return fail(4, t[3], "unknown stage (expected " + kStages + ")");
  if (t.size() < 10)
    return fail(int(t.size()), t.back(), // the last token there is, so the message names one
                "expected 6 factors after the stage, got " + std::to_string(t.size() - 4) + " (format: " + kFormat + ")");
  if (t.size() > 10) return fail(11, t[10], "extra token after the 6 factors");
  for (int i = 0; i < 6; ++i) {
    std::string why;
    if (!parseFactor(t[4 + i], p.factors[i], &why))
      return fail(5 + i, t[4 + i], std::string("factor ") + factorName(p.domain, i) + ": " + why);
  }
  patch = p;
  return true;
}

std::string formatBatchLine(const Patch& patch) {
  std::string out = std::string(toString(patch.domain)) + ' ' + toString(patch.partitioning) + ' ' +
                    toString(patch.primitive) + ' ' + toString(patch.stage);
  for (float f : patch.factors) {
    out += " 0x";
    appendHex8(out, fx::bitsOf(f));
  }
  return out;
}

int indicesPerLine(const Patch& patch) {
  if (patch.primitive == OutputPrimitive::Point) return 1;
  if (patch.domain == Domain::Isoline || patch.primitive == OutputPrimitive::Line) return 2;
  return 3;
}

void appendHexBlock(std::string& out, int n, const Patch& patch, const Tessellator& result) {
  appendHexBlock(out, n, patch, result.points().data(), int(result.points().size()), result.indices().data(),
                 int(result.indices().size()));
}

void appendHexBlock(std::string& out, int n, const Patch& patch, const DomainPoint* points, int numPoints,
                    const int32_t* indices, int numIndices) {
  out += "patch " + std::to_string(n) + " points " + std::to_string(numPoints) + " indices " +
         std::to_string(numIndices) + "\n";
  for (int k = 0; k < numPoints; ++k) {
    appendHex8(out, fx::bitsOf(points[k].u));
    out += ' ';
    appendHex8(out, fx::bitsOf(points[k].v));
    out += '\n';
  }
  const int per = indicesPerLine(patch);
  for (int i = 0; i < numIndices; ++i) {
    out += std::to_string(indices[i]);
    out += ((i + 1) % per == 0 || i + 1 == numIndices) ? '\n' : ' ';
  }
}

uint64_t fnv1a64(const std::string& bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

} // namespace fftess
