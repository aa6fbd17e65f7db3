// --cameras FILE: CSV with a header, or a JSON array of objects (camera_file.h; docs/cli.md "Camera files").
#include "camera_file.h"
#include "common.h"

#include "verify/internal.h" // validateCamera

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

namespace fftess::cli {

namespace vf = fftess::verify;

namespace {

constexpr size_t kMaxCameras = 10000000; // 10^7 cameras (about 0.6 GB): a bound on what a file can make fftess hold

enum Field { EyeX, EyeY, EyeZ, TargetX, TargetY, TargetZ, UpX, UpY, UpZ, FovY, Near, Far, Width, Height, Convention,
             kFieldCount };
constexpr int kRequired = 6; // eye_x .. target_z

// Where an error is: "FILE:LINE:FIELD: " (FIELD left out when empty).
[[noreturn]] void fail(const std::string& path, int line, const std::string& field, const std::string& what) {
  throw UsageError("--cameras " + path + ":" + std::to_string(line) + (field.empty() ? "" : ":" + field) + ": " + what);
}

int fieldIndex(const std::string& name) {
  const std::vector<std::string>& f = cameraFields();
  for (size_t i = 0; i < f.size(); ++i)
    if (f[i] == name) return static_cast<int>(i);
  return -1;
}

std::string fieldList() {
  std::string s;
  for (const std::string& f : cameraFields()) s += (s.empty() ? "" : ", ") + f;
  return s;
}

// A number as the scene reader takes one (verify Reader::number): finite, within float range, then rounded to float.
float toFloat(double d, const std::string& path, int line, const std::string& field, const std::string& text) {
  if (!std::isfinite(d)) fail(path, line, field, "\"" + text + "\" is not a finite number");
  if (std::fabs(d) > 3.0e38) fail(path, line, field, "\"" + text + "\" is out of float range");
  return static_cast<float>(d);
}

float* floatField(vf::Camera& c, int f) {
  switch (f) {
  case EyeX: return &c.eye.x;
  case EyeY: return &c.eye.y;
  case EyeZ: return &c.eye.z;
  case TargetX: return &c.target.x;
  case TargetY: return &c.target.y;
  case TargetZ: return &c.target.z;
  case UpX: return &c.up.x;
  case UpY: return &c.up.y;
  case UpZ: return &c.up.z;
  case FovY: return &c.fovY;
  case Near: return &c.nearZ;
  case Far: return &c.farZ;
  default: return nullptr;
  }
}

void setInteger(vf::Camera& c, int f, int64_t v, const std::string& path, int line) {
  if (v < 1 || v > 65536)
    fail(path, line, cameraFields()[f], "must be in [1, 65536] (got " + std::to_string(v) + ")");
  (f == Width ? c.width : c.height) = static_cast<int>(v);
}

void setConvention(vf::Camera& c, const std::string& v, const std::string& path, int line) {
  if (v == "gl") c.convention = vf::CameraConvention::Gl;
  else if (v == "d3d") c.convention = vf::CameraConvention::D3d;
  else fail(path, line, "convention", "unknown value \"" + printable(v, 80) + "\" (expected \"gl\" | \"d3d\")");
}

// validateCamera's "camera.KEY: what" as FILE:LINE:KEY: what.
void validate(const vf::Camera& c, const std::string& path, int line) {
  std::string err;
  if (vf::detail::validateCamera(c, err)) return;
  const size_t colon = err.find(':');
  std::string key = err.substr(0, colon);
  if (key.rfind("camera.", 0) == 0) key = key.substr(7);
  fail(path, line, key, colon == std::string::npos ? err : err.substr(colon + 2));
}

struct Fnv {
  uint64_t h = 0xcbf29ce484222325ull;
  void add(const char* p, size_t n) {
    for (size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(p[i])) * 0x100000001b3ull;
  }
};

// The largest camera file read: 64 MiB, about a million CSV rows (an hour's camera path at 60 frames a second is
// 216,000). Larger than the scene files' 16 MiB (kMaxSceneBytes), which hold no per-frame data. Bounded so that
// `--cameras /dev/zero` or a mistaken multi-gigabyte file is refused at once (issue [8/8]: it read 5 GB).
constexpr size_t kMaxCameraFileBytes = size_t(64) << 20;

std::string readWhole(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw UsageError("--cameras " + quotePath(path) + ": is a directory, not a camera file");
  std::string text;
  const int rc = vf::detail::readBounded(path, kMaxCameraFileBytes, text);
  if (rc < 0)
    throw UsageError("--cameras " + quotePath(path) + ": larger than " + std::to_string(kMaxCameraFileBytes) +
                     " bytes (64 MiB, the limit for a camera file)");
  if (rc == 0) throw UsageError("--cameras " + quotePath(path) + ": cannot read the file");
  return text;
}

// ---- CSV -----------------------------------------------------------------------------------------------------------

std::string trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

// A line's comma-separated fields, each trimmed of spaces; a field in double quotes ("10", "eye_x") is taken without
// them ("" inside stands for one quote), and a comma inside quotes belongs to the field (spreadsheet CSV).
std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false, wasQuoted = false;
  for (size_t i = 0; i <= line.size(); ++i) {
    const char ch = i < line.size() ? line[i] : ',';
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        field += ch;
      }
    } else if (ch == '"' && trim(field).empty()) {
      quoted = wasQuoted = true;
      field.clear();
    } else if (ch == ',') {
      out.push_back(wasQuoted ? field : trim(field));
      field.clear();
      wasQuoted = false;
    } else if (!(wasQuoted && (ch == ' ' || ch == '\t' || ch == '\r'))) {
      field += ch;
    }
  }
  return out;
}

