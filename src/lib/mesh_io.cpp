// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Mesh_io.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/internal/Mesh_encoding.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/IO/PLY/PLY_reader.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <unordered_map>

namespace CGAL {
namespace MPM {

namespace {

namespace fs = std::filesystem;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;

std::string lower_extension(const std::string& path)
{
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// A token from a file, fit for a one-line message: garbage bytes would
// otherwise break the line or the terminal.
std::string printable(std::string_view token)
{
  std::string r = "\"";
  for(std::size_t i = 0; i < token.size() && i < 24; ++i)
    r += std::isprint(static_cast<unsigned char>(token[i])) ? token[i] : '?';
  if(token.size() > 24) r += "...";
  return r + "\"";
}

std::string face_name(int f) { return "face " + std::to_string(f); }
std::string vertex_name(int v) { return "vertex " + std::to_string(v); }

// Largest coordinate magnitude accepted: its square, and sums of a few such
// squares, stay far below the largest double (1.8e308).
constexpr double max_coordinate_magnitude = 1e150;

// ----------------------------------------------------------------------------
// Text scanning, shared by the OFF header check, the diagnosis of files CGAL
// rejects and the .seg reader.

struct Token
{
  std::string_view text;
  int line = 0;
};

class Text_scanner
{
public:
  explicit Text_scanner(std::string_view text) : text_(text) {}

  // Next white-space separated token; '#' starts a comment up to the end of the line.
  bool next(Token& t)
  {
    for(;;) {
      while(pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
        if(text_[pos_] == '\n') ++line_;
        ++pos_;
      }
      if(pos_ >= text_.size()) return false;
      if(comments_ && text_[pos_] == '#') {
        while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        continue;
      }
      break;
    }
    const std::size_t b = pos_;
    while(pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))
          && !(comments_ && text_[pos_] == '#'))
      ++pos_;
    t.text = text_.substr(b, pos_ - b);
    t.line = line_;
    return true;
  }

  // The tokens left on the line of the last token (OFF vertices and faces are lines).
  std::vector<Token> rest_of_line()
  {
    std::vector<Token> r;
    const int line = line_;
    Token t;
    std::size_t save_pos = pos_;
    int save_line = line_;
    while(next(t) && t.line == line) {
      r.push_back(t);
      save_pos = pos_;
      save_line = line_;
    }
    pos_ = save_pos;
    line_ = save_line;
    return r;
  }

