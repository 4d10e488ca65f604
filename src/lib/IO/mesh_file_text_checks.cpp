// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Mesh_file_checks.h>

#include <CGAL/MPM/IO/Mesh_io.h>
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
namespace internal {

namespace {

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

} // namespace

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

} // namespace internal
} // namespace MPM
} // namespace CGAL