// The header: each name once, every required column present. columns[k] = the field of column k.
std::vector<int> csvHeader(const std::string& line, const std::string& path, int lineNo) {
  std::vector<int> columns;
  std::vector<char> seen(kFieldCount, 0);
  for (const std::string& name : splitCommas(line)) {
    const int f = fieldIndex(name);
    if (f < 0) fail(path, lineNo, name, "unknown column (expected a header of " + fieldList() + ")");
    if (seen[f]) fail(path, lineNo, name, "column given twice");
    seen[f] = 1;
    columns.push_back(f);
  }
  for (int f = 0; f < kRequired; ++f)
    if (!seen[f]) fail(path, lineNo, cameraFields()[f], "missing column (required: eye_x, eye_y, eye_z, target_x, target_y, target_z)");
  return columns;
}

void csvValue(vf::Camera& c, int f, const std::string& v, const std::string& path, int line) {
  const std::string& name = cameraFields()[f];
  if (v.empty()) {
    if (f < kRequired) fail(path, line, name, "missing value");
    return; // from [camera]
  }
  if (f == Convention) return setConvention(c, v, path, line);
  const char* b = v.data();
  const char* e = b + v.size();
  if (f == Width || f == Height) {
    int64_t i = 0;
    const auto r = std::from_chars(b, e, i);
    if (r.ec != std::errc() || r.ptr != e) fail(path, line, name, "\"" + printable(v, 80) + "\" is not a whole number");
    return setInteger(c, f, i, path, line);
  }
  double d = 0;
  const auto r = std::from_chars(b, e, d);
  if (r.ec == std::errc::result_out_of_range) fail(path, line, name, "\"" + printable(v, 80) + "\" is out of float range");
  if (r.ec != std::errc() || r.ptr != e) fail(path, line, name, "\"" + printable(v, 80) + "\" is not a number");
  *floatField(c, f) = toFloat(d, path, line, name, v);
}

