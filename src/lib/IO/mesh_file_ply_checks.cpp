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

} // namespace

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

} // namespace internal
} // namespace MPM
} // namespace CGAL
