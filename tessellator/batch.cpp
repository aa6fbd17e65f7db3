#include "batch.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

#include "fixed.h"

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
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') return false;
  }
  return true;
}

bool parseFactor(const std::string& token, float& out) {
  if (token.size() >= 2 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X')) {
    if (token.size() != 10) return false;
    uint32_t bits = 0;
    for (size_t i = 2; i < 10; ++i) {
      const int d = hexDigit(token[i]);
      if (d < 0) return false;
      bits = (bits << 4) | uint32_t(d);
    }
    out = fx::floatOf(bits);
    return true;
  }
  if (token.empty()) return false;
  // Decimal: digits, sign, point, exponent, or the words strtof knows (inf, nan).
  char* end = nullptr;
  errno = 0;
  const float v = std::strtof(token.c_str(), &end);
  if (end != token.c_str() + token.size()) return false;
  out = v; // overflow gives +-Inf and underflow a denormal or zero, as a float literal would
  return true;
}

bool parseBatchLine(const std::string& line, Patch& patch, BatchError& err) {
  const std::vector<std::string> t = tokens(line);
  auto fail = [&](int column, const std::string& token, const std::string& message) {
    err.column = column;
    err.token = token;
    err.message = message;
    return false;
  };
  if (t.size() < 10)
    return fail(int(t.size()) + 1, "",
                "expected 10 tokens (DOMAIN PARTITIONING TOPOLOGY STAGE f0..f5), got " + std::to_string(t.size()));
  if (t.size() > 10) return fail(11, t[10], "unexpected extra token after f5");
  Patch p;
  if (!parseDomain(t[0].c_str(), p.domain)) return fail(1, t[0], "unknown domain (quad|tri|isoline)");
  if (!parsePartitioning(t[1].c_str(), p.partitioning))
    return fail(2, t[1], "unknown partitioning (integer|pow2|fractional_odd|fractional_even)");
  if (!parseOutputPrimitive(t[2].c_str(), p.primitive))
    return fail(3, t[2], "unknown topology (point|line|triangle_cw|triangle_ccw)");
  if (!parseStage(t[3].c_str(), p.stage))
    return fail(4, t[3], "unknown stage (hw|hlsl-avg|hlsl-min|hlsl-max|hlsl-avg-1axis|hlsl-min-1axis|hlsl-max-1axis)");
  for (int i = 0; i < 6; ++i)
    if (!parseFactor(t[4 + i], p.factors[i]))
      return fail(5 + i, t[4 + i], "bad factor f" + std::to_string(i) + " (decimal float or 0x + 8 hex digits)");
  patch = p;
  return true;
}

int indicesPerLine(const Patch& patch) {
  if (patch.primitive == OutputPrimitive::Point) return 1;
  if (patch.domain == Domain::Isoline || patch.primitive == OutputPrimitive::Line) return 2;
  return 3;
}

void appendHexBlock(std::string& out, int n, const Patch& patch, const Tessellator& result) {
  const auto& pts = result.points();
  const auto& idx = result.indices();
  out += "patch " + std::to_string(n) + " points " + std::to_string(pts.size()) + " indices " +
         std::to_string(idx.size()) + "\n";
  for (const DomainPoint& p : pts) {
    appendHex8(out, fx::bitsOf(p.u));
    out += ' ';
    appendHex8(out, fx::bitsOf(p.v));
    out += '\n';
  }
  const size_t per = size_t(indicesPerLine(patch));
  for (size_t i = 0; i < idx.size(); ++i) {
    out += std::to_string(idx[i]);
    out += ((i + 1) % per == 0 || i + 1 == idx.size()) ? '\n' : ' ';
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