void readCsv(const std::string& text, const std::string& path, const vf::Camera& base, CameraFile& out) {
  // A UTF-8 byte order mark (spreadsheet exports) is skipped; CRLF line ends are trimmed with the spaces.
  std::istringstream in(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text);
  std::string line;
  int lineNo = 0;
  std::vector<int> columns;
  bool header = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue; // blank lines (a trailing newline, spacing) and # comments
    if (!header) {
      columns = csvHeader(line, path, lineNo);
      header = true;
      continue;
    }
    const std::vector<std::string> values = splitCommas(line);
    if (values.size() != columns.size())
      fail(path, lineNo, "", "expected " + std::to_string(columns.size()) + " comma-separated values (the header's), got " +
                                 std::to_string(values.size()));
    if (out.cameras.size() >= kMaxCameras) fail(path, lineNo, "", "more than 10000000 cameras");
    vf::Camera c = base;
    for (size_t k = 0; k < columns.size(); ++k) csvValue(c, columns[k], values[k], path, lineNo);
    validate(c, path, lineNo);
    out.cameras.push_back(c);
    out.lines.push_back(lineNo);
  }
  if (!header) fail(path, 1, "", "empty file (expected a header: eye_x,eye_y,eye_z,target_x,target_y,target_z, ...)");
}

// ---- JSON ----------------------------------------------------------------------------------------------------------

// The text's characters handed to nlohmann's parser one at a time; `consumed` tells the handler how far it has read
// (the lexer reads one character past a number, none past a string, a literal or a bracket).
struct CountingIterator {
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  const char* p = nullptr;
  const char** consumed = nullptr;
  reference operator*() const { return *p; }
  CountingIterator& operator++() {
    ++p;
    *consumed = p;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p == o.p; }
  bool operator!=(const CountingIterator& o) const { return p != o.p; }
};

// SAX handler: an array of flat objects; each value checked against its field as it is read.
class JsonCameras : public nlohmann::json_sax<nlohmann::json> {
public:
  JsonCameras(const std::string& text, const std::string& path, const vf::Camera& base, CameraFile& out)
      : text_(text), path_(path), base_(base), out_(out) {}
  const char* consumed = nullptr;

  bool null() override { return scalar("null"); }
  bool boolean(bool) override { return scalar("a boolean"); }
  bool number_integer(number_integer_t v) override { return integer(v, std::to_string(v)); }
  bool number_unsigned(number_unsigned_t v) override {
    return integer(v > uint64_t(INT64_MAX) ? INT64_MAX : int64_t(v), std::to_string(v));
  }
  bool number_float(number_float_t v, const string_t& s) override {
    if (depth_ == 2 && field_ >= 0 && (field_ == Width || field_ == Height))
      fail(path_, line(), name(), "expected a whole number, got " + s);
    return number(v, s);
  }
  bool string(string_t& v) override {
    if (depth_ == 2 && field_ == Convention) {
      setConvention(cam_, v, path_, line());
      return true;
    }
    return scalar("a string");
  }
  bool binary(binary_t&) override { return scalar("binary data"); }
  bool start_object(std::size_t) override {
    if (depth_ == 0) fail(path_, line(), "", "expected a JSON array of camera objects, got an object");
    if (depth_ == 2) return scalar("an object");
    ++depth_;
    cam_ = base_;
    seen_.assign(kFieldCount, 0);
    objectLine_ = line();
    if (out_.cameras.size() >= kMaxCameras) fail(path_, objectLine_, "", "more than 10000000 cameras");
    return true;
  }
  bool key(string_t& k) override {
    field_ = fieldIndex(k);
    key_ = k;
    if (field_ < 0) fail(path_, line(), printable(k, 80), "unknown field (expected " + fieldList() + ")");
    if (seen_[field_]) fail(path_, line(), k, "field given twice");
    seen_[field_] = 1;
    return true;
  }
  bool end_object() override {
    for (int f = 0; f < kRequired; ++f)
      if (!seen_[f]) fail(path_, objectLine_, cameraFields()[f], "missing field (required: eye_x, eye_y, eye_z, target_x, target_y, target_z)");
    validate(cam_, path_, objectLine_);
    out_.cameras.push_back(cam_);
    out_.lines.push_back(objectLine_);
    --depth_;
    return true;
  }
  bool start_array(std::size_t) override {
    if (depth_ == 0) {
      depth_ = 1;
      return true;
    }
    return scalar("an array");
  }
  bool end_array() override {
    depth_ = 0;
    return true;
  }
  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) override {
    std::string what = e.what();
    const size_t at = what.find("syntax error");
    // A number too large for a double (out_of_range.406) is the value of the field just named.
    const std::string field = e.id == 406 && depth_ == 2 ? name() : "";
    fail(path_, lineAt(byte > 0 ? byte - 1 : 0), field, "not valid JSON: " + (at == std::string::npos ? what : what.substr(at)));
  }