  std::size_t position() const { return pos_; }
  // Skips the character at the current position (even a '#').
  void skip_character() { if(pos_ < text_.size()) ++pos_; }
  void disable_comments() { comments_ = false; }

private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool comments_ = true;
};

template <class Integer>
bool parse_integer(std::string_view s, Integer& value)
{
  if(!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), value);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parse_double(std::string_view s, double& value)
{
  // strtod, unlike from_chars in older libraries, also accepts "nan" and "inf",
  // which must be recognized to be reported as non-finite.
  const std::string copy(s);
  char* end = nullptr;
  value = std::strtod(copy.c_str(), &end);
  return !copy.empty() && end == copy.c_str() + copy.size();
}

// A vertex coordinate of a text mesh file (OFF, OBJ) must be a finite number.
void check_coordinate(const std::string& path, const std::string& element, int line, std::string_view text)
{
  double x;
  if(!parse_double(text, x))
    throw Input_error(path, element, "line " + std::to_string(line) + ": " + printable(text) + " is not a number");
  if(!std::isfinite(x))
    throw Input_error(path, element, "non-finite coordinate " + printable(text) + " (line " + std::to_string(line) +
                                       ")");
}

// A text file that ends before all the elements its header announced.
[[noreturn]] void throw_truncated(const std::string& path, std::uint64_t read, std::uint64_t announced,
                                  const char* elements)
{
  throw Input_error(path, "", "truncated: the file ends after " + std::to_string(read) + " of " +
                                std::to_string(announced) + " " + elements);
}

// ----------------------------------------------------------------------------
// OFF specifics.

struct Off_header
{
  bool binary = false;
  // What the keyword's prefix announces on each vertex line (CGAL's order: [ST][C][N][4][n]OFF).
  bool textures = false, colors = false, normals = false, homogeneous = false;
  std::uint64_t vertices = 0, faces = 0;
  std::string bad_count; // what is wrong with a count CGAL would misread, or empty
};

// CGAL reads the edge count as an int and doubles it (undefined behaviour
// beyond INT_MAX / 2, found by fuzz_mesh_io), and reads it only up to the
// first character that is no digit, so that the rest of a token like "2-1"
// becomes the first vertex or face line it reads: the edge count must be a
// whole number from 0 to INT_MAX / 2. Returns what is wrong, or nothing.
std::string edge_count_problem(std::string_view token)
{
  std::uint64_t value = 0;
  if(!parse_integer(token, value))
    return "the edge count " + printable(token) + " is not a non-negative integer";
  if(value > std::uint64_t(std::numeric_limits<int>::max() / 2))
    return "the edge count " + printable(token) + " is too large for CGAL's reader";
  return {};
}

// The vertex, face and edge counts as tokens (`edges` null when the file
// ends before it); `keyword`: the header started with an OFF keyword, so a
// vertex count that is no integer is a broken header, not another format.
bool parse_vertex_count(std::string_view vertices, bool keyword, Off_header& h)
{
  if(parse_integer(vertices, h.vertices)) return true;
  if(keyword) h.bad_count = "the vertex count " + printable(vertices) + " is not a non-negative integer";
  return false;
}

bool parse_off_counts(const Token& vertices, const Token& faces, const Token* edges, bool keyword, Off_header& h)
{
  if(!parse_vertex_count(vertices.text, keyword, h)) return false;
  if(!parse_integer(faces.text, h.faces)) {
    h.bad_count = "the face count " + printable(faces.text) + " is not a non-negative integer";
    return false;
  }
  if(edges) h.bad_count = edge_count_problem(edges->text);
  return true;
}

// Parses the counts of an OFF header, or returns false when they cannot be
// found (CGAL's reader then reports the failure).
bool parse_off_header(std::string_view text, Off_header& h, Text_scanner& s)
{
  Token t;
  if(!s.next(t)) return false;
  bool counts_follow = true;
  // CGAL's keyword ends at the first character that is not alphanumeric,
  // which it consumes ("OFF/4" is "OFF" and the vertex count 4).
  std::string_view after_keyword_character;
  {
    std::size_t k = 0;
    while(k < t.text.size() && std::isalnum(static_cast<unsigned char>(t.text[k]))) ++k;
    if(k >= 3 && k < t.text.size() && t.text.substr(k - 3, 3) == "OFF") {
      after_keyword_character = t.text.substr(k + 1);
      t.text = t.text.substr(0, k);
    }
  }
  const bool keyword = t.text.size() >= 3 && t.text.substr(t.text.size() - 3) == "OFF";
  // CGAL consumes the character that ends the keyword, so a '#' right
  // after it starts no comment: `COFF#3 2 0` announces 3 vertices.
  if(keyword && after_keyword_character.empty() && s.position() < text.size() && text[s.position()] == '#')
    s.skip_character();
  if(keyword) {
    std::string_view prefix = t.text.substr(0, t.text.size() - 3);
    const auto take = [&prefix](std::string_view flag) {
      if(prefix.substr(0, flag.size()) != flag) return false;
      prefix.remove_prefix(flag.size());
      return true;
    };
    h.textures = take("ST");
    h.colors = take("C");
    h.normals = take("N");
    h.homogeneous = take("4");
  }
  if(!after_keyword_character.empty()) {
    Token nv = t, nf, ne;
    nv.text = after_keyword_character;
    // Refused before looking further: CGAL would read `OFF(BINARY` as a
    // binary header (found by fuzz_mesh_io: its counts escaped this check).
    if(!parse_vertex_count(nv.text, true, h) || !s.next(nf)) return false;
    const bool has_edges = s.next(ne);
    return parse_off_counts(nv, nf, has_edges ? &ne : nullptr, true, h);
  }
  if(keyword) {
    if(t.text.find('n') != std::string_view::npos) { // nOFF: a dimension precedes the counts
      Token dimension;
      if(!s.next(dimension)) return false;
    }
    const std::size_t after_keyword = s.position();
    Token b;
    Text_scanner peek = s;
    if(peek.next(b) && b.text == "BINARY") {
      h.binary = true;
      std::size_t p = text.find('\n', after_keyword);
      if(p == std::string_view::npos) return false;
      ++p;
      if(text.size() < p + 12) return false;
      auto be32 = [&](std::size_t o) {
        std::uint32_t v = 0;
        for(int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(text[o + i]);
        return v;
      };
      h.vertices = be32(p);
      h.faces = be32(p + 4);
      h.bad_count = edge_count_problem(std::to_string(be32(p + 8)));
      return true;
    }
  } else {
    counts_follow = false; // header-less OFF: t is already the vertex count
  }
  Token nv = t, nf;
  if(counts_follow && !s.next(nv)) return false;
  if(!s.next(nf)) return false;
  Token ne;
  const bool has_edges = s.next(ne);
  return parse_off_counts(nv, nf, has_edges ? &ne : nullptr, counts_follow, h);
}

// CGAL's OFF reader allocates the announced number of vertices and faces
// before reading them: refuse counts the file is too small to hold.
void check_off_counts_fit(const std::string& path, std::uintmax_t file_size)
{
  std::ifstream in(path, std::ios::in | std::ios::binary);
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  Off_header h;
  Text_scanner s(head);
  const bool parsed = parse_off_header(head, h, s);
  if(!h.bad_count.empty()) throw Input_error(path, "header", h.bad_count);
  if(!parsed) return;
  // Smallest possible records: "0 0 0\n" and "3 0 1 2\n" as text, three
  // floats and a corner count in binary.
  const std::uint64_t vertex_bytes = h.binary ? 12 : 6, face_bytes = h.binary ? 4 : 8;
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() / 16;
  if(h.vertices > limit || h.faces > limit
     || h.vertices * vertex_bytes + h.faces * face_bytes > file_size)
    throw Input_error(path, "header",
                      "announces " + std::to_string(h.vertices) + " vertices and " +
                        std::to_string(h.faces) + " faces, more than a file of " +
                        std::to_string(file_size) + " bytes can hold (truncated or corrupt)");
}

// The byte size of a PLY scalar type, 0 for a type CGAL does not read.
std::size_t ply_type_size(const std::string& type)
{
  if(type == "char" || type == "int8" || type == "uchar" || type == "uint8") return 1;
  if(type == "short" || type == "int16" || type == "ushort" || type == "uint16") return 2;
  if(type == "int" || type == "int32" || type == "uint" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if(type == "double" || type == "float64") return 8;
  return 0;
}

// Whether a PLY type name is a floating-point one.
bool ply_floating_type(const std::string& type)
{
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

struct Ply_property
{
  std::string name, type; // the item type of a list
  std::string count_type; // empty for a scalar
  int line = 0;           // in the header
};

// A property's type as the header declares it: "float", "list of int".
std::string ply_type_text(const Ply_property& p)
{
  return p.count_type.empty() ? p.type : "list of " + p.type;
}

struct Ply_element
{
  std::string name;
  unsigned long long count = 0;
  std::vector<Ply_property> properties;
};

// The value of a binary PLY number of `type` at `data`.
double ply_binary_value(const char* data, const std::string& type, bool big_endian)
{
  const std::size_t size = ply_type_size(type);
  unsigned char bytes[8];
  std::memcpy(bytes, data, size);
  if(big_endian) std::reverse(bytes, bytes + size);
  const auto as = [&bytes](auto value) {
    std::memcpy(&value, bytes, sizeof value);
    return double(value);
  };
  if(type == "char" || type == "int8") return as(std::int8_t());
  if(type == "uchar" || type == "uint8") return as(std::uint8_t());
  if(type == "short" || type == "int16") return as(std::int16_t());
  if(type == "ushort" || type == "uint16") return as(std::uint16_t());
  if(type == "int" || type == "int32") return as(std::int32_t());
  if(type == "uint" || type == "uint32") return as(std::uint32_t());
  if(type == "float" || type == "float32") return as(float());
  return as(double());
}

// Whether CGAL's PLY reader reads `p` (it skips, reading nothing, a scalar
// of an unknown type and a list whose count is no integer type).
bool read_by_cgal(const Ply_property& p)
{
  if(ply_type_size(p.type) == 0) return false;
  if(p.count_type.empty()) return true;
  return ply_type_size(p.count_type) != 0 && !ply_floating_type(p.count_type);
}

// Whether `token` is a number as CGAL's PLY reader reads one of `type`
// whole: an integer for integer types, digits, sign, point and exponent
// for floating-point ones.
bool ply_ascii_number(std::string_view token, const std::string& type, double& value)
{
  if(!ply_floating_type(type)) {
    long long integer;
    if(!parse_integer(token, integer)) return false;
    value = double(integer);
    return true;
  }
  return token.find_first_not_of("0123456789.eE+-") == std::string_view::npos && parse_double(token, value);
}

// CGAL's PLY reader sizes every list from the count it reads (of any list
// property of any element) before reading the items, and when the file
// ends early, or an ASCII number does not parse, it goes on with counts it
// never initialized: a binary header without `end_header` gave a count of
// 2^32 - 1 and 13.8 GB (found by fuzz_mesh_io). Walk the body as CGAL will
// and refuse a count that is negative or larger than the rest of the file
// can hold, a body that ends early, and ASCII tokens that are no numbers.
void check_ply_body(const std::string& path, const std::string& text, std::size_t body, const std::string& format,
                    const std::vector<Ply_element>& elements)
{
  const bool binary = format != "ascii", big_endian = format == "binary_big_endian";
  Text_scanner tokens(std::string_view(text).substr(std::min(body, text.size())));
  tokens.disable_comments();
  std::size_t at = body;
  for(const Ply_element& e : elements) {
    std::vector<Ply_property> read;
    std::copy_if(e.properties.begin(), e.properties.end(), std::back_inserter(read), read_by_cgal);
    if(read.empty()) continue;
    for(unsigned long long i = 0; i < e.count; ++i) {
      const std::string element = "element " + printable(e.name) + " " + std::to_string(i);
      const auto next = [&](const Ply_property& p, const std::string& type) {
        const std::size_t size = ply_type_size(type);
        double value = 0.;
        if(binary) {
          if(text.size() - std::min(at, text.size()) < size)
            throw Input_error(path, element, "truncated: the file ends in its property " + printable(p.name));
          value = ply_binary_value(text.data() + at, type, big_endian);
          at += size;
          return value;
        }
        Token t;
        if(!tokens.next(t))
          throw Input_error(path, element, "truncated: the file ends in its property " + printable(p.name));
        if(!ply_ascii_number(t.text, type, value))
          throw Input_error(path, element, "property " + printable(p.name) + ": " + printable(t.text) +
                                             " is not a number of type " + type);
        at = body + tokens.position();
        return value;
      };
      for(const Ply_property& p : read) {
        if(p.count_type.empty()) {
          next(p, p.type);
          continue;
        }
        const double count = next(p, p.count_type);
        const double room = double(text.size() - std::min(at, text.size())) / (binary ? double(ply_type_size(p.type)) : 2.);
        if(count < 0 || count > room) {
          std::ostringstream value;
          value << std::setprecision(17) << count;
          throw Input_error(path, element, "list " + printable(p.name) + " announces " + value.str() + " items, " +
                                             (count < 0 ? "a negative count"
                                                        : "more than the rest of the file can hold (corrupt file)"));
        }
        if(binary)
          at += std::size_t(count) * ply_type_size(p.type);
        else
          for(double k = 0; k < count; ++k) next(p, p.type);
      }
    }
  }
}

// CGAL's polygon-soup PLY reader reads a few properties with a fixed type
// and, when the property of that name has another, fails an assertion (in
// Release, dereferences a null pointer): the colours of a vertex or face
// element as uchar, once `red` (or `r`) and its two companions include a
// uchar each, and the `source` and `target` of a `halfedge` element as uint.
void check_ply_fixed_types(const std::string& path, const Ply_element& e)
{
  const auto find = [&e](const std::string& name) -> const Ply_property* {
    for(const Ply_property& p : e.properties)
      if(p.name == name && read_by_cgal(p)) return &p;
    return nullptr;
  };
  const bool vertex_or_face = e.name == "vertex" || e.name == "vertices" || e.name == "face" || e.name == "faces";
  const std::string type = vertex_or_face ? "uchar" : "uint", alias = vertex_or_face ? "uint8" : "uint32";
  const auto typed = [&](const std::string& name) {
    const Ply_property* p = find(name);
    return p != nullptr && p->count_type.empty() && (p->type == type || p->type == alias);
  };
  std::vector<std::string> fixed;
  if(vertex_or_face && (typed("red") || typed("r")) && (typed("green") || typed("g")) && (typed("blue") || typed("b")))
    fixed = typed("red") ? std::vector<std::string>{"red", "green", "blue"} : std::vector<std::string>{"r", "g", "b"};
  if(e.name == "halfedge") fixed = {"source", "target"};
  for(const std::string& name : fixed) {
    const Ply_property* p = find(name);
    if(p != nullptr && !typed(name))
      throw Input_error(path, "header line " + std::to_string(p->line),
                        "property " + printable(name) + " of element " + printable(e.name) + " has type " +
                          printable(ply_type_text(*p)) + " (CGAL reads it as " + type + ")");
  }
}

// CGAL's PLY header reader attaches each `property` line to the last
// `element` and has undefined behaviour (back() of an empty vector) for a
// property before any element; it reads an element count as std::size_t,
// so `-4` becomes 2^64 - 4 and the reader loops (and allocates) that many
// times. Refuse such headers first, then bodies CGAL would misread
// (check_ply_body()). Lines are split as CGAL splits them; the
// check stops where CGAL's would stop.
void check_ply_header(const std::string& path, std::uintmax_t file_size)
{
  const std::string text = internal::read_file(path);
  std::istringstream in(text);
  std::string line, format;
  std::vector<Ply_element> elements;
  for(int number = 1; std::getline(in, line); ++number) {
    std::istringstream iss(line);
    std::string keyword;
    if(number == 1 && !(iss >> keyword && keyword == "ply")) return; // CGAL refuses the signature
    if(number == 2) {
      std::string version;
      if(!(iss >> keyword >> format >> version)) return;
    }
    if(number <= 2) continue;
    if(!(iss >> keyword)) return;
    if(keyword == "end_header") {
      for(const Ply_element& e : elements) check_ply_fixed_types(path, e);
      // An `end_header` that ends the file (no line break) leaves the
      // stream at its end, where tellg() fails; the body is then empty.
      const std::streamoff body = in.tellg();
      check_ply_body(path, text, body >= 0 ? std::size_t(body) : text.size(), format, elements);
      return;
    }
    if(keyword == "element") {
      std::string name, count;
      if(!(iss >> name >> count)) return; // CGAL refuses the line
      const std::string element = "header line " + std::to_string(number);
      if(count[0] == '-')
        throw Input_error(path, element, "element " + printable(name) + " has a negative count " +
                                           printable(count));
      // Every element takes at least one byte, except ones without
      // properties, which are never meaningful in a mesh file.
      const unsigned long long n = std::strtoull(count.c_str(), nullptr, 10);
      if(n > file_size)
        throw Input_error(path, element, "announces " + printable(count) + " elements " + printable(name) +
                                           ", more than a file of " + std::to_string(file_size) +
                                           " bytes can hold (truncated or corrupt)");
      elements.push_back({name, n, {}});
    }
    if(keyword == "property" && elements.empty())
      throw Input_error(path, "header line " + std::to_string(number),
                        "a property declared before any element (malformed PLY header)");
    Ply_property property;
    property.line = number;
    if(keyword != "property" || !(iss >> property.type >> property.name)) continue;
    if(property.type == "list") {
      property.count_type = property.name;
      if(!(iss >> property.type >> property.name)) return; // CGAL refuses the line
    }
    // CGAL looks a property up by name and asserts (or, in Release,
    // dereferences a null pointer) when the first of that name is not of
    // the type it expects.
    for(const Ply_property& earlier : elements.back().properties)
      if(earlier.name == property.name)
        throw Input_error(path, "header line " + std::to_string(number),
                          "property " + printable(property.name) + " declared twice in element " +
                            printable(elements.back().name));
    elements.back().properties.push_back(property);
    // CGAL reads coordinates only from float or double properties: it
    // dereferences a null pointer for any other type, a list included
    // (`property list uchar uchar y` of an element `vertex`, or `vertices`
    // which CGAL reads alike, found by fuzz_mesh_io).
    const std::string& name = property.name;
    const bool vertex = elements.back().name == "vertex" || elements.back().name == "vertices";
    if(vertex && (name == "x" || name == "y" || name == "z")
       && (!property.count_type.empty() || !ply_floating_type(property.type)))
      throw Input_error(path, "header line " + std::to_string(number),
                        "vertex coordinate " + printable(name) + " has type " + printable(ply_type_text(property)) +
                          " (supported: float, double)");
  }
  // CGAL reads the body from wherever the header ends, with uninitialized
  // numbers when that is the end of the file.
  if(!elements.empty())
    throw Input_error(path, "header", "has no end_header line (truncated, or not a PLY file)");
}

// The numbers CGAL's ASCII OFF reader finds on a vertex or face line, read
// as it reads them (File_scanner_OFF with IO::iformat, which is operator>>
// of std::istream for a double except on old MSVC): the line ends at '#',
// and reading stops at the first thing that is no number ("1e", "+-5",
// "nan", "1e999" and a byte like NUL all stop it). Counting them otherwise
// than CGAL would miss its out-of-bounds reads.
struct Off_number
{
  double value;
  std::string text; // as CGAL read it
};

std::vector<Off_number> cgal_off_numbers(std::string_view line)
{
  const std::string text(line.substr(0, line.find('#')));
  std::istringstream in(text);
  std::vector<Off_number> numbers;
  for(;;) {
    in >> std::ws;
    const std::streamoff begin = in.tellg();
    double value;
    if(begin < 0 || !(in >> value)) return numbers;
    const std::streamoff end = in.eof() ? std::streamoff(text.size()) : std::streamoff(in.tellg());
    numbers.push_back({value, text.substr(std::size_t(begin), std::size_t(end - begin))});
  }
}

// The text of the line that starts at `t` (the line CGAL reads as one vertex or face).
std::string_view line_from(std::string_view text, const Token& t)
{
  const std::size_t begin = std::size_t(t.text.data() - text.data());
  return text.substr(begin, text.find('\n', begin) - begin);
}

// Whether `x` has a value when cast to an integer type whose range is [0, limit).
bool castable(double x, double limit) { return x > -1. && x < limit; }

// Checks the colour numbers of a vertex or face line of a COFF file.
// CGAL decides from the first line with colours that all later lines have
// them, then reads them by position: past the end of a line with none or
// with two; it casts a colour index to int and indexes a table with it, and
// casts components to unsigned char. `coloured`: an earlier line had colours.
void check_off_colour(const std::string& path, const std::string& element, int line,
                      const std::vector<Off_number>& numbers, std::size_t first, bool& coloured)
{
  const std::size_t count = numbers.size() - first;
  const std::string where = "line " + std::to_string(line) + ": ";
  if(count == 0 && coloured)
    throw Input_error(path, element, where + "no colour, but an earlier line of this COFF file has one");
  if(count == 0) return;
  coloured = true;
  if(count == 2)
    throw Input_error(path, element, where + "2 colour numbers (a colour is an index or 3 or 4 components)");
  if(count == 1) {
    if(!castable(numbers[first].value, 2147483648.))
      throw Input_error(path, element, where + "colour index " + printable(numbers[first].text) + " is out of range");
    return;
  }
  const bool integers = std::all_of(numbers.begin() + long(first), numbers.begin() + long(first) + 3,
                                    [](const Off_number& c) { return std::floor(c.value) == c.value; });
  for(std::size_t c = first; c < first + 3; ++c)
    if(!castable(integers ? numbers[c].value : numbers[c].value * 255., 256.))
      throw Input_error(path, element, where + "colour component " + printable(numbers[c].text) +
                                         " is out of range (0 to 255, or 0 to 1 when not all are integers)");
}

// CGAL's ASCII OFF reader reads vertex and face lines without checking
// them where it would overrun or cast out of range: refuse such lines
// first. It casts the corner count and vertex indices of a face (doubles)
// to std::size_t: undefined for -1 or less and for 2^64 or more. In a file
// with colours (COFF) see check_off_colour(); with texture coordinates
// (STOFF) it reads them past a vertex line that has too few numbers, and,
// without colours, at an uninitialized position. With homogeneous
// coordinates (4OFF) it asserts that w is not 0. Anything else is left to
// CGAL, whose failures diagnose_off() explains.
std::string check_off_lines(const std::string& path)
{
  const std::string text = internal::read_file(path);
  Text_scanner s(text);
  Off_header h;
  if(!parse_off_header(text, h, s) || h.binary) return "";
  if(h.textures && !h.colors)
    throw Input_error(path, "header", "texture coordinates without colours (STOFF) are not supported: "
                                      "CGAL's reader misreads them");
  const std::size_t w = h.homogeneous ? 1 : 0;
  const std::size_t vertex_numbers = 3 + w + (h.normals ? 3 + w : 0) + (h.textures ? 2 + w : 0);
  bool coloured = false;
  Token t;
  for(std::uint64_t v = 0; v < h.vertices; ++v) {
    if(!s.next(t)) {
      if(h.colors) throw_truncated(path, v, h.vertices, "vertices");
      return "";
    }
    const std::vector<Off_number> numbers = cgal_off_numbers(line_from(text, t));
    s.rest_of_line();
    const std::string element = vertex_name(int(std::min<std::uint64_t>(v, std::numeric_limits<int>::max())));
    if((h.colors || h.homogeneous) && numbers.size() < vertex_numbers)
      throw Input_error(path, element, "line " + std::to_string(t.line) + ": " + std::to_string(numbers.size()) +
                                         (numbers.size() == 1 ? " number" : " numbers") + ", fewer than the " + std::to_string(vertex_numbers) +
                                         " its header announces");
    if(h.homogeneous && numbers[3].value == 0.)
      throw Input_error(path, element, "line " + std::to_string(t.line) + ": homogeneous coordinate w is 0");
    if(h.colors) check_off_colour(path, element, t.line, numbers, vertex_numbers, coloured);
  }
  coloured = false;
  for(std::uint64_t f = 0; f < h.faces; ++f) {
    // At the end of the file CGAL reads an empty face and, once a face had
    // colours, its colour from past the end of no numbers.
    if(!s.next(t)) {
      if(h.colors) throw_truncated(path, f, h.faces, "faces");
      return "";
    }
    const std::vector<Off_number> numbers = cgal_off_numbers(line_from(text, t));
    s.rest_of_line();
    const std::string element = face_name(int(std::min<std::uint64_t>(f, std::numeric_limits<int>::max())));
    const std::string where = "line " + std::to_string(t.line) + ": ";
    if(numbers.empty() && h.colors) throw Input_error(path, element, where + "no corner count");
    if(numbers.empty()) return "";
    if(!castable(numbers[0].value, 18446744073709551616.))
      throw Input_error(path, element, where + "corner count " + printable(numbers[0].text) +
                                         " is not a non-negative integer");
    const std::size_t announced = std::size_t(numbers[0].value);
    for(std::size_t c = 1; c < numbers.size() && c <= announced; ++c)
      if(!castable(numbers[c].value, 18446744073709551616.))
        throw Input_error(path, element, where + "vertex index " + printable(numbers[c].text) + " is out of range");
    if(h.colors && numbers.size() > announced) check_off_colour(path, element, t.line, numbers, announced + 1, coloured);
  }
  // CGAL stops reading at the last announced face.
  if(s.next(t))
    return path + ": line " + std::to_string(t.line) + ": text after the last of the " + std::to_string(h.faces) +
           " faces (" + printable(t.text) + ") is ignored";
  return "";
}

// Finds why CGAL rejected an ASCII OFF file, so that the message names the
// element. Returns without throwing when it finds nothing wrong.
void diagnose_off(const std::string& path, const std::string& text)
{
  Text_scanner s(text);
  Off_header h;
  {
    Text_scanner first = s;
    Token t;
    if(!first.next(t))
      throw Input_error(path, "", "contains only comments and white space");
    const bool keyword = t.text.size() >= 3 && t.text.substr(t.text.size() - 3) == "OFF";
    std::uint64_t n;
    if(!keyword && !parse_integer(t.text, n))
      throw Input_error(path, "", "is not an OFF file (it starts with " + printable(t.text) + ")");
  }
  if(!parse_off_header(text, h, s))
    throw Input_error(path, "header", "expected the vertex, face and edge counts");
  if(h.binary) return;

  Token t;
  for(std::uint64_t v = 0; v < h.vertices; ++v) {
    const std::string element = vertex_name(int(v));
    if(!s.next(t)) throw_truncated(path, v, h.vertices, "vertices");
    std::vector<Token> line{t};
    for(const Token& r : s.rest_of_line()) line.push_back(r);
    if(line.size() < 3)
      throw Input_error(path, element, "line " + std::to_string(t.line) + ": fewer than 3 coordinates");
    for(int c = 0; c < 3; ++c) check_coordinate(path, element, t.line, line[c].text);
  }
  for(std::uint64_t f = 0; f < h.faces; ++f) {
    const std::string element = face_name(int(f));
    if(!s.next(t)) throw_truncated(path, f, h.faces, "faces");
    std::uint64_t corners;
    if(!parse_integer(t.text, corners))
      throw Input_error(path, element, "line " + std::to_string(t.line) + ": corner count " +
                                         printable(t.text) + " is not a non-negative integer");
    const std::vector<Token> line = s.rest_of_line();
    if(line.size() < corners)
      throw Input_error(path, element, "line " + std::to_string(t.line) + ": " +
                                         std::to_string(line.size()) + " of " + std::to_string(corners) +
                                         " vertex indices (truncated?)");
    for(std::uint64_t c = 0; c < corners; ++c) {
      std::int64_t id;
      if(!parse_integer(line[c].text, id))
        throw Input_error(path, element, "line " + std::to_string(t.line) + ": " + printable(line[c].text) +
                                           " is not a vertex index");
      if(id < 0 || std::uint64_t(id) >= h.vertices)
        throw Input_error(path, element, "vertex index " + std::to_string(id) +
                                           " is out of range (the file has " +
                                           std::to_string(h.vertices) + " vertices)");
    }
  }
}

// Finds the vertex coordinate or face corner that made CGAL reject an OBJ file.
void diagnose_obj(const std::string& path, const std::string& text)
{
  std::istringstream lines(text);
  std::string line;
  std::vector<std::pair<int, std::string>> face_lines;
  int line_number = 0;
  std::int64_t vertices = 0;
  while(std::getline(lines, line)) {
    ++line_number;
    if(line.size() < 2 || !std::isspace(static_cast<unsigned char>(line[1]))) continue;
    if(line[0] == 'f') face_lines.emplace_back(line_number, line.substr(1));
    if(line[0] != 'v') continue;
    Text_scanner s(std::string_view(line).substr(1));
    const std::string element = vertex_name(int(vertices++));
    Token t;
    for(int c = 0; c < 3; ++c) {
      if(!s.next(t))
        throw Input_error(path, element, "line " + std::to_string(line_number) + ": fewer than 3 coordinates");
      check_coordinate(path, element, line_number, t.text);
    }
  }
  for(std::size_t f = 0; f < face_lines.size(); ++f) {
    Text_scanner s(face_lines[f].second);
    Token t;
    while(s.next(t)) {
      // A corner is "v", "v/vt", "v//vn" or "v/vt/vn"; negative v counts back from the end.
      const std::string_view v = t.text.substr(0, t.text.find('/'));
      std::int64_t id;
      if(!parse_integer(v, id))
        throw Input_error(path, face_name(int(f)), "line " + std::to_string(face_lines[f].first) + ": " +
                                                     printable(t.text) + " is not a vertex index");
      if(id == 0)
        throw Input_error(path, face_name(int(f)), "line " + std::to_string(face_lines[f].first) +
                                                     ": vertex index 0 is not valid (OBJ indices start at 1; "
                                                     "negative ones count back from the last vertex)");
      if(id > vertices || id < -vertices)
        throw Input_error(path, face_name(int(f)), "vertex index " + std::to_string(id) +
                                                     " is out of range (the file has " +
                                                     std::to_string(vertices) + " vertices)");
    }
  }
}

// ----------------------------------------------------------------------------

// CGAL's OFF reader sizes a polygon from the corner count in the file before
// reading the corners: bound it by the file size so a corrupt count cannot
// allocate gigabytes.
struct Corner_limit_exceeded {};

struct Bounded_polygon : std::vector<std::size_t>
{
  static thread_local std::size_t corner_limit;

  void resize(std::size_t n)
  {
    if(n > corner_limit) throw Corner_limit_exceeded();
    std::vector<std::size_t>::resize(n);
  }
};
thread_local std::size_t Bounded_polygon::corner_limit = 0;

// Checks shared by the file reader and validate_labeled_mesh(): finite
// coordinates, in-range distinct corners, non-zero area. `file_face` maps
// triangles to the face numbers the user sees (null: triangle numbers).
void check_mesh_geometry(const Indexed_mesh& mesh, const std::string& source,
                         const std::vector<int>* file_face)
{
  if(mesh.number_of_faces() == 0)
    throw Input_error(source, "", "contains no faces");
  const int n = mesh.number_of_vertices();
  for(int v = 0; v < n; ++v)
    if(!mesh.points.row(v).allFinite()) {
      std::ostringstream c;
      c << mesh.points(v, 0) << ", " << mesh.points(v, 1) << ", " << mesh.points(v, 2);
      throw Input_error(source, vertex_name(v), "non-finite coordinate (" + c.str() + ")");
    }
  // Squared lengths (the bounding box, areas, every energy) must not
  // overflow: a coordinate beyond 1e150 in magnitude is refused rather than
  // turned into infinities downstream.
  for(int v = 0; v < n; ++v) {
    Eigen::Index axis;
    const double largest = mesh.points.row(v).cwiseAbs().maxCoeff(&axis);
    if(largest > max_coordinate_magnitude) {
      std::ostringstream c;
      c << mesh.points(v, axis);
      throw Input_error(source, vertex_name(v), "coordinate " + c.str() +
                                                  " is too large (beyond 1e150 in magnitude, squared lengths "
                                                  "would overflow)");
    }
  }
  // The bounding-box diagonal, without underflow for tiny coordinates.
  const double diagonal =
    n == 0 ? 0. : (mesh.points.colwise().maxCoeff() - mesh.points.colwise().minCoeff()).stableNorm();
  // Twice the area of a triangle counted as flat: 1e-14 of the squared
  // bounding-box diagonal, far below any modelled feature yet above rounding.
  // Edges are measured in diagonals, so that the test holds at any scale
  // (squares of coordinates near 1e-160 would underflow to zero).
  const double flat_cross_norm = 2e-14;

  for(int t = 0; t < mesh.number_of_faces(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const std::string element = face_name(file_face ? (*file_face)[t] : t);
    const std::string corners = std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
                                std::to_string(tri[2]);
    for(int c = 0; c < 3; ++c)
      if(tri[c] < 0 || tri[c] >= n)
        throw Input_error(source, element, "vertex index " + std::to_string(tri[c]) +
                                             " is out of range (the mesh has " + std::to_string(n) +
                                             " vertices)");
    if(tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw Input_error(source, element, "degenerate triangle (vertices " + corners + ")");
    const Eigen::Vector3d a = mesh.points.row(tri[0]), b = mesh.points.row(tri[1]),
                          c = mesh.points.row(tri[2]);
    if(diagonal == 0. || ((b - a) / diagonal).cross((c - a) / diagonal).norm() <= flat_cross_norm)
      throw Input_error(source, element, "degenerate triangle (zero area, vertices " + corners + ")");
  }
}

Mesh_file mesh_from_polygons(const std::string& path, const std::vector<Point_3>& points,
                             const std::vector<Bounded_polygon>& polygons, bool one_based_indices)
{
  if(polygons.empty())
    throw Input_error(path, "", "contains no faces");
  if(points.size() > std::size_t(std::numeric_limits<int>::max())
     || polygons.size() > std::size_t(std::numeric_limits<int>::max()))
    throw Input_error(path, "", "too many vertices or faces for this library (more than 2^31)");

  Mesh_file r;
  const std::size_t n = points.size();
  r.mesh.points.resize(Eigen::Index(n), 3);
  for(std::size_t v = 0; v < n; ++v)
    r.mesh.points.row(Eigen::Index(v)) << points[v].x(), points[v].y(), points[v].z();
  r.number_of_file_faces = int(polygons.size());

  int fanned = 0, first_fanned = -1;
  std::vector<char> used(n, 0);
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const Bounded_polygon& p = polygons[f];
    const std::string element = face_name(int(f));
    if(p.size() < 3)
      throw Input_error(path, element, "has " + std::to_string(p.size()) +
                                         " corners (a face needs at least 3)");
    for(std::size_t id : p)
      if(id >= n)
        throw Input_error(path, element, "vertex index " +
                                           std::to_string(one_based_indices ? id + 1 : id) +
                                           " is out of range (the file has " + std::to_string(n) +
                                           " vertices)");
    if(p.size() > 3 && fanned++ == 0) first_fanned = int(f);
    for(std::size_t c = 1; c + 1 < p.size(); ++c) {
      r.mesh.triangles.push_back({int(p[0]), int(p[c]), int(p[c + 1])});
      r.file_face.push_back(int(f));
    }
    for(std::size_t id : p) used[id] = 1;
  }
  check_mesh_geometry(r.mesh, path, &r.file_face);

  if(fanned > 0)
    r.warnings.push_back(path + ": " + std::to_string(fanned) + " polygon" + (fanned > 1 ? "s" : "") +
                         " with more than 3 corners " + (fanned > 1 ? "were" : "was") +
                         " fan-triangulated (first: face " + std::to_string(first_fanned) + ")");
  // Faces over the same three vertices (in any order): kept, but a mesh
  // with them is not manifold, and the user should know.
  std::map<std::array<int, 3>, int> file_face_of;
  int repeated = 0, first_repeat = -1, first_original = -1;
  for(std::size_t k = 0; k < r.mesh.triangles.size(); ++k) {
    std::array<int, 3> key = r.mesh.triangles[k];
    std::sort(key.begin(), key.end());
    const auto [it, added] = file_face_of.emplace(key, r.file_face[k]);
    if(!added && repeated++ == 0) {
      first_repeat = r.file_face[k];
      first_original = it->second;
    }
  }
  if(repeated > 0)
    r.warnings.push_back(path + ": " + std::to_string(repeated) + " face" + (repeated > 1 ? "s repeat" : " repeats") +
                         " the vertices of another (first: face " + std::to_string(first_repeat) + " repeats face " +
                         std::to_string(first_original) + "); kept");
  const std::size_t unused = std::size_t(std::count(used.begin(), used.end(), 0));
  if(unused > 0) {
    const std::size_t first = std::size_t(std::find(used.begin(), used.end(), 0) - used.begin());
    r.warnings.push_back(path + ": " + std::to_string(unused) + " " + (unused > 1 ? "vertices are" : "vertex is") +
                         " not used by any face (first: vertex " + std::to_string(first) +
                         "); kept");
  }
  return r;
}

// Calls `f` with a value of each C++ type CGAL's PLY reader gives a scalar
// property (double also stands for float: PLY_element reads both as double).
template <typename F>
void for_each_ply_scalar_type(F f)
{
  f(std::int8_t()), f(std::uint8_t()), f(std::int16_t()), f(std::uint16_t()), f(std::int32_t()), f(std::uint32_t()),
    f(double());
}

// Whether `e` has a scalar (not list) property `name`, and whether it is
// floating-point.
bool has_ply_scalar(CGAL::IO::internal::PLY_element& e, const std::string& name, bool& floating)
{
  bool found = false;
  for_each_ply_scalar_type([&](auto tag) {
    if(found || !e.template has_property<decltype(tag)>(name.c_str())) return;
    found = true;
    floating = std::is_floating_point<decltype(tag)>::value;
  });
  return found;
}

// The integer scalar property `name` of the item of `e` read last.
std::intmax_t ply_integer(CGAL::IO::internal::PLY_element& e, const std::string& name)
{
  std::intmax_t value = 0;
  for_each_ply_scalar_type([&](auto tag) {
    using T = decltype(tag);
    if constexpr(std::is_integral<T>::value)
      if(e.template has_property<T>(name.c_str())) {
        T v;
        e.assign(v, name.c_str());
        value = std::intmax_t(v);
      }
  });
  return value;
}

// Face labels stored as an integer face property of a PLY file, in file face
// order. Read with the PLY element reader behind CGAL's PLY readers, after
// check_ply_header() and check_ply_body() accepted the file. CGAL's
// Surface_mesh PLY reader is not used: it needs a manifold mesh, and an
// `edge` or `halfedge` element makes it branch on a flag it never set (found
// by fuzz_mesh_io) and index its vertex table with unchecked file values.
std::vector<int> read_ply_face_property(const std::string& path, const std::string& name)
{
  if(lower_extension(path) != ".ply")
    throw Input_error(path, "", "face property labels (property:" + name + ") need a PLY file");
  std::ifstream in(path, std::ios::in | std::ios::binary);
  CGAL::IO::internal::PLY_reader reader(false);
  if(!in || !reader.init(in))
    throw Input_error(path, "", "cannot be read as ply (for face property \"" + name + "\")");
  std::vector<int> labels;
  for(std::size_t i = 0; i < reader.number_of_elements(); ++i) {
    CGAL::IO::internal::PLY_element& e = reader.element(i);
    const bool face = e.name() == "face" || e.name() == "faces";
    bool floating = false;
    if(face && !has_ply_scalar(e, name, floating)) {
      std::string available;
      for(std::size_t k = 0; k < e.number_of_properties(); ++k) {
        bool unused;
        if(has_ply_scalar(e, e.property(k)->name(), unused))
          available += (available.empty() ? "" : ", ") + e.property(k)->name();
      }
      throw Input_error(path, "", "has no face property \"" + name + "\" (face properties: " +
                                    (available.empty() ? "none" : available) + ")");
    }
    if(floating)
      throw Input_error(path, "", "face property \"" + name + "\" holds floating-point values, not integer labels");
    for(std::size_t item = 0; item < e.number_of_items(); ++item) {
      for(std::size_t k = 0; k < e.number_of_properties(); ++k) e.property(k)->get(in);
      if(!in)
        throw Input_error(path, "element " + printable(e.name()) + " " + std::to_string(item),
                          "cannot be read (truncated or corrupt file)");
      if(!face) continue;
      const std::intmax_t value = ply_integer(e, name);
      if(value < 0)
        throw Input_error(path, face_name(int(labels.size())),
                          "negative label " + std::to_string(value) + " in face property \"" + name + "\"");
      if(value > std::numeric_limits<int>::max())
        throw Input_error(path, face_name(int(labels.size())), "label " + std::to_string(value) + " is too large");
      labels.push_back(int(value));
    }
  }
  return labels;
}

} // namespace

Mesh_file read_mesh_file(const std::string& path)
{
  internal::check_readable_file(path);
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if(ec || size == 0)
    throw Input_error(path, "", "file is empty");
  const std::string ext = lower_extension(path);
  if(ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl")
    throw Input_error(path, "", "unsupported mesh file extension " + printable(ext.empty() ? "(none)" : ext) +
                                  " (supported: .off, .obj, .ply, .stl)");
  if(ext == ".off")
    check_off_counts_fit(path, size);
  std::string trailing_text;
  if(ext == ".off")
    trailing_text = check_off_lines(path);
  if(ext == ".ply")
    check_ply_header(path, size);
  // CGAL reads the OBJ index 0 (invalid: indices start at 1) as another
  // vertex, and the error then names the wrong one.
  if(ext == ".obj")
    diagnose_obj(path, internal::read_file(path));

  std::vector<Point_3> points;
  std::vector<Bounded_polygon> polygons;
  Bounded_polygon::corner_limit = std::size_t(size / 2);
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch(const Corner_limit_exceeded&) {
    throw Input_error(path, "", "a face announces more corners than the file can hold (corrupt file)");
  } catch(const std::length_error&) {
    // CGAL's PLY reader sizes a list from a (possibly negative) count it read.
    throw Input_error(path, "", "cannot be read as " + ext.substr(1) + " (a list size is negative or absurd: corrupt file)");
  }
  if(!ok) {
    if(ext == ".off") diagnose_off(path, internal::read_file(path));
    throw Input_error(path, "", "cannot be read as " + ext.substr(1) + " (malformed or truncated file)");
  }
  if(polygons.empty() && ext == ".stl") // CGAL reads a cut or foreign STL file as one without facets
    throw Input_error(path, "", "contains no faces (an empty, truncated or non-STL file)");
  Mesh_file file = mesh_from_polygons(path, points, polygons, ext == ".obj");
  if(!trailing_text.empty()) file.warnings.push_back(trailing_text);
  return file;
}

std::vector<int> read_seg_file(const std::string& path)
{
  const std::string text = internal::read_file(path);
  Text_scanner s(text);
  s.disable_comments();
  std::vector<int> labels;
  Token t;
  while(s.next(t)) {
    const std::string element = "line " + std::to_string(t.line);
    long long value;
    const bool integer = parse_integer(t.text, value);
    if(!integer) {
      const bool digits = !t.text.empty() &&
        std::all_of(t.text.begin() + (t.text[0] == '-' || t.text[0] == '+'), t.text.end(),
                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
      throw Input_error(path, element, printable(t.text) + (digits ? " is too large for a label"
                                                                : " is not an integer label"));
    }
    if(value < 0)
      throw Input_error(path, element, "negative label " + std::to_string(value));
    if(value > std::numeric_limits<int>::max())
      throw Input_error(path, element, printable(t.text) + " is too large for a label");
    labels.push_back(int(value));
  }
  if(labels.empty())
    throw Input_error(path, "", "is empty (expected one label per face)");
  return labels;
}

std::vector<int> connected_component_labels(const Indexed_mesh& mesh)
{
  const int nf = mesh.number_of_faces();
  std::vector<int> parent(static_cast<std::size_t>(nf));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int f) {
    while(parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  std::unordered_map<std::uint64_t, int> face_of_edge;
  face_of_edge.reserve(std::size_t(nf) * 2);
  for(int f = 0; f < nf; ++f)
    for(int c = 0; c < 3; ++c) {
      const std::uint32_t a = std::uint32_t(mesh.triangles[f][c]), b = std::uint32_t(mesh.triangles[f][(c + 1) % 3]);
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      const auto inserted = face_of_edge.emplace(key, f);
      if(!inserted.second) {
        const int r1 = find(f), r2 = find(inserted.first->second);
        parent[std::max(r1, r2)] = std::min(r1, r2);
      }
    }
  std::vector<int> labels(std::size_t(nf), -1), label_of_root(std::size_t(nf), -1);
  int next = 0;
  for(int f = 0; f < nf; ++f) {
    int& l = label_of_root[find(f)];
    if(l < 0) l = next++;
    labels[f] = l;
  }
  return labels;
}

Labeled_mesh read_labeled_mesh(const std::string& mesh_path, const std::string& labels,
                               std::vector<std::string>* warnings)
{
  Mesh_file file = read_mesh_file(mesh_path);
  if(warnings) warnings->insert(warnings->end(), file.warnings.begin(), file.warnings.end());

  Labeled_mesh r;
  r.source = mesh_path;
  if(labels == "components") {
    r.face_labels = connected_component_labels(file.mesh);
  } else {
    const std::string property_prefix = "property:";
    const bool from_property = labels.rfind(property_prefix, 0) == 0;
    const std::vector<int> per_file_face = from_property
      ? read_ply_face_property(mesh_path, labels.substr(property_prefix.size()))
      : read_seg_file(labels);
    if(per_file_face.size() != std::size_t(file.number_of_file_faces))
      throw Input_error(from_property ? mesh_path : labels, "",
                        "has " + std::to_string(per_file_face.size()) + " labels but " + mesh_path +
                          " has " + std::to_string(file.number_of_file_faces) + " faces");
    r.face_labels.reserve(file.file_face.size());
    for(int f : file.file_face) r.face_labels.push_back(per_file_face[std::size_t(f)]);
  }
  r.mesh = std::move(file.mesh);
  return r;
}

void write_mesh_file(const Indexed_mesh& mesh, const std::string& path,
                     const Eigen::Matrix<unsigned char, Eigen::Dynamic, 3>* face_colors,
                     const Mesh_write_options& options)
{
  const std::string ext = lower_extension(path);
  if(ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl")
    throw Input_error(path, "", "unsupported extension " + printable(ext.empty() ? "(none)" : ext) +
                                  " for writing a mesh (supported: .off, .obj, .ply, .stl)");
  if(face_colors && face_colors->rows() != mesh.number_of_faces())
    throw Input_error(path, "", std::to_string(face_colors->rows()) + " face colours for " +
                                  std::to_string(mesh.number_of_faces()) + " faces");
  const bool colors = face_colors && ext == ".ply";
  if(ext == ".stl")
    return internal::write_file_atomically(
      path, [&](std::ostream& out) { internal::write_stl(out, mesh, options.binary); }, options.binary);
  if(ext == ".ply" && options.binary)
    return internal::write_file_atomically(
      path, [&](std::ostream& out) { internal::write_binary_ply(out, mesh, colors ? face_colors : nullptr); }, true);

  internal::write_file_atomically(path, [&](std::ostream& out) {
    // 17 significant digits make every double read back exactly.
    out << std::setprecision(17);
    const int nv = mesh.number_of_vertices(), nf = mesh.number_of_faces();
    if(ext == ".off") {
      out << "OFF\n" << nv << ' ' << nf << " 0\n";
    } else if(ext == ".ply") {
      out << "ply\nformat ascii 1.0\ncomment written by CGAL-MPM\n"
          << "element vertex " << nv << "\nproperty double x\nproperty double y\nproperty double z\n"
          << "element face " << nf << "\nproperty list uchar int vertex_indices\n";
      if(colors) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
      out << "end_header\n";
    }
    for(int v = 0; v < nv; ++v)
      out << (ext == ".obj" ? "v " : "") << mesh.points(v, 0) << ' ' << mesh.points(v, 1) << ' '
          << mesh.points(v, 2) << '\n';
    for(int f = 0; f < nf; ++f) {
      const Triangle& t = mesh.triangles[f];
      if(ext == ".obj")
        out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
      else
        out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2];
      if(colors)
        out << ' ' << int((*face_colors)(f, 0)) << ' ' << int((*face_colors)(f, 1)) << ' '
            << int((*face_colors)(f, 2));
      if(ext != ".obj") out << '\n';
    }
  });
}

void write_seg_file(const std::vector<int>& labels, const std::string& path)
{
  internal::write_file_atomically(path, [&](std::ostream& out) {
    for(int l : labels) out << l << '\n';
  });
}

void validate_labeled_mesh(const Labeled_mesh& mesh)
{
  check_mesh_geometry(mesh.mesh, mesh.source, nullptr);
  if(mesh.face_labels.size() != std::size_t(mesh.mesh.number_of_faces()))
    throw Input_error(mesh.source, "", "has " + std::to_string(mesh.face_labels.size()) +
                                         " face labels for " + std::to_string(mesh.mesh.number_of_faces()) +
                                         " faces");
  for(std::size_t f = 0; f < mesh.face_labels.size(); ++f)
    if(mesh.face_labels[f] < 0)
      throw Input_error(mesh.source, face_name(int(f)), "negative label " + std::to_string(mesh.face_labels[f]));
}

} // namespace MPM
} // namespace CGAL