private:
  // The line of the last character read (a number's look-ahead character is past its line's end at worst).
  int line() {
    const size_t end = consumed ? static_cast<size_t>(consumed - text_.data()) : 0;
    return lineAt(end > 0 ? end - 1 : 0);
  }
  int lineAt(size_t offset) {
    if (offset < scanned_) scanned_ = 0, lines_ = 1; // never happens in one pass; kept correct anyway
    for (; scanned_ < offset && scanned_ < text_.size(); ++scanned_) lines_ += text_[scanned_] == '\n';
    return lines_;
  }
  std::string name() const { return field_ >= 0 ? cameraFields()[field_] : key_; }
  bool scalar(const char* got) {
    if (depth_ == 0) fail(path_, line(), "", std::string("expected a JSON array of camera objects, got ") + got);
    if (depth_ == 1) fail(path_, line(), "", std::string("expected a camera object, got ") + got);
    const char* want = field_ == Convention ? "a string (\"gl\" | \"d3d\")"
                       : field_ == Width || field_ == Height ? "a whole number"
                                                               : "a number";
    fail(path_, line(), name(), std::string("expected ") + want + ", got " + got);
  }
  bool integer(int64_t v, const std::string& text) {
    if (depth_ != 2 || field_ == Convention) return scalar("a number");
    if (field_ == Width || field_ == Height) {
      setInteger(cam_, field_, v, path_, line());
      return true;
    }
    return number(static_cast<double>(v), text);
  }
  bool number(double v, const std::string& text) {
    if (depth_ != 2 || field_ == Convention || field_ == Width || field_ == Height) return scalar("a number");
    *floatField(cam_, field_) = toFloat(v, path_, line(), name(), text);
    return true;
  }

  const std::string& text_;
  const std::string& path_;
  const vf::Camera& base_;
  CameraFile& out_;
  int depth_ = 0; // 0 outside, 1 in the array, 2 in a camera object
  int field_ = -1;
  std::string key_;
  std::vector<char> seen_;
  vf::Camera cam_;
  int objectLine_ = 0;
  size_t scanned_ = 0;
  int lines_ = 1;
};

void readJson(const std::string& text, const std::string& path, const vf::Camera& base, CameraFile& out) {
  JsonCameras handler(text, path, base, out);
  handler.consumed = text.data();
  CountingIterator first{text.data(), &handler.consumed}, last{text.data() + text.size(), &handler.consumed};
  nlohmann::json::sax_parse(first, last, &handler);
}

bool endsWithJson(const std::string& path) {
  if (path.size() < 5) return false;
  std::string ext = path.substr(path.size() - 5);
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".json";
}

} // namespace

const std::vector<std::string>& cameraFields() {
  static const std::vector<std::string> f{"eye_x", "eye_y", "eye_z", "target_x", "target_y", "target_z", "up_x",
                                          "up_y",  "up_z",  "fov_y", "near",     "far",      "width",    "height",
                                          "convention"};
  return f;
}

std::string CameraFile::hashText() const {
  char b[32];
  std::snprintf(b, sizeof b, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
  return b;
}

CameraFile readCameraFile(const std::string& path, const vf::Camera& base) {
  CameraFile out;
  out.path = path;
  const std::string text = readWhole(path);
  Fnv fnv;
  fnv.add(text.data(), text.size());
  out.hash = fnv.h;
  if (endsWithJson(path)) readJson(text, path, base, out);
  else readCsv(text, path, base, out);
  if (out.cameras.empty()) fail(path, 1, "", "no cameras in the file");
  return out;
}

} // namespace fftess::cli
